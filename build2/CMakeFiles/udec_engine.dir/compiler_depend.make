# Empty compiler generated dependencies file for udec_engine.
# This may be replaced when dependencies are built.
