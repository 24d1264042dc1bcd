/**
 * @file noether.hpp  Conserved quantities from continuous symmetries of L (Noether's theorem), beyond cyclic
 * coordinates.
 *
 * An infinitesimal point transformation δq = ξ(q) that leaves L unchanged,
 *
 *     δL = Σ_i ∂L/∂q_i ξ_i + Σ_i ∂L/∂q̇_i ξ̇_i ≡ 0,   ξ̇_i = Σ_j ∂ξ_i/∂q_j q̇_j,
 *
 * along which the forces do no work (Q·ξ ≡ 0) and which every constraint allows (A ξ ≡ 0, so that the
 * constraint forces do no work along it either), conserves J = Σ p_i ξ_i: dJ/dt = δL + Q·ξ + λᵀ A ξ = 0
 * (Goldstein §13.7; Arnold, Mathematical Methods, §20). A cyclic coordinate is the case ξ = e_i.
 *
 * The search is over affine generators ξ = c + B q with constant c and B — translations and rotations of the
 * configuration in the coordinates, and of the bodies whose positions are linear in them. δL, Q·ξ and A ξ are
 * linear in (c, B): their values at random states give a linear system whose null space is the symmetry
 * algebra. Its basis, in reduced echelon form, is rounded to small rationals and each generator is then
 * verified symbolically (mechanics/lagrangian.hpp's is_zero), so nothing found numerically is reported unless it
 * holds exactly. Generators whose coefficients depend on the parameters are not found (the points vary them).
 * Up to kAffineCoordinates coordinates the full affine family is searched; up to kTranslationCoordinates the
 * translations only; beyond, nothing (the cost grows as n⁴).
 */
#pragma once

#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <cstddef>
#include <vector>

namespace eomgen {

constexpr std::size_t kAffineCoordinates = 6;
constexpr std::size_t kTranslationCoordinates = 12;

/// The conserved quantities of the affine symmetries of `eq` that are not among `eq.conserved` already (the
/// cyclic momenta), each with a name (L_z for a rotation of x and y, J_a_b for another pair, P_... for a
/// translation, N<k> otherwise), its LaTeX, the generator in words, and J = Σ p_i ξ_i.
std::vector<ConservedQuantity> noether_symmetries(const Model& model, const Equations& eq);

}  // namespace eomgen
