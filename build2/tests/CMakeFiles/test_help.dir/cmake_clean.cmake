file(REMOVE_RECURSE
  "CMakeFiles/test_help.dir/unit/test_help.f90.o"
  "test_help"
  "test_help.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_help.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
