# One command-line case: runs COMMAND (a ;-list), checks its exit code, that stderr/stdout contain
# EXPECT (a regex), with REJECT that they do not contain that regex, and, with NO_FILE, that the file was not
# created.
string(REPLACE "|" ";" COMMAND "${COMMAND}")  # arguments arrive joined by | (a ; would split them early)
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc STREQUAL "${EXIT}")
  message(FATAL_ERROR "exit code ${rc}, expected ${EXIT}\nstdout: ${out}\nstderr: ${err}")
endif()
if(DEFINED EXPECT AND NOT "${out}${err}" MATCHES "${EXPECT}")
  message(FATAL_ERROR "output does not match '${EXPECT}'\nstdout: ${out}\nstderr: ${err}")
endif()
if(DEFINED REJECT AND "${out}${err}" MATCHES "${REJECT}")
  message(FATAL_ERROR "output matches '${REJECT}', which it must not\nstdout: ${out}\nstderr: ${err}")
endif()
if(DEFINED NO_FILE AND EXISTS "${NO_FILE}")
  message(FATAL_ERROR "${NO_FILE} was written although the command failed")
endif()
message(STATUS "ok: ${out}${err}")
