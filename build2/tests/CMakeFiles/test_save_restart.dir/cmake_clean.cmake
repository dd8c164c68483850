file(REMOVE_RECURSE
  "CMakeFiles/test_save_restart.dir/unit/test_save_restart.f90.o"
  "test_save_restart"
  "test_save_restart.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_save_restart.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
