/**
 * @file particle_tree.hpp  A tree of point masses in T, for an O(n) solve of M q̈ = f.
 *
 * When T is written as a sum of squared speeds, T = Σ_r ½ w_r s_r² + Σ_k ½ J_k q̇_k², each s_r linear in the
 * velocities, s_r = Σ_k α_rk(q_k) q̇_k with every coefficient depending on its own coordinate only, and the
 * coordinates each s_r moves are the path from a root to one coordinate of a tree, then the coordinates are the
 * joints of a tree of point masses (an n-link pendulum in absolute angles, a branching one, a chain of carts):
 * every square that joint k moves has the same lever a_k(q_k) in its component. The Euler–Lagrange equation of q_k
 * is then a_kᵀ Σ_{subtree of k} W ṗ̇ + J_k q̈_k = Q_k, which the articulated-body recursion (Featherstone, "Rigid
 * Body Dynamics Algorithms", ch. 7, here with translational inertias only) solves in O(n) with no M formed:
 * runtime/eomgen/particle_tree.hpp. Anything else (T written out as a polynomial in the velocities, bodies with
 * rotational inertia, a lever that depends on another coordinate, explicit time in T) is not a tree, and the
 * header solves the dense M.
 */
#pragma once

#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <optional>
#include <vector>

namespace eomgen {

struct ParticleTree {
    std::vector<int> parent;                    ///< per coordinate: its parent coordinate, −1 for the ground
    std::vector<int> order;                     ///< the coordinates, every parent before its children
    std::size_t components = 0;                 ///< D: the components the levers have (2 for a planar chain)
    std::vector<std::vector<GiNaC::ex>> lever;  ///< [k][c]: a_ck(q_k), 0 where component c does not pass k
    std::vector<std::vector<GiNaC::ex>> bias;   ///< [k][c]: ∂a_ck/∂q_k q̇_k², the lever's own acceleration
    std::vector<std::vector<GiNaC::ex>> weight; ///< [k][c]: Σ w_r of the squares of component c ending at k
    std::vector<GiNaC::ex> joint_inertia;       ///< J_k (parameters only)
    std::vector<GiNaC::ex> force;               ///< Q_k: the generalized forces less ∂V/∂q_k
};

/// The tree T describes, or nothing when T is not of that form (see the file comment). Requires no constraints
/// and T, V free of t and V free of the velocities.
std::optional<ParticleTree> find_particle_tree(const Model& model, const Equations& eq);

}  // namespace eomgen
