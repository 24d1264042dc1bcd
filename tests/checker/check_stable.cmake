# Runs COMMAND (a |-joined list) twice, as two processes, and requires byte-identical output: the report is
# printed in a canonical order, not in GiNaC's, which changes with the addresses ASLR gives each process.
string(REPLACE "|" ";" COMMAND "${COMMAND}")
execute_process(COMMAND ${COMMAND} OUTPUT_VARIABLE first RESULT_VARIABLE rc1)
execute_process(COMMAND ${COMMAND} OUTPUT_VARIABLE second RESULT_VARIABLE rc2)
if(NOT first STREQUAL second)
  message(FATAL_ERROR "two runs differ:\n--- first\n${first}\n--- second\n${second}")
endif()
if(first STREQUAL "")
  message(FATAL_ERROR "no output (exit ${rc1})")
endif()
message(STATUS "identical (exit ${rc1}, ${rc2})")
