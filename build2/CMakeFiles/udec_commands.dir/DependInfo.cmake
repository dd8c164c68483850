
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  "Fortran"
  )
# The set of files for implicit dependencies of each language:
set(CMAKE_DEPENDS_CHECK_Fortran
  "/work/wt-lead/src/commands/commands_address.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_address.f90.o"
  "/work/wt-lead/src/commands/commands_be.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_be.f90.o"
  "/work/wt-lead/src/commands/commands_boundary.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_boundary.f90.o"
  "/work/wt-lead/src/commands/commands_catalog.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_catalog.f90.o"
  "/work/wt-lead/src/commands/commands_context.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_context.f90.o"
  "/work/wt-lead/src/commands/commands_control.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_control.f90.o"
  "/work/wt-lead/src/commands/commands_export.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_export.f90.o"
  "/work/wt-lead/src/commands/commands_fluid.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_fluid.f90.o"
  "/work/wt-lead/src/commands/commands_geometry.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_geometry.f90.o"
  "/work/wt-lead/src/commands/commands_geometry_extras.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_geometry_extras.f90.o"
  "/work/wt-lead/src/commands/commands_grammar.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_grammar.f90.o"
  "/work/wt-lead/src/commands/commands_help.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_help.f90.o"
  "/work/wt-lead/src/commands/commands_io.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_io.f90.o"
  "/work/wt-lead/src/commands/commands_mechanics.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_mechanics.f90.o"
  "/work/wt-lead/src/commands/commands_numbers.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_numbers.f90.o"
  "/work/wt-lead/src/commands/commands_parser.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_parser.f90.o"
  "/work/wt-lead/src/commands/commands_plot.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_plot.f90.o"
  "/work/wt-lead/src/commands/commands_plot_state.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_plot_state.f90.o"
  "/work/wt-lead/src/commands/commands_print.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_print.f90.o"
  "/work/wt-lead/src/commands/commands_print_zones.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_print_zones.f90.o"
  "/work/wt-lead/src/commands/commands_properties.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_properties.f90.o"
  "/work/wt-lead/src/commands/commands_reinforce.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_reinforce.f90.o"
  "/work/wt-lead/src/commands/commands_session.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_session.f90.o"
  "/work/wt-lead/src/commands/commands_source.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_source.f90.o"
  "/work/wt-lead/src/commands/commands_structure.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_structure.f90.o"
  "/work/wt-lead/src/commands/commands_thermal.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_thermal.f90.o"
  "/work/wt-lead/src/commands/commands_tokens.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_tokens.f90.o"
  "/work/wt-lead/src/commands/commands_zones.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_zones.f90.o"
  "/work/wt-lead/src/commands/commands_zpress.f90" "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/src/commands/commands_zpress.f90.o"
  )
set(CMAKE_Fortran_COMPILER_ID "GNU")
set(CMAKE_Fortran_SUBMODULE_SEP "@")
set(CMAKE_Fortran_SUBMODULE_EXT ".smod")

# The include file search paths:
set(CMAKE_Fortran_TARGET_INCLUDE_PATH
  "mod/commands"
  "mod/engine"
  "mod/contact"
  "mod/geometry"
  "mod/model"
  "mod/core"
  "mod/zones"
  "mod/structure"
  "mod/fluid"
  "mod/thermal"
  "mod/be"
  "mod/io"
  "/usr/include/hdf5/serial"
  "mod/plot"
  "/usr/include/editline"
  "/usr/include"
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/wt-lead/build2/CMakeFiles/udec_engine.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_io.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_plot.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_contact.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_geometry.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_model.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_core.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_zones.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_structure.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_fluid.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_thermal.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_be.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "/work/wt-lead/build2/mod/commands")
