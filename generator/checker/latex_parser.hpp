/** @file latex_parser.hpp  LaTeX math as people write derivations → GiNaC expressions, with positions and
 * reasons. */
#pragma once

#include <ginac/ginac.h>

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace eomgen::checker {

// Operators the parser cannot evaluate because only the checker knows the model and eomgen's T, V, L:
// they stay in the expression as functions and are evaluated after the labels (T, V, L, ...) are replaced.
DECLARE_FUNCTION_1P(ddt)    ///< ddt(x): the total time derivative d/dt x (`\frac{d}{dt} x`, `\frac{dx}{dt}`)
DECLARE_FUNCTION_2P(pdiff)  ///< pdiff(x, y): ∂x/∂y (`\frac{\partial L}{\partial \dot{\theta}}`)
DECLARE_FUNCTION_2P(pbracket)  ///< pbracket(a, b): the Poisson bracket {a, b} (`\{\theta, p_\theta\}`)
DECLARE_FUNCTION_2P(dby)  ///< dby(x, s): dx/ds by a name the text introduces (`\frac{d^2X}{d\tau^2}`, τ = t/T)
/// antiderivative(f, x): the indefinite integral ∫ f dx (`\int F(x)\,dx`), known up to a constant of integration
/// (indefinite_integral.hpp)
DECLARE_FUNCTION_2P(antiderivative)
/// evalat(x, {y == a, ...}): x at the point y = a, put in after the derivatives in x are taken (`\left.\frac{\partial
/// V}{\partial \theta}\right|_{\theta = 0}`)
DECLARE_FUNCTION_2P(evalat)
/// limat(x, {y == a}): the limit of x as y → a (`\lim_{\theta \to 0} \frac{\sin\theta}{\theta}`): x at a where it is
/// regular there, else the constant term of its series about a; a pole there is no limit (evaluation.cpp)
DECLARE_FUNCTION_2P(limat)

/// What a name the parser did not find among the known names stands for.
enum class NameKind {
    Unknown,  ///< a scalar the checker does not know: `I_{3}`, `\Omega`, `v_{a}`
    Vector,   ///< `\mathbf{r}`, `\boldsymbol{\omega}`, `\vec{n}`, `\hat{k}`, `\underline{n}`: not compared
    Unit,     ///< `\mathrm{m}`, `\mathrm{~s}`: must cancel for a comparison
};

/// A name without a known meaning, as the parser created a symbol for it.
struct FreeName {
    std::string name;  ///< canonical LaTeX: `I_{3}`, `\dot{x}`, `T_{rod}`, `\mathbf{r}_{0}`
    NameKind kind = NameKind::Unknown;
    GiNaC::symbol symbol;
};

/**
 * The names a derivation may use and what they stand for, shared by all the math of one derivation so that
 * the same unknown name is the same symbol everywhere (an identity in unknown symbols is still an identity).
 *
 * Names are canonical LaTeX (see canonical_name): `\theta`, `\dot{\theta}`, `I_{3}`, `T_{rod}`, `x'`.
 */
struct LatexContext {
    /// Known names → their values: the model's symbols, labels such as T, the per-derivation map.
    std::map<std::string, GiNaC::ex> names;
    /// Time: `\frac{d}{dt}` needs `t` to be this symbol. Also `names["t"]` normally.
    GiNaC::ex time;
    /// The model's coordinates: `V'(\theta)`, `I_p(\theta)` are read as functions of them.
    std::vector<GiNaC::ex> coordinates;
    /// `\theta''` is θ̈: set for a text that writes no `\dot` anywhere (one that does uses primes for other
    /// quantities: another frame's angle, an integration variable).
    bool primes_are_time_derivatives = false;
    /// Names seen but not known, created on first use (by canonical name).
    std::map<std::string, FreeName> free_names;

    /// The free name a symbol stands for, or nullptr when the symbol is not one of them.
    const FreeName* free_name_of(const GiNaC::ex& symbol) const;
    /// The symbol for a free name, created when new.
    GiNaC::symbol free_symbol(const std::string& name, NameKind kind);
    /// A free name other than `name` that differs from it only in the case of its subscript (`I_{P}` for `I_{p}`,
    /// `I_{P}'` for `I_{p}'`), of the same kind; nullptr when there is none, when `name` is itself a free name, or when both
    /// subscripts are names of the model (`r_{M}`, `r_{m}` for the masses M and m: two points).
    const FreeName* subscript_case_variant(const std::string& name, NameKind kind) const;
};

/// A free name where it is used, for messages ("unknown symbol I_{3} at 12:7").
struct NameUse {
    std::string name;
    std::size_t offset = 0;  ///< byte offset into the parsed text
};

/// Adds `note` to a side's or a verdict's notes unless it is there already (a reading said once).
inline void add_note_once(std::vector<std::string>& notes, const std::string& note) {
    for (const std::string& n : notes)
        if (n == note) return;
    notes.push_back(note);
}

/// One side of a relation: `a` in `a = b = c`.
struct Side {
    std::size_t begin = 0, end = 0;  ///< byte range of the side in the parsed text (trimmed)
    std::string source;              ///< its LaTeX
    bool ok = false;                 ///< parsed; `value` is meaningful
    GiNaC::ex value;
    std::string error;             ///< why it could not be read, when !ok
    std::size_t error_offset = 0;  ///< where (byte offset into the parsed text)
    std::vector<NameUse> uses;     ///< free names used, with positions
    /// Relative uncertainty of the side from rounded decimals (`1.51` is ±0.005/1.51): the sum over its
    /// decimals with a fractional part; 0 when all its numbers are exact.
    double rounding = 0;
    std::vector<std::string>
        notes;  ///< readings the checker should mention (e.g. a primed integration variable)

    bool empty() const { return begin == end; }
};

enum class Relation {
    Equal,       ///< `=`, `\equiv`, `:=`
    Approx,      ///< `\approx`, `\simeq`: compared within the rounding of the numbers, at least 1%
    Inequality,  ///< `<`, `\le`, `\sim`, `\propto`, ...: not compared
    NotEqual,    ///< `\neq`: holds where the two sides are not identically equal
};

/// `a = b = c`: the sides and the relations between neighbours (relations.size() == sides.size() - 1).
struct Chain {
    std::vector<Side> sides;
    std::vector<Relation> relations;
    std::vector<std::size_t> relation_offsets;  ///< byte offset of each relation sign
    std::size_t begin = 0, end = 0;             ///< byte range of the chain
};

/**
 * Parses one row of math (a `$...$`, or one row of an aligned/gathered block) into chains of relations.
 *
 * The row is split at top-level `\rightarrow`, `\Rightarrow`, `\implies`, `\iff`, and at top-level `,` `;`
 * `\quad` `\text{...}` when the pieces on both sides contain a relation ("x = 1, y = 2"); each piece is split
 * at its top-level relations into sides, and each side is parsed on its own, so an unreadable side (an
 * integral over a region, a vector) does not hide the others.
 *
 * What a side may contain (anything else is an error with its position and a reason, never an exception):
 * numbers (`0.5` is 1/2, with its rounding recorded), letters (each letter a symbol: `ml` is m·l), Greek
 * letters (`\varphi` reads as `\phi`), `_` subscripts and primes (part of the name: `I_{3}`, `x'`,
 * `T_{\text{rod}}` is `T_{rod}`), `\dot`/`\ddot` (a known dotted name, else d/dt of a known name, else a free
 * name), `+ - * / \cdot \times`, implicit multiplication, `^` (`^{\circ}` is degrees), `\frac` `\dfrac`
 * `\tfrac` (`\frac{d}{dt}`, `\frac{dx}{dt}`, `\frac{\partial L}{\partial q}` are derivatives), `\sqrt`,
 * `\sqrt[n]`, groups `( ) [ ] { }` and `\left \right` (`\left| \right|` is |x|), `\sin \cos \tan \cot \sec
 * \csc \exp \ln \log \sinh \cosh \tanh \arcsin \arccos \arctan` with or without parentheses (`\sin \theta`,
 * `\cos (\phi-\theta)`, `\sin ^{2} \alpha`, `\cos \Omega t`: a bare argument is one factor, extended by a
 * following `t` or after a leading number), `\operatorname{...}` (`\operatorname{dot}` is `\dot`), `\text`,
 * `\mathrm` (units such as `\mathrm{~m}`), `\mathbf` `\boldsymbol` `\vec` `\hat` (vectors), `\pi`, definite
 * integrals `\int_{a}^{b} f \, dx` (the variable is bound), spacing (`\,` `\;` `\quad` `~`), `%` comments.
 *
 * @param text     the row; offsets in the result are byte offsets into it
 * @param context  known names; free names are added to it
 * @return         the chains, in order; a row without a relation gives one chain with one side
 */
std::vector<Chain> parse_math(std::string_view text, LatexContext& context);

/// Parses a single expression (no relations), e.g. the right-hand side of a map entry `I_{0}=M a^2/2`.
Side parse_expression(std::string_view text, LatexContext& context);

/**
 * The canonical form of a LaTeX name, as the parser names symbols: `I_3` → `I_{3}`, `T_{\text {rod }}` →
 * `T_{rod}`, `x^{\prime}` → `x'`, `\dot{\theta}_{1}` → `\dot{\theta_{1}}`, `\varphi` → `\phi`, `\text{Trod}`
 * → `Trod`. Returns "" when `latex` is not a single name.
 */
std::string canonical_name(std::string_view latex);

/// A name the text gives one coordinate of a point: x, y or z alone or with a subscript (`x_{2}`, `y_{bob}`).
struct PositionName {
    int axis = 0;       ///< 0, 1, 2 for x, y, z (or X, Y, Z)
    std::string point;  ///< the subscript, "" for none: `x_{2}` and `y_{2}` are one point's; "(capitals)" before it for X, Y, Z
};

/// The axis and the point of a canonical name (`x_{2}` → 0, "2"); nullopt for any other name.
std::optional<PositionName> position_name(const std::string& canonical);

/// True for the relations of `text` that are not inside braces or groups: whether it contains an equation.
bool has_relation(std::string_view text);

}  // namespace eomgen::checker
