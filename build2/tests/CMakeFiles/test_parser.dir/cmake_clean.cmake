file(REMOVE_RECURSE
  "CMakeFiles/test_parser.dir/unit/test_parser.f90.o"
  "test_parser"
  "test_parser.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_parser.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
