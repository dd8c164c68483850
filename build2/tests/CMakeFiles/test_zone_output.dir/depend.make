# Empty dependencies file for test_zone_output.
# This may be replaced when dependencies are built.
