file(REMOVE_RECURSE
  "CMakeFiles/udec_bench_common.dir/bench/bench_common.f90.o"
  "libudec_bench_common.a"
  "libudec_bench_common.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/udec_bench_common.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
