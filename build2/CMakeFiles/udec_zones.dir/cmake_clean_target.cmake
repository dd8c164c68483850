file(REMOVE_RECURSE
  "libudec_zones.a"
)
