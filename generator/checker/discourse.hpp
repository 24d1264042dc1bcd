/** @file discourse.hpp  What the text's rows are besides claims, read once from all of them before any is
 * compared: the conditions it states (the point or motion it considers), the letters it gives quantities, its
 * trial solutions and the frequencies it states. The comparisons ask it by file offset. */
#pragma once

#include "checker/amplitude_equations.hpp"
#include "checker/characteristic_equation.hpp"
#include "checker/derivation.hpp"
#include "checker/latex_parser.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace eomgen::checker {

/// One link `left = right` of the text, where it stands: what the discourse is read from.
struct DiscourseLink {
    const Side* left = nullptr;
    const Side* right = nullptr;
    Relation relation = Relation::Equal;
    std::size_t at = 0;          ///< file offset of its relation sign
    std::size_t until = 0;       ///< the end of its section (file offset)
    std::size_t paragraph = 0;   ///< the end of its paragraph (the next blank line)
    /// the end of the displays its paragraph runs on into (prose.hpp's paragraph_end): where the conditions of a
    /// steady motion or an equilibrium it states still hold ("for steady precession, $\ddot\theta = 0$, and dividing
    /// by $\sin\theta$," then the display alone)
    std::size_t runs_on = 0;
    std::size_t left_at = 0;     ///< file offset where its left side starts
    std::vector<const Side*> chain;  ///< every side of its chain, in order (`\dot r = \dot\theta = 0`)
};

/**
 * `s = \frac{1}{2h}`, `\dot\theta = 0`: a coordinate or a velocity alone set to a value free of the state and of t —
 * a condition of a particular point or motion, not an equation of the motion (an acceleration so set is one:
 * free fall). The coordinate's LaTeX ("" when the link is not one), and in `symbol`, `value` what it sets.
 */
std::string condition_of(const GiNaC::ex& a, const GiNaC::ex& b, const Model& model, GiNaC::ex* symbol = nullptr,
                         GiNaC::ex* value = nullptr);

/// What the checker knows of its labels, for the namings: the value of a label symbol (T, L, p_θ, …), if it is one.
struct LabelView {
    std::function<std::optional<GiNaC::ex>(const GiNaC::ex&)> value;
    std::function<bool(const GiNaC::ex&)> is_momentum;
    std::function<bool(const GiNaC::ex&, const GiNaC::ex&)> same;
};

class Discourse {
  public:
    /// A condition the text states: `symbol` is `value` from `from` to `until` (the end of its paragraph).
    struct Condition {
        GiNaC::ex symbol, value;
        std::size_t from, until;
        int line;
        bool is_position;    ///< a coordinate's value (a point), not a velocity's or an acceleration's
        bool limit = false;  ///< a parameter's limit the text takes in its prose ("as $c \to 0$"; limits.cpp)
        bool setting = false;  ///< an assumption of the problem's setting ("take", "let", "assume"): to its section's end
    };
    /// A letter the text gives another quantity (`p_\theta = L`), from the naming to its section's end.
    struct Naming {
        GiNaC::ex letter, quantity;
        std::string letter_latex, quantity_latex;
        std::size_t from, until;
        int line;
    };

    /**
     * Reads the links in file order. Conditions: condition_of() on links whose sides name nothing unknown, a
 * parameter set to an expression in the others (an assumption, `m_1 = m_2`), and an
 * acceleration set to a value free of the state where a condition on its coordinate is in force (`\dot\theta =
 * 0` and `\ddot\theta = 0`: a steady motion, not free fall).
     * Namings: a momentum label set equal to one of the one-letter labels L, H, h, E, T, V when the two differ.
     * Trial solutions: trial_solution(), those of one coordinate each with one frequency gathered. Stated
     * frequencies: a free name `\omega…` (or its square) set to a value in the parameters alone.
     */
    Discourse(const std::vector<DiscourseLink>& links, const Model& model, LatexContext& ctx, const Derivation& d,
              const LabelView& labels);

    const std::vector<Condition>& conditions() const { return conditions_; }
    /// "As $c \to 0$ it becomes": a parameter of the model sent to a number in an inline formula is that value for
    /// the display the sentence leads into, where M stays regular at it (limits.cpp). Called once, after the links.
    void read_limits(const Derivation& d, const Model& model, LatexContext& ctx, const GiNaC::matrix& mass);
    /// Whether the condition on `symbol` in force at `at` is a limit the text takes (its line in `line`).
    bool limit_at(const GiNaC::ex& symbol, std::size_t at) const {
        bool limit = false;  // the latest in force, as conditions_at() takes it
        for (const Condition& k : conditions_)
            if (k.from < at && at < k.until && k.symbol.is_equal(symbol)) limit = k.limit;
        return limit;
    }
    /// Whether the link at `at` states an assumption on the parameters (`m_1 = m_2`), in force to its paragraph's end.
    bool states_assumption(std::size_t at) const { return assumptions_.count(at) != 0; }
    /// Whether the link at `at` states a condition (`\dot\theta = 0`, and `\ddot\theta = 0` after one on θ).
    bool states_condition(std::size_t at) const {
        return std::any_of(conditions_.begin(), conditions_.end(), [&](const Condition& c) { return c.from == at; });
    }
    /// The conditions in force at `at` (stated before it in its paragraph), the latest per symbol, with its line.
    std::map<GiNaC::ex, std::pair<GiNaC::ex, int>, GiNaC::ex_is_less> conditions_at(std::size_t at) const;
    /// The end of the paragraph of a point (a coordinate's value) stated before `at` there, or 0: what that paragraph names a value
    /// free of the state (`y = r\cos\pi`) is the name's value at the point, not its definition.
    std::size_t condition_paragraph(std::size_t at) const;

    /// The naming made by the link at `at`, if it is one.
    const Naming* naming_at(std::size_t at) const;
    /// e with the letters named before `at` replaced by their quantities outside ∂·/∂·; a note for each used.
    GiNaC::ex renamed(const GiNaC::ex& e, std::size_t at, std::vector<std::string>& notes) const;

    /// Whether the link at `at` sets up a trial solution.
    bool sets_trial(std::size_t at) const { return trial_links_.count(at) != 0; }
    /// The trial solution in force at `at`, or nullptr.
    const TrialSolution* trial_at(std::size_t at) const;
    /// The exponential trial solution (`\varphi = e^{\lambda t}`) in force at `at`, or nullptr.
    const ExponentialTrial* exponential_at(std::size_t at) const;
    /// The squared frequency the text stated last before `at` in its section, if any.
    std::optional<GiNaC::ex> stated_frequency(std::size_t at) const;
    /// The frequencies stated before `at` in their section, by name: ω → its value (`\omega^2 = g/l` gives √(g/l)).
    GiNaC::exmap stated_frequencies(std::size_t at) const;

  private:
    std::vector<Condition> conditions_;
    std::set<std::size_t> assumptions_;
    std::vector<Naming> namings_;
    std::vector<TrialSolution> trials_;
    std::vector<ExponentialTrial> exponentials_;
    std::set<std::size_t> trial_links_;
    struct Stated {
        std::size_t at, until;
        GiNaC::ex omega2;
        GiNaC::ex symbol;  ///< the text's ω
    };
    std::vector<Stated> stated_;
};

}  // namespace eomgen::checker
