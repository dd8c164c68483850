file(REMOVE_RECURSE
  "CMakeFiles/zone_bench.dir/bench/zone_bench.f90.o"
  "bin/zone_bench"
  "bin/zone_bench.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/zone_bench.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
