# Empty compiler generated dependencies file for test_geometry_cutting.
# This may be replaced when dependencies are built.
