# Empty compiler generated dependencies file for test_save_errors.
# This may be replaced when dependencies are built.
