# Empty compiler generated dependencies file for udec_plot.
# This may be replaced when dependencies are built.
