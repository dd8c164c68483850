file(REMOVE_RECURSE
  "CMakeFiles/udec.dir/app/udec.f90.o"
  "bin/udec"
  "bin/udec.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/udec.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
