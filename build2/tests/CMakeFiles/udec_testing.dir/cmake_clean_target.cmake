file(REMOVE_RECURSE
  "libudec_testing.a"
)
