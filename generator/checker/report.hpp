/** @file report.hpp  The check report as terminal text, Markdown or JSON (format: docs/checker.md). */
#pragma once

#include "checker/checker.hpp"

#include <string>

namespace eomgen::checker {

/// One line per equation, `file:line:col: verdict: equation`, details indented under it, a summary last.
std::string format_text(const CheckReport& report);

/// A Markdown document: summary, the disagreements in full, then a table of every equation.
std::string format_markdown(const CheckReport& report);

/// A JSON object: model, derivation, sections, map, summary, and one object per equation.
std::string format_json(const CheckReport& report);

}  // namespace eomgen::checker
