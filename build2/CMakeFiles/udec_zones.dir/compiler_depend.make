# Empty compiler generated dependencies file for udec_zones.
# This may be replaced when dependencies are built.
