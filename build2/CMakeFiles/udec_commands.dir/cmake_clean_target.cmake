file(REMOVE_RECURSE
  "libudec_commands.a"
)
