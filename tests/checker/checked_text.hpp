/** @file checked_text.hpp  A derivation given as a string, checked against a model file of the source tree
 * (derived once per model): for the tests of the checker that write their derivations inline. */
#pragma once

#include "test_paths.hpp"
#include "checker/checker.hpp"
#include "model/model_file.hpp"

#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>

namespace eomgen::test {

/// The model at `path` (relative to the source tree) and its equations, derived once.
inline const std::pair<Model, Equations>& derived_model(const std::string& path) {
    static std::map<std::string, std::pair<Model, Equations>> cache;
    auto it = cache.find(path);
    if (it == cache.end()) {
        Model m = load_model(eomgen_test::source_dir() + "/" + path);
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

/// A verdict in one paragraph, for INFO(): line, verdict, equation, what it was compared with, the reason, the
/// wrong terms, notes and the correction.
inline std::string describe(const checker::EquationCheck& e) {
    std::string s = std::to_string(e.where.line) + ": " + checker::verdict_name(e.verdict) + ": " + e.equation + " [" +
                    e.compared_with + "] " + e.reason;
    for (const std::string& w : e.wrong_terms) s += "\n  - " + w;
    for (const std::string& n : e.notes) s += "\n  note: " + n;
    if (!e.corrected.empty()) s += "\n  corrected: " + e.corrected;
    return s;
}

/// Every verdict of a report, one describe() each, for INFO().
inline std::string describe_all(const checker::CheckReport& r) {
    std::string s;
    for (const checker::EquationCheck& e : r.equations) s += describe(e) + "\n";
    return s;
}

/// Whether one of the verdict's notes contains `part`.
inline bool has_note(const checker::EquationCheck& e, const std::string& part) {
    for (const std::string& n : e.notes)
        if (n.find(part) != std::string::npos) return true;
    return false;
}

/// The text of tests/checker/fixtures/`name`.
inline std::string fixture(const std::string& name) {
    std::ifstream in(eomgen_test::source_dir() + "/tests/checker/fixtures/" + name, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// Line → what the verdict on a planted mistake must contain, from the line's `% planted[...]`.
inline std::map<int, std::string> planted_mistakes(const std::string& text) {
    std::map<int, std::string> planted;
    std::istringstream in(text);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
        if (const std::size_t at = line.find("% planted["); at != std::string::npos)
            planted[n] = line.substr(at + 10, line.rfind(']') - at - 10);
    return planted;
}

/// The lines of the fixture at `path` marked `% planted[phrase]` (a planted mistake), with their phrase.
inline std::map<int, std::string> planted_lines(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return planted_mistakes(ss.str());
}

/// Every disagreement of `r` is at a planted line (no false alarm) and names its phrase (in the difference, the wrong
/// terms, the notes or the correction); returns how many there are.
inline int planted_found(const checker::CheckReport& r, const std::map<int, std::string>& planted) {
    int found = 0;
    for (const checker::EquationCheck& e : r.equations) {
        INFO(describe(e));
        if (e.verdict != checker::Verdict::Disagrees) continue;
        const auto p = planted.find(e.where.line);
        REQUIRE(p != planted.end());
        std::string all = e.difference + e.corrected;
        for (const std::string& w : e.wrong_terms) all += w;
        for (const std::string& n : e.notes) all += n;
        CHECK(all.find(p->second) != std::string::npos);
        ++found;
    }
    return found;
}

}  // namespace eomgen::test
