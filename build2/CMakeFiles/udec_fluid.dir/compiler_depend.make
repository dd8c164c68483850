# Empty compiler generated dependencies file for udec_fluid.
# This may be replaced when dependencies are built.
