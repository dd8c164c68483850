# Empty dependencies file for test_stability_mohr.
# This may be replaced when dependencies are built.
