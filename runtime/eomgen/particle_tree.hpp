/**
 * @file particle_tree.hpp  q̈ of a tree of point masses in O(n): the articulated-body recursion with
 * translational inertias (Featherstone, "Rigid Body Dynamics Algorithms", 2008, §7.3), for the headers whose T
 * the generator found to be such a tree (generator/mechanics/particle_tree.hpp).
 *
 * Node k (coordinate k) has a velocity v_k ∈ R^D with v_k = v_parent + a_k q̇_k, so its acceleration is
 * p̈_k = p̈_parent + a_k q̈_k + c_k (c_k the lever's own acceleration), a weight W_k (diagonal, D entries) and a
 * joint inertia J_k. Lagrange's equation of q_k is a_kᵀ f_k + J_k q̈_k = Q_k with f_k = Σ_{subtree of k} W p̈, and
 * f_k = I_k p̈_k + b_k in terms of the subtree's articulated inertia I_k and bias b_k:
 *
 *   backward (children first):  U_k = I_k a_k,  d_k = a_kᵀ U_k + J_k,  u_k = Q_k − a_kᵀ b_k,
 *                               I_parent += I_k − U_k U_kᵀ / d_k,
 *                               b_parent += b_k + (I_k − U_k U_kᵀ / d_k) c_k + U_k u_k / d_k;
 *   forward (parents first):    q̈_k = (u_k − U_kᵀ (p̈_parent + c_k)) / d_k,  p̈_k = p̈_parent + c_k + a_k q̈_k.
 *
 * The d_k are the pivots of M = L D Lᵀ eliminated leaves first (Schur complements of M), so the singularity test
 * is the dense solve's (pivots_regular in linear_solve.hpp), and the finite test is on the result only.
 */
#pragma once

#include "eomgen/errors.hpp"
#include "eomgen/linear_solve.hpp"

#include <Eigen/Core>

#include <array>
#include <cstddef>

namespace eomgen {

/// What the generated tree_terms() fills: per coordinate k (column k) the lever a_k, its acceleration c_k, the
/// weight W_k of its node (D components each), J_k and Q_k.
template <class Scalar, int N, int D>
struct ParticleTreeTerms {
    Eigen::Matrix<Scalar, D, N> lever, bias, weight;
    Eigen::Matrix<Scalar, N, 1> joint_inertia, force;
};

/**
 * q̈ for the tree whose coordinate k has parent parent[k] (−1: the ground) and that `order` lists parents first.
 * Throws SingularMassMatrix when the pivots d_k are not regular and NonFiniteState when the terms or q̈ are not
 * finite; `t` and `x` (the full state) only go into the message.
 */
template <class Scalar, int N, int D, class VecQ, class VecX>
void particle_tree_accelerations(const std::array<int, std::size_t(N)>& parent, const std::array<int, std::size_t(N)>& order,
                                 const ParticleTreeTerms<Scalar, N, D>& in, VecQ& qdd, const Scalar& t, const VecX& x) {
    using Vec = Eigen::Matrix<Scalar, D, 1>;
    using Mat = Eigen::Matrix<Scalar, D, D>;
    std::array<Mat, std::size_t(N)> I;
    Eigen::Matrix<Scalar, D, N> b, U;
    Eigen::Matrix<Scalar, N, 1> d, u;
    for (int k = 0; k < N; ++k) {
        I[std::size_t(k)] = in.weight.col(k).asDiagonal();
        b.col(k).setZero();
    }
    for (int i = N; i-- > 0;) {
        const int k = order[std::size_t(i)];
        const Mat& Ik = I[std::size_t(k)];
        U.col(k) = Ik * in.lever.col(k);
        d(k) = in.lever.col(k).dot(U.col(k)) + in.joint_inertia(k);
        u(k) = in.force(k) - in.lever.col(k).dot(b.col(k));
        const int p = parent[std::size_t(k)];
        if (p < 0) continue;
        const Scalar inv = Scalar(1) / d(k);
        const Mat Ia = Ik - inv * U.col(k) * U.col(k).transpose();
        I[std::size_t(p)] += Ia;
        b.col(p) += b.col(k) + Ia * in.bias.col(k) + (inv * u(k)) * U.col(k);
    }
    Eigen::Matrix<Scalar, D, N> acc;
    for (int i = 0; i < N; ++i) {
        const int k = order[std::size_t(i)];
        const int p = parent[std::size_t(k)];
        const Vec base = p < 0 ? Vec(in.bias.col(k)) : Vec(acc.col(p) + in.bias.col(k));
        qdd(k) = (u(k) - U.col(k).dot(base)) / d(k);
        acc.col(k) = base + in.lever.col(k) * qdd(k);
    }
    if (pivots_regular(d) && qdd.allFinite()) return;
    if (!in.lever.allFinite() || !in.bias.allFinite() || !in.weight.allFinite() || !in.joint_inertia.allFinite() ||
        !in.force.allFinite())
        throw NonFiniteState(describe_state("the tree's terms (levers, weights or forces) are not finite", t, x),
                             value_of(t));
    if (!pivots_regular(d))
        throw SingularMassMatrix(describe_state("mass matrix is singular or not positive definite", t, x),
                                 value_of(t));
    throw NonFiniteState(describe_state("accelerations are not finite", t, x), value_of(t));
}

}  // namespace eomgen
