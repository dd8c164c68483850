# Empty dependencies file for test_zpress.
# This may be replaced when dependencies are built.
