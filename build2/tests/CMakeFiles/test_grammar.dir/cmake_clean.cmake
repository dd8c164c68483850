file(REMOVE_RECURSE
  "CMakeFiles/test_grammar.dir/unit/test_grammar.f90.o"
  "test_grammar"
  "test_grammar.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_grammar.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
