file(REMOVE_RECURSE
  "libudec_thermal.a"
)
