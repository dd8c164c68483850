# Empty compiler generated dependencies file for test_be.
# This may be replaced when dependencies are built.
