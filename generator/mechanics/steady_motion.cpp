/** @file steady_motion.cpp  A steady motion of a constrained model and the linear equations about it. */
#include "mechanics/steady_motion.hpp"

#include "mechanics/double_evaluator.hpp"
#include "mechanics/gradient_evaluator.hpp"
#include "mechanics/small_oscillations.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

namespace eomgen {

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

std::string list(const Model& model, const std::vector<std::size_t>& idx, const char* suffix = "") {
    std::string s;
    for (std::size_t k = 0; k < idx.size(); ++k) s += (k ? ", " : "") + model.coordinates[idx[k]].name + suffix;
    return s;
}

/// The symbolic pieces and their derivatives (formed once), and their values at a state.
class Problem {
public:
    Problem(const Model& model, const Equations& eq) : model_(model), eq_(eq), n_(model.dof()), m_(eq.constraints.size()) {
        for (std::size_t k = 0; k < m_; ++k)
            if (eq.constraints[k].kind == ConstraintKind::Holonomic) holonomic_.push_back(k);
    }

    std::size_t n() const { return n_; }
    std::size_t m() const { return m_; }
    const std::vector<std::size_t>& holonomic() const { return holonomic_; }
    const std::vector<bool>& cyclic() const { return cyclic_; }

    SymbolValues values(const std::vector<double>& p, const std::vector<double>& q, const std::vector<double>& qd) const {
        SymbolValues v;
        for (std::size_t i = 0; i < model_.parameters.size(); ++i) v[model_.parameters[i].symbol] = p[i];
        for (std::size_t i = 0; i < n_; ++i) {
            v[model_.coordinates[i].q] = q[i];
            v[model_.coordinates[i].qd] = qd[i];
            v[model_.coordinates[i].qdd] = 0;
        }
        v[model_.t] = 0;
        return v;
    }

    static double value(DoubleEvaluator& at, const GiNaC::ex& e, const char* what) {
        const std::optional<double> x = at(e);
        if (!x) throw ModesError(std::string("the ") + what + " is not a finite number at the steady state");
        return *x;
    }

    /// Decides the cyclic coordinates: once.
    void prepare(const std::vector<double>& p) {
        if (prepared_) return;
        prepared_ = true;
        cyclic_.resize(n_);
        for (std::size_t j = 0; j < n_; ++j) cyclic_[j] = !depends_on(j, p);
    }

    /// Everything at one state: M, f, A, c, g and the derivatives (Fq with the multipliers λ), the derivatives by
    /// forward differentiation over the expressions (mechanics/gradient_evaluator.hpp).
    struct At {
        MatrixXd M, Fq, Fv, Av, Cq, G;
        VectorXd f, c, g;
    };
    At at(const std::vector<double>& p, const std::vector<double>& q, const std::vector<double>& qd,
          const std::vector<double>& lambda) const {
        const SymbolValues vals = values(p, q, qd);
        DoubleEvaluator plain(vals);
        // Seeds: q_j (j not cyclic) at j, q̇_j at n + j.
        SymbolValues seeds;
        for (std::size_t j = 0; j < n_; ++j) {
            if (!cyclic_[j]) seeds[model_.coordinates[j].q] = double(j);
            seeds[model_.coordinates[j].qd] = double(n_ + j);
        }
        GradientEvaluator ev(vals, seeds);
        auto dual = [&](const GiNaC::ex& e, const char* what) {
            std::optional<GradientEvaluator::Dual> d = ev(e);
            if (!d) throw ModesError(std::string("the ") + what + " or its derivative is not a finite number at the steady state");
            return *d;
        };
        const auto N = Eigen::Index(n_), Mc = Eigen::Index(m_);
        At a;
        a.M = MatrixXd::Zero(N, N), a.Fq = a.M, a.Fv = a.M;
        a.Av = MatrixXd::Zero(Mc, N), a.Cq = a.Av;
        a.f = VectorXd::Zero(N), a.c = VectorXd::Zero(Mc), a.g = VectorXd::Zero(Eigen::Index(holonomic_.size()));
        for (std::size_t i = 0; i < n_; ++i) {
            const GradientEvaluator::Dual f = dual(eq_.f[i], "force");
            a.f(Eigen::Index(i)) = f.value;
            a.Fq.row(Eigen::Index(i)) = f.gradient.head(N).transpose();
            a.Fv.row(Eigen::Index(i)) = f.gradient.tail(N).transpose();
            for (std::size_t j = 0; j < n_; ++j)
                a.M(Eigen::Index(i), Eigen::Index(j)) = value(plain, eq_.M(unsigned(i), unsigned(j)), "mass matrix");
        }
        for (std::size_t k = 0; k < m_; ++k) {
            const GradientEvaluator::Dual c = dual(eq_.constraints[k].velocity, "constraint");
            a.c(Eigen::Index(k)) = c.value;
            a.Cq.row(Eigen::Index(k)) = c.gradient.head(N).transpose();
            for (std::size_t i = 0; i < n_; ++i) {
                const GradientEvaluator::Dual A = dual(eq_.constraints[k].jacobian[i], "constraint Jacobian");
                a.Av(Eigen::Index(k), Eigen::Index(i)) = A.value;
                a.Fq.row(Eigen::Index(i)) += lambda[k] * A.gradient.head(N).transpose();
            }
        }
        a.G = MatrixXd::Zero(Eigen::Index(holonomic_.size()), N);
        for (std::size_t h = 0; h < holonomic_.size(); ++h) {
            a.g(Eigen::Index(h)) = value(plain, eq_.constraints[holonomic_[h]].position, "constraint");
            a.G.row(Eigen::Index(h)) = a.Av.row(Eigen::Index(holonomic_[h]));
        }
        return a;
    }

    const Model& model_;
    const Equations& eq_;

private:
    /// Whether anything of the equations depends on q_j: structurally, then (for sin² + cos² = 1 and the like)
    /// by the derivatives' values at two random states.
    bool depends_on(std::size_t j, const std::vector<double>& p) const {
        const GiNaC::symbol& s = model_.coordinates[j].q;
        std::vector<GiNaC::ex> hits;
        for (std::size_t i = 0; i < n_; ++i) {
            if (eq_.f[i].has(s)) hits.push_back(eq_.f[i]);
            for (std::size_t k = 0; k < n_; ++k)
                if (eq_.M(unsigned(i), unsigned(k)).has(s)) hits.push_back(eq_.M(unsigned(i), unsigned(k)));
        }
        for (const ConstraintEquations& c : eq_.constraints) {
            if (c.velocity.has(s)) hits.push_back(c.velocity);
            if (c.position.has(s)) hits.push_back(c.position);
        }
        if (hits.empty()) return false;
        std::mt19937 random(7 + unsigned(j));
        std::uniform_real_distribution<double> u(-0.5, 0.5);
        for (int trial = 0; trial < 2; ++trial) {
            std::vector<double> q(n_), qd(n_);
            for (std::size_t i = 0; i < n_; ++i) q[i] = u(random), qd[i] = u(random);
            DoubleEvaluator ev(values(p, q, qd));
            for (const GiNaC::ex& e : hits) {
                const std::optional<double> d = ev(GiNaC::diff(e, s)), x = ev(e);
                if (!d || !x || std::abs(*d) > 1e-9 * (1 + std::abs(*x))) return true;
            }
        }
        return false;
    }

    std::size_t n_, m_;
    std::vector<std::size_t> holonomic_;
    bool prepared_ = false;
    std::vector<bool> cyclic_;
};

/// The steady state by Newton's method on f + Aᵀλ = 0, c = 0, g = 0 (least squares, minimum-norm steps):
/// unknowns the non-cyclic coordinates, the free cyclic rates and λ.
void find_steady_state(const Problem& P, const std::vector<double>& p, const std::vector<bool>& prescribed,
                       SteadyMotion& s) {
    const std::size_t n = P.n(), m = P.m(), nh = P.holonomic().size();
    const std::vector<bool>& cyclic = P.cyclic();
    std::vector<std::size_t> qs, vs;
    for (std::size_t i = 0; i < n; ++i) {
        if (!cyclic[i]) qs.push_back(i), s.qd[i] = 0;
        else if (!prescribed[i]) vs.push_back(i);
    }
    if (s.lambda.size() != m) s.lambda.assign(m, 0);
    const auto rows = Eigen::Index(n + m + nh), cols = Eigen::Index(qs.size() + vs.size() + m);
    double best = INFINITY;
    for (int iteration = 0; iteration < 60; ++iteration) {
        const Problem::At a = P.at(p, s.q, s.qd, s.lambda);
        VectorXd r(rows);
        const VectorXd lam = Eigen::Map<const VectorXd>(s.lambda.data(), Eigen::Index(m));
        r << a.f + a.Av.transpose() * lam, a.c, a.g;
        s.residual = r.lpNorm<Eigen::Infinity>();
        if (s.residual >= best && s.residual < 1e-12) break;
        best = std::min(best, s.residual);
        MatrixXd J = MatrixXd::Zero(rows, cols);
        Eigen::Index k = 0;
        for (std::size_t j : qs) {
            J.block(0, k, Eigen::Index(n), 1) = a.Fq.col(Eigen::Index(j));
            J.block(Eigen::Index(n), k, Eigen::Index(m), 1) = a.Cq.col(Eigen::Index(j));
            J.block(Eigen::Index(n + m), k, Eigen::Index(nh), 1) = a.G.col(Eigen::Index(j));
            ++k;
        }
        for (std::size_t j : vs) {
            J.block(0, k, Eigen::Index(n), 1) = a.Fv.col(Eigen::Index(j));
            J.block(Eigen::Index(n), k, Eigen::Index(m), 1) = a.Av.col(Eigen::Index(j));
            ++k;
        }
        J.block(0, k, Eigen::Index(n), Eigen::Index(m)) = a.Av.transpose();
        if (cols == 0) break;  // nothing to find: every rate given, no coordinate at rest, no constraint
        const VectorXd step = J.completeOrthogonalDecomposition().solve(-r);
        double size = 0;
        k = 0;
        for (std::size_t j : qs) size += s.q[j] * s.q[j], s.q[j] += step(k++);
        for (std::size_t j : vs) size += s.qd[j] * s.qd[j], s.qd[j] += step(k++);
        for (std::size_t c = 0; c < m; ++c) size += s.lambda[c] * s.lambda[c], s.lambda[c] += step(k++);
        if (step.norm() <= 1e-13 * (1 + std::sqrt(size))) break;  // converged: the linearization re-evaluates there
    }
    if (!(s.residual < 1e-8))
        throw ModesError("no steady motion found near the model's initial values (residual " + std::to_string(s.residual) +
                         "): give a starting guess with --at");
}

/// Indices in `order` whose columns of `A` raise the rank, until `rank` is reached.
std::vector<std::size_t> pick_columns(const MatrixXd& A, const std::vector<std::size_t>& order, Eigen::Index rank) {
    std::vector<std::size_t> picked;
    for (std::size_t j : order) {
        if (Eigen::Index(picked.size()) == rank) break;
        MatrixXd sub(A.rows(), Eigen::Index(picked.size() + 1));
        for (std::size_t k = 0; k < picked.size(); ++k) sub.col(Eigen::Index(k)) = A.col(Eigen::Index(picked[k]));
        sub.col(Eigen::Index(picked.size())) = A.col(Eigen::Index(j));
        Eigen::ColPivHouseholderQR<MatrixXd> qr(sub);
        qr.setThreshold(1e-10);
        if (qr.rank() == Eigen::Index(picked.size() + 1)) picked.push_back(j);
    }
    return picked;
}

using Linear = Problem::At;

/// δq̈ = Pq δq + Pv δq̇ from M δq̈ = Fq δq + Fv δq̇ + Aᵀ δλ, A δq̈ + Cq δq̇ = 0.
void accelerations(const Linear& L, MatrixXd& Pq, MatrixXd& Pv) {
    const Eigen::Index n = L.M.rows(), m = L.Av.rows();
    MatrixXd K = MatrixXd::Zero(n + m, n + m);
    K.topLeftCorner(n, n) = L.M;
    K.topRightCorner(n, m) = -L.Av.transpose();
    K.bottomLeftCorner(m, n) = L.Av;
    MatrixXd rhs = MatrixXd::Zero(n + m, 2 * n);
    rhs.topLeftCorner(n, n) = L.Fq;
    rhs.topRightCorner(n, n) = L.Fv;
    rhs.bottomRightCorner(m, n) = -L.Cq;
    Eigen::FullPivLU<MatrixXd> lu(K);
    if (!lu.isInvertible())
        throw ModesError(std::string(m ? "the mass matrix and the constraints are singular together"
                                       : "the mass matrix is singular") +
                         " at the steady state found: the coordinates are singular there (Euler angles at "
                         "sin(theta) = 0?) or the constraints dependent; give another starting guess with --at");
    const MatrixXd X = lu.solve(rhs);
    Pq = X.topLeftCorner(n, n);
    Pv = X.topRightCorner(n, n);
}

/// The reduction for one choice of dependent speeds: A on z = [coordinates, speeds], and B (speeds → q̇).
bool reduce(const Linear& L, const MatrixXd& Pq, const MatrixXd& Pv, const SteadyMotion& s,
            const std::vector<std::size_t>& dep_speeds, MatrixXd& A, MatrixXd& B, MatrixXd& Pz) {
    const Eigen::Index n = L.M.rows(), nc = Eigen::Index(s.coordinates.size()), nu = Eigen::Index(s.speeds.size());
    // δq from the minimal coordinates: dependent ones by G, cyclic ones 0.
    MatrixXd Q = MatrixXd::Zero(n, nc);
    for (Eigen::Index k = 0; k < nc; ++k) Q(Eigen::Index(s.coordinates[std::size_t(k)]), k) = 1;
    if (!s.dependent.empty()) {
        MatrixXd Gd(L.G.rows(), Eigen::Index(s.dependent.size())), Gc(L.G.rows(), nc);
        for (std::size_t k = 0; k < s.dependent.size(); ++k) Gd.col(Eigen::Index(k)) = L.G.col(Eigen::Index(s.dependent[k]));
        for (Eigen::Index k = 0; k < nc; ++k) Gc.col(k) = L.G.col(Eigen::Index(s.coordinates[std::size_t(k)]));
        const MatrixXd D = -Gd.colPivHouseholderQr().solve(Gc);
        for (std::size_t k = 0; k < s.dependent.size(); ++k) Q.row(Eigen::Index(s.dependent[k])) = D.row(Eigen::Index(k));
    }
    // δq̇ from the speeds and δq: A_d δq̇_d = −(A_i δu + Cq δq).
    MatrixXd Ad(L.Av.rows(), Eigen::Index(dep_speeds.size())), Ai(L.Av.rows(), nu);
    for (std::size_t k = 0; k < dep_speeds.size(); ++k) Ad.col(Eigen::Index(k)) = L.Av.col(Eigen::Index(dep_speeds[k]));
    for (Eigen::Index k = 0; k < nu; ++k) Ai.col(k) = L.Av.col(Eigen::Index(s.speeds[std::size_t(k)]));
    MatrixXd V = MatrixXd::Zero(n, nc + nu);  // δq̇ = V [δc; δu]
    for (Eigen::Index k = 0; k < nu; ++k) V(Eigen::Index(s.speeds[std::size_t(k)]), nc + k) = 1;
    MatrixXd Dv(0, nc + nu);
    if (!dep_speeds.empty()) {
        Eigen::ColPivHouseholderQR<MatrixXd> qr(Ad);
        qr.setThreshold(1e-10);
        if (qr.rank() != Ad.cols()) return false;
        MatrixXd rhs(L.Av.rows(), nc + nu);
        rhs << L.Cq * Q, Ai;
        Dv = -qr.solve(rhs);
    }
    for (std::size_t k = 0; k < dep_speeds.size(); ++k) V.row(Eigen::Index(dep_speeds[k])) = Dv.row(Eigen::Index(k));
    // The constraint rows must hold exactly (more rows than dependent speeds where some are redundant).
    MatrixXd QQ = MatrixXd::Zero(n, nc + nu);
    QQ.leftCols(nc) = Q;
    if ((L.Av * V + L.Cq * QQ).norm() > 1e-8 * (1 + L.Av.norm() * (1 + V.norm()))) return false;
    Pz = MatrixXd::Zero(2 * n, nc + nu);
    Pz.topLeftCorner(n, nc) = Q;
    Pz.bottomRows(n) = V;
    const MatrixXd acc = Pq * Pz.topRows(n) + Pv * Pz.bottomRows(n);  // δq̈
    A.resize(nc + nu, nc + nu);
    for (Eigen::Index k = 0; k < nc; ++k) A.row(k) = V.row(Eigen::Index(s.coordinates[std::size_t(k)]));
    for (Eigen::Index k = 0; k < nu; ++k) A.row(nc + k) = acc.row(Eigen::Index(s.speeds[std::size_t(k)]));
    B = V.rightCols(nu);
    return true;
}

bool zero_column(const MatrixXd& A, Eigen::Index j, double scale) { return A.col(j).norm() <= 1e-9 * scale; }

}  // namespace

struct SteadyMotionSolver::Impl {
    Impl(const Model& m, const Equations& e) : model(m), P(m, e) {}
    const Model& model;
    Problem P;
};

SteadyMotionSolver::SteadyMotionSolver(const Model& model, const Equations& eq) : impl_(std::make_unique<Impl>(model, eq)) {}
SteadyMotionSolver::~SteadyMotionSolver() = default;

SteadyMotion steady_motion(const Model& model, const Equations& eq, const SteadyMotionOptions& options) {
    SteadyMotionSolver solver(model, eq);
    return solver.solve(options);
}

SteadyMotion SteadyMotionSolver::solve(const SteadyMotionOptions& options, const SteadyMotion* guess) {
    const Model& model = impl_->model;
    Problem& P = impl_->P;
    const std::size_t n = model.dof();
    if (options.rates.empty() && P.m() == 0)
        throw ModesError("--steady needs a rate to prescribe (NAME_dot=EXPR)");
    SteadyMotion s;
    GiNaC::exmap pvals;
    for (const auto& [name, v] : options.set)
        if (std::none_of(model.parameters.begin(), model.parameters.end(), [&](const Parameter& p) { return p.name == name; }))
            throw ModesError("--set " + name + ": no parameter of that name");
    for (const Parameter& p : model.parameters) {
        const auto it = options.set.find(p.name);
        s.parameters.push_back(it != options.set.end() ? it->second : p.value);
        pvals[p.symbol] = s.parameters.back();
    }
    P.prepare(s.parameters);
    const std::vector<bool>& cyclic = P.cyclic();
    std::vector<bool> prescribed(n);
    s.q.resize(n);
    s.qd.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        s.q[i] = model.coordinates[i].initial;
        s.qd[i] = model.coordinates[i].rate;
        const auto it = options.at.find(model.coordinates[i].name);
        if (it != options.at.end()) s.q[i] = it->second;
    }
    if (guess && guess->q.size() == n) s.q = guess->q, s.qd = guess->qd, s.lambda = guess->lambda;
    for (const SteadyRate& r : options.rates) {
        if (!cyclic[r.coordinate]) {
            std::vector<std::size_t> c;
            for (std::size_t j = 0; j < n; ++j)
                if (cyclic[j]) c.push_back(j);
            throw ModesError("--steady " + r.text + ": the equations depend on " + model.coordinates[r.coordinate].name +
                             ", so it does not turn at a constant rate in a steady motion (the coordinates nothing depends on: " +
                             (c.empty() ? std::string("none") : list(model, c)) + ")");
        }
        const GiNaC::ex v = GiNaC::evalf(r.value.subs(pvals));
        if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real())
            throw ModesError("--steady " + r.text + ": not a number with the parameters' values");
        s.qd[r.coordinate] = GiNaC::ex_to<GiNaC::numeric>(v).to_double();
        prescribed[r.coordinate] = true;
    }
    find_steady_state(P, s.parameters, prescribed, s);

    // Minimal coordinates: non-cyclic, less those the holonomic constraints fix (pivots of G).
    const Linear L = P.at(s.parameters, s.q, s.qd, s.lambda);
    {
        VectorXd r(L.f.size() + L.c.size() + L.g.size());
        r << L.f + L.Av.transpose() * Eigen::Map<const VectorXd>(s.lambda.data(), Eigen::Index(s.lambda.size())), L.c, L.g;
        s.residual = r.size() ? r.lpNorm<Eigen::Infinity>() : 0.0;
    }
    std::vector<std::size_t> noncyclic;
    for (std::size_t j = 0; j < n; ++j) (cyclic[j] ? s.cyclic : noncyclic).push_back(j);
    if (L.G.rows() > 0) {
        Eigen::ColPivHouseholderQR<MatrixXd> qr(L.G);
        qr.setThreshold(1e-10);
        // Prefer as dependent the coordinates with the largest pivots, among the non-cyclic ones.
        std::vector<std::size_t> order = noncyclic;
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return L.G.col(Eigen::Index(a)).norm() > L.G.col(Eigen::Index(b)).norm();
        });
        s.dependent = pick_columns(L.G, order, qr.rank());
    }
    for (std::size_t j : noncyclic)
        if (std::find(s.dependent.begin(), s.dependent.end(), j) == s.dependent.end()) s.coordinates.push_back(j);

    MatrixXd Pq, Pv;
    accelerations(L, Pq, Pv);

    // Independent speeds: the dependent ones are picked first among the free cyclic rates, then the dependent
    // coordinates' rates, then (trying each choice) among the minimal coordinates' rates, keeping a choice whose
    // minimal coordinates with dependent rates are ignorable (their columns of A vanish).
    Eigen::Index rank = 0;
    if (L.Av.rows() > 0) {
        Eigen::ColPivHouseholderQR<MatrixXd> qrA(L.Av);
        qrA.setThreshold(1e-10);
        rank = qrA.rank();
    }
    std::vector<std::size_t> first;
    for (std::size_t j : s.cyclic)
        if (!prescribed[j]) first.push_back(j);
    for (std::size_t j : s.dependent) first.push_back(j);
    const std::vector<std::size_t> base = pick_columns(L.Av, first, rank);
    const std::size_t still = std::size_t(rank) - base.size();
    std::vector<std::size_t> pool = s.coordinates;
    for (std::size_t j : s.cyclic)
        if (prescribed[j]) pool.push_back(j);
    std::vector<std::vector<std::size_t>> choices;
    {
        std::vector<bool> mask(pool.size(), false);
        std::fill(mask.begin(), mask.begin() + std::ptrdiff_t(std::min(still, pool.size())), true);
        do {
            std::vector<std::size_t> c = base;
            for (std::size_t k = 0; k < pool.size(); ++k)
                if (mask[k]) c.push_back(pool[k]);
            choices.push_back(c);
        } while (std::prev_permutation(mask.begin(), mask.end()) && choices.size() < 200);
    }
    bool found = false;
    MatrixXd A, B, Pz;
    SteadyMotion best;
    for (const std::vector<std::size_t>& dep : choices) {
        SteadyMotion trial = s;
        trial.speeds.clear();
        for (std::size_t j = 0; j < n; ++j)
            if (std::find(dep.begin(), dep.end(), j) == dep.end()) trial.speeds.push_back(j);
        if (trial.speeds.size() != n - std::size_t(rank)) continue;
        MatrixXd At, Bt, Pzt;
        if (!reduce(L, Pq, Pv, trial, dep, At, Bt, Pzt)) continue;
        const double scale = 1 + At.norm();
        bool ok = true;
        for (std::size_t k = 0; k < trial.coordinates.size(); ++k) {
            const std::size_t j = trial.coordinates[k];
            if (std::find(trial.speeds.begin(), trial.speeds.end(), j) != trial.speeds.end()) continue;
            if (zero_column(At, Eigen::Index(k), scale)) trial.ignorable.push_back(j);
            else ok = false;
        }
        if (!found || ok) {
            best = trial;
            A = At, B = Bt, Pz = Pzt;
            found = true;
        }
        if (ok) break;
    }
    if (!found) throw ModesError("the velocity constraints leave no consistent choice of independent speeds here");
    s = best;
    s.A = A;
    const Eigen::Index nc = Eigen::Index(s.coordinates.size()), nu = Eigen::Index(s.speeds.size());
    for (std::size_t j : s.coordinates)
        if (std::find(s.speeds.begin(), s.speeds.end(), j) != s.speeds.end() &&
            std::find(s.ignorable.begin(), s.ignorable.end(), j) == s.ignorable.end())
            s.second_order.push_back(j);
    for (std::size_t j : s.speeds)
        if (std::find(s.second_order.begin(), s.second_order.end(), j) == s.second_order.end()) s.extra_speeds.push_back(j);

    // Kane's form: M_r = Bᵀ M B; C_r, K_r from the accelerations.
    s.Mr = B.transpose() * L.M * B;
    s.Cr = -s.Mr * A.bottomRightCorner(nu, nu);
    s.Kr = -s.Mr * A.bottomLeftCorner(nu, nc);
    auto position = [](const std::vector<std::size_t>& v, std::size_t j) {
        return Eigen::Index(std::find(v.begin(), v.end(), j) - v.begin());
    };
    const Eigen::Index ns = Eigen::Index(s.second_order.size());
    std::vector<Eigen::Index> rows, cols;
    for (std::size_t j : s.second_order) rows.push_back(position(s.speeds, j)), cols.push_back(position(s.coordinates, j));
    s.M.resize(ns, ns), s.C.resize(ns, ns), s.K.resize(ns, ns);
    for (Eigen::Index a = 0; a < ns; ++a)
        for (Eigen::Index b = 0; b < ns; ++b) {
            s.M(a, b) = s.Mr(rows[std::size_t(a)], rows[std::size_t(b)]);
            s.C(a, b) = s.Cr(rows[std::size_t(a)], rows[std::size_t(b)]);
            s.K(a, b) = s.Kr(rows[std::size_t(a)], cols[std::size_t(b)]);
        }
    // Decoupled: the second-order rows and columns meet nothing else.
    const double scale = 1 + s.Mr.norm() + s.Cr.norm() + s.Kr.norm();
    std::ostringstream why;
    for (std::size_t e : s.extra_speeds) {
        const Eigen::Index k = position(s.speeds, e);
        for (Eigen::Index a = 0; a < ns; ++a)
            if (std::abs(s.Mr(rows[std::size_t(a)], k)) + std::abs(s.Cr(rows[std::size_t(a)], k)) +
                    std::abs(s.Cr(k, rows[std::size_t(a)])) + std::abs(s.Kr(k, cols[std::size_t(a)])) > 1e-9 * scale)
                why << (why.tellp() > 0 ? "; " : "") << model.coordinates[e].name << "_dot is coupled to "
                    << model.coordinates[s.second_order[std::size_t(a)]].name;
    }
    s.decoupled = ns > 0 && why.str().empty();
    s.coupling = why.str();

    MatrixXd S;
    if (s.decoupled) {
        Eigen::FullPivLU<MatrixXd> lu(s.M);
        if (!lu.isInvertible()) throw ModesError("the reduced mass matrix is singular at the steady state");
        S = MatrixXd::Zero(2 * ns, 2 * ns);
        S.topRightCorner(ns, ns).setIdentity();
        S.bottomLeftCorner(ns, ns) = -lu.solve(s.K);
        S.bottomRightCorner(ns, ns) = -lu.solve(s.C);
    } else {
        S = A;
    }
    if (S.rows() == 0)
        throw ModesError("the constraints leave no motion about the steady state (no coordinate or speed is free)");
    Eigen::EigenSolver<MatrixXd> es(S);
    if (es.info() != Eigen::Success) throw ModesError("the eigenvalues did not converge");
    std::vector<Eigen::Index> keep;
    const double tiny = 1e-10 * (1 + S.norm());
    for (Eigen::Index k = 0; k < S.rows(); ++k)
        if (s.decoupled || std::abs(es.eigenvalues()(k)) > tiny) keep.push_back(k);
    std::sort(keep.begin(), keep.end(), [&](Eigen::Index a, Eigen::Index b) {
        const auto x = es.eigenvalues()(a), y = es.eigenvalues()(b);
        return x.real() != y.real() ? x.real() < y.real() : x.imag() < y.imag();
    });
    s.eigenvalues.resize(Eigen::Index(keep.size()));
    s.eigenvectors.resize(S.rows(), Eigen::Index(keep.size()));
    s.growth_rate = -INFINITY;
    for (std::size_t k = 0; k < keep.size(); ++k) {
        s.eigenvalues(Eigen::Index(k)) = es.eigenvalues()(keep[k]);
        s.eigenvectors.col(Eigen::Index(k)) = es.eigenvectors().col(keep[k]);
        s.growth_rate = std::max(s.growth_rate, es.eigenvalues()(keep[k]).real());
    }
    if (keep.empty()) s.growth_rate = 0;
    const double tol = 1e-9 * (1 + S.norm());
    s.stability = s.growth_rate > tol ? "unstable" : s.growth_rate < -tol ? "stable" : "marginally stable";
    return s;
}

}  // namespace eomgen
