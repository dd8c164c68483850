file(REMOVE_RECURSE
  "CMakeFiles/test_zone_output.dir/unit/test_zone_output.f90.o"
  "test_zone_output"
  "test_zone_output.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_zone_output.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
