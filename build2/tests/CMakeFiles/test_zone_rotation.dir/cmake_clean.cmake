file(REMOVE_RECURSE
  "CMakeFiles/test_zone_rotation.dir/unit/test_zone_rotation.f90.o"
  "test_zone_rotation"
  "test_zone_rotation.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_zone_rotation.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
