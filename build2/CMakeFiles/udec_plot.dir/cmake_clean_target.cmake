file(REMOVE_RECURSE
  "libudec_plot.a"
)
