/** @file lagrangian.cpp  Euler–Lagrange equations by the chain rule on plain symbols. */
#include "mechanics/lagrangian.hpp"

#include "mechanics/double_evaluator.hpp"
#include "mechanics/results.hpp"

#include "mechanics/constraints.hpp"
#include "mechanics/differentiator.hpp"
#include "mechanics/noether.hpp"
#include "mechanics/pole_free_subs.hpp"
#include "mechanics/time_dependence.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <random>
#include <functional>
#include <optional>
#include <sstream>
#include <unordered_map>

namespace eomgen {
namespace {

double to_double(const GiNaC::ex& e) {
    const GiNaC::ex v = GiNaC::evalf(e);
    if (!GiNaC::is_a<GiNaC::numeric>(v)) throw std::runtime_error("expression did not evaluate to a number");
    const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(v);
    if (!n.is_real()) return std::nan("");
    return n.to_double();
}

// In doubles, one walk of the entries sharing the values of their common subexpressions (DoubleEvaluator):
// GiNaC's subs() and evalf() of every entry were a fifth of deriving the 60-link pendulum. An entry the walk
// cannot evaluate (a function it does not know) goes through subs() and evalf(); the maps from random_point()
// have plain symbols as keys, so subs_options::no_pattern makes each node one hash look-up.
Eigen::MatrixXd evaluate(const GiNaC::matrix& m, const GiNaC::exmap& at) {
    DoubleEvaluator fast = DoubleEvaluator::at(at);
    Eigen::MatrixXd out(m.rows(), m.cols());
    for (unsigned i = 0; i < m.rows(); ++i)
        for (unsigned j = 0; j < m.cols(); ++j) {
            // M(j, i) is the same expression as M(i, j) (derive_equations stores it twice): evaluated once.
            if (j < i && m(i, j).is_equal(m(j, i))) {
                out(i, j) = out(j, i);
                continue;
            }
            const std::optional<double> v = fast(m(i, j));
            out(i, j) = v ? *v : to_double(m(i, j).subs(at, GiNaC::subs_options::no_pattern));
        }
    return out;
}

/// Where a problem of T is reported: T's text, or, in a model of bodies alone (no [lagrangian] T), the first
/// body, whose mass and inertia make T (found by tests/fuzz/fuzz_structure.cpp: the place was the bare file name).
SourceLocation kinetic_energy_place(const Model& model) {
    if (model.T.where.line > 0 || model.bodies.empty()) return model.T.where;
    return model.bodies.front().where;
}

/// The velocity-dependence check: every entry of ∂²T/∂q̇² must be free of velocities.
void check_quadratic_in_velocities(const Model& model, const GiNaC::matrix& M) {
    // One walk of each entry for all the velocities (entry.has(q̇_k) for each k walked it n times: n³ walks, a
    // tenth of generating the 45-link chain); the entries that hold a velocity are then looked at one by one.
    GiNaC::exset velocities;
    for (const Coordinate& c : model.coordinates) velocities.insert(c.qd);
    auto holds_velocity = [&velocities](const GiNaC::ex& e) {
        for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::symbol>(*it) && velocities.count(*it)) return true;
        return false;
    };
    for (unsigned i = 0; i < M.rows(); ++i)
        for (unsigned j = 0; j < M.cols(); ++j) {
            if (!holds_velocity(M(i, j))) continue;
            for (const Coordinate& c : model.coordinates) {
                if (!M(i, j).has(c.qd)) continue;
                if (GiNaC::diff(M(i, j), c.qd).expand().is_zero()) continue;
                throw ModelError(kinetic_energy_place(model),
                                 "T is not quadratic + linear + zero order in the velocities: ∂²T/∂" +
                                     model.coordinates[i].name + "'∂" + model.coordinates[j].name +
                                     "' still depends on " + c.name + "'");
            }
        }
}


}  // namespace

GiNaC::exmap random_point(const Model& model, unsigned seed) {
    std::mt19937 rng(seed);
    // Rationals, not floats, so that exact zeros stay exact after substitution.
    std::uniform_int_distribution<int> pick(500, 1500);
    auto value = [&] { return GiNaC::numeric(pick(rng), 1000); };
    GiNaC::exmap at;
    at[model.t] = value();
    for (const Coordinate& c : model.coordinates) {
        at[c.q] = value();
        at[c.qd] = value();
        at[c.qdd] = value();
    }
    for (const Parameter& p : model.parameters) at[p.symbol] = value();
    return at;
}

namespace {

/// True when e, evaluated at random_point(model, 1) with 40 significant digits, is a real number clearly
/// away from zero: beyond 1e-20 of its largest top-level term (round-off at 40 digits stays far below
/// that unless the terms cancel across 20 orders of magnitude). False when undecided (e does not evaluate
/// to a real number there, or a pole): the caller then goes on with the exact tests.
bool clearly_nonzero(const GiNaC::ex& e, const Model& model) {
    // First in double and in long double from the same inputs (a walk of the tree each, no CLN): a value well
    // above its terms' round-off on which both precisions agree to three digits is not round-off. Undecided
    // otherwise (a symbolic zero evaluates to round-off, on which the two disagree, or to exactly 0), and the
    // 40-digit look below decides; the 60-link pendulum's ∂L/∂q took a second at 40 digits.
    {
        const GiNaC::exmap at = random_point(model, 1);
        DoubleEvaluator in_double = DoubleEvaluator::at(at);
        LongDoubleEvaluator in_long = LongDoubleEvaluator::at(at);
        double sum = 0, scale = 1.0;
        long double sum_long = 0;
        bool decided = true;
        for (std::size_t k = 0, terms = GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1; k < terms && decided; ++k) {
            const GiNaC::ex term = terms > 1 ? e.op(k) : e;
            const std::optional<double> v = in_double(term);
            const std::optional<long double> w = in_long(term);
            decided = v && w;
            if (!decided) break;
            sum += *v;
            sum_long += *w;
            scale = std::max(scale, std::abs(*v));
        }
        if (decided && std::isfinite(sum) && std::abs(sum) > 1e-9 * scale &&
            std::abs(static_cast<long double>(sum) - sum_long) <= 1e-3L * std::abs(sum_long))
            return true;
    }
    struct Precision {
        long saved = GiNaC::Digits;
        Precision() { GiNaC::Digits = 40; }
        ~Precision() { GiNaC::Digits = saved; }
    } precision;
    try {
        const GiNaC::exmap at = random_point(model, 1);
        // The terms one by one (their sum is e's value), each a real number or undecided.
        GiNaC::numeric sum = 0;
        double scale = 1.0;
        for (std::size_t k = 0, terms = GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1; k < terms; ++k) {
            const GiNaC::ex v = GiNaC::evalf((terms > 1 ? e.op(k) : e).subs(at, GiNaC::subs_options::no_pattern));
            if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) return false;
            const GiNaC::numeric& x = GiNaC::ex_to<GiNaC::numeric>(v);
            const double m = std::abs(x.to_double());
            if (!std::isfinite(m)) return false;
            scale = std::max(scale, m);
            sum += x;
        }
        const double v = std::abs(sum.to_double());
        return std::isfinite(v) && v > 1e-20 * scale;
    } catch (...) {
        return false;
    }
}

}  // namespace

bool is_zero(const GiNaC::ex& e, const Model& model) {
    // A numeric look first: most expressions tested are not zero, and expand() and normal() of a large one
    // take long (∂L/∂q of the 24-link pendulum: a tenth of derive_equations).
    if (clearly_nonzero(e, model)) return false;
    const GiNaC::ex x = e.expand();
    if (x.is_zero()) return true;
    if (GiNaC::normal(x).is_zero()) return true;
    // Three points where e can be evaluated; a point where it has a pole (a denominator the random values make
    // exactly 0, found by the structural fuzzer: GiNaC threw "division by zero" out of derive_equations) is skipped.
    int good = 0;
    for (unsigned seed = 1; seed <= 12 && good < 3; ++seed) {
        const GiNaC::exmap at = random_point(model, seed);
        const std::optional<GiNaC::ex> value = subs_unless_pole(x, at, GiNaC::subs_options::no_pattern);
        if (!value) continue;
        double v = 0, scale = 1.0;
        try {
            v = to_double(*value);
            // Scale by the magnitude of the terms so that round-off in a large sum is not taken for non-zero.
            if (GiNaC::is_a<GiNaC::add>(x))
                for (const GiNaC::ex& term : x)
                    if (const auto t = subs_unless_pole(term, at, GiNaC::subs_options::no_pattern))
                        scale = std::max(scale, std::abs(to_double(*t)));
        } catch (const std::exception&) {
            continue;  // not a number there
        }
        if (std::isnan(v)) continue;
        if (!(std::abs(v) <= 1e-12 * scale)) return false;
        ++good;
    }
    return good == 3;
}

GiNaC::ex time_derivative(const GiNaC::ex& e, const Model& model) {
    install_chain_rule();
    GiNaC::ex d = GiNaC::diff(e, model.t);
    for (const Coordinate& c : model.coordinates) d += GiNaC::diff(e, c.q) * c.qd + GiNaC::diff(e, c.qd) * c.qdd;
    return d;
}

namespace {

/// det M = 0 on a set of configurations (Euler angles at sin θ = 0, polar coordinates at r = 0): the
/// factors of det M that are a coordinate, or the sine or cosine of an expression in the coordinates,
/// each reported as a warning "det M = 0 where ... = 0". Up to 5 coordinates (symbolic determinant).
void warn_singular_configurations(const Model& model, Equations& eq) {
    const std::size_t n = model.dof();
    if (n == 0 || n > 5) return;
    // A symbolic determinant of a dense 4×4 or 5×5 with trigonometric entries, expanded and factored,
    // takes seconds (12 s for the 4-link pendulum): beyond 3 coordinates only mostly-diagonal M.
    std::size_t nonzero = 0;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) nonzero += eq.M(unsigned(i), unsigned(j)).is_zero() ? 0 : 1;
    if (n > 3 && nonzero > n + 4) return;
    // Only factors in the coordinates are reported, so parameters that enter M polynomially are set to
    // distinct generic values first: with them symbolic, det M of T = ½(p₁+…+p₄₉)²(…) expands to 10⁵ terms
    // and factor() ran for minutes. Parameters inside sin/cos stay symbols, to be named in the warning.
    GiNaC::exmap generic;
    {
        std::function<bool(const GiNaC::ex&, const GiNaC::symbol&, bool)> in_function =
            [&](const GiNaC::ex& e, const GiNaC::symbol& p, bool inside) {
                if (GiNaC::is_a<GiNaC::symbol>(e)) return inside && e.is_equal(p);
                const bool f = inside || GiNaC::is_exactly_a<GiNaC::function>(e);
                for (std::size_t i = 0; i < e.nops(); ++i)
                    if (in_function(e.op(i), p, f)) return true;
                return false;
            };
        long prime = 1;
        for (const Parameter& p : model.parameters) {
            bool trig = false;
            for (std::size_t i = 0; i < n && !trig; ++i)
                for (std::size_t j = 0; j < n && !trig; ++j) trig = in_function(eq.M(unsigned(i), unsigned(j)), p.symbol, false);
            if (trig) continue;
            const auto is_prime = [](long k) {
                for (long d = 2; d * d <= k; ++d)
                    if (k % d == 0) return false;
                return true;
            };
            do ++prime; while (!is_prime(prime));
            generic[p.symbol] = GiNaC::numeric(prime, 97);
        }
    }
    // No trigonometric simplifier: of det, det with cos² → 1 − sin² and with sin² → 1 − cos², the shortest.
    GiNaC::ex shortest = GiNaC::ex_to<GiNaC::matrix>(eq.M.subs(generic)).determinant().expand();
    // A budget: factoring a polynomial of this many terms would take longer than the rest of generate.
    constexpr std::size_t kMaxDetTerms = 4000;
    if (GiNaC::is_a<GiNaC::add>(shortest) && shortest.nops() > kMaxDetTerms) {
        eq.warnings.push_back("det M not examined for singular configurations: too large to factor (" +
                              std::to_string(shortest.nops()) + " terms)");
        return;
    }
    const GiNaC::ex x = GiNaC::wild(0);
    for (const GiNaC::ex& rule : {GiNaC::pow(GiNaC::cos(x), 2) == 1 - GiNaC::pow(GiNaC::sin(x), 2),
                                  GiNaC::pow(GiNaC::sin(x), 2) == 1 - GiNaC::pow(GiNaC::cos(x), 2)}) {
        const GiNaC::ex candidate = shortest.subs(rule, GiNaC::subs_options::algebraic).expand();
        auto terms = [](const GiNaC::ex& e) { return GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1; };
        if (terms(candidate) < terms(shortest)) shortest = candidate;
    }
    // factor() works on polynomials: stand-in symbols for sin(...), cos(...) while factoring.
    GiNaC::exmap to_symbols, back;
    std::function<void(const GiNaC::ex&)> collect = [&](const GiNaC::ex& e) {
        if (GiNaC::is_exactly_a<GiNaC::function>(e)) {
            if (!to_symbols.count(e)) {
                const GiNaC::symbol s;
                to_symbols[e] = s;
                back[s] = e;
            }
            return;
        }
        for (std::size_t i = 0; i < e.nops(); ++i) collect(e.op(i));
    };
    collect(shortest);
    const GiNaC::ex det = GiNaC::factor(shortest.subs(to_symbols)).subs(back);
    std::vector<GiNaC::ex> factors;
    if (GiNaC::is_a<GiNaC::mul>(det))
        for (std::size_t i = 0; i < det.nops(); ++i) factors.push_back(det.op(i));
    else
        factors.push_back(det);
    for (GiNaC::ex f : factors) {
        if (GiNaC::is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::posint)) f = f.op(0);
        if (f.has(model.t)) continue;
        bool in_q = false, velocities = false;
        for (const Coordinate& c : model.coordinates) {
            in_q = in_q || f.has(c.q);
            velocities = velocities || f.has(c.qd);
        }
        if (!in_q || velocities) continue;
        bool coordinate = false;
        for (const Coordinate& c : model.coordinates) coordinate = coordinate || f.is_equal(c.q);
        const bool trig = GiNaC::is_exactly_a<GiNaC::function>(f) &&
                          (GiNaC::ex_to<GiNaC::function>(f).get_name() == "sin" ||
                           GiNaC::ex_to<GiNaC::function>(f).get_name() == "cos");
        if (!coordinate && !trig) continue;
        std::ostringstream os;
        os << "det M = 0 where " << f << " = 0: the coordinates are singular there (M cannot be inverted)";
        eq.warnings.push_back(os.str());
    }
}

}  // namespace

Equations derive_equations(const Model& model) {
    const std::size_t n = model.dof();
    install_chain_rule();
    Equations eq;
    eq.T = model.T.expr;
    eq.V = model.V.expr;
    eq.bodies = body_energies(model);
    for (const BodyEnergy& b : eq.bodies) {
        eq.T += b.T;
        eq.V += b.V;
    }
    eq.springs = spring_energies(model);
    for (const SpringEnergy& s : eq.springs) eq.V += s.V;
    const std::vector<GiNaC::ex> body_forces = body_generalized_forces(model);
    eq.L = eq.T - eq.V;

    // Which of q, q̇, t each node holds, once: every derivative below skips the parts without its variable.
    std::vector<GiNaC::ex> variables{model.t};
    for (const Coordinate& c : model.coordinates) {
        variables.push_back(c.q);
        variables.push_back(c.qd);
    }
    SymbolSupport support(variables);

    eq.momenta.resize(n);
    eq.dLdq.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        eq.momenta[i] = Differentiator(model.coordinates[i].qd, &support)(eq.L);
        eq.dLdq[i] = Differentiator(model.coordinates[i].q, &support)(eq.L);
    }

    // M = ∂p/∂q̇; for T quadratic in q̇ it is free of q̇, which is checked before anything else relies on it.
    // One Differentiator per variable, over all p_i: they share their subexpressions.
    eq.M = GiNaC::matrix(n, n);
    for (std::size_t j = 0; j < n; ++j) {
        Differentiator d_dqdj(model.coordinates[j].qd, &support);
        for (std::size_t i = 0; i <= j; ++i) {
            const GiNaC::ex mij = d_dqdj(eq.momenta[i]);
            eq.M(i, j) = mij;
            eq.M(j, i) = mij;
        }
    }
    check_quadratic_in_velocities(model, eq.M);
    // (∂p_i/∂q) q̇ = Σ_j q̇_j ∂p_i/∂q_j, one directional derivative (n derivatives of each p_i multiplied back
    // were a tenth of generating the 30-link pendulum), and ∂p_i/∂t, for f below.
    std::vector<GiNaC::ex> dp_dq_qd(n), dp_dt(n);
    {
        GiNaC::exmap along_velocity;
        for (const Coordinate& c : model.coordinates) along_velocity[c.q] = c.qd;
        Differentiator d_along(along_velocity, &support);
        for (std::size_t i = 0; i < n; ++i) dp_dq_qd[i] = d_along(eq.momenta[i]);
    }
    {
        Differentiator d_dt(model.t, &support);
        for (std::size_t i = 0; i < n; ++i) dp_dt[i] = d_dt(eq.momenta[i]);
    }

    // f = ∂L/∂q − (∂p/∂q) q̇ − ∂p/∂t + Q − ∂R/∂q̇: everything of d/dt p − ∂L/∂q − Q + ∂R/∂q̇ but the
    // q̈ terms, moved to the right.
    eq.f.resize(n);
    eq.euler_lagrange.resize(n);
    eq.generalized_forces.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Coordinate& ci = model.coordinates[i];
        const GiNaC::ex Qi = (i < model.forces.size() ? model.forces[i].expr : GiNaC::ex(0)) -
                             GiNaC::diff(model.R.expr, ci.qd) + body_forces[i];
        eq.generalized_forces[i] = Qi;
        const GiNaC::ex fi = eq.dLdq[i] - dp_dt[i] + Qi - dp_dq_qd[i];
        eq.f[i] = fi;
        // d/dt p_i − ∂L/∂q_i = Σ_j M_ij q̈_j − (f_i − Q_i): the same expression, without differentiating again.
        GiNaC::ex el = Qi - fi;
        for (std::size_t j = 0; j < n; ++j)
            el += eq.M(static_cast<unsigned>(i), static_cast<unsigned>(j)) * model.coordinates[j].qdd;
        eq.euler_lagrange[i] = el;
    }
    eq.constraints = derive_constraints(model);
    eq.frobenius = analyse_integrability(model, eq.constraints);

    // A coordinate nothing depends on has the equation 0 = 0 (and a singular M): named, at its place.
    for (std::size_t i = 0; i < n; ++i) {
        const Coordinate& c = model.coordinates[i];
        auto involves = [&](const GiNaC::ex& e) { return e.has(c.q) || e.has(c.qd); };
        if (involves(eq.L) ||
            std::any_of(eq.generalized_forces.begin(), eq.generalized_forces.end(), involves) ||
            std::any_of(model.constraints.begin(), model.constraints.end(),
                        [&](const Constraint& k) { return involves(k.expr.expr); }))
            continue;
        throw ModelError(c.where, "coordinate '" + c.name + "' appears nowhere: not in T, V, the forces or the "
                                  "constraints, so its equation of motion is 0 = 0 (remove it, or write the "
                                  "energy it carries)");
    }

    // M must be invertible somewhere; positive definite wherever T is a proper kinetic energy.
    bool singular_everywhere = true;
    Eigen::MatrixXd last;
    for (unsigned seed = 11; seed <= 13; ++seed) {
        last = evaluate(eq.M, random_point(model, seed));
        Eigen::FullPivLU<Eigen::MatrixXd> lu(last);
        lu.setThreshold(1e-10);
        if (lu.rank() == static_cast<Eigen::Index>(n)) {
            singular_everywhere = false;
            // A kinetic energy is positive for every motion: a negative eigenvalue means some velocity
            // gives T < 0, a sign slip in T, and every trajectory of it would be wrong.
            Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(last);
            if (es.eigenvalues().minCoeff() <= 0) {
                const Eigen::VectorXd v = es.eigenvectors().col(0);
                std::ostringstream os;
                os << "T is not positive for every velocity: at a sample point (parameters and coordinates "
                      "between 0.5 and 1.5) the mass matrix ∂²T/∂q̇² has the eigenvalue "
                   << es.eigenvalues()(0) << ", so T < 0 for q̇ along (";
                for (std::size_t i = 0; i < n; ++i)
                    os << (i ? ", " : "") << model.coordinates[i].name << "' = " << v(Eigen::Index(i));
                os << "): check the signs in T";
                throw ModelError(kinetic_energy_place(model), os.str());
            }
        }
    }
    if (n > 0 && singular_everywhere) {
        Eigen::FullPivLU<Eigen::MatrixXd> lu(last);
        lu.setThreshold(1e-10);
        const Eigen::MatrixXd kernel = lu.kernel();
        std::ostringstream os;
        os << "the mass matrix ∂²T/∂q̇² is singular for every q (rank " << lu.rank() << " of " << n << "): ";
        // Name the velocity combination T cannot see, e.g. "y'" or "x' - y'".
        Eigen::VectorXd k = kernel.col(0) / kernel.col(0).cwiseAbs().maxCoeff();
        if (k.sum() < 0) k = -k;
        std::string combination;
        int terms = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const double c = k(Eigen::Index(i));
            if (std::abs(c) < 1e-9) continue;
            std::ostringstream term;
            if (std::abs(std::abs(c) - 1) > 1e-9) term << std::abs(c) << "*";
            term << model.coordinates[i].name << "'";
            combination += (terms == 0 ? (c < 0 ? "-" : "") : (c < 0 ? " - " : " + ")) + term.str();
            ++terms;
        }
        os << (terms == 1 ? "T does not involve " : "T does not involve the combination ") << combination;
        throw ModelError(kinetic_energy_place(model), os.str());
    }

    warn_singular_configurations(model, eq);

    // h = Σ q̇ ∂L/∂q̇ − L is conserved when L has no explicit t (no non-conservative forces here). With T
    // homogeneous quadratic in q̇ and V free of q̇ it is T + V (Euler's theorem), as a person writes it: T's
    // terms as the model wrote them. Otherwise expanded, so that the T₁ terms cancel and h reads T₂ − T₀ + V.
    // (Expanding T + V of the 60-link pendulum, O(n³) terms, was a sixth of generating its header.)
    // T is quadratic + linear + zero order in q̇ (checked above): T₀ = T(q̇ = 0), and T₁ = 0 when every
    // ∂T/∂q̇_i = p_i vanishes at q̇ = 0.
    {
        GiNaC::exmap at_rest;
        for (const Coordinate& c : model.coordinates) at_rest[c.qd] = 0;
        eq.natural = eq.T.subs(at_rest, GiNaC::subs_options::no_pattern).expand().is_zero();
        for (const Coordinate& c : model.coordinates) eq.natural = eq.natural && !eq.V.has(c.qd);
        for (std::size_t i = 0; i < n && eq.natural; ++i)
            eq.natural = eq.momenta[i].subs(at_rest, GiNaC::subs_options::no_pattern).expand().is_zero();
    }
    if (eq.natural) {
        eq.energy = eq.T + eq.V;
    } else {
        eq.energy = -eq.L;
        for (std::size_t i = 0; i < n; ++i) eq.energy += model.coordinates[i].qd * eq.momenta[i];
        eq.energy = eq.energy.expand();
    }
    eq.explicit_time = depends_on_time(eq.L, model);  // after sin² + cos² = 1 (mechanics/time_dependence.hpp)
    // dh/dt = −∂L/∂t + q̇·(Q − ∂R/∂q̇) − λ·b (constraint forces do work only through b = ∂g/∂t).
    const bool forced = std::any_of(eq.generalized_forces.begin(), eq.generalized_forces.end(),
                                    [&](const GiNaC::ex& q) { return !is_zero(q, model); });
    const bool moving_constraints = std::any_of(eq.constraints.begin(), eq.constraints.end(),
                                                [&](const ConstraintEquations& c) { return moves_with_time(c, model); });
    if (!eq.explicit_time && !forced && !moving_constraints)
        eq.conserved.push_back({"h", "h",
                                eq.constraints.empty() ? "L does not depend on t explicitly"
                                                       : "L and the constraints do not depend on t, no forces",
                                eq.energy});

    eq.cyclic.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        eq.cyclic[i] = is_zero(eq.dLdq[i], model);
        // p_i is conserved when nothing else acts along q_i: no force, no constraint involving q̇_i.
        const bool free_direction =
            is_zero(eq.generalized_forces[i], model) &&
            std::none_of(eq.constraints.begin(), eq.constraints.end(),
                         [&](const auto& c) { return !is_zero(c.jacobian[i], model); });
        if (eq.cyclic[i] && free_direction) {
            const Coordinate& c = model.coordinates[i];
            eq.conserved.push_back({"p_" + c.name, "p_{" + c.latex + "}", c.name + " is cyclic (∂L/∂" + c.name + " = 0)",
                                    eq.momenta[i]});
        }
    }
    // Symmetries beyond cyclic coordinates: rotations and translations of the configuration (mechanics/noether.hpp).
    for (ConservedQuantity& c : noether_symmetries(model, eq)) eq.conserved.push_back(std::move(c));
    verify_results(model, eq);  // [[results]] with `equals` (mechanics/results.hpp)
    return eq;
}

}  // namespace eomgen
