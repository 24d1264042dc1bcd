/** @file constrained_motion.cpp  q̈ from the constrained equations at sample states, and the residual there. */
#include "checker/constrained_motion.hpp"

#include "checker/linear_solve.hpp"

#include "mechanics/double_evaluator.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <random>

namespace eomgen::checker {

std::optional<bool> holds_on_constrained_motion(const GiNaC::ex& r, const Model& model, const Equations& eq,
                                                double tol, const std::vector<GiNaC::symbol>& multipliers, int sign,
                                                const GiNaC::exmap& assumed) {
    const std::size_t n = model.dof(), m = eq.constraints.size();
    if (m == 0 || n == 0) return std::nullopt;
    std::mt19937 rng(20261126);
    std::uniform_real_distribution<double> pick(0.3, 1.2);
    for (int state = 0; state < 3; ++state) {
        SymbolValues v;
        for (const Parameter& p : model.parameters) v[p.symbol] = p.value;
        for (int round = 0; round < 3; ++round)  // m_1 = m_2 (= m): the text's assumption for its paragraph
            for (const Parameter& p : model.parameters)
                if (const auto it = assumed.find(p.symbol); it != assumed.end())
                    if (const auto x = DoubleEvaluator(v)(it->second)) v[p.symbol] = *x;
        v[model.t] = pick(rng);
        for (const Coordinate& c : model.coordinates) v[c.q] = pick(rng);
        Eigen::VectorXd qd(n);
        for (std::size_t i = 0; i < n; ++i) qd[Eigen::Index(i)] = pick(rng) - 0.75;
        auto value = [&](const GiNaC::ex& e) -> std::optional<double> {
            DoubleEvaluator ev(v);
            return ev(e);
        };
        // q moved onto the holonomic constraints g(q, t) = 0 (ρ² = a z), by Gauss–Newton steps of least change: the
        // equations of motion hold only there (ż φ̇ + z φ̈ = 0 is ρ² φ̈ + 2ρρ̇φ̇ = 0 only where ρ² = a z).
        std::vector<std::size_t> holonomic;
        for (std::size_t k = 0; k < m; ++k)
            if (!eq.constraints[k].position.is_zero()) holonomic.push_back(k);
        for (int step = 0; step < 30 && !holonomic.empty(); ++step) {
            const Eigen::Index h = Eigen::Index(holonomic.size());
            Eigen::MatrixXd G(h, Eigen::Index(n));
            Eigen::VectorXd g(h);
            for (Eigen::Index k = 0; k < h; ++k) {
                const ConstraintEquations& c = eq.constraints[holonomic[std::size_t(k)]];
                const auto gk = value(c.position);
                if (!gk) return std::nullopt;
                g[k] = *gk;
                for (std::size_t i = 0; i < n; ++i) {
                    const auto a = value(c.jacobian[i]);
                    if (!a) return std::nullopt;
                    G(k, Eigen::Index(i)) = *a;
                }
            }
            if (g.norm() < 1e-14) break;
            Eigen::FullPivLU<Eigen::MatrixXd> lu_g(G * G.transpose());
            if (!lu_g.isInvertible()) return std::nullopt;
            const Eigen::VectorXd dq = G.transpose() * lu_g.solve(g);
            for (std::size_t i = 0; i < n; ++i)
                v[model.coordinates[i].q] = v[model.coordinates[i].q] - dq[Eigen::Index(i)];
        }
        // A and b at q, t; q̇ moved onto A q̇ + b = 0 by the least change.
        Eigen::MatrixXd A(m, n);
        Eigen::VectorXd b(m);
        for (std::size_t k = 0; k < m; ++k) {
            for (std::size_t i = 0; i < n; ++i) {
                const auto a = value(eq.constraints[k].jacobian[i]);
                if (!a) return std::nullopt;
                A(Eigen::Index(k), Eigen::Index(i)) = *a;
            }
            const auto bk = value(eq.constraints[k].bias);
            if (!bk) return std::nullopt;
            b[Eigen::Index(k)] = *bk;
        }
        const Eigen::MatrixXd AAt = A * A.transpose();
        Eigen::FullPivLU<Eigen::MatrixXd> lu_a(AAt);
        if (!lu_a.isInvertible()) return std::nullopt;
        qd -= A.transpose() * lu_a.solve(A * qd + b);
        for (std::size_t i = 0; i < n; ++i) v[model.coordinates[i].qd] = qd[Eigen::Index(i)];
        // [M Aᵀ; A 0] [q̈; −λ] = [f + Q; γ].
        Eigen::MatrixXd K = Eigen::MatrixXd::Zero(Eigen::Index(n + m), Eigen::Index(n + m));
        Eigen::VectorXd rhs(Eigen::Index(n + m));
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t j = 0; j < n; ++j) {
                const auto mij = value(eq.M(unsigned(i), unsigned(j)));
                if (!mij) return std::nullopt;
                K(Eigen::Index(i), Eigen::Index(j)) = *mij;
            }
            const GiNaC::ex force = eq.f[i] + (i < eq.generalized_forces.size() ? eq.generalized_forces[i] : 0);
            const auto fi = value(force);
            if (!fi) return std::nullopt;
            rhs[Eigen::Index(i)] = *fi;
        }
        for (std::size_t k = 0; k < m; ++k) {
            for (std::size_t i = 0; i < n; ++i) {
                K(Eigen::Index(n + k), Eigen::Index(i)) = A(Eigen::Index(k), Eigen::Index(i));
                K(Eigen::Index(i), Eigen::Index(n + k)) = A(Eigen::Index(k), Eigen::Index(i));
            }
            const auto gk = value(eq.constraints[k].gamma);
            if (!gk) return std::nullopt;
            rhs[Eigen::Index(n + k)] = *gk;
        }
        Eigen::FullPivLU<Eigen::MatrixXd> lu(K);
        if (!lu.isInvertible()) return std::nullopt;
        const Eigen::VectorXd x = lu.solve(rhs);
        for (std::size_t i = 0; i < n; ++i) v[model.coordinates[i].qdd] = x[Eigen::Index(i)];
        for (std::size_t k = 0; k < multipliers.size() && k < m; ++k) v[multipliers[k]] = -sign * x[Eigen::Index(n + k)];
        // The residual against the size of its terms.
        const GiNaC::ex e = r.expand();
        const auto total = value(e);
        if (!total) return std::nullopt;
        double scale = std::abs(*total);
        if (GiNaC::is_a<GiNaC::add>(e))
            for (std::size_t k = 0; k < e.nops(); ++k) {
                const auto term = value(e.op(k));
                if (!term) return std::nullopt;
                scale = std::max(scale, std::abs(*term));
            }
        if (std::abs(*total) > std::max(tol, 1e-9) * std::max(scale, 1e-12)) return false;
    }
    return true;
}

std::optional<GiNaC::ex> solved_multiplier(const Model& model, const Equations& eq, std::size_t k) {
    const std::size_t n = model.dof(), m = eq.constraints.size();
    if (n + m > 6 || k >= m) return std::nullopt;
    const unsigned size = static_cast<unsigned>(n + m);
    GiNaC::matrix K(size, size), rhs(size, 1);
    for (unsigned i = 0; i < n; ++i) {
        for (unsigned j = 0; j < n; ++j) K(i, j) = eq.M(i, j);
        for (unsigned c = 0; c < m; ++c) K(i, unsigned(n) + c) = -eq.constraints[c].jacobian[i];
        rhs(i, 0) = eq.f[i] + (i < eq.generalized_forces.size() ? eq.generalized_forces[i] : 0);
    }
    for (unsigned c = 0; c < m; ++c) {
        for (unsigned j = 0; j < n; ++j) K(unsigned(n) + c, j) = eq.constraints[c].jacobian[j];
        rhs(unsigned(n) + c, 0) = eq.constraints[c].gamma;
    }
    return solved_unknown(K, rhs, unsigned(n + k));
}

}  // namespace eomgen::checker
