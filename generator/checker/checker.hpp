/** @file checker.hpp  Compares each equation of a derivation text with what eomgen derived for the model. */
#pragma once

#include "checker/derivation.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace eomgen::checker {

enum class Verdict {
    Agrees,         ///< equal to eomgen's quantity, an identity, or a consequence of the equations of motion
    Disagrees,      ///< wrong: with the difference, the wrong terms and the corrected equation
    NotComparable,  ///< with the reason: unknown symbol, not an equation of this model, cannot be read
    NotRead,        ///< a row of math with a relation from which no equation could be taken, with the reason
    NotJudged,      ///< not a claim (a definition, an assumption, the conditions of a motion): its role says which
};

/// "agrees", "disagrees", "not comparable", "not read", "not judged".
const char* verdict_name(Verdict v);

/// The role the checker took a row for. Only a claim is judged true or false; the others set up what follows
/// (a definition is used in the rows after it, a condition of a motion is put into the equations that follow).
enum class Role {
    Claim,        ///< follows from the mechanics and the rows before it (T, an Euler–Lagrange equation, a number)
    Definition,   ///< introduces a name, or gives the text's meaning of one (`\omega^2 = g/l`, "h the height")
    Assumption,   ///< restricts the parameters for what follows (`m_1 = m_2 = m`)
    Condition,    ///< the conditions of a particular motion or point (`\dot\theta = 0` at rest, an initial angle)
    Trial,        ///< a trial solution, whose amplitudes' equations follow (`x_j = A_j e^{i\omega t}`)
    ChosenValue,  ///< a value the text chooses for a parameter, for the numbers that follow
};

/// "claim", "definition", "assumption", "condition", "trial solution", "chosen value".
const char* role_name(Role r);

/**
 * The verdict on one equation: a link `a = b` of a chain `a = b = c` (each link is checked on its own), at
 * the place of its relation sign. LaTeX in the strings is wrapped in `$...$` so that every format can show
 * it.
 */
struct EquationCheck {
    Verdict verdict = Verdict::NotComparable;
    Role role = Role::Claim;  ///< what the row was taken for; a verdict other than NotJudged is on a claim
    std::string section;   ///< title of the innermost section holding it
    SourcePos where;       ///< line:col of the relation sign
    std::string equation;  ///< the link as the text writes it, LaTeX without $: "T = \frac{1}{2} ..."
    std::string
        compared_with;  ///< what it was compared with: "T", "the Euler–Lagrange equation for $\theta$", ...
    std::string reason;      ///< agrees: on what grounds; not comparable: why
    std::string difference;  ///< disagrees: text − eomgen (after scaling), LaTeX without $
    std::vector<std::string>
        wrong_terms;        ///< disagrees: each wrong, missing or extra term, one sentence each
    std::string corrected;  ///< disagrees: the corrected equation, LaTeX without $
    std::vector<std::string>
        notes;  ///< readings worth knowing (a map entry used, a part of T taken from line N)
};

/// Takes the row for something other than a claim: not judged, with its role and the reason.
inline void not_judged(EquationCheck& r, Role role, std::string reason) {
    r.verdict = Verdict::NotJudged;
    r.role = role;
    r.reason = std::move(reason);
}

/// One entry of the per-derivation symbol map: a LaTeX name stands for a LaTeX expression of the model.
struct MapEntry {
    std::string name;    ///< e.g. "I_{0}"
    std::string value;   ///< e.g. "M a^{2}/2"
    std::string origin;  ///< where it was given, for messages: "--map", "pendulum.map.toml:4"
    int first_line = 0;  ///< with last_line: only for the text's rows on these lines (0: everywhere)
    int last_line = 0;
};

struct CheckOptions {
    std::vector<std::string>
        sections;               ///< --section patterns (case-insensitive substrings of headings); empty: all
    std::vector<MapEntry> map;  ///< applied in order; later entries may use earlier ones
    /// --set NAME=VALUE: parameter values for the numbers the text works out (printed_numbers.hpp)
    std::vector<std::pair<std::string, double>> set;
};

/// A map entry or a --section that cannot be used; the message says which and why.
class CheckError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

struct CheckReport {
    std::string model_path;
    std::string model_title;
    std::string derivation_path;
    std::vector<std::string> sections;  ///< titles of the sections checked (empty: the whole file)
    std::vector<MapEntry> map;
    std::vector<EquationCheck> equations;
    /// Delimiters of the checked sections that do not pair up (Derivation::problems), with their places.
    struct Problem {
        SourcePos where;
        std::string message;
    };
    std::vector<Problem> problems;

    int count(Verdict v) const;
};

/**
 * Checks every equation in the selected sections of `derivation` against the model.
 *
 * Each link a = b of each chain (display rows, and inline math containing a relation) is compared as follows,
 * symbolically first and at random points when simplification is inconclusive (GiNaC has no trigonometric
 * simplifier): the labels T, V, L, E (= T + V), H, p_q and ∂L/∂q, d/dt written with them stand for eomgen's
 * values; T_{x} and V_{x} are parts of T and V, taken from where the text defines them; a link that is an
 * identity agrees; one with accelerations agrees when it is a combination of the Euler–Lagrange equations
 * (equal up to a non-zero factor, terms moved across `=`); one without agrees when it is proportional to
 * h − h(0) or p − p(0) for a conserved momentum (also after squaring a square root). Otherwise it disagrees
 * when it can be matched with what it tries to be (a label, an Euler–Lagrange equation, the energy integral,
 * the neighbouring side of a chain), else it is not comparable.
 *
 * @throws CheckError for a map entry that does not parse, a --section that matches no heading, or a --set name
 *         that is not a parameter
 */
CheckReport check_derivation(const Model& model, const Equations& eq, const Derivation& derivation,
                             const CheckOptions& options);

}  // namespace eomgen::checker
