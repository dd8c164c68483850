# Empty dependencies file for geometry_bench.
# This may be replaced when dependencies are built.
