# eomgen_add_model(<target> MODEL <file.toml> [NAME <model name>])
#
# Available in eomgen's own build and, installed, after find_package(eomgen CONFIG REQUIRED); it runs the
# executable target eomgen::eomgen (eomgen's own, or the installed one).
#
# Regenerates <build>/eomgen_generated/eomgen/models/<name>.hpp from the model file whenever the model
# file or the generator changes, and defines the INTERFACE target <target> that carries the header, the
# runtime and Eigen. Link it and `#include "eomgen/models/<name>.hpp"`. NAME (default: <target>) is the
# model's namespace, eomgen::models::<name>, and overrides the `name` in the model file.
function(eomgen_add_model target)
  cmake_parse_arguments(ARG "" "MODEL;NAME" "" ${ARGN})
  if(NOT ARG_MODEL)
    message(FATAL_ERROR "eomgen_add_model(${target}): MODEL <file.toml> is required")
  endif()
  if(NOT ARG_NAME)
    set(ARG_NAME ${target})
  endif()
  get_filename_component(model_file "${ARG_MODEL}" ABSOLUTE)
  set(include_dir "${CMAKE_BINARY_DIR}/eomgen_generated")
  set(out_dir "${include_dir}/eomgen/models")
  set(header "${out_dir}/${ARG_NAME}.hpp")
  # generate leaves an unchanged header alone, so a rebuilt generator that writes the same code recompiles
  # nothing that includes it; the stamp records that the header was brought up to date.
  set(stamp "${out_dir}/${ARG_NAME}.hpp.stamp")
  # The generator: eomgen's own target in its build tree, the installed one after find_package(eomgen).
  set(generator_depends "$<TARGET_FILE:eomgen::eomgen>")
  get_target_property(generator_target eomgen::eomgen ALIASED_TARGET)
  if(generator_target)
    list(APPEND generator_depends ${generator_target})  # build it first
  endif()
  add_custom_command(
    OUTPUT "${stamp}"
    BYPRODUCTS "${header}"
    COMMAND eomgen::eomgen generate "${model_file}" --name "${ARG_NAME}" -o "${out_dir}"
    COMMAND ${CMAKE_COMMAND} -E touch "${stamp}"
    DEPENDS "${model_file}" ${generator_depends}
    COMMENT "eomgen: ${ARG_MODEL} -> eomgen/models/${ARG_NAME}.hpp"
    VERBATIM)
  add_custom_target(${target}_header DEPENDS "${stamp}")
  add_library(${target} INTERFACE)
  add_dependencies(${target} ${target}_header)
  target_include_directories(${target} INTERFACE "${include_dir}")
  target_link_libraries(${target} INTERFACE eomgen::runtime)
  set_property(GLOBAL APPEND PROPERTY EOMGEN_MODEL_TARGETS ${target})
  set_property(TARGET ${target} PROPERTY EOMGEN_MODEL_NAME ${ARG_NAME})
  set_property(TARGET ${target} PROPERTY EOMGEN_MODEL_FILE "${model_file}")
endfunction()
