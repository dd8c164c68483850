file(REMOVE_RECURSE
  "CMakeFiles/test_structure.dir/unit/test_structure.f90.o"
  "test_structure"
  "test_structure.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_structure.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
