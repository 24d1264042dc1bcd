/** @file model.cpp  Formatting of source locations and model errors. */
#include "model/model.hpp"

#include <utility>

namespace eomgen {

std::string SourceLocation::str() const {
    if (line <= 0) return file;
    std::string s = file + ":" + std::to_string(line);
    if (column > 0) s += ":" + std::to_string(column);
    return s;
}

ModelError::ModelError(SourceLocation where, const std::string& message)
    : std::runtime_error(where.str() + ": " + message), where_(std::move(where)), message_(message) {}

}  // namespace eomgen
