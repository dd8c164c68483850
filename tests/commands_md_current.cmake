# docs/commands.md is generated from the command registry (udec --commands-md);
# this test fails when the checked-in file differs from what the program prints.
execute_process(COMMAND ${UDEC} --commands-md OUTPUT_VARIABLE generated RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "udec --commands-md failed with status ${rc}")
endif()
file(READ ${DOC} checked_in)
if(NOT generated STREQUAL checked_in)
  message(FATAL_ERROR "docs/commands.md is stale: regenerate it with\n"
                      "  build/bin/udec --commands-md > docs/commands.md")
endif()
message(STATUS "docs/commands.md matches the command registry")
