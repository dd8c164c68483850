# Empty compiler generated dependencies file for test_geometry_contacts.
# This may be replaced when dependencies are built.
