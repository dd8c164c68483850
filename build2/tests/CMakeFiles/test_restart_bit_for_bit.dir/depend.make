# Empty dependencies file for test_restart_bit_for_bit.
# This may be replaced when dependencies are built.
