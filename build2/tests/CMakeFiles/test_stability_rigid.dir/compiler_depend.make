# Empty compiler generated dependencies file for test_stability_rigid.
# This may be replaced when dependencies are built.
