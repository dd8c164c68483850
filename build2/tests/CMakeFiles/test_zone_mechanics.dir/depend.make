# Empty dependencies file for test_zone_mechanics.
# This may be replaced when dependencies are built.
