/** @file checked_text.hpp  A derivation given as a string, checked against a model file of the source tree
 * (derived once per model): for the tests of the checker that write their derivations inline. */
#pragma once

#include "checker/checker.hpp"
#include "model/model_file.hpp"

#include <map>
#include <string>
#include <utility>

namespace eomgen::test {

/// The model at `path` (relative to the source tree) and its equations, derived once.
inline const std::pair<Model, Equations>& derived_model(const std::string& path) {
    static std::map<std::string, std::pair<Model, Equations>> cache;
    auto it = cache.find(path);
    if (it == cache.end()) {
        Model m = load_model(std::string(EOMGEN_SOURCE_DIR) + "/" + path);
        Equations e = derive_equations(m);
        it = cache.emplace(path, std::make_pair(std::move(m), std::move(e))).first;
    }
    return it->second;
}

/// Checks `text` (Markdown + LaTeX) against the model at `model_path`.
inline checker::CheckReport check_text(const std::string& model_path, const std::string& text,
                                       const checker::CheckOptions& options = {}) {
    const auto& d = derived_model(model_path);
    return checker::check_derivation(d.first, d.second, checker::parse_derivation(text, "text.md"), options);
}

}  // namespace eomgen::test
