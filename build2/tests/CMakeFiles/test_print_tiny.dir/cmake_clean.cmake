file(REMOVE_RECURSE
  "CMakeFiles/test_print_tiny.dir/unit/test_print_tiny.f90.o"
  "test_print_tiny"
  "test_print_tiny.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_print_tiny.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
