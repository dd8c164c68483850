# Empty compiler generated dependencies file for udec_contact.
# This may be replaced when dependencies are built.
