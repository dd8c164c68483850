# Empty compiler generated dependencies file for test_boundary.
# This may be replaced when dependencies are built.
