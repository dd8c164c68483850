file(REMOVE_RECURSE
  "CMakeFiles/test_be.dir/unit/test_be.f90.o"
  "test_be"
  "test_be.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_be.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
