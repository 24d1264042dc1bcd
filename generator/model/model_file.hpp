/** @file model_file.hpp  Reading a model file (TOML, see docs/model_files.md) into a checked Model. */
#pragma once

#include "model/model.hpp"

#include <string>
#include <string_view>

namespace eomgen {

/**
 * Reads and checks the model file at `path` (format: docs/model_files.md).
 *
 * Every coordinate gets symbols q, qd, qdd named `<name>`, `<name>_dot`, `<name>_ddot` (TeX `\psi`,
 * `\dot{\psi}`, `\ddot{\psi}`); every parameter a symbol named after it with its LaTeX as TeX name;
 * T and V are exact GiNaC expressions in those symbols and Model::t.
 *
 * @param path  the model file; also Model::path and the file part of error locations
 * @return      the model, with LaTeX defaults filled in and a default name (the file's stem) when
 *              the file has none
 * @throws ModelError  for the first problem found, located at file:line:col (column in bytes),
 *                     e.g. "models/door.toml:47:23: unknown symbol 'thta'; did you mean 'theta'?"
 */
Model load_model(const std::string& path);

/// The bytes of a model file, as load_model reads them (ModelError when it cannot be read).
std::string read_model_file(const std::string& path);

/// As load_model, for the text of a model file; `path` is only used in messages and as Model::path. A file that
/// gives no name is named `default_name`, or where that is empty after the file name (`path`'s stem).
Model parse_model(std::string_view text, const std::string& path, const std::string& default_name = "");

}  // namespace eomgen
