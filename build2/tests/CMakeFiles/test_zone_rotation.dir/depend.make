# Empty dependencies file for test_zone_rotation.
# This may be replaced when dependencies are built.
