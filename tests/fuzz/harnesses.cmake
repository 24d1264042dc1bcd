# The fuzz harnesses of tests/fuzz/ and the libraries each calls into, shared by tests/fuzz/CMakeLists.txt
# (the standalone driver, ctest) and tests/fuzz/libfuzzer/CMakeLists.txt (libFuzzer, tests/fuzz/run.sh).
# For each harness NAME, the caller's eomgen_fuzz_target(NAME SOURCE LIBS...) makes its executable.
set(_fuzz_dir "${CMAKE_CURRENT_LIST_DIR}")
eomgen_fuzz_target(text_fields "${_fuzz_dir}/fuzz_text_fields.cpp" eomgen_codegen)
eomgen_fuzz_target(expression "${_fuzz_dir}/fuzz_expression.cpp" eomgen_model)
eomgen_fuzz_target(model_file "${_fuzz_dir}/fuzz_model_file.cpp" eomgen_codegen)
eomgen_fuzz_target(latex "${_fuzz_dir}/fuzz_latex.cpp" eomgen_checker)
eomgen_fuzz_target(check "${_fuzz_dir}/fuzz_check.cpp" eomgen_checker)
eomgen_fuzz_target(sim_values "${_fuzz_dir}/fuzz_sim_values.cpp" eomgen::runtime)
eomgen_fuzz_target(structure "${_fuzz_dir}/fuzz_structure.cpp" eomgen_codegen eomgen_animation eomgen_interpreter)
