/** @file model_matrices.cpp  The matrices of a text's small oscillations by their usual names: `M` (or `\mathbf{M}`,
 * `\mathbf{T}`) the mass matrix, `K` (or `\mathbf{K}`, `\mathbf{V}`) the stiffness matrix, as LinearAlgebra
 * compares them entry by entry (`M = \begin{pmatrix} m & 0 \\ 0 & m \end{pmatrix}`, `|\mathbf{V} - \omega^2
 * \mathbf{T}| = 0`). A text's matrix in the coordinates is the model's M(q) or the Hessian of V; one free of them
 * is M₀ and K₀ at an equilibrium that is not unstable (the one it matches, where there are several). */
#include "checker/checker_internals.hpp"

namespace eomgen::checker::detail {

std::optional<LinearAlgebra::NamedMatrix> Checker::model_matrix(const std::string& key, const GiNaC::matrix* text) {
    const bool mass = key == "M" || key == "T", stiffness = key == "K" || key == "V";
    if (!mass && !stiffness) return std::nullopt;
    // A name the model gives a quantity of its own (a mass M, a spring constant K) is that quantity.
    for (const Parameter& p : model_.parameters)
        if (p.name == key || p.latex == key) return std::nullopt;
    for (const Coordinate& c : model_.coordinates)
        if (c.name == key || c.latex == key) return std::nullopt;
    const unsigned n = unsigned(model_.dof());
    if (n == 0 || (text && (text->rows() != n || text->cols() != n))) return std::nullopt;
    const std::string name = mass ? "mass matrix" : "stiffness matrix";
    GiNaC::matrix general(n, n);
    for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < n; ++j)
            general(i, j) = mass ? eq_.M(i, j)
                                 : GiNaC::diff(GiNaC::diff(eq_.V, model_.coordinates[i].q), model_.coordinates[j].q);
    bool general_constant = true, text_in_state = false;
    for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < n; ++j) {
            general_constant = general_constant && !depends_on_state(general(i, j));
            if (text) text_in_state = text_in_state || depends_on_state((*text)(i, j));
        }
    const std::string general_what =
        mass ? "eomgen's " + name + " $M(q)$" : "eomgen's " + name + " $\\partial^2 V/\\partial q_i \\partial q_j$";
    if (general_constant || text_in_state) return LinearAlgebra::NamedMatrix{general, general_what};
    // Free of the coordinates, where the model's is not: at an equilibrium (small oscillations).
    const auto rests = modes_.rest_matrices(*this);
    if (rests.empty()) return std::nullopt;
    const NormalModesCheck::RestMatrices* best = &rests.front();
    if (text)
        for (const auto& rest : rests) {
            const GiNaC::matrix& x = mass ? rest.M : rest.K;
            bool all = true;
            for (unsigned i = 0; i < n && all; ++i)
                for (unsigned j = 0; j < n && all; ++j) all = equal((*text)(i, j), x(i, j), 1e-9) == Tri::Yes;
            if (all) {
                best = &rest;
                break;
            }
        }
    return LinearAlgebra::NamedMatrix{mass ? best->M : best->K,
                                      "eomgen's " + name + (mass ? " $M_0$" : " $K_0$") + " at the equilibrium " +
                                          best->at};
}

}  // namespace eomgen::checker::detail
