# Empty dependencies file for test_save_restart.
# This may be replaced when dependencies are built.
