file(REMOVE_RECURSE
  "libudec_geometry.a"
)
