/** @file source_location.hpp  A place in a model file, for every message about it. */
#pragma once

#include <string>

namespace eomgen {

/// A place in a model file, 1-based line and column (column counts bytes).
struct SourceLocation {
    std::string file;
    int line = 0;
    int column = 0;

    /// "file:line:col" (or just "file" when the line is unknown).
    std::string str() const;
};

}  // namespace eomgen
