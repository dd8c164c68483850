# Empty compiler generated dependencies file for udec.
# This may be replaced when dependencies are built.
