# Empty compiler generated dependencies file for test_grammar.
# This may be replaced when dependencies are built.
