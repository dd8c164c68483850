# Empty dependencies file for test_fmt_real.
# This may be replaced when dependencies are built.
