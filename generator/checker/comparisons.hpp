/** @file comparisons.hpp  What the checker's comparisons offer the files of one capability (approximations,
 * constants): equality for all values, the equations-of-motion test, eomgen's LaTeX and the wrong terms. */
#pragma once

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace eomgen::checker {

/// e holds a power with a fractional exponent (a square root, a cube root).
inline bool has_root(const GiNaC::ex& e) {
    if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)) &&
        !GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_integer())
        return true;
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (has_root(e.op(i))) return true;
    return false;
}

class Comparisons {
  public:
    virtual ~Comparisons() = default;
    /// a = b for all values: symbolically, else at random points, within the relative tolerance `tol`.
    virtual bool same(const GiNaC::ex& a, const GiNaC::ex& b, double tol) = 0;
    /// r (with accelerations) is a combination Σ c_i EL_i of the model's Euler–Lagrange equations.
    virtual bool equation_of_motion(const GiNaC::ex& r, double tol) = 0;
    /// Which Euler–Lagrange equations r = Σ c_i EL_i combines (c_i ≠ 0), one flag per coordinate; empty when r
    /// is no such combination.
    virtual std::vector<bool> euler_lagrange_terms(const GiNaC::ex& r, double tol) = 0;
    /// The coordinate whose Euler–Lagrange equation r (with accelerations) is closest to, as a disagreement is
    /// compared (the most groups of terms equal after the best factor); −1 when no group matches.
    virtual int closest_euler_lagrange(const GiNaC::ex& r, double tol) = 0;
    /// r (with accelerations) vanishes at every state on the model's constraints, q̈ from the constrained equations
    /// (constrained_motion.hpp); false for a model without constraints.
    virtual bool vanishes_on_constrained_motion(const GiNaC::ex& r, double tol) = 0;
    /// LaTeX by eomgen's canonical printer (symbols in the model's order).
    virtual std::string latex(const GiNaC::ex& e) = 0;
    /// The wrong, missing and extra terms of `text` against `truth`, one sentence each.
    virtual std::vector<std::string> wrong_terms(const GiNaC::ex& text, const GiNaC::ex& truth, double tol) = 0;
};

}  // namespace eomgen::checker
