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

}  // namespace eomgen
