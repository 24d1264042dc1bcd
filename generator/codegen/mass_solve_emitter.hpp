/** @file mass_solve_emitter.hpp  The generated solve of M q'' = f: an LDL^T factorization of M unrolled for small n,
 * skipping the entries that are zero for every q. */
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace eomgen::codegen {

/// Models with up to this many coordinates get the unrolled solve; above, rhs() calls the runtime's loop
/// (eomgen::solve_mass_matrix, the same factorization), whose code does not grow with n².
constexpr std::size_t kUnrolledSolveMaxN = 12;

/**
 * The static member `solve_for_accelerations(t, x_, M_, f_, qdd_)` of a generated model (4-space indented, with its
 * doc comment): q'' from M q'' = f by M = L D L^T, unrolled, with u_ij = L_ij d_j,
 *   u_ij = M_ij - sum_{k<j} u_ik L_jk,  L_ij = u_ij / d_j,  d_i = M_ii - sum_{k<i} u_ik L_ik,
 * then L y = f, and L^T q'' = D^-1 y. `zero[i][j]` (i > j) says M_ij is zero for every q; an entry of L is left out
 * where it is zero by that pattern and its fill-in. The pivots are tested as eomgen::solve_mass_matrix tests them
 * (eomgen::pivots_regular) and the result's finiteness after (eomgen::throw_solve_failure says which error).
 */
std::string emit_mass_solve(const std::vector<std::vector<bool>>& zero);

}  // namespace eomgen::codegen
