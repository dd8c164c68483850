# Empty dependencies file for test_thermal_rigid.
# This may be replaced when dependencies are built.
