file(REMOVE_RECURSE
  "libudec_core.a"
)
