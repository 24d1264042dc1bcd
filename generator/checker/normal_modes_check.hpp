/** @file normal_modes_check.hpp  A text's normal frequencies and secular equation, compared with the model's
 * small oscillations (mechanics/small_oscillations.hpp: `eomgen modes`). */
#pragma once

#include "checker/checker.hpp"
#include "checker/comparisons.hpp"
#include "checker/derivation.hpp"
#include "checker/latex_parser.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace eomgen::checker {

/**
 * The frequency of a derivation is ω: `\omega`, or `\omega` with a subscript (`\omega_1`, `\omega_{\pm}`), when it
 * is not a name of the model (a `--map` entry can name it: `--map '\nu=\omega'`). An equation whose only names
 * besides the model's parameters are one frequency, and which is a polynomial P(ω²) once its denominators are
 * cleared, is compared with the secular equation det(K₀ − ω² M₀) = 0 at the model's equilibria that are not
 * unstable (Goldstein §6.2), K₀ and M₀ in the parameters where `eomgen modes` finds the equilibrium exactly:
 *
 *  - P of the same degree as det(K₀ − ω² M₀) (the number of coordinates): agrees when the two are proportional
 *    (P·lc(det) − det·lc(P) = 0), the secular equation itself, however it is scaled;
 *  - P of lower degree: agrees when it divides det(K₀ − ω² M₀), its roots are some of the model's ω² (a single
 *    `ω² = …` or `ω = …` is degree 1: a normal frequency of the model);
 *  - otherwise it disagrees, naming the model's secular equation or frequencies.
 *
 * `\pm` and `\mp` (which the parser does not read) give two equations, upper and lower signs, and both must
 * hold; a side `\begin{vmatrix} … \end{vmatrix}` is its determinant. Equality is decided by normal() (exact),
 * else at random parameter values to 1e-10 relative (the verdict says which); a text that writes numbers
 * only is compared at the model's parameter values. A frequency the text defines (`\omega_0^2 = g/l`) and
 * later uses with another (`\omega^2 = \omega_0^2 (2 \mp \sqrt2)`) is an abbreviation: its definition is not
 * compared, and its value is substituted where it is used. Where modes cannot be computed (a nonholonomic constraint,
 * no equilibrium found, damping or gyroscopic terms) the link is compared as usual (ω an unknown symbol: not
 * comparable), with a note giving the reason.
 */
class NormalModesCheck {
  public:
    NormalModesCheck(const Model& model, const Equations& eq, const Derivation& d) : model_(model), eq_(eq), d_(d) {}

    /**
     * Judges the link left = right into r (its `where`, `section` and `equation` already set). False when the
     * link is not an equation in a frequency (r untouched), or when the model's modes cannot be compared (a note
     * in r says why): the caller compares it as usual.
     */
    bool check(const Side& left, const Side& right, LatexContext& ctx, Comparisons& cmp, EquationCheck& r);

    /// M₀ and K₀ (exact, in the parameters) at each equilibrium that is not unstable, with where it is
    /// ("$x_{1} = 0$, $x_{2} = 0$"); empty where the modes cannot be computed or are known in numbers only.
    struct RestMatrices {
        GiNaC::matrix M, K;
        std::string at;
    };
    std::vector<RestMatrices> rest_matrices(Comparisons& cmp) {
        if (!computed_) compute(cmp);
        std::vector<RestMatrices> out;
        for (const Rest& r : rests_)
            if (r.M) out.push_back({*r.M, *r.K, r.at});
        return out;
    }

  private:
    /// One equilibrium that is not unstable, as the comparison needs it.
    struct Rest {
        std::string at;                 ///< "$\theta_{1} = 0$, $\theta_{2} = 0$"
        std::optional<GiNaC::matrix> M, K;  ///< M₀ and K₀ where exact
        std::optional<GiNaC::ex> poly;  ///< det(K₀ − w M₀) in the parameters, expanded (where exact)
        std::vector<double> omega2;     ///< at the model's parameter values
        std::vector<std::optional<GiNaC::ex>> omega2_exact;
    };
    /// How one reading P(w) = 0 compares with one equilibrium.
    struct Judgement {
        bool agrees = false;
        bool comparable = true;  ///< false: a frequency in the parameters against an equilibrium known in numbers only
        std::string how;    ///< "exactly", "numerically, …", "at the model's parameter values"
        std::string what;   ///< agrees: what it is ("the secular equation", "a normal frequency of the model")
        std::string wrong;  ///< disagrees: a degree the model cannot have ("" otherwise)
        int mode = -1;      ///< degree 1: the model's mode nearest to its root at the parameter values
    };
    Judgement judge(const Rest& rest, const GiNaC::ex& P, const std::string& omega, double tol, Comparisons& cmp) const;
    void compute(Comparisons& cmp);
    /// The frequencies the text defines and then uses with another frequency (abbreviations), from all its rows.
    void find_abbreviations(const LatexContext& ctx);
    /// The frequencies in `values` (name → symbol); false when they hold a name that is neither a frequency nor
    /// a parameter of the model.
    bool frequencies_in(const std::vector<GiNaC::ex>& values, const LatexContext& ctx,
                        std::map<std::string, GiNaC::symbol>& out) const;
    /// The text's polynomial P(w) of one reading a = b, or std::nullopt when it is not an equation in ω².
    std::optional<GiNaC::ex> polynomial(const GiNaC::ex& a, const GiNaC::ex& b, const GiNaC::symbol& omega) const;
    /// The model's frequencies at `rest`, for a verdict: "$\omega^2 = …$ or $\omega^2 = …$".
    std::string frequencies(const Rest& rest, const std::string& omega, Comparisons& cmp) const;

    const Model& model_;
    const Equations& eq_;
    const Derivation& d_;
    /// An abbreviation: its value of ω² and the line of its definition.
    struct Abbreviation {
        GiNaC::ex omega2;
        int line = 0;     ///< where the text defines it
        int used_at = 0;  ///< the last line that uses it with another frequency
    };
    std::map<std::string, Abbreviation> abbreviations_;
    bool scanned_ = false;
    bool computed_ = false;
    std::string why_not_;  ///< why the model's modes cannot be compared (empty: they can)
    std::vector<Rest> rests_;
    GiNaC::exmap values_;  ///< the model's parameter values
    GiNaC::symbol w_{"w"};
};

}  // namespace eomgen::checker
