/** @file symbol_map.hpp  The per-derivation symbol map: `--map 'I_{0}=M a^2/2'` and map files ([latex] in
 * TOML). */
#pragma once

#include "checker/checker.hpp"

#include <string>
#include <utility>
#include <vector>

namespace eomgen::checker {

/**
 * One `--map` option, `NAME=VALUE` with NAME a LaTeX name (`I_{0}`, `\omega_{a}`, `Trod`) and VALUE LaTeX in
 * the model's symbols (`M a^{2}/2`, `\dot{\phi}`, `T_{rod}`). Split at the first `=` outside braces.
 * @throws CheckError when there is no `=` or a side is empty
 */
MapEntry parse_map_option(const std::string& text);

/**
 * A map file (docs/checker.md): TOML whose only table is `[latex]`, each key a LaTeX name and each value a
 * LaTeX string, applied in file order:
 *
 *     [latex]
 *     'I_{0}' = 'M a^{2}/2'      # the disk's moment of inertia about its centre
 *     '\omega_{a}' = '\dot{\phi}'
 *
 * @throws CheckError "file:line:col: message" for a TOML error, another table or key, or a non-string value
 */
std::vector<MapEntry> load_map_file(const std::string& path);

/// `--set NAME=VALUE` → {NAME, VALUE}. @throws CheckError when it is not NAME=<finite number>
std::pair<std::string, double> parse_set_option(const std::string& text);

}  // namespace eomgen::checker
