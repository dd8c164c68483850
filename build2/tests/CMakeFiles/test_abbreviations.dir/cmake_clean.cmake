file(REMOVE_RECURSE
  "CMakeFiles/test_abbreviations.dir/unit/test_abbreviations.f90.o"
  "test_abbreviations"
  "test_abbreviations.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_abbreviations.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
