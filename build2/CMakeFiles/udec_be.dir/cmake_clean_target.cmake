file(REMOVE_RECURSE
  "libudec_be.a"
)
