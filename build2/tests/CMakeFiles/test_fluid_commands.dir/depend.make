# Empty dependencies file for test_fluid_commands.
# This may be replaced when dependencies are built.
