file(REMOVE_RECURSE
  "CMakeFiles/udec_testing_session.dir/lib/testing_session.f90.o"
  "libudec_testing_session.a"
  "libudec_testing_session.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/udec_testing_session.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
