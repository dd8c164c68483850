file(REMOVE_RECURSE
  "CMakeFiles/test_command_order.dir/unit/test_command_order.f90.o"
  "test_command_order"
  "test_command_order.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_command_order.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
