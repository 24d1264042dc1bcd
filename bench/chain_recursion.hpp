/** @file chain_recursion.hpp  The floor of the chain benchmark: an O(n) hand-written right-hand side of the
 * n-link planar chain of point masses (`eomgen generate --family pendulum:n=N`) through its link tensions. */
#pragma once

#include <cmath>
#include <cstddef>

namespace eomgen::bench {

/**
 * θ̈ of the n-link planar chain of point masses m_i on massless links l_i (θ_i: link i's absolute angle from the
 * downward vertical), in O(n): the link tensions T_i from a tridiagonal system, then each θ̈_i from them.
 *
 * Mass i sits at r_i = Σ_{k≤i} l_k e_k, e_k = (sin θ_k, −cos θ_k), n_k = (cos θ_k, sin θ_k); link i pulls it with
 * −T_i e_i and link i+1 with +T_{i+1} e_{i+1} (T_{n+1} = 0), so m_i r̈_i = T_{i+1} e_{i+1} − T_i e_i + m_i g.
 * Differentiating r_i − r_{i−1} = l_i e_i twice (r_0 fixed): e_i·(r̈_i − r̈_{i−1}) = −l_i θ̇_i² and
 * n_i·(r̈_i − r̈_{i−1}) = l_i θ̈_i. The first, with c_ij = cos(θ_i − θ_j), is symmetric tridiagonal in T:
 *   c_{i−1,i}/m_{i−1} T_{i−1} − (1/m_i + 1/m_{i−1}) T_i + c_{i,i+1}/m_i T_{i+1} = −l_i θ̇_i²   (i ≥ 2),
 *   −T_1/m_1 + c_12/m_1 T_2 = −l_1 θ̇_1² − g cos θ_1,
 * solved by Thomas' algorithm; the second gives, with s_ij = sin(θ_j − θ_i),
 *   l_i θ̈_i = s_{i,i+1} T_{i+1}/m_i + s_{i,i−1} T_{i−1}/m_{i−1}  (− g sin θ_1 for i = 1).
 * The cosines and sines of the differences come from those of the angles (2n calls of sin/cos in all).
 *
 * x = [θ_1..θ_n, θ̇_1..θ̇_n], m and l of length n, xdot = [θ̇, θ̈]. Scalar: double or long double.
 */
template <int N, class Scalar>
void chain_rhs_recursive(const Scalar* x, const Scalar* m, const Scalar* l, Scalar g, Scalar* xdot) {
    Scalar s[N], c[N], cd[N], sd[N], inv_m[N], diag[N], rhs[N], tension[N];
    for (int i = 0; i < N; ++i) {
        s[i] = std::sin(x[i]);
        c[i] = std::cos(x[i]);
        inv_m[i] = Scalar(1) / m[i];
    }
    // cd[i] = cos(θ_{i+1} − θ_i), sd[i] = sin(θ_{i+1} − θ_i) for i < N−1 (0-based links i, i+1).
    for (int i = 0; i + 1 < N; ++i) {
        cd[i] = c[i + 1] * c[i] + s[i + 1] * s[i];
        sd[i] = s[i + 1] * c[i] - c[i + 1] * s[i];
    }
    for (int i = 0; i < N; ++i) {
        const Scalar w = x[N + i];
        diag[i] = -(inv_m[i] + (i > 0 ? inv_m[i - 1] : Scalar(0)));
        rhs[i] = -l[i] * w * w;
    }
    rhs[0] -= g * c[0];
    // Thomas' algorithm on the symmetric tridiagonal system (off-diagonal i: cd[i]/m_i, between rows i and i+1).
    for (int i = 1; i < N; ++i) {
        const Scalar off = cd[i - 1] * inv_m[i - 1];
        const Scalar factor = off / diag[i - 1];
        diag[i] -= factor * off;
        rhs[i] -= factor * rhs[i - 1];
    }
    tension[N - 1] = rhs[N - 1] / diag[N - 1];
    for (int i = N - 2; i >= 0; --i) tension[i] = (rhs[i] - cd[i] * inv_m[i] * tension[i + 1]) / diag[i];
    for (int i = 0; i < N; ++i) {
        Scalar a = i + 1 < N ? sd[i] * tension[i + 1] * inv_m[i] : Scalar(0);
        if (i > 0) a -= sd[i - 1] * tension[i - 1] * inv_m[i - 1];  // sin(θ_{i−1} − θ_i) = −sd[i−1]
        if (i == 0) a -= g * s[0];
        xdot[i] = x[N + i];
        xdot[N + i] = a / l[i];
    }
}

}  // namespace eomgen::bench
