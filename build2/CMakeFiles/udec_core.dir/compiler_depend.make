# Empty compiler generated dependencies file for udec_core.
# This may be replaced when dependencies are built.
