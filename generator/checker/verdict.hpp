/** @file verdict.hpp  What the checker says of one equation: its verdict, the role it took the row for, and the
 * details the reports print (report.hpp). The plain data the stages hand on; the driver is checker.hpp. */
#pragma once

#include "checker/derivation.hpp"

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

}  // namespace eomgen::checker
