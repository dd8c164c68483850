file(REMOVE_RECURSE
  "libudec_bench_common.a"
)
