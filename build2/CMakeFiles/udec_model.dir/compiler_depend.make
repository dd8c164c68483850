# Empty compiler generated dependencies file for udec_model.
# This may be replaced when dependencies are built.
