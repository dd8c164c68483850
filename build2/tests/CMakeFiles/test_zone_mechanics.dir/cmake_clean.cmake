file(REMOVE_RECURSE
  "CMakeFiles/test_zone_mechanics.dir/unit/test_zone_mechanics.f90.o"
  "test_zone_mechanics"
  "test_zone_mechanics.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_zone_mechanics.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
