# Empty dependencies file for test_tokens.
# This may be replaced when dependencies are built.
