# Empty dependencies file for test_contact_flat_corner.
# This may be replaced when dependencies are built.
