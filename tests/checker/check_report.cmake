# Regenerates the checker's part of a committed report in docs/checks/ and requires it, byte for byte, in the
# report (whose first part is written by hand), one heading level down. Skipped, with a message, when the seed text is absent.
string(REPLACE "|" ";" COMMAND "${COMMAND}")
if(NOT EXISTS "${SEED}")
  message(STATUS "seed text ${SEED} not found: skipped")
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
string(FIND "${committed}" "${generated}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${REPORT} does not contain what `eomgen check` prints now (exit ${rc}); regenerate it:\n${generated}")
endif()
message(STATUS "${REPORT}: up to date (exit ${rc})")
