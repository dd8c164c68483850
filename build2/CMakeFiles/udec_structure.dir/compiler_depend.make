# Empty compiler generated dependencies file for udec_structure.
# This may be replaced when dependencies are built.
