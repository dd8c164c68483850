file(REMOVE_RECURSE
  "CMakeFiles/geometry_bench.dir/bench/geometry_bench.f90.o"
  "bin/geometry_bench"
  "bin/geometry_bench.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/geometry_bench.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
