/** @file test_paths.hpp  Where the suite finds the checkout, the build folder and the eomgen executable.
 *
 * The paths are compiled into one small file (test_paths.cpp), not into every test file: a test file's compile
 * command then holds no path of this checkout, and ccache (scripts/ccache_env.sh) finds what another clone on the
 * same machine compiled (docs/benchmarks.md, "Build time"). */
#pragma once

#include <string>

namespace eomgen_test {

/// The checkout's root (CMake's PROJECT_SOURCE_DIR): models/, examples/, tests/checker/fixtures/ lie under it.
const std::string& source_dir();
/// The build folder (PROJECT_BINARY_DIR), where tests write their work files.
const std::string& binary_dir();
/// The eomgen executable this build made.
const std::string& eomgen_exe();

}  // namespace eomgen_test
