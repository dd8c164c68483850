file(REMOVE_RECURSE
  "libudec_io.a"
)
