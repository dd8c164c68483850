# Empty dependencies file for test_rigid_velocity.
# This may be replaced when dependencies are built.
