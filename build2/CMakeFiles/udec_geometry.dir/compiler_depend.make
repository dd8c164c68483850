# Empty compiler generated dependencies file for udec_geometry.
# This may be replaced when dependencies are built.
