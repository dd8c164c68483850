# Empty compiler generated dependencies file for test_zones_mixed.
# This may be replaced when dependencies are built.
