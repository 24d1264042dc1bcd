/** @file constraints.cpp  Constraints at position, velocity and acceleration level; Frobenius on Pfaffian forms. */
#include "mechanics/constraints.hpp"

#include "mechanics/pole_free_subs.hpp"
#include "mechanics/time_dependence.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <map>
#include <sstream>

namespace eomgen {
namespace {

/// e's value at `at`; NaN where it is not a real number, or where GiNaC meets a pole (1/0 in floating point: a
/// wheel lying flat at the initial state, found by the structural fuzzer) — the callers treat NaN as singular.
double number(const GiNaC::ex& e, const GiNaC::exmap& at) {
    // The poles are looked for before substituting: GiNaC leaks the product it was building when it throws.
    const std::optional<GiNaC::ex> substituted = subs_unless_pole(e, at);
    if (!substituted) return std::nan("");
    GiNaC::ex v;
    try {
        v = GiNaC::evalf(*substituted);
    } catch (const std::exception&) {
        return std::nan("");
    }
    if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) return std::nan("");
    return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

/// A differential form with numeric coefficients: sorted index list → coefficient.
using Form = std::map<std::vector<int>, double>;

Form wedge(const Form& a, const Form& b) {
    Form out;
    for (const auto& [I, x] : a)
        for (const auto& [J, y] : b) {
            std::vector<int> K = I;
            K.insert(K.end(), J.begin(), J.end());
            // Sign of the permutation that sorts K (0 when an index repeats).
            int sign = 1;
            for (std::size_t i = 0; i < K.size(); ++i)
                for (std::size_t j = i + 1; j < K.size(); ++j) {
                    if (K[i] == K[j]) sign = 0;
                    if (K[i] > K[j]) sign = -sign;
                }
            if (sign == 0) continue;
            std::sort(K.begin(), K.end());
            out[K] += sign * x * y;
        }
    return out;
}

double magnitude(const Form& f) {
    double m = 0;
    for (const auto& [I, x] : f) m = std::max(m, std::abs(x));
    return m;
}

/// The one-form ω = Σ a_i dz_i on z = (q, t) and its exterior derivative, at one point.
struct PointForms {
    Form omega, d_omega;
};

/// As many independent constraints as coordinates, none of them moving with t, leave no motion: every q is
/// held still and nothing is derived. (Moving ones prescribe the motion, and their multipliers are the forces
/// the drive must supply: the dumbbell of Goldstein's Exercise 5-18 turned about a tilted axis.)
void check_freedom_left(const Model& model, const std::vector<ConstraintEquations>& out) {
    const std::size_t n = model.dof();
    if (out.size() < n) return;  // redundant rows were refused before: out.size() is the rank
    if (std::any_of(out.begin(), out.end(), [&](const ConstraintEquations& c) { return moves_with_time(c, model); }))
        return;
    std::string names, coordinates;
    for (const ConstraintEquations& c : out) names += (names.empty() ? "" : ", ") + c.name;
    for (const Coordinate& c : model.coordinates) coordinates += (coordinates.empty() ? "" : ", ") + c.name;
    const std::string what = n == 1 ? "the constraint " + names + " on the only coordinate (" + coordinates + ") leaves"
                                    : std::to_string(n) + " independent constraints (" + names + ") on " +
                                          std::to_string(n) + " coordinates (" + coordinates + ") leave";
    throw ModelError(model.constraints.back().where,
                     what + " no motion: every coordinate is fixed, and there is nothing to integrate (remove a "
                            "constraint, or add a coordinate)");
}

/// Constraints that are independent at generic q can be dependent at the model's initial state (two surfaces
/// that touch there): the multipliers are not determined, and a run cannot start.
void check_initial_rank(const Model& model, const std::vector<ConstraintEquations>& out) {
    GiNaC::exmap at;
    std::ostringstream state;
    for (const Coordinate& c : model.coordinates) {
        at[c.q] = GiNaC::numeric(c.initial);
        at[c.qd] = GiNaC::numeric(c.rate);
        state << (state.tellp() > 0 ? ", " : "") << c.name << " = " << c.initial;
    }
    for (const Parameter& p : model.parameters) at[p.symbol] = GiNaC::numeric(p.value);
    at[model.t] = 0;
    const auto n = static_cast<Eigen::Index>(model.dof());
    Eigen::MatrixXd A(static_cast<Eigen::Index>(out.size()), n);
    for (std::size_t k = 0; k < out.size(); ++k)
        for (Eigen::Index i = 0; i < n; ++i) A(Eigen::Index(k), i) = number(out[k].jacobian[std::size_t(i)], at);
    if (!A.allFinite()) return;  // a singular configuration: derive_equations warns of those
    const double scale = std::max(1.0, A.cwiseAbs().maxCoeff());
    for (Eigen::Index k = 0; k < A.rows(); ++k) {
        Eigen::JacobiSVD<Eigen::MatrixXd> svd(A.topRows(k + 1));
        const Eigen::VectorXd s = svd.singularValues();
        if (s(s.size() - 1) > 1e-10 * scale) continue;
        const std::string& name = out[std::size_t(k)].name;
        throw ModelError(model.constraints[std::size_t(k)].where,
                         k == 0 ? "constraint '" + name + "' has a zero gradient at the initial state (" + state.str() +
                                      "): its multiplier is not determined there, and a run cannot start; give "
                                      "initial values where it is regular"
                                : "constraint '" + name + "' is dependent on the constraints before it at the initial "
                                  "state (" + state.str() + "): their gradients are not independent there, so the "
                                  "multipliers are not determined and a run cannot start; give initial values where "
                                  "they are independent");
    }
}

}  // namespace

bool moves_with_time(const ConstraintEquations& c, const Model& model) {
    return !is_zero(c.bias, model) ||
           std::any_of(c.jacobian.begin(), c.jacobian.end(), [&](const GiNaC::ex& a) { return depends_on_time(a, model); });
}

std::vector<ConstraintEquations> derive_constraints(const Model& model) {
    const std::size_t n = model.dof();
    std::vector<ConstraintEquations> out;
    for (const Constraint& c : model.constraints) {
        ConstraintEquations ce;
        ce.name = c.name;
        ce.kind = c.kind;
        if (c.kind == ConstraintKind::Holonomic) {
            ce.position = c.expr.expr;
            ce.velocity = time_derivative(c.expr.expr, model);
        } else {
            ce.position = 0;
            ce.velocity = c.expr.expr;
            for (const Coordinate& i : model.coordinates)
                for (const Coordinate& j : model.coordinates)
                    if (!GiNaC::diff(GiNaC::diff(c.expr.expr, i.qd), j.qd).expand().is_zero())
                        throw ModelError(c.expr.where,
                                         "constraint '" + c.name +
                                             "' is declared nonholonomic but is not linear in the velocities (" +
                                             (i.name == j.name ? "it is not linear in " + i.name + "'"
                                                               : "it has a product of " + i.name + "' and " + j.name + "'") +
                                             "); a Pfaffian constraint is a(q,t)·q' + b(q,t) = 0");
        }
        ce.jacobian.resize(n);
        GiNaC::exmap no_velocity;
        for (std::size_t i = 0; i < n; ++i) {
            ce.jacobian[i] = GiNaC::diff(ce.velocity, model.coordinates[i].qd);
            no_velocity[model.coordinates[i].qd] = 0;
        }
        ce.bias = ce.velocity.subs(no_velocity);
        if (std::all_of(ce.jacobian.begin(), ce.jacobian.end(), [&](const GiNaC::ex& a) { return is_zero(a, model); }))
            throw ModelError(c.expr.where, "constraint '" + c.name + "' " +
                                               (c.kind == ConstraintKind::Holonomic
                                                    ? "does not depend on the coordinates"
                                                    : "involves no velocity") +
                                               ": it constrains nothing, or nothing that can move");
        GiNaC::exmap no_acceleration;
        for (const Coordinate& q : model.coordinates) no_acceleration[q.qdd] = 0;
        ce.gamma = -time_derivative(ce.velocity, model).subs(no_acceleration);
        out.push_back(std::move(ce));
    }

    // Redundant constraints: a row of A in the span of the rows before it, at every sampled point.
    if (!out.empty()) {
        std::vector<int> dependent_at(out.size(), 0);
        for (unsigned seed = 21; seed <= 23; ++seed) {
            const GiNaC::exmap at = random_point(model, seed);
            Eigen::MatrixXd A(static_cast<Eigen::Index>(out.size()), static_cast<Eigen::Index>(n));
            for (std::size_t k = 0; k < out.size(); ++k)
                for (std::size_t i = 0; i < n; ++i)
                    A(Eigen::Index(k), Eigen::Index(i)) = number(out[k].jacobian[i], at);
            Eigen::Index rank = 0;
            for (Eigen::Index k = 0; k < A.rows(); ++k) {
                Eigen::FullPivLU<Eigen::MatrixXd> lu(A.topRows(k + 1));
                lu.setThreshold(1e-10);
                if (lu.rank() == rank) ++dependent_at[std::size_t(k)];
                rank = lu.rank();
            }
        }
        for (std::size_t k = 0; k < out.size(); ++k)
            if (dependent_at[k] == 3)
                throw ModelError(model.constraints[k].where,
                                 "constraint '" + out[k].name + "' is redundant: its Jacobian row is a combination of "
                                 "the constraints before it at every q, so its multiplier is not determined");
        check_freedom_left(model, out);
        check_initial_rank(model, out);
    }
    return out;
}

std::string analyse_integrability(const Model& model, std::vector<ConstraintEquations>& constraints) {
    const std::size_t n = model.dof();
    std::vector<GiNaC::symbol> z;  // extended coordinates (q, t)
    std::vector<std::string> z_name;
    for (const Coordinate& c : model.coordinates) {
        z.push_back(c.q);
        z_name.push_back(c.name);
    }
    z.push_back(model.t);
    z_name.push_back("t");

    std::vector<std::size_t> pfaffian;
    for (std::size_t k = 0; k < constraints.size(); ++k)
        if (constraints[k].kind == ConstraintKind::Nonholonomic) pfaffian.push_back(k);
    if (pfaffian.empty()) return "";

    // Symbolic coefficients a_i (with a_t = b) and their derivatives, evaluated at a few random points.
    const unsigned seeds[] = {31, 32, 33};
    std::map<std::size_t, std::vector<PointForms>> forms;
    for (std::size_t k : pfaffian) {
        ConstraintEquations& ce = constraints[k];
        std::vector<GiNaC::ex> a = ce.jacobian;
        a.push_back(ce.bias);
        std::string witness;
        for (unsigned seed : seeds) {
            const GiNaC::exmap at = random_point(model, seed);
            PointForms pf;
            for (std::size_t i = 0; i <= n; ++i) pf.omega[{int(i)}] = number(a[i], at);
            for (std::size_t i = 0; i <= n; ++i)
                for (std::size_t j = i + 1; j <= n; ++j) {
                    const GiNaC::ex curl = GiNaC::diff(a[j], z[i]) - GiNaC::diff(a[i], z[j]);
                    const double v = number(curl, at);
                    pf.d_omega[{int(i), int(j)}] = v;
                    if (std::abs(v) > 1e-9 && witness.empty()) {
                        std::ostringstream os;
                        os << "∂a_" << z_name[j] << "/∂" << z_name[i] << " = " << GiNaC::diff(a[j], z[i])
                           << " ≠ ∂a_" << z_name[i] << "/∂" << z_name[j] << " = " << GiNaC::diff(a[i], z[j]);
                        witness = os.str();
                    }
                }
            forms[k].push_back(pf);
        }
        double closed = 0, frob = 0;
        for (const PointForms& pf : forms[k]) {
            closed = std::max(closed, magnitude(pf.d_omega) / std::max(1.0, magnitude(pf.omega)));
            frob = std::max(frob, magnitude(wedge(pf.omega, pf.d_omega)) /
                                      std::max(1.0, magnitude(pf.omega) * magnitude(pf.omega)));
        }
        ce.exact = closed < 1e-9;
        ce.integrable = frob < 1e-9;
        if (ce.exact)
            ce.verdict = "exact (dω = 0): it is the time derivative of a function of q and t, a holonomic constraint "
                         "in disguise";
        else if (ce.integrable)
            ce.verdict = "not exact, but integrable with an integrating factor (ω ∧ dω = 0): holonomic in disguise; " +
                         witness;
        else
            ce.verdict = "not integrable (ω ∧ dω ≠ 0), truly nonholonomic; not exact: " + witness;
    }
    if (pfaffian.size() < 2) return "";

    // Frobenius for the set: dω_k ∧ ω_1 ∧ … ∧ ω_m = 0 for every k.
    double worst = 0;
    std::string failing;
    for (std::size_t p = 0; p < std::size(seeds); ++p) {
        Form all = forms[pfaffian[0]][p].omega;
        for (std::size_t i = 1; i < pfaffian.size(); ++i) all = wedge(all, forms[pfaffian[i]][p].omega);
        const double scale = std::max(1.0, magnitude(all));
        for (std::size_t k : pfaffian) {
            const double v = magnitude(wedge(forms[k][p].d_omega, all)) / scale;
            if (v > worst) {
                worst = v;
                failing = constraints[k].name;
            }
        }
    }
    std::string names;
    for (std::size_t k : pfaffian) names += (names.empty() ? "" : ", ") + constraints[k].name;
    if (worst < 1e-9)
        return "the nonholonomic constraints " + names +
               " together satisfy the Frobenius condition: integrable, the motion stays on a submanifold";
    return "the nonholonomic constraints " + names + " together are not integrable (Frobenius: dω_" + failing +
           " ∧ ω_1 ∧ … ∧ ω_m ≠ 0): they cannot be replaced by holonomic ones";
}

}  // namespace eomgen
