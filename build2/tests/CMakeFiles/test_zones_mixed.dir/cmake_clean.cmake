file(REMOVE_RECURSE
  "CMakeFiles/test_zones_mixed.dir/unit/test_zones_mixed.f90.o"
  "test_zones_mixed"
  "test_zones_mixed.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_zones_mixed.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
