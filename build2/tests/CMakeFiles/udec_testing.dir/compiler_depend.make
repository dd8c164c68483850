# Empty compiler generated dependencies file for udec_testing.
# This may be replaced when dependencies are built.
