/** @file rotations.hpp  A body's orientation as a chain of elementary rotations: the plain data a model file
 * declares (Euler angles, or any sequence of rotations about body axes, after another body's), and the
 * rotation matrix and angular velocity it defines. */
#pragma once

#include <ginac/ginac.h>

#include <array>
#include <string>
#include <vector>

namespace eomgen {

/// One rotation of a chain: by `angle` (an expression in q and t) about the body-fixed axis 'x', 'y' or 'z'.
struct Rotation {
    char axis = 'z';
    GiNaC::ex angle;
};

/// The passive rotation by `angle` about the axis 'x', 'y' or 'z', e.g. R_z(φ) = [[cos φ, sin φ, 0],
/// [−sin φ, cos φ, 0], [0, 0, 1]] (Goldstein's D); throws std::invalid_argument on another axis.
GiNaC::matrix axis_rotation(char axis, const GiNaC::ex& angle);

/// The chain of Euler angles (φ, θ, ψ) in the sequence "abc": [(a, φ), (b, θ), (c, ψ)]; throws
/// std::invalid_argument unless the sequence is three of x, y, z with no axis twice in a row.
std::vector<Rotation> euler_chain(const std::array<GiNaC::ex, 3>& angles, const std::string& sequence);

/// Vectors as 3×1 matrices: the unit vector along 'x', 'y' or 'z', a · b and a × b.
GiNaC::matrix axis_vector(char axis);
GiNaC::ex dot(const GiNaC::matrix& a, const GiNaC::matrix& b);
GiNaC::matrix cross(const GiNaC::matrix& a, const GiNaC::matrix& b);

/// A = R_n ⋯ R_2 R_1 for the chain (R_1 first): space components to body components, x' = A x.
GiNaC::matrix chain_rotation(const std::vector<Rotation>& chain);

/**
 * The body-axis angular velocity of a chain from the rates of its angles, composed rotation by rotation:
 * ω' = Σ_k (R_n ⋯ R_{k+1}) e_k θ̇_k, i.e. w ← R_k w + e_k θ̇_k for k = 1 … n (each rotation's own axis is
 * unmoved by it, R_k e_k = e_k). For the Euler sequence "zxz" this is Goldstein (4.87).
 */
GiNaC::matrix chain_body_angular_velocity(const std::vector<Rotation>& chain, const std::vector<GiNaC::ex>& rates);

/// The same in space axes, ω = Aᵀ ω' composed from the other end, w ← R_kᵀ w + e_k θ̇_k for k = n … 1,
/// so that no sin² + cos² is left to simplify.
GiNaC::matrix chain_space_angular_velocity(const std::vector<Rotation>& chain, const std::vector<GiNaC::ex>& rates);

}  // namespace eomgen
