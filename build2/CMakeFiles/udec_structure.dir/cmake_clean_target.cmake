file(REMOVE_RECURSE
  "libudec_structure.a"
)
