file(REMOVE_RECURSE
  "CMakeFiles/test_sdef_insitu.dir/unit/test_sdef_insitu.f90.o"
  "test_sdef_insitu"
  "test_sdef_insitu.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_sdef_insitu.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
