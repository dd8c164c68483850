file(REMOVE_RECURSE
  "CMakeFiles/test_print.dir/unit/test_print.f90.o"
  "test_print"
  "test_print.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_print.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
