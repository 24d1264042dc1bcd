/**
 * @file kinks.hpp  Where a derivative the text takes does not exist (issue 36): ∂e/∂x across a switching surface
 * s = 0 of e's non-smooth functions (|x|, sgn, H, max, min) that depends on x, where e jumps (sgn(v − ẋ) of Coulomb
 * friction) or its one-sided derivatives differ (|ẋ| at ẋ = 0). The derivative GiNaC gives holds away from the
 * surface; the checker's verdict says that it does not hold on it. ẋ|ẋ| (a quadratic drag) has a derivative on its
 * surface, 0, and is not named.
 */
#pragma once

#include <ginac/ginac.h>

#include <vector>

namespace eomgen::checker {

/// A surface on which ∂e/∂x does not exist.
struct Kink {
    GiNaC::ex surface;  ///< s, as e's function holds it
    bool jump = false;  ///< e itself jumps there (sgn); else e is continuous and its one-sided slopes differ (|x|)
};

/// The surfaces of e's non-smooth functions on which ∂e/∂x does not exist: e's two sides (model/nonsmooth.hpp,
/// one_sided) differ there, or their derivatives in x do, at points of the surface (s solved for x where it is
/// linear in x; a surface it cannot solve is left out, not guessed).
std::vector<Kink> surfaces_without_derivative(const GiNaC::ex& e, const GiNaC::symbol& x);

}  // namespace eomgen::checker
