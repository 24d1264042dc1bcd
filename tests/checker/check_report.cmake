# Regenerates the checker's part of a committed report in docs/checks/ and requires it, byte for byte, in the
# report (whose first part is written by hand), one heading level down: the report ends with exactly what
# `eomgen check` prints, and check's exit code is the one its summary implies (5 with a disagreement, else 0).
# Without the seed text it prints "[skipped]", which ctest reports as skipped (SKIP_REGULAR_EXPRESSION).
string(REPLACE "|" ";" COMMAND "${COMMAND}")
if(NOT EXISTS "${SEED}")
  message(STATUS "[skipped] seed text ${SEED} not found")
  return()
endif()
execute_process(COMMAND ${COMMAND} WORKING_DIRECTORY "${WORKDIR}" OUTPUT_VARIABLE generated RESULT_VARIABLE rc)
if(generated STREQUAL "")
  message(FATAL_ERROR "no output (exit ${rc})")
endif()
# The report nests the checker's part one heading level down ("# Check of" is "## Check of" there): compare
# with the report's headings one level up. Both strings go through the same string(REGEX REPLACE), which
# treats the "\;" of LaTeX the same way in both.
file(READ "${REPORT}" committed)
# (No "^" in the patterns: string(REGEX REPLACE) matches it again after each replacement.)
string(REGEX REPLACE "\n##" "\n#" committed "${committed}")
string(REGEX REPLACE "\n#" "\n#" generated "${generated}")
string(FIND "${committed}" "${generated}" at REVERSE)
string(LENGTH "${committed}" committed_length)
string(LENGTH "${generated}" generated_length)
math(EXPR end "${at} + ${generated_length}")
if(at EQUAL -1 OR NOT end EQUAL committed_length)
  message(FATAL_ERROR "${REPORT} does not end with what `eomgen check` prints now (exit ${rc}); regenerate it:\n${generated}")
endif()
if(NOT generated MATCHES "\\*\\*Summary:\\*\\*[^\n]* ([0-9]+) disagree")
  message(FATAL_ERROR "`eomgen check` printed no summary line (exit ${rc})")
endif()
if(CMAKE_MATCH_1 GREATER 0)
  set(expected 5)
else()
  set(expected 0)
endif()
if(NOT rc STREQUAL expected)
  message(FATAL_ERROR "`eomgen check` exited with ${rc}; its summary (${CMAKE_MATCH_1} disagree) implies ${expected}")
endif()
message(STATUS "${REPORT}: up to date (exit ${rc})")
