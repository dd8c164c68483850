# Empty compiler generated dependencies file for udec_be.
# This may be replaced when dependencies are built.
