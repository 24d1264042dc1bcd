/** @file drawing_file.hpp  Reading the [[draw]] entries of a model file (docs/model_files.md, "Drawing"). */
#pragma once

#include "model/file_reading.hpp"
#include "model/model.hpp"

namespace eomgen {

/// The [[draw]] entries of `root`, in file order, checked against `model` (its bodies) and `symbols` (the
/// coordinates, parameters and t); a ModelError at file:line:col for the first problem.
std::vector<DrawItem> read_drawing(const toml::table& root, const FileReading& file, const SymbolTable& symbols,
                                   const Model& model);

}  // namespace eomgen
