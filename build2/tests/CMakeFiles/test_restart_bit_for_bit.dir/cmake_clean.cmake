file(REMOVE_RECURSE
  "CMakeFiles/test_restart_bit_for_bit.dir/restart/test_restart_bit_for_bit.f90.o"
  "test_restart_bit_for_bit"
  "test_restart_bit_for_bit.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_restart_bit_for_bit.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
