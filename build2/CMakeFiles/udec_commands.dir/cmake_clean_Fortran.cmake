# Remove fortran modules provided by this target.
FILE(REMOVE
  "mod/commands/commands_address.mod"
  "mod/commands/COMMANDS_ADDRESS.mod"
  "CMakeFiles/udec_commands.dir/commands_address.mod.stamp"

  "mod/commands/commands_be.mod"
  "mod/commands/COMMANDS_BE.mod"
  "CMakeFiles/udec_commands.dir/commands_be.mod.stamp"

  "mod/commands/commands_boundary.mod"
  "mod/commands/COMMANDS_BOUNDARY.mod"
  "CMakeFiles/udec_commands.dir/commands_boundary.mod.stamp"

  "mod/commands/commands_catalog.mod"
  "mod/commands/COMMANDS_CATALOG.mod"
  "CMakeFiles/udec_commands.dir/commands_catalog.mod.stamp"

  "mod/commands/commands_context.mod"
  "mod/commands/COMMANDS_CONTEXT.mod"
  "CMakeFiles/udec_commands.dir/commands_context.mod.stamp"

  "mod/commands/commands_control.mod"
  "mod/commands/COMMANDS_CONTROL.mod"
  "CMakeFiles/udec_commands.dir/commands_control.mod.stamp"

  "mod/commands/commands_export.mod"
  "mod/commands/COMMANDS_EXPORT.mod"
  "CMakeFiles/udec_commands.dir/commands_export.mod.stamp"

  "mod/commands/commands_fluid.mod"
  "mod/commands/COMMANDS_FLUID.mod"
  "CMakeFiles/udec_commands.dir/commands_fluid.mod.stamp"

  "mod/commands/commands_geometry.mod"
  "mod/commands/COMMANDS_GEOMETRY.mod"
  "CMakeFiles/udec_commands.dir/commands_geometry.mod.stamp"

  "mod/commands/commands_geometry_extras.mod"
  "mod/commands/COMMANDS_GEOMETRY_EXTRAS.mod"
  "CMakeFiles/udec_commands.dir/commands_geometry_extras.mod.stamp"

  "mod/commands/commands_grammar.mod"
  "mod/commands/COMMANDS_GRAMMAR.mod"
  "CMakeFiles/udec_commands.dir/commands_grammar.mod.stamp"

  "mod/commands/commands_help.mod"
  "mod/commands/COMMANDS_HELP.mod"
  "CMakeFiles/udec_commands.dir/commands_help.mod.stamp"

  "mod/commands/commands_io.mod"
  "mod/commands/COMMANDS_IO.mod"
  "CMakeFiles/udec_commands.dir/commands_io.mod.stamp"

  "mod/commands/commands_mechanics.mod"
  "mod/commands/COMMANDS_MECHANICS.mod"
  "CMakeFiles/udec_commands.dir/commands_mechanics.mod.stamp"

  "mod/commands/commands_numbers.mod"
  "mod/commands/COMMANDS_NUMBERS.mod"
  "CMakeFiles/udec_commands.dir/commands_numbers.mod.stamp"

  "mod/commands/commands_parser.mod"
  "mod/commands/COMMANDS_PARSER.mod"
  "CMakeFiles/udec_commands.dir/commands_parser.mod.stamp"

  "mod/commands/commands_plot.mod"
  "mod/commands/COMMANDS_PLOT.mod"
  "CMakeFiles/udec_commands.dir/commands_plot.mod.stamp"

  "mod/commands/commands_plot_state.mod"
  "mod/commands/COMMANDS_PLOT_STATE.mod"
  "CMakeFiles/udec_commands.dir/commands_plot_state.mod.stamp"

  "mod/commands/commands_print.mod"
  "mod/commands/COMMANDS_PRINT.mod"
  "CMakeFiles/udec_commands.dir/commands_print.mod.stamp"

  "mod/commands/commands_print_zones.mod"
  "mod/commands/COMMANDS_PRINT_ZONES.mod"
  "CMakeFiles/udec_commands.dir/commands_print_zones.mod.stamp"

  "mod/commands/commands_properties.mod"
  "mod/commands/COMMANDS_PROPERTIES.mod"
  "CMakeFiles/udec_commands.dir/commands_properties.mod.stamp"

  "mod/commands/commands_reinforce.mod"
  "mod/commands/COMMANDS_REINFORCE.mod"
  "CMakeFiles/udec_commands.dir/commands_reinforce.mod.stamp"

  "mod/commands/commands_session.mod"
  "mod/commands/COMMANDS_SESSION.mod"
  "CMakeFiles/udec_commands.dir/commands_session.mod.stamp"

  "mod/commands/commands_source.mod"
  "mod/commands/COMMANDS_SOURCE.mod"
  "CMakeFiles/udec_commands.dir/commands_source.mod.stamp"

  "mod/commands/commands_structure.mod"
  "mod/commands/COMMANDS_STRUCTURE.mod"
  "CMakeFiles/udec_commands.dir/commands_structure.mod.stamp"

  "mod/commands/commands_thermal.mod"
  "mod/commands/COMMANDS_THERMAL.mod"
  "CMakeFiles/udec_commands.dir/commands_thermal.mod.stamp"

  "mod/commands/commands_tokens.mod"
  "mod/commands/COMMANDS_TOKENS.mod"
  "CMakeFiles/udec_commands.dir/commands_tokens.mod.stamp"

  "mod/commands/commands_zones.mod"
  "mod/commands/COMMANDS_ZONES.mod"
  "CMakeFiles/udec_commands.dir/commands_zones.mod.stamp"

  "mod/commands/commands_zpress.mod"
  "mod/commands/COMMANDS_ZPRESS.mod"
  "CMakeFiles/udec_commands.dir/commands_zpress.mod.stamp"
  )
