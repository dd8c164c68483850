file(REMOVE_RECURSE
  "CMakeFiles/udec_be.dir/src/be/be_far_field.f90.o"
  "CMakeFiles/udec_be.dir/src/be/be_halfplane.f90.o"
  "CMakeFiles/udec_be.dir/src/be/be_kelvin.f90.o"
  "CMakeFiles/udec_be.dir/src/be/be_lapack.f90.o"
  "libudec_be.a"
  "libudec_be.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/udec_be.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
