# Empty dependencies file for test_abbreviations.
# This may be replaced when dependencies are built.
