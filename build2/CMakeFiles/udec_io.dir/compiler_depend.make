# Empty compiler generated dependencies file for udec_io.
# This may be replaced when dependencies are built.
