/** @file rolling_contacts.cpp  A wheel rolling without slipping on a plane, as the constraints it imposes. */
#include "model/rolling_contacts.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace eomgen {

namespace {

/// d e/dt for e in q and t (positions and angles have no velocities).
GiNaC::ex rate(const GiNaC::ex& e, const Model& model) {
    GiNaC::ex d = GiNaC::diff(e, model.t);
    for (const Coordinate& c : model.coordinates) d += GiNaC::diff(e, c.q) * c.qd;
    return d;
}

/// True where e (in q, t and the parameters) is zero at four random configurations with random parameters (each
/// within 30 % of its value, or in (0.5, 1.5) where that is 0, so that a parameter that happens to be 0 in the file
/// does not hide a constraint a --set would need): an analytic function that vanishes at random points vanishes
/// identically.
bool vanishes(const GiNaC::ex& e, const Model& model) {
    std::mt19937 random(20261127);
    std::uniform_real_distribution<double> angle(-0.6, 0.6), factor(0.7, 1.3), unit(0.5, 1.5);
    GiNaC::exmap values;
    for (int trial = 0; trial < 4; ++trial) {
        for (const Parameter& p : model.parameters) values[p.symbol] = p.value != 0 ? p.value * factor(random) : unit(random);
        for (const Coordinate& c : model.coordinates) values[c.q] = angle(random);
        values[model.t] = 0.3 + trial;
        const GiNaC::ex v = GiNaC::evalf(e.subs(values));
        if (!GiNaC::is_a<GiNaC::numeric>(v)) return false;
        const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(v);
        if (!n.is_real() || std::abs(n.to_double()) > 1e-10) return false;
    }
    return true;
}

}  // namespace

namespace {

std::vector<Constraint> contact_constraints(const Model& model, const RollingContact& contact) {
    const auto body = std::find_if(model.bodies.begin(), model.bodies.end(),
                                   [&](const Body& b) { return b.name == contact.body; });
    if (body == model.bodies.end())
        throw ModelError(contact.where, "contact '" + contact.name + "' names body '" + contact.body +
                                            "', which is not in [[bodies]]");
    const std::vector<Rotation> chain = body->rotations.empty() ? euler_chain(body->angles, body->sequence) : body->rotations;
    const GiNaC::matrix At = chain_rotation(chain).transpose();
    std::vector<GiNaC::ex> rates;
    for (const Rotation& r : chain) rates.push_back(rate(r.angle, model));
    const GiNaC::matrix omega = chain_space_angular_velocity(chain, rates);

    const GiNaC::matrix C{{body->centre[0]}, {body->centre[1]}, {body->centre[2]}};
    const GiNaC::matrix v = GiNaC::matrix{{rate(C(0, 0), model)}, {rate(C(1, 0), model)}, {rate(C(2, 0), model)}};
    const GiNaC::matrix n = axis_vector(contact.normal).mul_scalar(contact.normal_sign);
    const GiNaC::matrix a = At.mul(axis_vector(contact.axis));
    const GiNaC::ex na = dot(n, a).expand();
    const GiNaC::ex flat = (1 - GiNaC::pow(na, 2)).expand();
    if (flat.is_zero() || vanishes(flat, model))
        throw ModelError(contact.where, "contact '" + contact.name + "': the axis " + std::string(1, contact.axis) +
                                            " of body '" + contact.body + "' is along the plane's normal in every "
                                            "configuration: the wheel lies flat and no point of its rim is the lowest");
    const GiNaC::ex s = GiNaC::sqrt(flat);
    GiNaC::matrix d(3, 1);
    for (unsigned i = 0; i < 3; ++i) d(i, 0) = -(n(i, 0) - na * a(i, 0)) / s;

    std::vector<Constraint> out;
    auto add = [&](const std::string& suffix, ConstraintKind kind, const GiNaC::ex& e, const std::string& text) {
        Constraint c;
        c.name = contact.name + "_" + suffix;
        c.kind = kind;
        c.where = contact.where;
        c.expr = {e, text, contact.where};
        out.push_back(std::move(c));
    };
    // The point of contact from the centre: down the wheel's plane to the rim (the tube's centre circle), then
    // down the normal by the tube's radius (0 for a knife edge).
    GiNaC::matrix arm(3, 1);
    for (unsigned i = 0; i < 3; ++i) arm(i, 0) = contact.radius * d(i, 0) - contact.tube * n(i, 0);
    const GiNaC::ex touch = (dot(n, C) - contact.radius * s - contact.tube - contact.height).expand();
    if (!vanishes(touch, model))
        add("height", ConstraintKind::Holonomic, touch, "the rim of '" + contact.body + "' touches the plane");
    const GiNaC::matrix slip = v.add(cross(omega, arm));
    for (char axis : {'x', 'y', 'z'}) {
        if (axis == contact.normal) continue;
        add(std::string("slip_") + axis, ConstraintKind::Nonholonomic, slip(static_cast<unsigned>(axis - 'x'), 0).expand(),
            "the rim of '" + contact.body + "' does not slip along " + axis);
    }
    return out;
}

}  // namespace

std::vector<Constraint> rolling_contact_constraints(const Model& model, const RollingContact& contact) {
    try {
        return contact_constraints(model, contact);
    } catch (const ModelError&) {
        throw;
    } catch (const std::exception& e) {  // GiNaC: a pole where the geometry divides by zero identically
        throw ModelError(contact.where, "contact '" + contact.name + "': its geometry cannot be formed (" + e.what() + ")");
    }
}

}  // namespace eomgen
