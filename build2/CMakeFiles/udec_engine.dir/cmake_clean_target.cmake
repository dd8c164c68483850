file(REMOVE_RECURSE
  "libudec_engine.a"
)
