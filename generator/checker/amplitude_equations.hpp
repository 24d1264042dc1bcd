/** @file amplitude_equations.hpp  A trial solution the text tries (`x_j = A_j e^{i\omega t}`, `\theta_1 =
 * A_1\cos\omega t`) and the equations it gives for the amplitudes: rows of (K₀ − ω² M₀) A = 0, the model's
 * small oscillations about q = 0, with the frequency left free or at one of the model's normal frequencies. */
#pragma once

#include "checker/checker.hpp"
#include "checker/comparisons.hpp"
#include "checker/latex_parser.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace eomgen::checker {

/// What a trial solution sets up: an amplitude for each coordinate it names and the frequency.
struct TrialSolution {
    std::vector<GiNaC::ex> amplitude;  ///< per coordinate: the text's free name A_k, or 0 where it names none
    GiNaC::ex omega = 0;               ///< the frequency, a free name of the text (`\omega`), or 0
    std::size_t from = 0;              ///< file offset of its relation: it holds after it ...
    std::size_t until = 0;             ///< ... to the end of its section
    int line = 0;
    std::string source;                ///< "x_j = A_j e^{i \omega t}"
    /// How the reports name it: "" for "the trial solution of line N"; the amplitudes a text names without writing
    /// a trial solution say so (implied_amplitudes).
    std::string what;
    std::string described() const { return what.empty() ? "the trial solution of line " + std::to_string(line) : what; }
};

/**
 * The trial solution a link `left = right` sets up, when it is one: a coordinate (`x_1`), or a name with the
 * model's coordinates' letter and a letter for an index (`x_j` for the model's x_{1}, x_{2}, …), set equal to an
 * amplitude (a free name, `A_1` or `A_j` with the same index) times a function of t that holds a frequency (a
 * free name multiplying t: `e^{i\omega t}`, `\cos(\omega t + \phi)`). std::nullopt otherwise.
 */
std::optional<TrialSolution> trial_solution(const GiNaC::ex& left, const GiNaC::ex& right, const Model& model,
                                            LatexContext& ctx);

/**
 * `A_2 = \sqrt{2} A_1` after the normal frequencies, with no trial solution written: the names of `names` (the text's
 * unknowns in a link) as the amplitudes of the model's coordinates, when they are two or more names of one letter with
 * the coordinates' subscripts (θ₁, θ₂ ↔ A_1, A_2), or, for coordinates without subscripts, 1 … n in their order. The
 * frequency is left free (0). std::nullopt when the names are not such amplitudes.
 */
std::optional<TrialSolution> implied_amplitudes(const std::vector<const FreeName*>& names, const Model& model);

/**
 * The amplitude equations of the model: with q = A f(t) and q̈ = −ω² q about q = 0 (an equilibrium of the model,
 * or any point when the equations are linear; no velocity terms there), row i is Σ_k (K₀ − ω² M₀)_{ik} A_k = 0, K₀ and M₀ the derivatives of the i-th
 * Euler–Lagrange equation by q_k and q̈_k at rest.
 */
class AmplitudeEquations {
  public:
    AmplitudeEquations(const Model& model, const std::vector<GiNaC::ex>& motion) : model_(model), motion_(motion) {}

    /**
     * Judges r = left − right = 0 (a link, the text's definitions applied) as an equation of `trial`'s
     * amplitudes into out: r must hold an amplitude, no coordinate, velocity or acceleration, no amplitude
     * squared, and no name other than the amplitudes and the frequency once the factors in t (`e^{i\omega t}`)
     * are taken out. Agrees when r is a multiple of one row, with ω free, or, when r has no ω, at one of the
     * model's normal frequencies (a root of det(K₀ − w M₀): the one the text has just stated, `stated` ω², when
     * it is a root); disagrees otherwise, against the row it matches best (a term missing its amplitude counts
     * as that amplitude's), which the correction writes out — solved for the amplitude a side holds alone
     * (`A_1 = …`). False (out untouched) when r is not such an equation or the model
     * has no such rows (not at rest at q = 0, or velocity terms about it); a note in `why_not` says which.
     */
    bool check(const GiNaC::ex& left, const GiNaC::ex& right, const std::string& left_source,
               const std::string& right_source, const std::vector<std::string>& written, const TrialSolution& trial,
               const std::optional<GiNaC::ex>& stated, const LatexContext& ctx, Comparisons& cmp, EquationCheck& out);

    /**
     * Judges `name = (v_1, …, v_n)` (a vector the text names after the amplitude equations of a mode: `e_1 = (1, 1,
     * 1)`) as that mode's shape, at the frequency `stated` (ω²) of `trial`: agrees when v is a multiple of the null
     * vector of K₀ − ω² M₀ there; disagrees otherwise, corrected to the shape scaled to v's first entry that is
     * not 0 in both. False (out untouched) when there is no such frequency or shape, or v has another length.
     */
    bool check_shape(const std::vector<GiNaC::ex>& v, const std::string& name, const TrialSolution& trial,
                     const std::optional<GiNaC::ex>& stated, Comparisons& cmp, EquationCheck& out);

    /// The text's assumptions on the parameters where the next checks are (`m_1 = m_2`): K₀ and M₀ are taken with
    /// them put in, so that the frequencies and corrections read as the text's (empty: none).
    void assume(GiNaC::exmap assumed) { assumed_ = std::move(assumed); }

  private:
    bool prepare(Comparisons& cmp);
    /// The mode's shape at ω² = w2: the null vector of K₀ − w2 M₀ (one component 1), when its null space is a line.
    std::optional<std::vector<GiNaC::ex>> mode_shape(const GiNaC::ex& w2) const;
    /// `A_1 = A_3` (two amplitudes, c their coefficients in left − right) against the ratio of the mode at w2.
    bool ratio_correction(const GiNaC::ex& left, const GiNaC::ex& right, const std::string& left_source,
                          const std::string& right_source, const TrialSolution& trial, const std::vector<GiNaC::ex>& c,
                          const GiNaC::ex& w2, Comparisons& cmp, EquationCheck& out) const;
    const Model& model_;
    const std::vector<GiNaC::ex>& motion_;
    bool prepared_ = false, usable_ = false;
    GiNaC::exmap assumed_;
    GiNaC::matrix K_, M_;  ///< about q = 0
};

}  // namespace eomgen::checker
