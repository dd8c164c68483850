file(REMOVE_RECURSE
  "CMakeFiles/test_tokens.dir/unit/test_tokens.f90.o"
  "test_tokens"
  "test_tokens.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_tokens.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
