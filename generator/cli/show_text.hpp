/**
 * @file show_text.hpp  A model's derived mechanics as plain text: what `eomgen show` prints, and what the Python
 * module's Model.show() prints (python/).
 */
#pragma once

#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace eomgen::cli {

/**
 * T, V, L; bodies, constraints, the Euler–Lagrange equations, M q'' = f, h, the momenta, the Hamiltonian, the
 * conserved quantities, results and outputs, each under a ruled title; then `equilibria` (the section that
 * `eomgen modes` computes; omitted when empty) and the derivation's warnings.
 */
void show_text(const Model& model, const Equations& eq, std::ostream& os, const std::string& equilibria = "");

/// The main quantities, each printed as show_text prints it (the model file's language: `1/2*m*l^2*theta'^2`).
struct EquationsText {
    std::string T, V, L, h;                  ///< the energies and the energy function
    std::vector<std::string> euler_lagrange; ///< per coordinate: d/dt(dL/dq') - dL/dq, which the equation sets to
                                             ///< `forces` (Q - dR/dq' + A^T lambda)
    std::vector<std::string> forces;         ///< per coordinate: the right-hand side, "0" where nothing acts
    std::vector<std::vector<std::string>> M; ///< the mass matrix, n x n
    std::vector<std::string> f;              ///< per coordinate: M q'' = f
    std::vector<std::string> momenta;        ///< per coordinate: dL/dq'
};
EquationsText equations_text(const Model& model, const Equations& eq);

}  // namespace eomgen::cli
