/** @file kinematics.hpp  Rigid-body kinematics: Euler-angle rotations, angular velocity, positions and
 * velocities of points. */
#pragma once

#include "model/model.hpp"
#include "model/rotations.hpp"

#include <ginac/ginac.h>

#include <array>
#include <string>

namespace eomgen {

/**
 * Conventions (Goldstein, Classical Mechanics, 3rd ed., §4.4): A is the rotation matrix that takes a
 * vector's space components to its body components, x' = A x (4.46); vectors are 3×1 GiNaC matrices.
 * An Euler sequence "abc" (letters x, y, z, consecutive letters different) means rotations about the
 * body-fixed axes a, then b, then c by the three angles: A = R_c(ψ) R_b(θ) R_a(φ), each R a passive
 * rotation, e.g. R_z(φ) = [[cos φ, sin φ, 0], [−sin φ, cos φ, 0], [0, 0, 1]] (Goldstein's D). "zxz" is
 * Goldstein's A = BCD; "xyz" and friends are the Tait–Bryan sequences.
 */

/// True for the 12 valid sequences ("zxz", "zyz", "xyz", ...).
bool valid_euler_sequence(const std::string& sequence);

/// A = R_c(ψ) R_b(θ) R_a(φ) for angles (φ, θ, ψ); throws std::invalid_argument on a bad sequence.
GiNaC::matrix euler_rotation(const std::array<GiNaC::ex, 3>& angles, const std::string& sequence = "zxz");

/**
 * Angular velocity in body axes from the angles and their rates, composed rotation by rotation:
 * ω' = ψ̇ e_c + R_c(ψ) (θ̇ e_b + R_b(θ) φ̇ e_a). For "zxz" this is Goldstein (4.87):
 * ω_x' = φ̇ sin θ sin ψ + θ̇ cos ψ, ω_y' = φ̇ sin θ cos ψ − θ̇ sin ψ, ω_z' = φ̇ cos θ + ψ̇.
 */
GiNaC::matrix body_angular_velocity(const std::array<GiNaC::ex, 3>& angles,
                                    const std::array<GiNaC::ex, 3>& rates,
                                    const std::string& sequence = "zxz");

/// Angular velocity in space axes, ω = Aᵀ ω'. For "zxz": ω_x = θ̇ cos φ + ψ̇ sin θ sin φ,
/// ω_y = θ̇ sin φ − ψ̇ sin θ cos φ, ω_z = φ̇ + ψ̇ cos θ.
GiNaC::matrix space_angular_velocity(const std::array<GiNaC::ex, 3>& angles,
                                     const std::array<GiNaC::ex, 3>& rates,
                                     const std::string& sequence = "zxz");

/// The same with the angles given as expressions in a model's q and t, their rates by the chain rule.
GiNaC::matrix body_angular_velocity(const std::array<GiNaC::ex, 3>& angles, const Model& model,
                                    const std::string& sequence = "zxz");
GiNaC::matrix space_angular_velocity(const std::array<GiNaC::ex, 3>& angles, const Model& model,
                                     const std::string& sequence = "zxz");

/// A body's rotation A (space → body) and angular velocity in body and space axes, from its rotation chain
/// (Body::rotations: its Euler angles, or any chain, after the body it is oriented from), rates by the chain rule.
GiNaC::matrix body_rotation(const Body& body);
GiNaC::matrix body_angular_velocity(const Body& body, const Model& model);
GiNaC::matrix space_angular_velocity(const Body& body, const Model& model);

/// ω' from A and Ȧ by [ω']_× = A Ȧᵀ (and ω = Aᵀ ω'): the independent route, for any parametrisation.
GiNaC::matrix body_angular_velocity_from_rotation(const GiNaC::matrix& A, const GiNaC::matrix& A_dot);

/// The skew matrix [v]_× with [v]_× u = v × u.
GiNaC::matrix skew(const GiNaC::matrix& v);

/// Space position of a point at body coordinates ρ of a body whose centre is at r_c: r = r_c + Aᵀ ρ.
GiNaC::matrix point_position(const GiNaC::matrix& centre, const GiNaC::matrix& A, const GiNaC::matrix& rho);

/// Elementwise total time derivative d/dt of a matrix of expressions in q, q̇, t of `model`
/// (mechanics/lagrangian.hpp time_derivative): the velocity of a point from its position.
GiNaC::matrix time_derivative(const GiNaC::matrix& m, const Model& model);

}  // namespace eomgen
