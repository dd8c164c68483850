# Empty compiler generated dependencies file for test_sdef_insitu.
# This may be replaced when dependencies are built.
