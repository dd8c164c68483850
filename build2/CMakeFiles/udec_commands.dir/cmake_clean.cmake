file(REMOVE_RECURSE
  "CMakeFiles/udec_commands.dir/src/commands/commands_address.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_be.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_boundary.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_catalog.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_context.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_control.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_export.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_fluid.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_geometry.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_geometry_extras.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_grammar.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_help.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_io.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_mechanics.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_numbers.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_parser.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_plot.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_plot_state.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_print.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_print_zones.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_properties.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_reinforce.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_session.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_source.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_structure.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_thermal.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_tokens.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_zones.f90.o"
  "CMakeFiles/udec_commands.dir/src/commands/commands_zpress.f90.o"
  "libudec_commands.a"
  "libudec_commands.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/udec_commands.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
