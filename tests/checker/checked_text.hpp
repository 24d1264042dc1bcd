/** @file checked_text.hpp  A derivation given as a string, checked against a model file of the source tree
 * (derived once per model): for the tests of the checker that write their derivations inline. */
#pragma once

#include "checker/checker.hpp"
#include "model/model_file.hpp"

#include <fstream>
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

/// The lines of the fixture at `path` marked `% planted[phrase]` (a planted mistake), with their phrase.
inline std::map<int, std::string> planted_lines(const std::string& path) {
    std::ifstream in(path);
    std::map<int, std::string> out;
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        const std::size_t at = line.find("% planted[");
        if (at == std::string::npos) continue;
        const std::size_t close = line.rfind(']');
        out[n] = line.substr(at + 10, close - at - 10);
    }
    return out;
}

}  // namespace eomgen::test
