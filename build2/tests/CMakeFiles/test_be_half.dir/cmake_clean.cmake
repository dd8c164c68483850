file(REMOVE_RECURSE
  "CMakeFiles/test_be_half.dir/unit/test_be_half.f90.o"
  "test_be_half"
  "test_be_half.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_be_half.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
