# Empty dependencies file for test_stability_scenes.
# This may be replaced when dependencies are built.
