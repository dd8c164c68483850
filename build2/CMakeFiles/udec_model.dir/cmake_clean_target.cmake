file(REMOVE_RECURSE
  "libudec_model.a"
)
