file(REMOVE_RECURSE
  "CMakeFiles/udec_testing.dir/lib/testing.f90.o"
  "CMakeFiles/udec_testing.dir/lib/testing_model.f90.o"
  "libudec_testing.a"
  "libudec_testing.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/udec_testing.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
