file(REMOVE_RECURSE
  "libudec_fluid.a"
)
