# Empty compiler generated dependencies file for test_command_order.
# This may be replaced when dependencies are built.
