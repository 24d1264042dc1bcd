/** @file motions.hpp  Lines that hold only on one particular motion of the model ([[motions]] in the model
 * file: steady precession, an equilibrium, a circular orbit): compared after the motion's conditions, and their
 * time derivatives, are substituted. The motion itself must solve the Euler–Lagrange equations. */
#pragma once

#include "checker/checker.hpp"
#include "checker/comparisons.hpp"
#include "checker/latex_parser.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <cstddef>
#include <string>
#include <vector>

namespace eomgen::checker {

class ParticularMotions {
  public:
    /// `ctx` receives the motions' constants as free names (`\Omega`) when a motion is first used, so that
    /// the text's Ω is the motion's.
    ParticularMotions(const Model& model, const Equations& eq, LatexContext& ctx) : model_(model), eq_(eq), ctx_(ctx) {}

    bool empty() const { return model_.motions.empty(); }

    /**
     * Judges a = b on the first motion that applies to `sections` (the titles of the sections holding the
     * line; a motion without `section` applies everywhere). Fills `r` and returns true when it decides:
     * agrees when a − b vanishes on the motion; an equation `c = f` with c a name the text does not define
     * agrees when f is constant on the motion (c is a constant of it); disagrees when a − b does not vanish
     * and holds no name of the text's own (the correction gives `left_source` its value on the motion);
     * otherwise it leaves `r` alone. A motion that does not solve the Euler–Lagrange equations decides
     * nothing: the line is not comparable, and says why.
     */
    bool check(const GiNaC::ex& a, const GiNaC::ex& b, const std::string& left_source,
               const std::vector<std::string>& sections, Comparisons& cmp, double tol, EquationCheck& r);

  private:
    struct Reading {
        const Motion* motion = nullptr;
        GiNaC::exmap subs;        ///< q, q', q'' of the conditions → their values on the motion
        std::string conditions;   ///< "$\dot{\theta} = 0$, ..." for the report
        std::string problem;      ///< why it is not a solution of the Euler–Lagrange equations ("" when it is)
        std::vector<GiNaC::ex> constants;  ///< the constants as the text's free symbols
    };
    Reading& reading(const Motion& m, Comparisons& cmp);
    GiNaC::ex on(const Reading& rd, const GiNaC::ex& e) const;
    /// Names of the text in e other than the motion's constants (a constant of the motion such as ω₀).
    std::vector<GiNaC::ex> text_names(const Reading& rd, const GiNaC::ex& e) const;

    const Model& model_;
    const Equations& eq_;
    LatexContext& ctx_;
    std::vector<Reading> readings_;
};

}  // namespace eomgen::checker
