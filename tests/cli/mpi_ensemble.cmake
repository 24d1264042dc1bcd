# `mpirun -n 2 eomgen run ... --sweep ...` writes the table a single process writes, byte for byte: a door
# sweep to its closing (the ranks' results gathered to rank 0) with a failed member among them (w = 0: the
# mass matrix is singular). Without MPI in eomgen (MPIEXEC empty) it says "skipped" (SKIP_REGULAR_EXPRESSION).
if(NOT MPIEXEC)
  message(STATUS "eomgen was built without MPI: skipped")
  return()
endif()
string(REPLACE "|" ";" MPI_FLAGS "${MPI_FLAGS}")
file(MAKE_DIRECTORY "${WORK}")
set(args run "${MODEL}" --until psi=-pi/2 --t-end 100 --rtol 1e-12 --sweep theta=0.02:1.5:97 --sweep w=0.9,0,1.3
         --quiet)
# XDG_CACHE_HOME: the test's own cache, filled by the first (single-process) run and read by both ranks.
set(env ${CMAKE_COMMAND} -E env XDG_CACHE_HOME=${WORK}/cache)
execute_process(COMMAND ${env} ${EOMGEN} ${args} --threads 2 --out "${WORK}/single.csv" RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "single process: exit ${rc}\n${out}${err}")
endif()
execute_process(COMMAND ${env} ${MPIEXEC} -n 2 ${MPI_FLAGS} ${EOMGEN} ${args} --threads 1 --out "${WORK}/ranks.csv"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "mpirun -n 2: exit ${rc}\n${out}${err}")
endif()
if(NOT out MATCHES "291 members \\(grid 97 x 3 over theta, w\\), 97 failed, on 1 thread in each of 2 MPI ranks")
  message(FATAL_ERROR "mpirun -n 2 did not run across 2 ranks:\n${out}${err}")
endif()
file(READ "${WORK}/single.csv" single)
file(READ "${WORK}/ranks.csv" ranks)
if(NOT single STREQUAL ranks)
  message(FATAL_ERROR "the table of 2 ranks differs from the single process's (${WORK}/single.csv, ranks.csv)")
endif()
string(LENGTH "${single}" size)
message(STATUS "ok: 2 ranks wrote the single process's table (${size} bytes)")
