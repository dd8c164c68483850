file(REMOVE_RECURSE
  "CMakeFiles/udec_geometry.dir/src/geometry/geometry_blocks.f90.o"
  "CMakeFiles/udec_geometry.dir/src/geometry/geometry_cutting.f90.o"
  "CMakeFiles/udec_geometry.dir/src/geometry/geometry_joint_sets.f90.o"
  "CMakeFiles/udec_geometry.dir/src/geometry/geometry_polygon.f90.o"
  "libudec_geometry.a"
  "libudec_geometry.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/udec_geometry.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
