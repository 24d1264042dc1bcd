/**
 * @file latex_equations.hpp  A model's derived mechanics as LaTeX, once, for every place that shows it:
 * `eomgen show --latex` (a fragment of align environments, or with --standalone a whole document) and
 * `eomgen report` (Markdown `$$ \begin{aligned} … \end{aligned} $$` displays, or a .tex document).
 *
 * Text from the model file (titles, names of bodies, constraints, results and outputs) is escaped for
 * LaTeX here (docs/security.md); LaTeX names of symbols are checked when the model is read (latex_name.hpp).
 */
#pragma once

#include "codegen/cpp_emitter.hpp"
#include "mechanics/hamiltonian.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <string>
#include <vector>

namespace eomgen::cli {

/// The model's symbols plus one λ per constraint (lambda_<name>), for printing equations with multipliers,
/// and the canonical momenta p_<name> of `h` when given, for printing the Hamiltonian.
struct MultiplierTable {
    codegen::SymbolTable table;
    std::vector<GiNaC::symbol> lambda;
};
MultiplierTable multiplier_table(const Model& model, const Equations& eq, const Hamiltonian* h = nullptr);

/// The title of the block that lists the conserved quantities (a report lists them with their reasons instead).
constexpr const char* kConservedBlock = "conserved quantities";

/// One group of equations: what it is (plain text, already escaped for LaTeX) and its rows, each `lhs &= rhs`.
struct LatexBlock {
    std::string title;
    std::vector<std::string> rows;
    std::vector<std::string> notes;  ///< one per row ("" for none): escaped text, shown as a comment or a tag
};

/**
 * T, V, L; each body's and spring's share; Euler's equations of each rotating body; the constraints, their
 * Jacobian rows A and γ; the Euler–Lagrange equations (with Q − ∂R/∂q̇ + Aᵀλ where forces or constraints
 * act); the mass-matrix form M q̈ = f; h and the momenta; the Hamiltonian H(q, p, t) and Hamilton's
 * equations (mechanics/hamiltonian.hpp; a note instead where M⁻¹ is not formed); the conserved quantities; declared results and
 * outputs. Every expression is printed by MathPrinter in canonical order, expanded.
 */
std::vector<LatexBlock> latex_equations(const Model& model, const Equations& eq);

/// The blocks as `show --latex` prints them: a `%` comment and an align environment each (needs amsmath).
std::string latex_fragment(const Model& model, const std::vector<LatexBlock>& blocks);

/// A complete LaTeX document (article, amsmath) around `body`, titled with the model's title (escaped).
std::string latex_document(const Model& model, const std::string& body, const std::string& preamble_extra = "");

/// The rows of one block as the inside of a Markdown `$$ … $$` display: `\begin{aligned} … \end{aligned}`.
std::string markdown_display(const LatexBlock& block);

}  // namespace eomgen::cli
