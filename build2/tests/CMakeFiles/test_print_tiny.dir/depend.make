# Empty dependencies file for test_print_tiny.
# This may be replaced when dependencies are built.
