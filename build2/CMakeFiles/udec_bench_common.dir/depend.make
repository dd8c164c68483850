# Empty dependencies file for udec_bench_common.
# This may be replaced when dependencies are built.
