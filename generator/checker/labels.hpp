/** @file labels.hpp  What the sentence that introduces a display says its equation is ("Lagrange's equation
 * for ψ", "the θ equation", "the energy", "the angular momentum", "the Lagrangian"), and whether it is. */
#pragma once

#include "checker/checker.hpp"
#include "checker/comparisons.hpp"
#include "checker/derivation.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace eomgen::checker {

/// What a label names.
enum class LabelKind {
    EulerLagrange,  ///< "Lagrange's equation for θ", "the θ equation", "the equation of motion for $\phi$"
    Energy,         ///< "the energy", "the total energy", "the energy integral": E = T + V or h
    Hamiltonian,    ///< "the Hamiltonian", "the Jacobi integral", "the energy function": h only (H in velocities)
    Momentum,       ///< "the angular momentum", "the momentum conjugate to φ", "$p_\phi$ is conserved"
    Kinetic,        ///< "the kinetic energy"
    Potential,      ///< "the potential energy"
    Lagrangian,     ///< "the Lagrangian"
};

struct ProseLabel {
    LabelKind kind = LabelKind::Energy;
    /// EulerLagrange and Momentum: the model's coordinates it names (indices); for Momentum, empty: any momentum.
    std::vector<std::size_t> coordinates;
    std::vector<std::string> unknown;  ///< names it gives that are no coordinate of the model (LaTeX); then unchecked
    std::string phrase;                ///< the words as the text writes them: "Lagrange's equation for $\theta$"
    int line = 0;                      ///< the line of the phrase
};

/**
 * The label of the display whose rows hold file offset `at`: in the last sentence of the prose before the
 * display (after the previous display or blank line; a sentence that ends right before the display counts),
 * outside parentheses, the last phrase that names an equation or a quantity, provided that it is what the
 * sentence says the display is — within 12 words of the display, followed by nothing or by a verb that names
 * ("is", "reads", "becomes", "gives", "we obtain", "is conserved", ...), and not an ingredient ("using the
 * energy", "substituting into the θ equation", "from", "with", "in"). A coordinate is written as inline math
 * (`$\theta_1$`), a Unicode letter (θ), the model's name for it (`theta`) or one letter (`x`); `coordinate`
 * says which coordinate a LaTeX name stands for (−1: none). std::nullopt when `at` is inline math or the
 * sentence has no such label.
 */
std::optional<ProseLabel> label_before(const Derivation& d, std::size_t at,
                                       const std::function<int(const std::string&)>& coordinate,
                                       const Model& model);

/**
 * Compares the link a = b (its sides' values; r its verdict so far) with what `label` names, and changes r only
 * when the label can be judged:
 * - an Euler–Lagrange label on a link with accelerations that agrees: it agrees still when the combination of
 *   Euler–Lagrange equations it is includes a labelled coordinate's (with a note naming the label), else it
 *   **disagrees**: "labelled the $\theta$ equation, but it is the $\phi$ equation"; a label naming no
 *   coordinate of the model adds a note to such a link (any verdict) and is not checked; on a link that
 *   disagrees already, a note when the equation is closest to another coordinate's than the labelled one;
 * - a quantity label on a link without accelerations that agrees: what the link is — a side equal to T, V, L,
 *   E = T + V, h or a momentum p_q, or a − b a function of a conserved quantity (h, or the momentum of a cyclic
 *   coordinate) — must include what the label names, else it **disagrees**, saying what it is.
 * Links of the other family (an equation of motion after "the energy"), links that are not comparable, and links
 * that are none of these quantities are left as they are.
 */
void check_label(const ProseLabel& label, const GiNaC::ex& a, const GiNaC::ex& b, const Model& model,
                 const Equations& eq, Comparisons& cmp, double tol, EquationCheck& r);

}  // namespace eomgen::checker
