/** @file coverage.hpp  Never silent: every row of math that holds a relation ends in the report, with a verdict or
 * as "not read" with its place and the reason (issue 28). */
#pragma once

#include "checker/checker.hpp"
#include "checker/derivation.hpp"

#include <vector>

namespace eomgen::checker {

/**
 * For each of `rows` (the rows of math that were read) that holds a relation sign (`=`, `\approx`, `\le`, `<`, …
 * at any depth) and has no entry of `reported` inside its range of the file, an EquationCheck with the verdict
 * NotRead at the first such sign, saying why no equation was taken from it: the sign is inside a group that is
 * not closed, inside a group or a command's argument, or the row could not be split.
 */
std::vector<EquationCheck> unread_rows(const Derivation& d, const std::vector<const MathRow*>& rows,
                                       const std::vector<EquationCheck>& reported);

}  // namespace eomgen::checker
