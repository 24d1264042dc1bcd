/** @file report.hpp  The check report as terminal text, Markdown or JSON (format: docs/checker.md). */
#pragma once

#include "checker/checker.hpp"

#include <string>

namespace eomgen::checker {

/// "12 equations: 7 agree, 1 disagree, 2 not comparable, 2 not judged (definitions, conditions: not claims)".
std::string summary_line(const CheckReport& report);

/// A verdict as the reports show it: its name, and for a row that is not a claim the role it was taken for,
/// "not judged (definition)".
std::string verdict_shown(const EquationCheck& e);

/// One line per equation, `file:line:col: verdict: equation`, details indented under it, a summary last.
std::string format_text(const CheckReport& report);

/// A Markdown document: summary, the disagreements in full, then a table of every equation.
std::string format_markdown(const CheckReport& report);

/// A JSON object: model, derivation, sections, map, summary, and one object per equation.
std::string format_json(const CheckReport& report);

}  // namespace eomgen::checker
