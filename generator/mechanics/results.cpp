/** @file results.cpp  Declared results: the constraints solved, the targets of `equals`, verification. */
#include "mechanics/results.hpp"

#include "mechanics/bodies.hpp"
#include "mechanics/inertia.hpp"
#include "mechanics/kinematics.hpp"
#include "mechanics/pole_free_subs.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <optional>
#include <sstream>

namespace eomgen {

namespace {

std::string text(const GiNaC::ex& e) {
    std::ostringstream os;
    os << e;
    std::string s = os.str();
    if (s.size() > 400) s = s.substr(0, 400) + " ...";
    return s;
}

std::string fmt_number(double v) {
    std::ostringstream os;
    os << std::setprecision(6) << v;
    return os.str();
}

/// Coordinates in the order they should be solved for: those `keep` does not use first, later ones first.
std::vector<std::size_t> solve_order(const Model& model, const GiNaC::ex& keep, bool velocities) {
    std::vector<std::size_t> out;
    for (int pass = 0; pass < 2; ++pass)
        for (std::size_t k = model.dof(); k-- > 0;) {
            const Coordinate& c = model.coordinates[k];
            const bool used = velocities ? keep.has(c.qd) : keep.has(c.q);
            if (used == (pass == 1)) out.push_back(k);
        }
    return out;
}

/// e = 0 at random points of every symbol of the model (relative to the size of e's terms as written);
/// GiNaC's expand() and normal() of a residual with products of sines and cosines take seconds, and cannot
/// see sin² + cos² = 1 anyway. Falls back on is_zero when e does not evaluate to numbers.
bool vanishes(const GiNaC::ex& e, const Model& model) {
    try {
        for (unsigned seed = 1; seed <= 4; ++seed) {
            const GiNaC::exmap at = random_point(model, seed);
            const GiNaC::ex v = GiNaC::evalf(e.subs(at));
            if (!GiNaC::is_a<GiNaC::numeric>(v)) return is_zero(e, model);
            double scale = 1e-300;
            if (GiNaC::is_a<GiNaC::add>(e))
                for (const GiNaC::ex& term : e) {
                    const GiNaC::ex tv = GiNaC::evalf(term.subs(at));
                    if (GiNaC::is_a<GiNaC::numeric>(tv)) scale = std::max(scale, std::abs(GiNaC::ex_to<GiNaC::numeric>(tv).to_double()));
                }
            else
                scale = 1.0;
            if (!(std::abs(GiNaC::ex_to<GiNaC::numeric>(v).to_double()) <= 1e-10 * scale)) return false;
        }
        return true;
    } catch (...) {
        return is_zero(e, model);
    }
}

unsigned component(char c) {
    return c == 'x' ? 0u : (c == 'y' ? 1u : 2u);
}

}  // namespace

ConstraintReduction reduce_on_constraints(const Model& model, const Equations& eq, const GiNaC::ex& keep) {
    ConstraintReduction r;
    std::vector<bool> solved_q(model.dof(), false), solved_v(model.dof(), false);
    std::vector<GiNaC::ex> velocity_level;
    for (const ConstraintEquations& c : eq.constraints) {
        bool done = false;
        if (c.kind == ConstraintKind::Holonomic) {
            const GiNaC::ex g = c.position.subs(r.coordinates).expand();
            for (std::size_t j : solve_order(model, keep, false)) {
                const Coordinate& q = model.coordinates[j];
                if (solved_q[j] || g.degree(q.q) != 1 || g.ldegree(q.q) < 0) continue;
                const GiNaC::ex a = g.coeff(q.q, 1);
                if (a.has(q.q) || is_zero(a, model)) continue;
                const GiNaC::ex s = GiNaC::normal(q.q - g / a);
                if (s.has(q.q)) continue;
                const GiNaC::ex sd = time_derivative(s, model), sdd = time_derivative(sd, model);
                GiNaC::exmap one{{q.q, s}, {q.qd, sd}, {q.qdd, sdd}};
                for (auto& [k, v] : r.coordinates) v = v.subs(one);
                r.coordinates.insert(one.begin(), one.end());
                solved_q[j] = solved_v[j] = true;
                r.solved.push_back(q.name + " = " + text(s));
                done = true;
                break;
            }
        }
        if (!done) velocity_level.push_back(c.velocity);
    }
    for (const GiNaC::ex& c0 : velocity_level) {
        const GiNaC::ex c = c0.subs(r.coordinates).subs(r.velocities).expand();
        for (std::size_t j : solve_order(model, keep, true)) {
            const Coordinate& q = model.coordinates[j];
            if (solved_v[j]) continue;
            const GiNaC::ex a = c.coeff(q.qd, 1);
            if (c.degree(q.qd) != 1 || a.has(q.qd) || is_zero(a, model)) continue;
            const GiNaC::ex s = GiNaC::normal(q.qd - c / a);
            GiNaC::exmap one{{q.qd, s}};
            for (auto& [k, v] : r.velocities) v = v.subs(one);
            r.velocities.insert(one.begin(), one.end());
            solved_v[j] = true;
            r.solved.push_back(q.name + "' = " + text(s));
            break;
        }
    }
    return r;
}

std::string result_target_name(const Result& result) {
    const std::string& t = result.equals;
    if (t == "T" || t == "V" || t == "L") return "eomgen's " + t;
    if (t == "energy") return "eomgen's energy function h";
    if (t.rfind("p_", 0) == 0) return "eomgen's momentum " + t;
    const std::size_t dot = t.find('.');
    const std::string head = t.substr(0, dot), rest = t.substr(dot + 1);
    if (head == "omega") return "the component " + rest + " of the body's angular velocity (body axes)";
    if (head == "omega_space") return "the component " + rest + " of the body's angular velocity (space axes)";
    if (head == "principal") return "a principal moment of body '" + rest + "' (about its centre of mass)";
    if (head == "principal_origin") return "a principal moment of body '" + rest + "' about the origin";
    return "the component " + t + " of the inertia tensor" +
           (head == "inertia" ? std::string(" (about the centre of mass)") : " (about the origin)");
}

namespace {

/// Each body's inertia tensor about its centre of mass and about the origin, formed once for all the results
/// that name it: the one about the origin goes through the rotation of the centre (trigonometric entries),
/// and forming it for each of eleven results was most of `generate`'s time on the triangle plate.
class BodyTensors {
public:
    const GiNaC::matrix& of(const Body& b, bool about_origin) {
        const auto key = std::make_pair(b.name, about_origin);
        auto it = done_.find(key);
        if (it != done_.end()) return it->second;
        GiNaC::matrix I = body_inertia(b);
        if (about_origin) {
            const GiNaC::matrix r{{b.centre[0]}, {b.centre[1]}, {b.centre[2]}};
            I = parallel_axis(I, b.mass, body_rotation(b).mul(r));
        }
        return done_.emplace(key, I).first->second;
    }

private:
    std::map<std::pair<std::string, bool>, GiNaC::matrix> done_;
};

/// The tensor a principal.<body> or principal_origin.<body> result is an eigenvalue of, minus expr·1.
GiNaC::matrix shifted_tensor(const Model& model, const Result& result, BodyTensors& tensors);

GiNaC::ex residual_of(const Model& model, const Equations& eq, const Result& result, BodyTensors& tensors);

}  // namespace

GiNaC::ex result_residual(const Model& model, const Equations& eq, const Result& result) {
    BodyTensors tensors;
    return residual_of(model, eq, result, tensors);
}

namespace {

GiNaC::ex residual_of(const Model& model, const Equations& eq, const Result& result, BodyTensors& tensors) {
    const std::string& t = result.equals;
    const GiNaC::ex& x = result.expr.expr;
    if (t == "T") return x - eq.T;
    if (t == "V") return x - eq.V;
    if (t == "L") return x - eq.L;
    if (t == "energy") return x - eq.energy;
    if (t.rfind("p_", 0) == 0)
        for (std::size_t i = 0; i < model.dof(); ++i)
            if (model.coordinates[i].name == t.substr(2)) return x - eq.momenta[i];
    const std::size_t dot = t.find('.');
    if (dot != std::string::npos) {
        const std::string head = t.substr(0, dot), rest = t.substr(dot + 1);
        const bool omega = head == "omega" || head == "omega_space";
        const bool component_form = head == "inertia" || head == "inertia_origin" || omega;
        const std::string body_name = component_form ? rest.substr(0, rest.find('.')) : rest;
        for (const Body& b : model.bodies) {
            if (b.name != body_name) continue;
            if (omega) {
                const GiNaC::matrix w = head == "omega" ? body_angular_velocity(b, model)
                                                        : space_angular_velocity(b, model);
                return x - w(component(rest.substr(rest.find('.') + 1)[0]), 0);
            }
            if (component_form) {
                const GiNaC::matrix& I = tensors.of(b, head == "inertia_origin");
                const std::string ij = rest.substr(rest.find('.') + 1);
                return x - I(component(ij[0]), component(ij[1]));
            }
            return shifted_tensor(model, result, tensors).determinant(GiNaC::determinant_algo::laplace);
        }
    }
    throw ModelError(result.equals_where, "'equals = \"" + t + "\"' names nothing eomgen derives");
}

GiNaC::matrix shifted_tensor(const Model& model, const Result& result, BodyTensors& tensors) {
    const std::string& t = result.equals;
    const std::string head = t.substr(0, t.find('.')), name = t.substr(t.find('.') + 1);
    for (const Body& b : model.bodies) {
        if (b.name != name) continue;
        GiNaC::matrix I = tensors.of(b, head == "principal_origin");
        for (unsigned i = 0; i < 3; ++i) I(i, i) -= result.expr.expr;
        return I;
    }
    throw ModelError(result.equals_where, "'equals = \"" + t + "\"': no such body");
}

/// e at `at` as a real double; nothing where it is not one there (a pole, a complex value, a symbol left).
std::optional<double> real_at(const GiNaC::ex& e, const GiNaC::exmap& at) {
    const std::optional<GiNaC::ex> x = subs_unless_pole(e, at);
    if (!x) return std::nullopt;
    const GiNaC::ex n = GiNaC::evalf(*x);
    if (!GiNaC::is_a<GiNaC::numeric>(n) || !GiNaC::ex_to<GiNaC::numeric>(n).is_real()) return std::nullopt;
    return GiNaC::ex_to<GiNaC::numeric>(n).to_double();
}

/// A 3×3 tensor at `at` in doubles; nothing where an entry is not a real number there.
std::optional<Eigen::Matrix3d> numbers_of(const GiNaC::matrix& m, const GiNaC::exmap& at) {
    Eigen::Matrix3d v;
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j) {
            const std::optional<double> x = real_at(m(i, j), at);
            if (!x) return std::nullopt;
            v(int(i), int(j)) = *x;
        }
    return v;
}

/// det(I − λ1) = 0 at random points, the determinant taken of the numbers (the symbolic one of a tensor moved
/// by rotations is large), relative to the size of the tensor.
std::optional<bool> singular_at_points(const GiNaC::matrix& m, const Model& model) {
    for (unsigned seed = 1; seed <= 4; ++seed) {
        const std::optional<Eigen::Matrix3d> v = numbers_of(m, random_point(model, seed));
        if (!v) return std::nullopt;
        const double size = std::max(1e-300, v->cwiseAbs().maxCoeff());
        if (!(std::abs(v->determinant()) <= 1e-10 * size * size * size)) return false;
    }
    return true;
}

/// The principal moments the result could have been: the eigenvalues of the tensor `equals` names, with the
/// parameters' values and the coordinates' initial values, and the result's own value there. For the message of
/// a wrong principal moment, instead of det(I − expr·1) expanded (trigonometric entries: 0.5 s, and 400
/// characters of polynomial). Empty where the tensor does not evaluate to numbers.
std::string principal_moments_text(const Model& model, const Result& result, BodyTensors& tensors) {
    const std::string& t = result.equals;
    const std::string head = t.substr(0, t.find('.')), name = t.substr(t.find('.') + 1);
    GiNaC::exmap at;
    std::string where;
    for (const Parameter& p : model.parameters) {
        at[p.symbol] = GiNaC::numeric(p.value);
        where += (where.empty() ? "" : ", ") + p.name + " = " + fmt_number(p.value);
    }
    for (const Coordinate& c : model.coordinates) at[c.q] = GiNaC::numeric(c.initial);
    for (const Body& b : model.bodies) {
        if (b.name != name) continue;
        const std::optional<Eigen::Matrix3d> v = numbers_of(tensors.of(b, head == "principal_origin"), at);
        const std::optional<double> x = real_at(result.expr.expr, at);
        if (!v || !x) return "";
        const Eigen::Vector3d moments =
            Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(*v, Eigen::EigenvaluesOnly).eigenvalues();
        bool matches = false;  // right at these values only (M a/24 for M a²/12 at a = 0.5): say so
        for (int k = 0; k < 3; ++k) matches = matches || std::abs(*x - moments(k)) <= 1e-9 * moments.cwiseAbs().maxCoeff();
        return "with " + (where.empty() ? std::string("no parameters") : where) + " the principal moments are " +
               fmt_number(moments(0)) + ", " + fmt_number(moments(1)) + " and " + fmt_number(moments(2)) + ", and " +
               result.expr.text + " = " + fmt_number(*x) +
               (matches ? " (one of them at these values, but not for other values of the parameters)" : "");
    }
    return "";
}

}  // namespace

void verify_results(const Model& model, const Equations& eq) {
    BodyTensors tensors;
    for (const Result& r : model.results) {
        if (r.equals.empty()) continue;
        const bool principal = r.equals.rfind("principal", 0) == 0;
        if (principal && !r.on_constraints) {
            const std::optional<bool> singular = singular_at_points(shifted_tensor(model, r, tensors), model);
            if (singular && *singular) continue;
            // Not singular at a random point (to 1e-10 of |I|³ in doubles): not a principal moment. Said with
            // numbers, without expanding the determinant.
            if (singular) {
                const std::string moments = principal_moments_text(model, r, tensors);
                if (!moments.empty())
                    throw ModelError(r.expr.where, "result '" + r.name + "' = " + r.expr.text + " is not " +
                                                       result_target_name(r) + ": " + moments);
            }
        }
        GiNaC::ex residual = residual_of(model, eq, r, tensors);
        std::string how;
        if (r.on_constraints) {
            const ConstraintReduction red = reduce_on_constraints(model, eq, r.expr.expr);
            residual = red.apply(residual);
            for (std::size_t k = 0; k < red.solved.size(); ++k) how += (k ? ", " : "") + red.solved[k];
            how = " on the constraints (" + how + ")";
        }
        if (vanishes(residual, model)) continue;
        std::string message = "result '" + r.name + "' = " + r.expr.text + " is not " +
                              result_target_name(r) + how + ": ";
        message += principal ? "det(I - (" + r.expr.text + ") 1) = " + text(residual) + ", not 0"
                             : "the difference is " + text(residual);
        throw ModelError(r.expr.where, message);
    }
}

}  // namespace eomgen
