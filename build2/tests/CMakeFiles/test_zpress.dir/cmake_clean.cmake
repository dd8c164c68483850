file(REMOVE_RECURSE
  "CMakeFiles/test_zpress.dir/unit/test_zpress.f90.o"
  "test_zpress"
  "test_zpress.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_zpress.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
