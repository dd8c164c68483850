file(REMOVE_RECURSE
  "CMakeFiles/rigid_bench.dir/bench/rigid_bench.f90.o"
  "bin/rigid_bench"
  "bin/rigid_bench.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/rigid_bench.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
