/** @file linear_solve.hpp  One unknown of a small linear system A x = b, solved symbolically: the accelerations of
 * M q̈ = f, the multipliers of the constrained equations, a mode's shape. */
#pragma once

#include <ginac/ginac.h>

#include <optional>
#include <vector>

namespace eomgen::checker {

/// x_i of A x = b (A square), by elimination, normal()-ised; nothing when the system is singular or GiNaC fails.
inline std::optional<GiNaC::ex> solved_unknown(const GiNaC::matrix& A, const GiNaC::matrix& b, unsigned i) {
    try {
        const unsigned n = A.rows();
        std::vector<GiNaC::symbol> unknowns(n);
        GiNaC::matrix x(n, 1);
        for (unsigned k = 0; k < n; ++k) x(k, 0) = unknowns[k];
        return GiNaC::normal(A.solve(x, b, GiNaC::solve_algo::gauss)(i, 0));
    } catch (...) {
        return std::nullopt;
    }
}

}  // namespace eomgen::checker
