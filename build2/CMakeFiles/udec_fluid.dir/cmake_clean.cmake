file(REMOVE_RECURSE
  "CMakeFiles/udec_fluid.dir/src/fluid/fluid_flow.f90.o"
  "libudec_fluid.a"
  "libudec_fluid.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/udec_fluid.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
