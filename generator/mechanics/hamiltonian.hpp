/** @file hamiltonian.hpp  The canonical momenta, the Hamiltonian H(q, p, t) by the Legendre transform and
 * Hamilton's equations (Goldstein §8.1). */
#pragma once

#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace eomgen {

/**
 * With L = ½ q̇ᵀ M(q,t) q̇ + b(q,t)ᵀ q̇ + L₀(q,t) (L₀ = T₀ − V, T₀ the part of T without velocities):
 * \f[ p = \frac{\partial L}{\partial \dot q} = M\dot q + b, \qquad
 *     H(q,p,t) = \tfrac12 (p-b)^T M^{-1} (p-b) - L_0, \f]
 * and Hamilton's equations \f$\dot q_i = \partial H/\partial p_i\f$,
 * \f$\dot p_i = -\partial H/\partial q_i + Q_i + \sum_k A_{ki}\lambda_k\f$ (Q the generalized and dissipative
 * forces, A the constraints' Jacobian, λ their multipliers with the sign of M q̈ = f + Aᵀλ; all written in q
 * and p), the partial derivatives at fixed p. The constraints themselves, A q̇ + b = 0, hold beside them.
 *
 * M⁻¹ is formed symbolically block by block (the blocks of coordinates M couples), when every block has at
 * most 3 coordinates and a determinant GiNaC's gcd simplifies in bounded time (a polynomial in at most 12
 * variables, sines and cosines counted as variables): diagonal M, the heavy top's 3×3, two coupled pendulums, the
 * triangle plate (11). Otherwise `symbolic` is false
 * and only p(q, q̇) and the matrices are given: H is then compared through p = p(q, q̇), where
 * H(q, p(q, q̇)) = h(q, q̇), ∂H/∂p_i = q̇_i and ∂H/∂q_i|_p = −∂L/∂q_i|_q̇ hold without M⁻¹.
 */
struct Hamiltonian {
    std::vector<GiNaC::symbol> p;       ///< one momentum symbol per coordinate: name p_<name>, LaTeX p_{<latex>}
    std::vector<GiNaC::symbol> lambda;  ///< one multiplier per constraint: name lambda_<constraint>
    std::vector<GiNaC::ex> momenta;     ///< p_i(q, q̇, t) = ∂L/∂q̇_i
    GiNaC::matrix M;                    ///< n×n, = Equations::M
    std::vector<GiNaC::ex> b;           ///< n, ∂L/∂q̇ at q̇ = 0
    GiNaC::ex L0;                       ///< L at q̇ = 0
    bool symbolic = false;              ///< M⁻¹, H, q̇(q, p) and Hamilton's equations below are formed
    std::string why_not_symbolic;       ///< when !symbolic: which block of M is too large (over 3×3, or its det too large to simplify)
    GiNaC::matrix Minv;                 ///< n×n, entries simplified by normal()
    GiNaC::ex H;                        ///< H(q, p, t)
    std::vector<GiNaC::ex> velocities;  ///< q̇_i(q, p, t) = (M⁻¹ (p − b))_i
    std::vector<GiNaC::ex> qdot;        ///< Hamilton's equations: q̇_i = ∂H/∂p_i (in q, p, t)
    std::vector<GiNaC::ex> pdot;        ///< ṗ_i = −∂H/∂q_i + Q_i + Σ_k A_ki λ_k (in q, p, t, λ)
};

/// Forms the Hamiltonian of a model whose equations `eq` are derived (derive_equations).
Hamiltonian derive_hamiltonian(const Model& model, const Equations& eq);

/// sin² + cos² = 1 applied where it shortens e (GiNaC has no trigonometric simplifier): the shortest, as
/// printed, of e and e with cos² → 1 − sin² or sin² → 1 − cos², over a common denominator and factored.
GiNaC::ex shorter_trig(const GiNaC::ex& e);

/// e(q, p, t) with every momentum symbol replaced by p_i(q, q̇, t): how a Hamiltonian expression is compared
/// with the Lagrangian quantities.
GiNaC::ex in_velocities(const GiNaC::ex& e, const Hamiltonian& h);

}  // namespace eomgen
