file(REMOVE_RECURSE
  "CMakeFiles/test_zones_mesh.dir/unit/test_zones_mesh.f90.o"
  "test_zones_mesh"
  "test_zones_mesh.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_zones_mesh.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
