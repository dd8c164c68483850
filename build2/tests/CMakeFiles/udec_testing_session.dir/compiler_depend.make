# Empty compiler generated dependencies file for udec_testing_session.
# This may be replaced when dependencies are built.
