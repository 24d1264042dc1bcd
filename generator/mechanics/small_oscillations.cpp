/** @file small_oscillations.cpp  Equilibria, linearization, normal modes, stability (small_oscillations.hpp). */
#include "mechanics/small_oscillations.hpp"
#include "model/names.hpp"

#include "mechanics/quantity_units.hpp"

#include "model/nonsmooth.hpp"

#include "mechanics/constrained_equilibria.hpp"
#include "mechanics/pole_free_subs.hpp"
#include "mechanics/time_dependence.hpp"
#include "mechanics/rest_linearization.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <optional>
#include <random>
#include <set>

namespace eomgen {

using GiNaC::ex;
using GiNaC::exmap;
using GiNaC::symbol;

namespace {

constexpr double kPi = 3.141592653589793238462643383279502884;

/// The Lagrangian-like function the linearization works on: L(q_r, q̇_r) of the remaining coordinates, and the
/// generalized forces on them (Q − ∂R/∂q̇), both in the remaining q, q̇ and the parameters.
struct Reduced {
    std::vector<std::size_t> index;  ///< model coordinate of each remaining one
    std::vector<symbol> q, qd;
    ex L;
    std::vector<ex> Q;
};

/// Numbers for the parameters (the model's values, or --set's) and the momenta.
struct Values {
    exmap params;
};

/// e as a double at `at`; NaN where it cannot be evaluated (a pole, a complex value). A pole is found before
/// substituting (subs_unless_pole): GiNaC would throw from inside the product it builds, and leak it.
double evaluate(const ex& e, const exmap& at) {
    try {
        const std::optional<ex> substituted = subs_unless_pole(e, at, GiNaC::subs_options::no_pattern);
        if (!substituted) return std::nan("");
        const ex v = GiNaC::evalf(*substituted);
        if (!GiNaC::is_a<GiNaC::numeric>(v)) return std::nan("");
        const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(v);
        if (!n.is_real()) {
            const double im = GiNaC::imag(n).to_double(), re = GiNaC::real(n).to_double();
            return std::abs(im) <= 1e-12 * (1 + std::abs(re)) ? re : std::nan("");
        }
        return n.to_double();
    } catch (const std::exception&) {
        return std::nan("");
    }
}

/// x as an exact rational (m·2^e), so that an evaluation at many digits is not spoiled by x's rounding.
GiNaC::numeric exact(double x) {
    if (x == 0 || !std::isfinite(x)) return 0;
    int e = 0;
    const double m = std::frexp(x, &e);
    const auto mantissa = static_cast<long long>(std::ldexp(m, 53));
    return GiNaC::numeric(mantissa) * GiNaC::ex_to<GiNaC::numeric>(GiNaC::pow(GiNaC::numeric(2), e - 53));
}

/// x exactly: the multiple of π/2, π/3, π/4 or π/6 that x rounds (within 1e-12), else the rational x is.
ex exact_coordinate(double x) {
    for (const int d : {1, 2, 3, 4, 6}) {
        const double k = std::round(x * d / kPi);
        if (std::abs(k) <= 64 * d && std::abs(x - k * kPi / d) <= 1e-12 * std::max(1.0, std::abs(x)))
            return GiNaC::numeric(static_cast<long>(k), d) * GiNaC::Pi;
    }
    return exact(x);
}

/// The point (q0 and the parameters) in exact numbers. A removable singularity met there, such as the 0/0 of
/// (1 − cos θ)/sin θ at θ = 0 or of terms in sin θ at θ = π, is then an exact 0/0 (a division by zero) and not
/// rounding noise divided by rounding noise: in floating point the noise, and so the value, would depend on
/// GiNaC's term order, which changes from process to process.
exmap exact_point(const std::vector<symbol>& q, const std::vector<double>& q0, const exmap& params) {
    exmap at;
    for (const auto& [k, v] : params)
        at[k] = GiNaC::is_a<GiNaC::numeric>(v) && !GiNaC::ex_to<GiNaC::numeric>(v).is_rational()
                    ? ex(exact(GiNaC::ex_to<GiNaC::numeric>(v).to_double()))
                    : v;
    for (std::size_t i = 0; i < q.size(); ++i) at[q[i]] = exact_coordinate(q0[i]);
    return at;
}

/// Floating-point evaluations with 40 digits while it lives: near a removable singularity the terms that
/// cancel lose digits, and 40 leave enough of them for doubles.
class ManyDigits {
public:
    ManyDigits() : saved_(GiNaC::Digits) { GiNaC::Digits = 40; }
    ~ManyDigits() { GiNaC::Digits = saved_; }
    ManyDigits(const ManyDigits&) = delete;
    ManyDigits& operator=(const ManyDigits&) = delete;

private:
    long saved_;
};

/// The limit of e at the exact point `at` along the coordinates: the ε⁰ term of e(q0 + ε d) for a fixed
/// direction d, taken in exact arithmetic. For a removable singularity such as (1 − cos θ)²/sin²θ at θ = 0.
double limit_at(const ex& e, const std::vector<symbol>& q, const exmap& at) {
    // GiNaC's series of abs, sign … goes through derivatives that can divide by zero inside GiNaC, which then
    // leaks what it was building (LeakSanitizer, the structural fuzzer's V = k*abs(th1)): no limit taken there.
    if (contains_nonsmooth(e)) return std::nan("");
    static const int direction[][2] = {{1, 1},       {7071, 10000}, {5477, 10000}, {4472, 10000},
                                       {3780, 10000}, {3333, 10000}, {3015, 10000}, {2774, 10000}};
    const symbol eps("eps");
    exmap shifted = at;
    for (std::size_t i = 0; i < q.size(); ++i)
        shifted[q[i]] = at.at(q[i]) + eps * GiNaC::numeric(direction[i % 8][0], direction[i % 8][1]);
    try {
        const std::optional<ex> along = subs_unless_pole(e, shifted, GiNaC::subs_options::no_pattern);
        if (!along) return std::nan("");  // a pole along the whole line, not a removable 0/0
        // A root of something that vanishes at the point (sqrt(s^2) at s = 0) is a branch point: GiNaC's series
        // throws there from inside what it builds, and leaks it (LeakSanitizer, the structural fuzzer); no limit.
        for (auto it = along->preorder_begin(); it != along->preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::power>(*it) && GiNaC::is_a<GiNaC::numeric>(it->op(1)) &&
                !GiNaC::ex_to<GiNaC::numeric>(it->op(1)).is_integer()) {
                const std::optional<ex> base = subs_unless_pole(it->op(0), exmap{{eps, 0}}, GiNaC::subs_options::no_pattern);
                if (!base || GiNaC::normal(*base).is_zero()) return std::nan("");
            }
        const ex s = GiNaC::series_to_poly(along->series(eps == 0, 2));
        // A term in a negative power of ε is a pole, not a removable 0/0: e has no limit there (the ε⁰ term
        // alone would be the regular part of a Laurent series, a finite number that is no value of e).
        for (int k = s.ldegree(eps); k < 0; ++k)
            if (!(std::abs(evaluate(s.coeff(eps, k), {})) <= 1e-25)) return std::nan("");
        return evaluate(s.coeff(eps, 0), {});
    } catch (const std::exception&) {
        return std::nan("");
    }
}

/// e at q0 with 40 digits from exact inputs: directly, or as a limit where e is 0/0 there. Newton in doubles
/// can stop where cancellation makes g look like 0; this tells a root from such a point.
double value_at(const ex& e, const std::vector<symbol>& q, const std::vector<double>& q0, const exmap& params) {
    const ManyDigits digits;
    const exmap at = exact_point(q, q0, params);
    const double v = evaluate(e, at);
    return std::isfinite(v) ? v : limit_at(e, q, at);
}

/// max |g_i(x)|, each as value_at gives it; infinity where one cannot be evaluated.
double precise_residual(const std::vector<ex>& g, const std::vector<symbol>& q, const std::vector<double>& x,
                        const exmap& params) {
    double worst = 0;
    for (const ex& gi : g) {
        const double v = value_at(gi, q, x, params);
        worst = std::max(worst, std::isfinite(v) ? std::abs(v) : std::numeric_limits<double>::infinity());
    }
    return worst;
}

/// `eq` with t taken out of L, the momenta and the forces, which do not depend on it at the values in `fixed`;
/// ModesError, naming what does, otherwise.
Equations steady_equations(const Model& model, const Equations& eq, const exmap& fixed) {
    Equations out = eq;
    auto steady = [&](ex& e, const std::string& what) {
        const std::optional<ex> free = without_time(e, model, fixed);
        if (!free) throw ModesError(what + " depends on t explicitly: the system has no equilibria in these coordinates");
        e = *free;
    };
    steady(out.L, "L");
    for (std::size_t i = 0; i < out.generalized_forces.size(); ++i)
        steady(out.generalized_forces[i], "the force on " + model.coordinates[i].name +
                                              (fixed.empty() ? "" : " (at the --set values)"));
    for (ex& p : out.momenta) steady(p, "L");
    for (ConstraintEquations& k : out.constraints)
        if (const std::optional<ex> free = without_time(k.position, model, fixed)) k.position = *free;
    return out;
}

/// The remaining coordinates' Lagrangian: L itself, or Routh's L − p_c·q̇_c with q̇_c from p_c = ∂L/∂q̇_c.
Reduced reduce(const Model& model, const Equations& eq, const ModesOptions& options,
               std::vector<std::pair<symbol, std::size_t>>& momentum_symbols, std::vector<std::string>& reduced) {
    const std::size_t n = model.dof();
    std::vector<std::size_t> cyclic;
    for (const auto& entry : options.momentum) {
        const std::string& name = entry.first;  // not a structured binding: clang 14 refuses one in a lambda
        std::size_t i = 0;
        while (i < n && "p_" + model.coordinates[i].name != name) ++i;
        if (i == n) throw ModesError("--momentum " + name + ": no coordinate '" + name.substr(name.rfind('_') + 1) +
                                     "' (write p_<coordinate>)");
        if (!eq.cyclic[i])
            throw ModesError("--momentum " + name + ": " + model.coordinates[i].name +
                             " is not cyclic (L depends on it), so its momentum is not a constant");
        if (std::none_of(eq.conserved.begin(), eq.conserved.end(), [&](const auto& c) { return c.name == name; }))
            throw ModesError("--momentum " + name + ": " + name + " is not conserved (a force acts along " +
                             model.coordinates[i].name + ")");
        cyclic.push_back(i);
        momentum_symbols.emplace_back(symbol(name), i);
        reduced.push_back(model.coordinates[i].name);
    }
    Reduced r;
    for (std::size_t i = 0; i < n; ++i)
        if (std::find(cyclic.begin(), cyclic.end(), i) == cyclic.end()) {
            r.index.push_back(i);
            r.q.push_back(model.coordinates[i].q);
            r.qd.push_back(model.coordinates[i].qd);
        }
    if (r.index.empty()) throw ModesError("every coordinate was reduced away: nothing is left to oscillate");
    r.L = eq.L;
    for (std::size_t i : r.index) r.Q.push_back(eq.generalized_forces[i]);
    if (cyclic.empty()) return r;

    // p_c = ∂L/∂q̇_c is linear in the velocities: p_c = M_cc q̇_c + (M_cr q̇_r + b_c). Solve for q̇_c.
    const std::size_t m = cyclic.size();
    GiNaC::matrix Mcc{static_cast<unsigned>(m), static_cast<unsigned>(m)};
    GiNaC::matrix rest{static_cast<unsigned>(m), 1};
    exmap zero_c;
    for (std::size_t k = 0; k < m; ++k) zero_c[model.coordinates[cyclic[k]].qd] = 0;
    for (std::size_t k = 0; k < m; ++k) {
        const ex p = eq.momenta[cyclic[k]];
        for (std::size_t l = 0; l < m; ++l) Mcc(unsigned(k), unsigned(l)) = p.diff(model.coordinates[cyclic[l]].qd);
        rest(unsigned(k), 0) = momentum_symbols[k].first - p.subs(zero_c);
    }
    GiNaC::matrix qd_c;
    try {
        qd_c = GiNaC::ex_to<GiNaC::matrix>(Mcc.inverse().mul(rest));
    } catch (const std::exception&) {
        throw ModesError("the cyclic coordinates' block of the mass matrix is singular for every q: their "
                         "velocities do not follow from their momenta");
    }
    exmap velocity;
    ex pq = 0;
    for (std::size_t k = 0; k < m; ++k) {
        velocity[model.coordinates[cyclic[k]].qd] = qd_c(unsigned(k), 0);
        pq += momentum_symbols[k].first * qd_c(unsigned(k), 0);
    }
    // M_cc⁻¹ brings sin² + cos² that GiNaC does not cancel (a top's det M_cc = I₃(I₁ sin²θ + I₃ cos²θ) −
    // I₃² cos²θ): sin² → 1 − cos², then normal(), gives the amended potential in its usual form.
    const ex x = GiNaC::wild(0);
    auto tidy = [&](const ex& e) {
        try {
            return e.subs(GiNaC::pow(GiNaC::sin(x), 2) == 1 - GiNaC::pow(GiNaC::cos(x), 2), GiNaC::subs_options::algebraic)
                .normal();
        } catch (const std::exception&) {
            return e;
        }
    };
    r.L = tidy(eq.L.subs(velocity, GiNaC::subs_options::no_pattern) - pq);
    for (ex& Q : r.Q) Q = Q.subs(velocity, GiNaC::subs_options::no_pattern);
    return r;
}

/// Coordinates that the gradient repeats in after 2π (angles): compared at a few random points.
std::vector<bool> periodic(const std::vector<ex>& g, const std::vector<symbol>& q, const exmap& params) {
    std::vector<bool> out(q.size(), true);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.3, 1.3);
    for (std::size_t i = 0; i < q.size(); ++i)
        for (int trial = 0; trial < 3 && out[i]; ++trial) {
            std::vector<double> a(q.size());
            for (double& x : a) x = u(rng);
            std::vector<double> b = a;
            b[i] += 2 * kPi;
            for (const ex& gi : g) {
                const double va = value_at(gi, q, a, params), vb = value_at(gi, q, b, params);
                if (!(std::abs(va - vb) <= 1e-9 * (1 + std::abs(va)))) {
                    out[i] = false;
                    break;
                }
            }
        }
    return out;
}

/// Exact roots of one factor that depends on a single coordinate x: A·sin x + B, A·cos x + B, A·tan x + B or
/// A·x + B with A, B free of x.
std::vector<ex> solve_factor(const ex& f, const symbol& x) {
    const symbol s("s_");
    std::vector<ex> roots;
    auto linear_in = [&](const ex& e, const symbol& v, ex& A, ex& B) {
        if (!e.is_polynomial(v) || e.degree(v) != 1) return false;
        A = e.coeff(v, 1);
        B = e.coeff(v, 0);
        return !A.has(x) && !B.has(x) && !A.is_zero();
    };
    ex A, B;
    const ex e = f.expand();
    if (linear_in(e, x, A, B)) return {-B / A};
    const std::pair<ex, int> kinds[] = {{GiNaC::sin(x), 0}, {GiNaC::cos(x), 1}, {GiNaC::tan(x), 2}};
    for (const auto& [fn, kind] : kinds) {
        exmap sub;
        sub[fn] = s;
        const ex t = e.subs(sub, GiNaC::subs_options::no_pattern);
        if (t.has(x) || !linear_in(t, s, A, B)) continue;
        const ex c = (-B / A).normal();
        if (kind == 0) roots = {GiNaC::asin(c), GiNaC::Pi - GiNaC::asin(c)};
        if (kind == 1) roots = {GiNaC::acos(c), -GiNaC::acos(c)};
        if (kind == 2) roots = {GiNaC::atan(c), GiNaC::atan(c) + GiNaC::Pi};
        return roots;
    }
    return roots;
}

/// Factors of e (products and powers taken apart; sums kept whole).
void factors_of(const ex& e, std::vector<ex>& out) {
    if (GiNaC::is_a<GiNaC::mul>(e)) {
        for (std::size_t k = 0; k < e.nops(); ++k) factors_of(e.op(k), out);
    } else if (GiNaC::is_a<GiNaC::power>(e) && e.op(1).info(GiNaC::info_flags::posint)) {
        factors_of(e.op(0), out);
    } else {
        out.push_back(e);
    }
}

/// e factored as a polynomial in its symbols and in the function calls in it (sin a, cos a taken as
/// unknowns): m R sin a (g − R ω² cos a) from m g R sin a − m R² ω² sin a cos a.
ex factor_through_functions(const ex& e) {
    try {
        exmap calls;
        const ex p = e.expand().to_polynomial(calls);
        return GiNaC::factor(p).subs(calls, GiNaC::subs_options::no_pattern);
    } catch (const std::exception&) {
        return e;
    }
}

/// sin, cos, tan of asin, acos, atan written out (GiNaC does it for numbers only): cos(acos x) = x,
/// sin(acos x) = √(1 − x²), ...; then normal().
ex simplify_inverse_trig(const ex& e) {
    using namespace GiNaC;
    // Each rule in a subs() of its own: in one subs() with several, cos(acos($0)) tried first keeps
    // cos(-acos($1)) from matching at all (GiNaC 1.8.6).
    unsigned k = 0;
    std::vector<ex> rules;
    auto rule = [&](auto outer, auto inner, auto value) {
        const ex x = wild(k++);
        rules.push_back(outer(inner(x)) == value(x));
    };
    auto sin_ = [](const ex& x) { return ex(sin(x)); };
    auto cos_ = [](const ex& x) { return ex(cos(x)); };
    auto tan_ = [](const ex& x) { return ex(tan(x)); };
    auto acos_ = [](const ex& x) { return ex(acos(x)); };
    auto asin_ = [](const ex& x) { return ex(asin(x)); };
    auto atan_ = [](const ex& x) { return ex(atan(x)); };
    auto neg_acos = [](const ex& x) { return -acos(x); };
    auto pi_asin = [](const ex& x) { return Pi - asin(x); };
    auto atan_pi = [](const ex& x) { return atan(x) + Pi; };
    auto same = [](const ex& x) { return x; };
    auto root = [](const ex& x) { return sqrt(1 - x * x); };
    rule(cos_, acos_, same);
    rule(sin_, acos_, root);
    rule(tan_, acos_, [&](const ex& x) { return root(x) / x; });
    rule(sin_, asin_, same);
    rule(cos_, asin_, root);
    rule(tan_, asin_, [&](const ex& x) { return x / root(x); });
    rule(tan_, atan_, same);
    rule(sin_, atan_, [](const ex& x) { return x / sqrt(1 + x * x); });
    rule(cos_, atan_, [](const ex& x) { return 1 / sqrt(1 + x * x); });
    // the other roots solve_factor gives: −acos x, π − asin x, atan x + π
    rule(cos_, neg_acos, same);
    rule(sin_, neg_acos, [&](const ex& x) { return -root(x); });
    rule(tan_, neg_acos, [&](const ex& x) { return -root(x) / x; });
    rule(sin_, pi_asin, same);
    rule(cos_, pi_asin, [&](const ex& x) { return -root(x); });
    rule(tan_, pi_asin, [&](const ex& x) { return -x / root(x); });
    rule(tan_, atan_pi, same);
    rule(sin_, atan_pi, [](const ex& x) { return -x / sqrt(1 + x * x); });
    rule(cos_, atan_pi, [](const ex& x) { return -1 / sqrt(1 + x * x); });
    ex out = e;
    for (int pass = 0; pass < 3; ++pass) {
        ex next = out;
        for (const ex& r : rules) next = next.subs(r);
        if (next.is_equal(out)) break;
        out = next;
    }
    try {
        return out.normal();
    } catch (const std::exception&) {
        return out;
    }
}

/// A matrix as rows of numbers (the results' form).
std::vector<std::vector<double>> rows_of(const Eigen::MatrixXd& m) {
    std::vector<std::vector<double>> out(std::size_t(m.rows()), std::vector<double>(std::size_t(m.cols())));
    for (Eigen::Index i = 0; i < m.rows(); ++i)
        for (Eigen::Index j = 0; j < m.cols(); ++j) out[std::size_t(i)][std::size_t(j)] = m(i, j);
    return out;
}

double wrap(double x) {
    double w = std::remainder(x, 2 * kPi);
    if (w <= -kPi + 1e-12) w += 2 * kPi;
    return w;
}

/// Damped Newton on g(q) = 0 with Jacobian K(q); true when |g| falls below tol.
constexpr long kNewtonBudget = 8000;
/// And of processor time: an evaluation of a large model's rest conditions can take milliseconds, so that 8 000 of
/// them took 20 s (tests/fuzz/findings_structure/slow_modes_large_rest_conditions.toml). The search stops at
/// whichever comes first; the shipped models use a fraction of a second.
constexpr double kNewtonSeconds = 3.0;

/// Processor seconds since `start`.
double cpu_seconds_since(std::clock_t start) { return double(std::clock() - start) / CLOCKS_PER_SEC; }

/// `budget`: evaluations of g left to the whole search (each at 40 digits); spent here, and the iteration stops
/// when it is gone, so that a search where no start converges (an empty constraint manifold) ends in bounded time.
bool newton(const std::vector<ex>& g, const std::vector<std::vector<ex>>& K, const std::vector<symbol>& q,
            const exmap& params, std::vector<double>& x, long& budget, std::clock_t started) {
    const std::size_t n = q.size();
    auto residual = [&](const std::vector<double>& at, Eigen::VectorXd& r) {
        if (--budget < 0 || cpu_seconds_since(started) > kNewtonSeconds) {
            budget = -1;
            return std::numeric_limits<double>::infinity();
        }
        r.resize(Eigen::Index(n));
        for (std::size_t i = 0; i < n; ++i) r(Eigen::Index(i)) = value_at(g[i], q, at, params);
        return r.allFinite() ? r.norm() : std::numeric_limits<double>::infinity();
    };
    Eigen::VectorXd r;
    double norm = residual(x, r);
    for (int iteration = 0; iteration < 60 && std::isfinite(norm); ++iteration) {
        if (norm < 1e-12) return true;
        Eigen::MatrixXd J(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) J(Eigen::Index(i), Eigen::Index(j)) = value_at(K[i][j], q, x, params);
        if (!J.allFinite()) return false;
        const Eigen::VectorXd step = J.completeOrthogonalDecomposition().solve(-r);
        double lambda = 1;
        bool improved = false;
        for (int half = 0; half < 30; ++half, lambda /= 2) {
            std::vector<double> y = x;
            for (std::size_t i = 0; i < n; ++i) y[i] += lambda * step(Eigen::Index(i));
            Eigen::VectorXd ry;
            const double ny = residual(y, ry);
            if (ny < norm) {
                x = y;
                r = ry;
                norm = ny;
                improved = true;
                break;
            }
        }
        if (!improved) break;
    }
    return norm < 1e-10;
}

/// det(K − w M) for a small symbolic matrix, by cofactors (n ≤ 4 here).
ex char_poly(const GiNaC::matrix& K, const GiNaC::matrix& M, const symbol& w) {
    const unsigned n = K.rows();
    GiNaC::matrix A(n, n);
    for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < n; ++j) A(i, j) = K(i, j) - w * M(i, j);
    return A.determinant(GiNaC::determinant_algo::laplace);
}

/// The largest characteristic polynomials factored for exact roots (exact_roots): at most 60 terms, and at most 16
/// where it holds more than 8 symbols besides w.
constexpr std::size_t kMaxFactorTerms = 60;
constexpr std::size_t kMaxFactorTermsManySymbols = 16;
constexpr std::size_t kMaxFactorVariables = 8;

/// The symbols of e other than w, in name order (a deterministic substitution below).
void collect_symbols_except(const ex& e, const symbol& w, GiNaC::lst& out) {
    std::vector<GiNaC::symbol> found;
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it) && !it->is_equal(w)) {
            const auto& s = GiNaC::ex_to<GiNaC::symbol>(*it);
            if (std::none_of(found.begin(), found.end(), [&](const GiNaC::symbol& f) { return f.is_equal(s); }))
                found.push_back(s);
        }
    std::sort(found.begin(), found.end(),
              [](const GiNaC::symbol& a, const GiNaC::symbol& b) { return a.get_name() < b.get_name(); });
    for (const auto& s : found) out.append(s);
}

/// Whether p(w), a polynomial in w whose coefficients are polynomials in the parameters, may split into factors in w
/// of which one has degree 1 or 2 (the only ones whose roots are written out). A factorisation p = A·B with both in w
/// survives substituting integers for the parameters (where the leading coefficient stays nonzero), so when the
/// univariate integer polynomial at two such points does not split so, neither does p, and the multivariate
/// factorisation — seconds to a minute for a quadratic or quartic in eight parameters (the fuzzer's slow_modes
/// findings) — is skipped.
bool may_split(const ex& p, const symbol& w) {
    const int degree = p.degree(w);
    if (degree <= 1) return false;
    GiNaC::lst others;
    collect_symbols_except(p, w, others);
    static constexpr int kPoints[2][12] = {{7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47},
                                           {53, 59, 61, 67, 71, 73, 79, 83, 89, 97, 101, 103}};
    for (const auto& point : kPoints) {
        GiNaC::exmap at;
        std::size_t k = 0;
        for (const ex& s : others) {
            at[s] = point[k % 12] + int(k / 12);
            ++k;
        }
        const ex u = p.subs(at, GiNaC::subs_options::no_pattern).expand();
        if (!u.is_polynomial(w) || u.degree(w) != degree) return true;  // a vanishing leading coefficient: no test
        std::vector<ex> fs;
        factors_of(GiNaC::factor(u), fs);
        const bool splits = std::any_of(fs.begin(), fs.end(), [&](const ex& f) {
            const int d = f.degree(w);
            return d >= 1 && d <= 2 && d < degree;
        });
        if (!splits) return false;
    }
    return true;
}

std::vector<ex> exact_roots(const ex& p, const symbol& w) {
    std::vector<ex> roots;
    ex num = p.normal().numer().expand();
    if (!num.is_polynomial(w)) return roots;
    // Factoring a large multivariate polynomial takes GiNaC many seconds (149 terms of degree 4: 6 s of a modes run,
    // tests/fuzz/findings_structure/slow_modes_factor_characteristic_polynomial.toml); the shipped models' and tests'
    // have at most 8 terms. Beyond kMaxFactorTerms the frequencies stay numbers.
    if (GiNaC::is_a<GiNaC::add>(num) && num.nops() > kMaxFactorTerms) return roots;
    // Nor beyond kMaxFactorVariables symbols once it has more than a few terms: 57 terms of degree 4 in 11 symbols
    // took 10 s per equilibrium to factor (tests/fuzz/findings_structure/slow_modes_factor_eleven_symbols.toml).
    GiNaC::lst others;
    collect_symbols_except(num, w, others);
    if (GiNaC::is_a<GiNaC::add>(num) && num.nops() > kMaxFactorTermsManySymbols && others.nops() > kMaxFactorVariables)
        return roots;
    ex f = num;
    if (may_split(num, w)) {
        try {
            f = GiNaC::factor(num);
        } catch (const std::exception&) {
            f = num;
        }
    }
    std::vector<ex> fs;
    factors_of(f, fs);
    for (const ex& factor : fs) {
        if (!factor.has(w)) continue;
        const ex e = factor.expand();
        if (!e.is_polynomial(w)) continue;
        const int d = e.degree(w);
        if (d == 1) roots.push_back((-e.coeff(w, 0) / e.coeff(w, 1)).normal());
        if (d == 2) {
            const ex a = e.coeff(w, 2), b = e.coeff(w, 1), c = e.coeff(w, 0);
            const ex disc = (b * b - 4 * a * c).expand();
            roots.push_back(((-b - GiNaC::sqrt(disc)) / (2 * a)));
            roots.push_back(((-b + GiNaC::sqrt(disc)) / (2 * a)));
        }
    }
    return roots;
}

/// The most variables the entries of a block of K0 and M0 may hold together, as polynomials (every symbol, and every
/// function or non-integer power counted as one variable, as GiNaC::to_polynomial introduces them), for their
/// characteristic polynomial to be formed exactly: GiNaC's determinant normalizes rational entries, whose
/// multivariate gcds are exponential in the variables. A fuzzed 4×4 block of 14 (a square root of masses and a
/// force, cosines, sign(omega)) took 4.4 s per equilibrium (seed 36001); the exact frequencies of such a block would
/// not be read anyway. The numbers stand there. The same bound as the Legendre transform's (hamiltonian.cpp).
constexpr std::size_t kMaxExactVariables = 12;

std::size_t polynomial_variables(const GiNaC::matrix& K, const GiNaC::matrix& M) {
    GiNaC::exmap introduced;
    GiNaC::exset symbols;
    for (const GiNaC::matrix* m : {&K, &M})
        for (unsigned i = 0; i < m->rows(); ++i)
            for (unsigned j = 0; j < m->cols(); ++j) {
                const ex poly = (*m)(i, j).to_polynomial(introduced);
                for (auto it = poly.preorder_begin(); it != poly.preorder_end(); ++it)
                    if (GiNaC::is_a<GiNaC::symbol>(*it)) symbols.insert(*it);
            }
    return symbols.size();
}

/// The exact roots of det(K − w M), block by block: coordinates that neither K nor M couples (a decoupled pendulum
/// beside a top) give separate factors, found without factoring their product — GiNaC's multivariate factorisation
/// of a quartic in eight parameters takes tens of seconds (tests/fuzz/findings_structure/slow_modes_*.toml).
std::vector<ex> block_roots(const GiNaC::matrix& K, const GiNaC::matrix& M, const symbol& w) {
    const unsigned n = K.rows();
    std::vector<unsigned> block(n);
    for (unsigned i = 0; i < n; ++i) block[i] = i;
    const auto root = [&](unsigned i) {
        while (block[i] != i) i = block[i];
        return i;
    };
    for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < n; ++j)
            if (!K(i, j).is_zero() || !M(i, j).is_zero()) block[root(i)] = root(j);
    std::vector<ex> roots;
    for (unsigned b = 0; b < n; ++b) {
        if (root(b) != b) continue;
        std::vector<unsigned> members;
        for (unsigned i = 0; i < n; ++i)
            if (root(i) == b) members.push_back(i);
        const auto size = static_cast<unsigned>(members.size());
        GiNaC::matrix Kb(size, size), Mb(size, size);
        for (unsigned i = 0; i < size; ++i)
            for (unsigned j = 0; j < size; ++j) {
                Kb(i, j) = K(members[i], members[j]);
                Mb(i, j) = M(members[i], members[j]);
            }
        if (size > 1 && polynomial_variables(Kb, Mb) > kMaxExactVariables) continue;
        const std::vector<ex> found = exact_roots(char_poly(Kb, Mb, w), w);
        roots.insert(roots.end(), found.begin(), found.end());
    }
    return roots;
}

}  // namespace

namespace {

/// Where a factor of a denominator of the gradient, in one coordinate, vanishes and the gradient has a pole (not a
/// removable 0/0): a singular point of the reduced system (V_eff of a spherical pendulum with p_φ ≠ 0 at θ = 0),
/// never an equilibrium. One note per coordinate value.
std::vector<std::string> singular_points(const std::vector<ex>& g, const std::vector<symbol>& q,
                                         const std::vector<bool>& angle, const exmap& params,
                                         const std::vector<std::string>& names) {
    std::vector<std::string> out;
    std::vector<std::pair<std::size_t, double>> seen;
    for (const ex& gi : g) {
        std::vector<ex> fs;
        try {
            factors_of(factor_through_functions(gi.normal().denom()), fs);
        } catch (const std::exception&) {
            continue;
        }
        for (const ex& f : fs) {
            std::size_t which = q.size();
            int count = 0;
            for (std::size_t j = 0; j < q.size(); ++j)
                if (f.has(q[j])) {
                    which = j;
                    ++count;
                }
            if (count != 1) continue;
            for (const ex& root : solve_factor(f, q[which])) {
                double v = evaluate(root, params);
                if (!std::isfinite(v)) continue;
                if (angle[which]) v = wrap(v);
                if (std::any_of(seen.begin(), seen.end(), [&](const auto& s) {
                        return s.first == which && std::abs(s.second - v) < 1e-9;
                    }))
                    continue;
                // The other coordinates at generic values: the pole is where this one takes v, whatever they are.
                std::vector<double> x(q.size(), 0.7);
                x[which] = v;
                if (std::isfinite(value_at(gi, q, x, params))) continue;  // removable there
                seen.emplace_back(which, v);
                std::ostringstream os;
                os << names[which] << " = " << (std::abs(v) < 1e-13 ? 0.0 : v)
                   << ": a singular point (V_eff or the forces have a pole there), not an equilibrium";
                out.push_back(os.str());
            }
        }
    }
    return out;
}

}  // namespace

const char* stability_name(Stability s) {
    switch (s) {
    case Stability::Stable: return "stable";
    case Stability::Marginal: return "marginally stable";
    case Stability::Unstable: return "unstable";
    case Stability::GyroscopicallyStable: return "gyroscopically stabilized";
    }
    return "?";
}

/// "; did you mean 'l1'?" for a parameter name close to `name`, else "".
static std::string parameter_hint(const Model& model, const std::string& name) {
    std::vector<std::string> names;
    for (const Parameter& p : model.parameters) names.push_back(p.name);
    const std::string closest = closest_name(name, names);
    return closest.empty() ? "" : "; did you mean '" + closest + "'?";
}

ModesResult small_oscillations(const Model& model, const Equations& eq_in, const ModesOptions& options) {
    exmap fixed;  // the parameters --set gives: a term that vanishes at their values does not count
    for (const auto& entry : options.set) {
        const std::string& name = entry.first;  // not a structured binding: clang 14 refuses one in a lambda
        const auto it = std::find_if(model.parameters.begin(), model.parameters.end(),
                                     [&](const Parameter& p) { return p.name == name; });
        if (it == model.parameters.end()) throw ModesError("--set " + name + ": no such parameter" + parameter_hint(model, name));
        fixed[it->symbol] = GiNaC::numeric(exact(entry.second));
    }
    // Explicit time, decided as every command decides it (mechanics/time_dependence.hpp); the equations are then
    // taken at t = 0, which is every t.
    const Equations eq = steady_equations(model, eq_in, fixed);

    std::vector<symbol> inputs;
    for (const std::string& name : options.inputs) {
        const auto it = std::find_if(model.parameters.begin(), model.parameters.end(),
                                     [&](const Parameter& p) { return p.name == name; });
        if (it == model.parameters.end())
            throw ModesError("--input " + name + ": no such parameter" + parameter_hint(model, name) +
                             " (an input is a parameter of the model, e.g. a torque in [forces])");
        inputs.push_back(it->symbol);
    }

    ModesResult result;
    std::vector<std::pair<symbol, std::size_t>> momenta;
    const Reduced r = reduce(model, eq, options, momenta, result.reduced);
    const std::size_t n = r.q.size();
    for (std::size_t i : r.index) {
        result.coordinates.push_back(model.coordinates[i].name);
        result.latex.push_back(model.coordinates[i].latex);
    }
    for (const auto& [s, i] : momenta) result.momentum_symbols.push_back({s, "p_{" + model.coordinates[i].latex + "}"});
    // Holonomic constraints: rest on their manifold, with multipliers (constrained_equilibria.hpp).
    const ManifoldConstraints manifold = manifold_constraints(model, eq, r.q, result.reduced);
    const std::size_t m = manifold.size();
    result.constraints = manifold.names;
    const QuantityUnits units = quantity_units(model, eq_in);
    for (const std::string& name : manifold.names)
        for (std::size_t k = 0; k < eq_in.constraints.size(); ++k)
            if (eq_in.constraints[k].name == name) result.multiplier_units.push_back(units.multipliers[k]);
    result.multiplier_units.resize(result.constraints.size());

    Values values;
    for (const Parameter& p : model.parameters) {
        const auto it = options.set.find(p.name);
        values.params[p.symbol] = GiNaC::numeric(it == options.set.end() ? p.value : it->second);
    }
    for (const auto& [s, i] : momenta) values.params[s] = GiNaC::numeric(options.momentum.at(s.get_name()));
    for (const auto& c : model.coordinates)
        if (std::none_of(r.index.begin(), r.index.end(), [&](std::size_t i) { return model.coordinates[i].q == c.q; }))
            values.params[c.q] = GiNaC::numeric(0);  // a cyclic coordinate does not appear; 0 if it did

    // L = ½ q̇ᵀ M q̇ + βᵀ q̇ + L₀ (L is at most quadratic in the velocities: derive_equations checked T).
    RestLinearization lin;
    try {
        lin = linearize_about_rest(r.L, r.Q, r.q, r.qd);
    } catch (const NoValueAtRest& e) {
        throw ModesError(std::string("the linearization about rest is not defined: ") + e.what());
    }
    result.V_eff = lin.V_eff;
    for (const std::string& why : lin.undefined)
        result.notes.push_back("the damping about rest is not defined: " + why +
                               "; the modes below leave that term out (dry friction holds a state of rest, or not, "
                               "beyond any linearization)");
    const std::vector<ex>& g = lin.gradient;
    const std::vector<std::vector<ex>>&M = lin.M, &K = lin.K, &D = lin.D;

    // The rest conditions in (q, λ): G − Aᵀλ = 0 and g = 0 (just G = 0 without constraints), with their Jacobian,
    // whose q-block is the stiffness K₀ − Σ λ_k ∂²g_k/∂q².
    std::vector<ex> rest_eq;
    std::vector<std::vector<ex>> rest_jac;
    rest_conditions(g, K, manifold, rest_eq, rest_jac);
    std::vector<symbol> unknowns = r.q;
    unknowns.insert(unknowns.end(), manifold.lambda.begin(), manifold.lambda.end());

    // Exact candidates per coordinate, from the factors of the gradient that depend on that coordinate alone
    // (without constraints: with them the gradient is balanced by the multipliers, and the roots are numbers).
    std::vector<std::vector<ex>> exact_candidates(n);
    for (std::size_t i = 0; i < n && m == 0; ++i) {
        std::vector<ex> fs;
        factors_of(factor_through_functions(g[i].normal().numer()), fs);
        for (const ex& f : fs) {
            std::vector<std::size_t> depends;
            for (std::size_t j = 0; j < n; ++j)
                if (f.has(r.q[j])) depends.push_back(j);
            if (depends.size() != 1) continue;
            for (const ex& root : solve_factor(f, r.q[depends[0]])) {
                auto& list = exact_candidates[depends[0]];
                if (std::none_of(list.begin(), list.end(), [&](const ex& e) { return (e - root).is_zero(); }))
                    list.push_back(root);
            }
        }
    }
    std::vector<ex> position_terms = g;
    position_terms.insert(position_terms.end(), manifold.g.begin(), manifold.g.end());
    const std::vector<bool> angle = periodic(position_terms, r.q, values.params);

    // Starting points: the exact candidates' combinations, --at, the model's initial q, 0, and a scan.
    std::vector<std::vector<double>> starts;
    {
        std::vector<std::vector<double>> numeric(n);
        for (std::size_t i = 0; i < n; ++i)
            for (const ex& c : exact_candidates[i]) {
                const double v = evaluate(c, values.params);
                if (std::isfinite(v)) numeric[i].push_back(v);
            }
        // Coordinates without candidates start from the model's value.
        std::vector<std::size_t> counter(n, 0);
        for (int combo = 0; combo < 256; ++combo) {
            std::vector<double> x(n);
            for (std::size_t i = 0; i < n; ++i)
                x[i] = numeric[i].empty() ? model.coordinates[r.index[i]].initial : numeric[i][counter[i]];
            starts.push_back(x);
            std::size_t k = 0;
            while (k < n && (numeric[k].empty() || ++counter[k] == numeric[k].size())) {
                counter[k] = 0;
                ++k;
            }
            if (k == n) break;
        }
    }
    for (const auto& guess : options.at) {
        std::vector<double> x(n);
        for (std::size_t i = 0; i < n; ++i) {
            const auto it = guess.find(result.coordinates[i]);
            x[i] = it == guess.end() ? model.coordinates[r.index[i]].initial : it->second;
        }
        for (const auto& [name, v] : guess) {
            static_cast<void>(v);
            if (std::find(result.coordinates.begin(), result.coordinates.end(), name) == result.coordinates.end())
                throw ModesError("--at " + name + ": no coordinate of that name remains");
        }
        starts.push_back(x);
    }
    {
        std::vector<double> initial(n), zero(n, 0.0);
        for (std::size_t i = 0; i < n; ++i) initial[i] = model.coordinates[r.index[i]].initial;
        starts.push_back(initial);
        starts.push_back(zero);
        std::mt19937 rng(20261124);
        std::uniform_real_distribution<double> u(-1, 1);
        const int scans = n <= 2 ? 48 : 96;
        for (int k = 0; k < scans; ++k) {
            std::vector<double> x(n);
            for (std::size_t i = 0; i < n; ++i)
                x[i] = angle[i] ? kPi * u(rng) : initial[i] + (1 + std::abs(initial[i])) * 2 * u(rng);
            starts.push_back(x);
        }
    }

    // Solve, and keep each equilibrium once (angles modulo 2π).
    // Equilibria that differ only along the null space of K₀ (a free translation, an unreduced cyclic
    // coordinate) are one family: the first found stands for it, the others are dropped.
    struct Found {
        std::vector<double> x;
        std::vector<double> lambda;  ///< the multipliers there (none without constraints)
        Eigen::MatrixXd null;  ///< orthonormal basis of K₀'s null space there (n × k; on the manifold's tangent space)
    };
    // The stiffness at (q, λ) and the tangent space of the constraints at q (the identity without constraints).
    auto numeric_matrix = [&](const std::vector<std::vector<ex>>& S, std::size_t rows, std::size_t cols,
                              const std::vector<double>& at) {
        Eigen::MatrixXd out(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
        for (std::size_t i = 0; i < rows; ++i)
            for (std::size_t j = 0; j < cols; ++j)
                out(Eigen::Index(i), Eigen::Index(j)) = value_at(S[i][j], unknowns, at, values.params);
        return out;
    };
    auto tangent_at = [&](const std::vector<double>& at) {
        return tangent_basis(numeric_matrix(manifold.jacobian, m, n, at));
    };
    std::vector<Found> found;
    // Evaluations of the rest conditions for all the starts together, at 40 digits: the shipped models, examples
    // and tests/cli/modes spend at most 1 874 of them; a constraint manifold that is empty (no start converges)
    // spent 75 000 in 19 s (tests/fuzz/findings_structure/slow_modes_unsatisfiable_constraint.toml).
    long budget = kNewtonBudget;
    const std::clock_t search_started = std::clock();
    std::size_t unsearched = 0;
    auto same = [&](const Found& f, const std::vector<double>& x) {
        Eigen::VectorXd d(static_cast<Eigen::Index>(n));
        double size = 1;
        for (std::size_t i = 0; i < n; ++i) {
            d(Eigen::Index(i)) = angle[i] ? wrap(x[i] - f.x[i]) : x[i] - f.x[i];
            size = std::max(size, std::abs(x[i]));
        }
        if (f.null.cols() > 0) d -= f.null * (f.null.transpose() * d);
        return d.norm() <= 1e-7 * size;
    };
    for (std::vector<double> x : starts) {
        x.resize(n + m, 0.0);  // the multipliers start at 0: the conditions are linear in them
        if (budget <= 0) {
            ++unsearched;
            continue;
        }
        if (!newton(rest_eq, rest_jac, unknowns, values.params, x, budget, search_started) ||
            !(precise_residual(rest_eq, unknowns, x, values.params) < 1e-9))
            continue;
        for (std::size_t i = 0; i < n; ++i)
            if (angle[i]) x[i] = wrap(x[i]);
        for (double& v : x)
            if (std::abs(v) < 1e-13) v = 0;
        const std::vector<double> lambda(x.begin() + Eigen::Index(n), x.end());
        x.resize(n);
        if (std::any_of(found.begin(), found.end(), [&](const Found& f) { return same(f, x); })) continue;
        std::vector<double> at = x;
        at.insert(at.end(), lambda.begin(), lambda.end());
        const Eigen::MatrixXd N = tangent_at(at);
        const Eigen::MatrixXd Kx = N.transpose() * numeric_matrix(rest_jac, n, n, at) * N;
        Found f{x, lambda, Eigen::MatrixXd(static_cast<Eigen::Index>(n), 0)};
        if (Kx.size() > 0 && Kx.allFinite()) {  // 0×0 where the constraints leave no freedom at this point
            const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es((Kx + Kx.transpose()) / 2);
            const double big = es.eigenvalues().cwiseAbs().maxCoeff();
            std::vector<Eigen::Index> zero;
            for (Eigen::Index k = 0; k < es.eigenvalues().size(); ++k)
                if (std::abs(es.eigenvalues()(k)) <= 1e-9 * std::max(big, 1e-300)) zero.push_back(k);
            f.null.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(zero.size()));
            for (std::size_t c = 0; c < zero.size(); ++c) f.null.col(Eigen::Index(c)) = N * es.eigenvectors().col(zero[c]);
        }
        found.push_back(std::move(f));
    }
    if (unsearched > 0)
        result.notes.push_back("the search for equilibria stopped at its budget (" + std::to_string(kNewtonBudget) +
                               " evaluations or " + std::to_string(int(kNewtonSeconds)) + " s of processor time): " +
                               std::to_string(unsearched) + " of " + std::to_string(starts.size()) +
                               " starting points were not tried" +
                               (found.empty() ? std::string(" (none of the others converged quickly: is the constraint "
                                                            "manifold empty?)")
                                              : std::string()));
    std::sort(found.begin(), found.end(), [](const Found& a, const Found& b) { return a.x < b.x; });

    for (const Found& family : found) {
        const std::vector<double>& x = family.x;
        std::vector<double> at = x;  // (q, λ)
        at.insert(at.end(), family.lambda.begin(), family.lambda.end());
        Equilibrium e;
        e.q = x;
        e.multipliers = family.lambda;
        e.exact.resize(n);
        exmap exact_at;
        for (std::size_t i = 0; i < n; ++i) {
            for (const ex& c : exact_candidates[i]) {
                const double v = evaluate(c, values.params);
                const double d = angle[i] ? wrap(v - x[i]) : v - x[i];
                if (std::isfinite(v) && std::abs(d) < 1e-8) {
                    e.exact[i] = std::abs(v - x[i]) < 1e-8 ? c : c + GiNaC::numeric(int(std::lround((x[i] - v) / (2 * kPi)))) * 2 * GiNaC::Pi;
                    break;
                }
            }
            if (e.exact[i])
                exact_at[r.q[i]] = *e.exact[i];
        }
        // The linearization, as numbers (K₀ with the constraints' curvature: the q-block of the rest conditions).
        auto mat = [&](const std::vector<std::vector<ex>>& S) {
            std::vector<std::vector<double>> out(n, std::vector<double>(n));
            for (std::size_t i = 0; i < n; ++i)
                for (std::size_t j = 0; j < n; ++j) out[i][j] = value_at(S[i][j], unknowns, at, values.params);
            return out;
        };
        e.M = mat(M);
        e.K = mat(rest_jac);
        const auto Dn = mat(D);
        e.C.assign(n, std::vector<double>(n));
        e.G.assign(n, std::vector<double>(n));
        double scale = 0;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) {
                e.C[i][j] = (Dn[i][j] + Dn[j][i]) / 2;
                e.G[i][j] = (Dn[i][j] - Dn[j][i]) / 2;
                scale = std::max({scale, std::abs(e.M[i][j]), std::abs(e.K[i][j])});
            }
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) {
                e.damped = e.damped || std::abs(e.C[i][j]) > 1e-12 * (1 + scale);
                e.gyroscopic = e.gyroscopic || std::abs(e.G[i][j]) > 1e-12 * (1 + scale);
            }
        Eigen::MatrixXd Mm(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
        Eigen::MatrixXd Km = Mm, Dm = Mm;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) {
                Mm(Eigen::Index(i), Eigen::Index(j)) = e.M[i][j];
                Km(Eigen::Index(i), Eigen::Index(j)) = e.K[i][j];
                Dm(Eigen::Index(i), Eigen::Index(j)) = Dn[i][j];
            }
        // b = −∂g/∂u: how each input pushes the generalized forces balance (g = ∂V_eff/∂q − Q).
        Eigen::MatrixXd Bq(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(inputs.size()));
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t k = 0; k < inputs.size(); ++k)
                Bq(Eigen::Index(i), Eigen::Index(k)) = -value_at(g[i].diff(inputs[k]), unknowns, at, values.params);
        // On the constraints' tangent space, δq = N δs (N = I without constraints); the modes live there.
        const Eigen::MatrixXd N = tangent_at(at);
        e.tangent = rows_of(N);
        Mm = N.transpose() * Mm * N;
        Km = N.transpose() * Km * N;
        Dm = N.transpose() * Dm * N;
        Bq = N.transpose() * Bq;
        const auto nr = static_cast<std::size_t>(N.cols());
        if (nr == 0) {
            result.notes.push_back("an equilibrium where the constraints leave no freedom (a rigid point) was left out");
            continue;
        }
        if (!Mm.allFinite() || !Km.allFinite() || !Dm.allFinite() || !Bq.allFinite()) {
            result.notes.push_back("an equilibrium where the linearization cannot be evaluated was left out");
            continue;
        }
        const Eigen::LLT<Eigen::MatrixXd> llt(Mm);
        if (llt.info() != Eigen::Success) {
            // Singular here only (Euler angles at θ = 0: reduce the cyclic coordinates), or at every q with these
            // parameter values (a mass or a length set to 0: nothing has inertia along some direction).
            bool everywhere = true;
            for (const double shift : {0.37, 1.21}) {
                std::vector<double> elsewhere = at;
                for (std::size_t i = 0; i < n; ++i) elsewhere[i] += shift * double(i + 1);
                const Eigen::MatrixXd Me = N.transpose() * numeric_matrix(M, n, n, elsewhere) * N;
                everywhere = everywhere && (!Me.allFinite() || Eigen::LLT<Eigen::MatrixXd>(Me).info() != Eigen::Success);
            }
            result.notes.push_back(everywhere ? "the mass matrix is singular at every q with these parameter values (a "
                                                "mass, a length or an inertia set to 0?): nothing to linearize"
                                              : "an equilibrium where the mass matrix is singular (the coordinates are "
                                                "singular there) was left out; reduce the cyclic coordinates with "
                                                "--momentum");
            continue;
        }
        // First-order system s' = A s, s = [δs, δṡ] on the tangent space; reported in x = [δq, δq̇] as T A Tᵀ,
        // T = diag(N, N) (zero on directions that leave the manifold; A itself without constraints).
        Eigen::MatrixXd A = Eigen::MatrixXd::Zero(Eigen::Index(2 * nr), Eigen::Index(2 * nr));
        A.topRightCorner(Eigen::Index(nr), Eigen::Index(nr)).setIdentity();
        A.bottomLeftCorner(Eigen::Index(nr), Eigen::Index(nr)) = -llt.solve(Km);
        A.bottomRightCorner(Eigen::Index(nr), Eigen::Index(nr)) = -llt.solve(Dm);
        Eigen::MatrixXd B = Eigen::MatrixXd::Zero(Eigen::Index(2 * nr), Bq.cols());
        // Without inputs B has no columns and no storage: a block of it would offset a null pointer (UBSan, clang).
        if (Bq.cols() > 0) B.bottomRows(Eigen::Index(nr)) = llt.solve(Bq);
        Eigen::MatrixXd T = Eigen::MatrixXd::Zero(Eigen::Index(2 * n), Eigen::Index(2 * nr));
        if (nr > 0) {  // (no free direction: T has no storage, as B above)
            T.topLeftCorner(Eigen::Index(n), Eigen::Index(nr)) = N;
            T.bottomRightCorner(Eigen::Index(n), Eigen::Index(nr)) = N;
        }
        e.A = rows_of(T * A * T.transpose());
        e.B = rows_of(T * B);
        // Normal modes of the symmetric part of K: ω² and shapes.
        const Eigen::MatrixXd Ks = (Km + Km.transpose()) / 2;
        const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ges(Ks, Mm);
        double omega_scale = 0;
        for (Eigen::Index k = 0; k < ges.eigenvalues().size(); ++k)
            omega_scale = std::max(omega_scale, std::abs(ges.eigenvalues()(k)));
        const double zero_tol = 1e-9 * std::max(omega_scale, 1e-300);
        bool negative = false, zero = false;
        for (Eigen::Index k = 0; k < ges.eigenvalues().size(); ++k) {
            NormalMode mode;
            mode.omega2 = ges.eigenvalues()(k);
            if (std::abs(mode.omega2) <= zero_tol) mode.omega2 = 0;
            negative = negative || mode.omega2 < 0;
            zero = zero || mode.omega2 == 0;
            Eigen::VectorXd v = N * ges.eigenvectors().col(k);  // the shape in the model's coordinates
            Eigen::Index big = 0;
            v.cwiseAbs().maxCoeff(&big);
            v /= v(big);
            for (Eigen::Index i = 0; i < v.size(); ++i) mode.shape.push_back(std::abs(v(i)) < 1e-12 ? 0.0 : v(i));
            e.modes.push_back(mode);
        }
        // The eigenvalues of A, on A scaled to time in units of 1/ω_max (S⁻¹ A S, S = diag(I, s I), s = ω_max: the
        // same eigenvalues): without it, a model in SI units of atoms (M ~ 1e-26 kg, K ~ 1e3 N/m, M⁻¹K ~ 1e29)
        // gives EigenSolver a matrix of 1s beside 1e29s, whose zero mode came back as ±8e20 (an "unstable"
        // molecule).
        const double s_scale = omega_scale > 0 ? std::sqrt(omega_scale) : 1.0;
        Eigen::MatrixXd As = A;
        if (nr > 0) {
            As.topRightCorner(Eigen::Index(nr), Eigen::Index(nr)) *= s_scale;
            As.bottomLeftCorner(Eigen::Index(nr), Eigen::Index(nr)) /= s_scale;
        }
        const Eigen::EigenSolver<Eigen::MatrixXd> es(As, false);
        double max_re = -std::numeric_limits<double>::infinity();
        double lambda_scale = 0;
        for (Eigen::Index k = 0; k < es.eigenvalues().size(); ++k) lambda_scale = std::max(lambda_scale, std::abs(es.eigenvalues()(k)));
        for (Eigen::Index k = 0; k < es.eigenvalues().size(); ++k) {
            std::complex<double> z = es.eigenvalues()(k);
            // A double zero eigenvalue (a zero mode) splits into ±√ε: show it as the 0 it is.
            if (std::abs(z) <= 1e-6 * std::max(lambda_scale, 1e-300)) z = 0;
            e.eigenvalues.push_back(z);
            max_re = std::max(max_re, z.real());
        }
        const double sort_tol = 1e-9 * std::max(lambda_scale, 1e-300);
        std::sort(e.eigenvalues.begin(), e.eigenvalues.end(), [sort_tol](const auto& a, const auto& b) {
            return std::abs(a.real() - b.real()) > sort_tol ? a.real() > b.real() : a.imag() > b.imag();
        });
        const double lambda_tol = 1e-7 * std::sqrt(std::max(omega_scale, 1e-300));
        // Conservative (no damping): every λ on the imaginary axis is stable (Lyapunov); with damping every λ must
        // have Re λ < 0 for asymptotic stability, and Re λ = 0 is marginal.
        if (max_re > lambda_tol) {
            e.stability = Stability::Unstable;
            e.growth_rate = max_re;
        } else if (zero || (e.damped && max_re > -lambda_tol)) {
            e.stability = Stability::Marginal;
        } else if (negative) {
            e.stability = Stability::GyroscopicallyStable;
        } else {
            e.stability = Stability::Stable;
        }
        if (zero)
            result.notes.push_back("a mode with ω = 0 at an equilibrium: the equilibria there are not isolated "
                                   "(a continuum along that shape, e.g. a free translation or a cyclic coordinate)");

        // Exact ω²: the characteristic polynomial at the exact equilibrium, in the parameters, where it factors.
        // (Where some coordinate has no exact value, K₀ and M₀ may still be free of it: a quadratic V.)
        if (!e.damped && !e.gyroscopic && n <= 4 && m == 0) {
            try {
                GiNaC::matrix Ke{static_cast<unsigned>(n), static_cast<unsigned>(n)}, Me{static_cast<unsigned>(n), static_cast<unsigned>(n)};
                // At a removable 0/0 (the sleeping top) there is no exact entry: no exact ω² then.
                const auto exact_entry = [&](const ex& e) {
                    const std::optional<ex> v = subs_unless_pole(e, exact_at, GiNaC::subs_options::no_pattern);
                    if (!v) throw std::runtime_error("0/0 at the exact equilibrium");
                    return simplify_inverse_trig(v->expand());
                };
                for (std::size_t i = 0; i < n; ++i)
                    for (std::size_t j = 0; j < n; ++j) {
                        Ke(unsigned(i), unsigned(j)) = exact_entry(K[i][j]);
                        Me(unsigned(i), unsigned(j)) = exact_entry(M[i][j]);
                    }
                bool free = true;
                for (const symbol& qi : r.q) free = free && !Ke.has(qi) && !Me.has(qi);
                if (!free) throw std::runtime_error("not exact");
                e.M_exact.assign(n, std::vector<ex>(n));
                e.K_exact.assign(n, std::vector<ex>(n));
                for (std::size_t i = 0; i < n; ++i)
                    for (std::size_t j = 0; j < n; ++j) {
                        e.M_exact[i][j] = Me(unsigned(i), unsigned(j));
                        e.K_exact[i][j] = Ke(unsigned(i), unsigned(j));
                    }
                const symbol w("w_");
                std::vector<ex> roots = block_roots(Ke, Me, w);
                for (NormalMode& mode : e.modes)
                    for (const ex& root : roots) {
                        const double v = evaluate(root, values.params);
                        if (std::isfinite(v) && std::abs(v - mode.omega2) <= 1e-8 * (1 + std::abs(mode.omega2))) {
                            mode.omega2_exact = root;
                            break;
                        }
                    }
            } catch (const std::exception&) {
                // no exact frequencies: the numbers stand
            }
        }
        result.equilibria.push_back(std::move(e));
    }
    if (result.equilibria.empty()) {
        // A gradient that no coordinate enters (V linear in q: a block on an incline) is never 0, or always.
        bool constant = m == 0;
        double largest = 0;
        for (std::size_t i = 0; i < n && constant; ++i) {
            constant = std::none_of(r.q.begin(), r.q.end(), [&](const symbol& x) { return g[i].has(x); });
            if (constant) largest = std::max(largest, std::abs(evaluate(g[i], values.params)));
        }
        std::ostringstream os;
        if (constant && largest > 0) {
            os << "∂V_eff/∂q − Q is the same at every q and not 0 (";
            for (std::size_t i = 0; i < n; ++i) os << (i ? ", " : "") << g[i];
            os << "): nothing balances it, so there is no equilibrium";
        } else if (constant) {
            os << "∂V_eff/∂q − Q vanishes at every q with these parameter values: every configuration is at rest, "
                  "none is an isolated equilibrium";
        } else if (found.empty()) {
            os << "the search from " << starts.size() << " starting points found none (give guesses with --at)";
        }
        if (os.tellp() > 0) result.notes.push_back(os.str());
    }
    for (const std::string& pole : singular_points(g, r.q, angle, values.params, result.coordinates))
        result.notes.push_back(pole);
    std::sort(result.notes.begin(), result.notes.end());
    result.notes.erase(std::unique(result.notes.begin(), result.notes.end()), result.notes.end());
    return result;
}

}  // namespace eomgen
