/** @file test_paths.cpp  The paths of test_paths.hpp, set by tests/CMakeLists.txt for this file alone. */
#include "test_paths.hpp"

namespace eomgen_test {

const std::string& source_dir() {
    static const std::string dir = EOMGEN_SOURCE_DIR;
    return dir;
}

const std::string& binary_dir() {
    static const std::string dir = EOMGEN_BINARY_DIR;
    return dir;
}

const std::string& eomgen_exe() {
    static const std::string exe = EOMGEN_EXE;
    return exe;
}

}  // namespace eomgen_test
