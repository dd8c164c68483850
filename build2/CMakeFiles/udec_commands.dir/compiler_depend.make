# Empty compiler generated dependencies file for udec_commands.
# This may be replaced when dependencies are built.
