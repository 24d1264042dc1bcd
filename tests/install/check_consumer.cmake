# Installs eomgen from BUILD_DIR into WORK/prefix, then configures, builds and runs the out-of-tree project
# CONSUMER (copied to WORK/src, so an edit does not touch the source tree) against that prefix only; edits
# the consumer's model file and checks that its header is regenerated and the program sees the change;
# and runs the installed `eomgen run` on that model file.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

step(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK}/prefix")
foreach(f bin/eomgen include/eomgen/simulation.hpp lib/cmake/eomgen/eomgenConfig.cmake
          lib/cmake/eomgen/eomgenConfigVersion.cmake lib/cmake/eomgen/eomgenTargets.cmake lib/cmake/eomgen/eomgen.cmake
          share/eomgen/models/door.toml share/doc/eomgen/README.md)
  if(NOT EXISTS "${WORK}/prefix/${f}")
    message(FATAL_ERROR "the install lacks ${f}")
  endif()
endforeach()
# Nothing installed points into the source tree.
file(GLOB cmake_files "${WORK}/prefix/lib/cmake/eomgen/*.cmake")
foreach(f ${cmake_files})
  file(READ "${f}" text)
  string(FIND "${text}" "${SOURCE_DIR}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "${f} names the source tree ${SOURCE_DIR}")
  endif()
endforeach()

file(COPY "${CONSUMER}/" DESTINATION "${WORK}/src")
step(${CMAKE_COMMAND} -S "${WORK}/src" -B "${WORK}/build" -DCMAKE_BUILD_TYPE=Release
     "-DCMAKE_PREFIX_PATH=${WORK}/prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
step(${CMAKE_COMMAND} --build "${WORK}/build")
step("${WORK}/build/consumer")
if(NOT out MATCHES "k = 8: x\\(T/2\\) = -1\\.0000000")
  message(FATAL_ERROR "unexpected output: ${out}")
endif()

# An edited model file regenerates the header on the next build.
set(header "${WORK}/build/eomgen_generated/eomgen/models/oscillator.hpp")
file(TIMESTAMP "${header}" before "%s")
file(READ "${WORK}/src/oscillator.toml" model)
string(REPLACE "value = 8.0" "value = 18.0" model "${model}")
execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1.1)
file(WRITE "${WORK}/src/oscillator.toml" "${model}")
step(${CMAKE_COMMAND} --build "${WORK}/build")
file(TIMESTAMP "${header}" after "%s")
if(after STREQUAL before)
  message(FATAL_ERROR "the header was not regenerated after the model file changed")
endif()
step("${WORK}/build/consumer")
if(NOT out MATCHES "k = 18: x\\(T/2\\) = -1\\.0000000")
  message(FATAL_ERROR "the rebuilt program does not see the edited model: ${out}")
endif()

# The installed generator runs the model file, compiling against the installed runtime headers: a compiler
# that records its arguments (and fails) shows the include path.
set(ENV{XDG_CACHE_HOME} "${WORK}/cache")
step("${WORK}/prefix/bin/eomgen" run "${WORK}/src/oscillator.toml" --t-end 1 --quiet)
file(WRITE "${WORK}/record-cxx.sh" "#!/bin/sh\necho \"$@\" > '${WORK}/cxx-arguments.txt'\nexit 1\n")
file(CHMOD "${WORK}/record-cxx.sh" PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
set(ENV{CXX} "${WORK}/record-cxx.sh")
execute_process(COMMAND "${WORK}/prefix/bin/eomgen" run "${WORK}/src/oscillator.toml" --no-cache --quiet
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
unset(ENV{CXX})
file(READ "${WORK}/cxx-arguments.txt" arguments)
if(NOT rc EQUAL 4 OR NOT arguments MATCHES "-I${WORK}/prefix/include " OR arguments MATCHES "${SOURCE_DIR}/runtime")
  message(FATAL_ERROR "the installed eomgen run did not compile against the installed runtime (exit ${rc}): ${arguments}")
endif()
message(STATUS "ok: installed, found, linked, regenerated and run")
