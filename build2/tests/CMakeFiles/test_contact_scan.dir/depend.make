# Empty dependencies file for test_contact_scan.
# This may be replaced when dependencies are built.
