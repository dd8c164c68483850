file(REMOVE_RECURSE
  "CMakeFiles/test_boundary.dir/unit/test_boundary.f90.o"
  "test_boundary"
  "test_boundary.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_boundary.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
