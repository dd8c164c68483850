# CMAKE generated file: DO NOT EDIT!
# Timestamp file for compiler generated dependencies management for test_restart_bit_for_bit.
