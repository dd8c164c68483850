# Empty compiler generated dependencies file for test_rigid_mechanics.
# This may be replaced when dependencies are built.
