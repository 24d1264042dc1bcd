/** @file lagrangian.hpp  Euler–Lagrange equations in mass-matrix form, energy, momenta and conserved quantities. */
#pragma once

#include "mechanics/bodies.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace eomgen {

/// A quantity that stays constant along every trajectory of the model.
struct ConservedQuantity {
    std::string name;    ///< identifier in generated code, e.g. "h", "p_phi"
    std::string latex;   ///< e.g. "p_{\\phi}"
    std::string reason;  ///< why it is conserved, for `eomgen show`
    GiNaC::ex value;     ///< function of q, q̇, t
};

/// One constraint, at every level the equations and the generated code need it.
struct ConstraintEquations {
    std::string name;
    ConstraintKind kind;
    GiNaC::ex position;               ///< g(q, t) for a holonomic constraint; 0 for a nonholonomic one
    GiNaC::ex velocity;               ///< c = A q̇ + b: d/dt g, or the Pfaffian form itself
    std::vector<GiNaC::ex> jacobian;  ///< A = ∂c/∂q̇ (= ∂g/∂q for a holonomic constraint), one row
    GiNaC::ex bias;                   ///< b = c − A q̇ (= ∂g/∂t)
    GiNaC::ex gamma;                  ///< acceleration level A q̈ = γ: γ = −(dc/dt − A q̈)
    bool exact = true;                ///< nonholonomic: the form a·dq + b dt is closed (dω = 0)
    bool integrable = true;           ///< nonholonomic: ω ∧ dω = 0 (integrable with a factor)
    std::string verdict;              ///< integrability, with a witness when it fails, for `eomgen show`
};

/**
 * The Euler–Lagrange equations d/dt(∂L/∂q̇_i) − ∂L/∂q_i = 0 of L = T − V, written as
 * \f[ M(q,t)\,\ddot q = f(q,\dot q,t), \quad M = \frac{\partial^2 L}{\partial\dot q\,\partial\dot q},\quad
 *     f = \frac{\partial L}{\partial q} - \frac{\partial^2 L}{\partial\dot q\,\partial q}\dot q
 *         - \frac{\partial^2 L}{\partial\dot q\,\partial t} \f]
 * (the total time derivative expanded by the chain rule on the plain symbols q, q̇, q̈; Goldstein §1.4, §2.3).
 * Also h = Σ q̇_i ∂L/∂q̇_i − L (Goldstein §2.7), p = ∂L/∂q̇, the cyclic coordinates and what is conserved.
 *
 * With generalized forces Q and a Rayleigh function R, f gains Q − ∂R/∂q̇ (Goldstein §1.5). With
 * constraints (Goldstein §2.4) the equations are M q̈ = f + Aᵀλ and A q̈ = γ: λ_k is the generalized force
 * that constraint k exerts, its sign fixed by the constraint as written (c_k = A_k q̇ + b_k = 0).
 */
struct Equations {
    GiNaC::ex T, V, L;                      ///< T and V: the model's explicit T, V plus every body's
    std::vector<BodyEnergy> bodies;         ///< each body's T and V (mechanics/bodies.hpp)
    std::vector<SpringEnergy> springs;      ///< each spring's V (mechanics/bodies.hpp)
    GiNaC::matrix M;                        ///< n×n mass matrix, symmetric
    std::vector<GiNaC::ex> f;               ///< n forcing terms
    std::vector<GiNaC::ex> momenta;         ///< p_i = ∂L/∂q̇_i
    std::vector<GiNaC::ex> dLdq;            ///< ∂L/∂q_i
    std::vector<GiNaC::ex> euler_lagrange;  ///< d/dt(∂L/∂q̇_i) − ∂L/∂q_i (in q, q̇, q̈, t)
    std::vector<GiNaC::ex> generalized_forces;  ///< Q_i − ∂R/∂q̇_i: euler_lagrange = these + Aᵀλ
    std::vector<ConstraintEquations> constraints;  ///< M q̈ = f + Aᵀλ, A q̈ = γ
    std::string frobenius;                  ///< verdict on the nonholonomic constraints together ("" if < 2)
    GiNaC::ex energy;                       ///< h: T + V where `natural`, else Σ q̇ p − L expanded
    /// T is homogeneous quadratic in q̇ (no T₁, T₀ terms) and V free of q̇: h = T + V and p = M q̇.
    bool natural = false;
    std::vector<bool> cyclic;               ///< ∂L/∂q_i ≡ 0
    bool explicit_time = false;             ///< ∂L/∂t ≢ 0
    std::vector<ConservedQuantity> conserved;
    std::vector<std::string> warnings;      ///< e.g. M not positive definite at a sample point
};

/// Derives the equations; throws ModelError (at T's place in the model file) when T is not quadratic +
/// linear + zero order in the velocities or when M is singular for every q.
Equations derive_equations(const Model& model);

/// Total time derivative d/dt e(q, q̇, t) = Σ ∂e/∂q_i q̇_i + Σ ∂e/∂q̇_i q̈_i + ∂e/∂t.
GiNaC::ex time_derivative(const GiNaC::ex& e, const Model& model);

/// True when e is zero: structurally after expand(), else by normal(), else numerically at random points
/// of every symbol in `model` (GiNaC has no trigonometric simplifier, so sin²+cos²−1 needs the last).
bool is_zero(const GiNaC::ex& e, const Model& model);

/// Substitutes reproducible pseudo-random values in (0.5, 1.5) for every symbol of the model (q, q̇, q̈,
/// parameters, t); `seed` picks the point.
GiNaC::exmap random_point(const Model& model, unsigned seed);

}  // namespace eomgen
