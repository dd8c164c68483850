# Empty compiler generated dependencies file for zone_bench.
# This may be replaced when dependencies are built.
