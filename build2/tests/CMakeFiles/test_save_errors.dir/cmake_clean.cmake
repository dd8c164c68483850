file(REMOVE_RECURSE
  "CMakeFiles/test_save_errors.dir/unit/test_save_errors.f90.o"
  "test_save_errors"
  "test_save_errors.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_save_errors.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
