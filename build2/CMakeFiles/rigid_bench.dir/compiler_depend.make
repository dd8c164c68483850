# Empty compiler generated dependencies file for rigid_bench.
# This may be replaced when dependencies are built.
