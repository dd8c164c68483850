file(REMOVE_RECURSE
  "CMakeFiles/test_fmt_real.dir/unit/test_fmt_real.f90.o"
  "test_fmt_real"
  "test_fmt_real.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_fmt_real.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
