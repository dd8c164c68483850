# docs/commands.md is generated from the command registry (udec --commands-md),
# and docs/udec.1 too (udec --man, with -DOPTION=--man -DDOC=.../udec.1);
# this test fails when the checked-in file differs from what the program prints.
if(NOT DEFINED OPTION)
  set(OPTION --commands-md)
endif()
execute_process(COMMAND ${UDEC} ${OPTION} OUTPUT_VARIABLE generated RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "udec ${OPTION} failed with status ${rc}")
endif()
file(READ ${DOC} checked_in)
get_filename_component(doc_name ${DOC} NAME)
if(NOT generated STREQUAL checked_in)
  message(FATAL_ERROR "docs/${doc_name} is stale: regenerate it with\n"
                      "  build/bin/udec ${OPTION} > docs/${doc_name}")
endif()
message(STATUS "docs/${doc_name} matches the command registry")
