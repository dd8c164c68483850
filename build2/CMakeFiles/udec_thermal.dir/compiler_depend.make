# Empty compiler generated dependencies file for udec_thermal.
# This may be replaced when dependencies are built.
