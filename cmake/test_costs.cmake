# The suite's longest tests and their seconds, so that ctest starts them first (the COST property) on a fresh
# clone too, where it has no timings of its own (build/Testing/Temporary/CTestCostData.txt): it runs tests in the
# order they were added, and the slowest (bench_smoke, about 3 minutes) was added last, so it ran alone at the end
# while the other core idled. Seconds of `ctest -j2` on 2 cores (2026-11-29); `bash scripts/test_costs.sh` prints
# the current ones from the last run. Order, not timing, is what they set: nothing fails on them.
set(EOMGEN_TEST_COSTS
  bench_smoke=190 python:pytest=50 fuzz:structure_bounded=37 install:deb=33 units:mutation_score=29
  generated_is_up_to_date=29 install:consumer=29 fuzz:text_fields_headers_compile=27 fuzz:check_bounded=26
  fuzz:structure_findings=19 animation:browser_spherical_pendulum=18 animation:browser_planar_pendulum=18
  fuzz:model_file_bounded=16 cli:modes_bicycle_declared_motion=14 python:notebook=13 bench_ensemble_smoke=11
  cli:modes_unknown_motion=11 cli:kinks_radau5_run=10 cli:run_noether_drift=9 cli:sticking_constrained_refused=7
  cli:sticking_radau5_refused=7 cli:tutorial=6 cli:mpi_ensemble_equals_single_process=6)

# Sets COST on those of the tests above that the calling directory added (a test's properties can be set only in
# the directory that added it, before CMake 3.28): call it at the end of each CMakeLists.txt that adds tests.
function(eomgen_apply_test_costs)
  foreach(entry IN LISTS EOMGEN_TEST_COSTS)
    string(FIND "${entry}" "=" eq REVERSE)
    string(SUBSTRING "${entry}" 0 ${eq} name)
    math(EXPR from "${eq} + 1")
    string(SUBSTRING "${entry}" ${from} -1 seconds)
    if(TEST "${name}")
      set_tests_properties("${name}" PROPERTIES COST ${seconds})
    endif()
  endforeach()
endfunction()
