/** @file bodies.hpp  Kinetic and potential energy of the rigid bodies of a body-based model. */
#pragma once

#include "model/model.hpp"

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace eomgen {

/// One body's contributions, kept apart so that `eomgen show` can print them.
struct BodyEnergy {
    std::string name;
    GiNaC::ex T;                  ///< ½ m v_c² + ½ ω'ᵀ I ω'
    GiNaC::ex V;                  ///< −m g·r_c
    GiNaC::matrix inertia{3, 3};  ///< about the centre of mass, body axes
};

/**
 * For each body of `model`: v_c = d r_c/dt by the chain rule, ω' the body-axis angular velocity of its
 * Euler angles (mechanics/kinematics.hpp, Goldstein (4.87) for "zxz"), I from its shape
 * (mechanics/inertia.hpp) or given, and
 * \f[ T_b = \tfrac12 m\, \dot r_c\cdot\dot r_c + \tfrac12\, \omega'^T I\, \omega', \qquad V_b = -m\, g\cdot
 * r_c \f] (Goldstein (5.14)-(5.15): T splits into the motion of the centre of mass and the rotation about
 * it). Throws ModelError at the body on an unknown shape, wrong dimensions or a bad Euler sequence.
 */
std::vector<BodyEnergy> body_energies(const Model& model);

/// The inertia tensor of a body about its centre of mass in body axes: its shape's or the given one.
/// Throws ModelError at the body on an unknown shape or wrong dimensions.
GiNaC::matrix body_inertia(const Body& body);

/**
 * Everything about one body's motion that its T does not show, as functions of q, q̇, q̈ and t:
 * the rotation A (space → body, mechanics/kinematics.hpp), ω' and ω, v_c, the angular momentum about
 * the centre of mass L' = I ω' (body axes) and L = Aᵀ I ω' + m r_c × v_c about the space origin, and
 * Euler's equations (Goldstein (5.39)) in their general form
 * \f[ N' = I\,\dot\omega' + \omega' \times (I\,\omega'), \f]
 * the torque about the centre of mass, body axes, that the motion requires (zero for a torque-free body).
 */
struct BodyDynamics {
    std::string name;
    GiNaC::matrix rotation{3, 3};
    GiNaC::matrix omega_body{3, 1}, omega_space{3, 1};
    GiNaC::matrix velocity{3, 1};
    GiNaC::matrix angular_momentum_body{3, 1};   ///< I ω', about the centre of mass
    GiNaC::matrix angular_momentum_space{3, 1};  ///< Aᵀ I ω' + m r_c × v_c, about the origin, space axes
    GiNaC::matrix euler_torque{3, 1};            ///< I ω̇' + ω' × I ω' (q̈ appears through ω̇')
};

BodyDynamics body_dynamics(const Model& model, const Body& body);

/// Generalized forces of the bodies' applied forces and torques, by virtual work:
/// Q_i = F · ∂v_c/∂q̇_i + N' · ∂ω'/∂q̇_i (one entry per coordinate).
std::vector<GiNaC::ex> body_generalized_forces(const Model& model);

/// One spring's potential energy ½ k (|d| − l₀)² (½ k d·d when l₀ = 0) and its length |d| in q, t.
struct SpringEnergy {
    std::string name;
    GiNaC::ex V;
    GiNaC::ex length;
};

/// The springs of `model`; a spring end on a body is r_c + Aᵀ ρ. Throws ModelError at the spring when an
/// end names no body of the model.
std::vector<SpringEnergy> spring_energies(const Model& model);

}  // namespace eomgen
