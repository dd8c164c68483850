# Empty dependencies file for test_stability_scenes_random.
# This may be replaced when dependencies are built.
