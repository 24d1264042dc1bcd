/** @file definitions.hpp  Quantities a derivation defines (`K = \frac12 m l^2 \dot\phi^2`) and uses inside
 * derivatives (`\frac{\partial K}{\partial \dot\phi}`): the definition is differentiated, never the bare
 * symbol, which would count as a constant and give 0. */
#pragma once

#include "checker/latex_parser.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <cstddef>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace eomgen::checker {

/// A derivative of a name the text does not define and the model does not know: it cannot be evaluated
/// (taking the name as a constant would make it 0). `name` is the canonical LaTeX name.
class UndefinedInDerivative : public std::runtime_error {
  public:
    UndefinedInDerivative(std::string name_, std::string what)
        : std::runtime_error(what), name(std::move(name_)) {}
    std::string name;
};

/**
 * The text's definitions, in file order: a free name set equal to an expression the checker can evaluate
 * (the last comparable side of a chain that starts with the name alone). A later definition of the same name
 * replaces an earlier one from its place on.
 */
class TextDefinitions {
  public:
    /// Records that `symbol` (the free name `name`) is `value` from file offset `offset` (line `line`) on;
    /// as an abbreviation everywhere (abbreviate()) up to `until`, the end of its section. `source` is the
    /// value as the text writes it, for the notes. `conserved`: the value is a constant of the motion, held
    /// fixed where the text differentiates by a coordinate (expand_holding()); `value_holding`: the value with the
    /// constants of the motion in it held (as set_holding() made prepare give it), or null for `value`.
    void add(const GiNaC::ex& symbol, const std::string& name, const GiNaC::ex& value, std::size_t offset,
             int line, std::size_t until = std::string::npos, const std::string& source = "",
             std::size_t head = std::string::npos, bool conserved = false,
             const GiNaC::ex* value_holding = nullptr, std::size_t section_begin = 0);

    /// While on, abbreviate() puts in the held symbols of the constants of the motion, not their values (to take
    /// a definition's value with them held: `V_{eff}` in J).
    void set_holding(bool on) const { holding_ = on; }
    /// While on, an abbreviation the text gives only later in the section of a use is in force there too, when none
    /// is before it (`I` in `I\ddot\theta = -\lambda r`, "the moment of inertia … is $I = \frac12 m r^2$" after).
    void set_forward(bool on) const { forward_ = on; }
    /// While on, an abbreviation an earlier section gave is in force after it too, when none is in the use's own
    /// section (`F_x` of a section "Forces" in the next section's `… = F_x`).
    void set_backward(bool on) const { backward_ = on; }
    bool has_conserved() const { return !held_values_.empty(); }

    /**
     * `e` (a side at file offset `at`, outside derivatives too) with the names defined before it in its
     * section replaced by their definitions: "with $\Omega = \omega_3 (I_3 - I)/I$" makes Ω an abbreviation
     * for the rest of the section. Records a note for each definition used (see take_abbreviations()).
     */
    GiNaC::ex abbreviate(const GiNaC::ex& e, std::size_t at) const;

    /// "using $\Omega = ...$ (line 15)", for each definition abbreviate() used since the last call.
    std::vector<std::string> take_abbreviations() const;

    /// "k = g/l" when the side at file offset `head` is a name the text defines there, else "".
    std::string defined_at(std::size_t head) const;

    /// The operand of a derivative at file offset `at`, with the defined names in it replaced by their
    /// definitions (which may use earlier ones). Records the definitions used (see take_used()).
    GiNaC::ex expand(const GiNaC::ex& operand, std::size_t at) const;

    /**
     * expand(), for a derivative by a coordinate: a name whose definition is a constant of the motion is held
     * fixed, as the text means it (`V_{eff} = \frac{J^2}{2 m l^2 \sin^2\theta} + …` with J = p_φ, differentiated
     * by θ at fixed J): it becomes a symbol of its own; `held` maps each such symbol to its value, to put in after
     * differentiating.
     */
    GiNaC::ex expand_holding(const GiNaC::ex& operand, std::size_t at, GiNaC::exmap& held) const;

    /**
     * Throws UndefinedInDerivative when `operand` (already expanded) holds a free name of `ctx` that is a
     * scalar without a definition (an additive constant, `\text{const}`, is a constant). `what`
     * says what the derivative is ("d/dt", "\partial/\partial \theta").
     */
    static void require_defined(const GiNaC::ex& operand, const LatexContext& ctx, const std::string& what);

    /// True when `operand` holds a vector name (`\mathbf{L}`): its derivative is left unevaluated, and the
    /// side is not compared because of the vector.
    static bool has_vector(const GiNaC::ex& operand, const LatexContext& ctx);

    /// "uses $K$ as the text defines it at line 12", for each definition expand() used since the last call.
    std::vector<std::string> take_used() const;

    /// The definition of `symbol` in force at file offset `at` in its section, with its line; nullptr when there
    /// is none (for `\dot{x}` after `x = l \sin\theta`: the derivative of the definition).
    const GiNaC::ex* value_at(const GiNaC::ex& symbol, std::size_t at, int* line = nullptr) const;
    /// Whether the definition value_at() gives is a correction of the text's (correct()).
    bool corrected_at(const GiNaC::ex& symbol, std::size_t at) const;

    bool empty() const { return defs_.empty(); }

    /// One definition put into a side (by expand(), abbreviate() or dotted_definitions()).
    struct Use {
        std::size_t head = 0;  ///< file offset of the defined name where it is defined (the definition's row)
        GiNaC::ex value;       ///< what the name stood for
        int line = 0;
    };
    /// The definitions put into sides since the last call (a comparison that agrees confirms them).
    std::vector<Use> take_uses() const {
        std::vector<Use> out;
        out.swap(uses_);
        return out;
    }
    /// Records a use of the definition in force for `symbol` at `at` (dotted_definitions() differentiates it).
    void note_use(const GiNaC::ex& symbol, std::size_t at) const;

    /// While suspended, the definitions of the name `name` (canonical LaTeX) are not in force anywhere: the name is
    /// the text's unknown again (to find what a line needs it to be).
    void suspend(const std::string& name) { suspended_.insert(name); }
    void resume() { suspended_.clear(); }

    /// While set, the definition of `symbol` in force anywhere is `value` (what a line needs it to be: to try the
    /// other lines that use it with that value); clear with reset_override().
    void override_with(const GiNaC::ex& symbol, const GiNaC::ex& value);
    void reset_override() { override_active_ = false; }

    /// The definition made at file offset `head` is wrong and `value` is what it must be (the text's own relation
    /// solved for the name, say): from its place on `value` is put in, so that one slip does not make every line
    /// after it disagree, and a later, independent slip is still found. The notes say "corrected".
    void correct(std::size_t head, const GiNaC::ex& value, const std::string& source);

  private:
    struct Definition {
        std::string name;
        GiNaC::ex value;
        std::size_t offset = 0;
        int line = 0;
        std::size_t until = std::string::npos;
        std::string source;
        std::size_t head = std::string::npos;
        std::size_t section_begin = 0;  ///< where its section starts (forward uses, set_forward())
        bool conserved = false;   ///< a constant of the motion: held fixed in a derivative by a coordinate
        GiNaC::ex value_holding;  ///< `value` with the constants of the motion in it held
        GiNaC::symbol held;       ///< stands for it while it is held
        bool corrected = false;   ///< `value` is not the text's but its correction (correct())
    };
    /// The definition of `symbol` in force at `at` (within its section when `in_section`), or nullptr.
    const Definition* in_force(const std::vector<Definition>& list, std::size_t at, bool in_section) const;
    GiNaC::ex expand_impl(const GiNaC::ex& operand, std::size_t at, GiNaC::exmap* held) const;
    std::map<GiNaC::ex, std::vector<Definition>, GiNaC::ex_is_less> defs_;
    mutable std::vector<std::string> used_;
    mutable std::vector<Use> uses_;
    mutable bool holding_ = false;
    mutable bool forward_ = false;
    mutable bool backward_ = false;
    GiNaC::exmap held_values_;  ///< each held symbol, its value
    std::map<GiNaC::ex, std::string, GiNaC::ex_is_less> held_notes_;  ///< each held symbol, what the note says
    std::set<std::string> suspended_;
    Definition override_;
    bool override_active_ = false;
    mutable std::vector<std::string> abbreviations_;
    /// The defined names where they are defined (never abbreviated): file offset, "k = g/l".
    std::vector<std::pair<std::size_t, std::string>> heads_;
};

/// Whether `e` reads as a speed squared written out: ≥ 0 by its form wherever it is real (a sum of terms, each a
/// positive number times even powers, `l^2\dot\theta^2`, `\sin^2\theta`, and the model's parameters, taken positive
/// as lengths and masses are), and no square of one quantity (`\dot\varphi^2`, `(\dot x - l\dot\theta)^2`: the root
/// of those is a velocity with a sign, which a text may go on to write as its name). `v^2 = \dot r^2 +
/// r^2\dot\theta^2` is one: its name is then the speed, the positive root.
bool speed_squared(const GiNaC::ex& e, const Model& model);

/// `\dot{x}`, `\ddot{x}` (free names) of a name the text defines (`x = l \sin\theta`) in the model's quantities:
/// the time derivative of its definition in force at file offset `at`, each noted in `notes`.
GiNaC::ex dotted_definitions(const TextDefinitions& definitions, const GiNaC::ex& e, std::size_t at,
                             const LatexContext& ctx, const Model& model, std::vector<std::string>& notes);

}  // namespace eomgen::checker
