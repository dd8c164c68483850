file(REMOVE_RECURSE
  "CMakeFiles/udec_zones.dir/src/zones/zones_boundary.f90.o"
  "CMakeFiles/udec_zones.dir/src/zones/zones_boundary_setup.f90.o"
  "CMakeFiles/udec_zones.dir/src/zones/zones_ffield.f90.o"
  "CMakeFiles/udec_zones.dir/src/zones/zones_generate.f90.o"
  "CMakeFiles/udec_zones.dir/src/zones/zones_mechanics.f90.o"
  "CMakeFiles/udec_zones.dir/src/zones/zones_mesh.f90.o"
  "CMakeFiles/udec_zones.dir/src/zones/zones_mesh_base.f90.o"
  "CMakeFiles/udec_zones.dir/src/zones/zones_mesh_manual.f90.o"
  "CMakeFiles/udec_zones.dir/src/zones/zones_mesh_quad.f90.o"
  "CMakeFiles/udec_zones.dir/src/zones/zones_mixed.f90.o"
  "CMakeFiles/udec_zones.dir/src/zones/zones_models.f90.o"
  "CMakeFiles/udec_zones.dir/src/zones/zones_pressure.f90.o"
  "CMakeFiles/udec_zones.dir/src/zones/zones_refinement.f90.o"
  "CMakeFiles/udec_zones.dir/src/zones/zones_triangulation.f90.o"
  "CMakeFiles/udec_zones.dir/src/zones/zones_viscous.f90.o"
  "libudec_zones.a"
  "libudec_zones.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/udec_zones.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
