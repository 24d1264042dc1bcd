/** @file bodies.cpp  Kinetic and potential energy of the rigid bodies of a body-based model. */
#include "mechanics/bodies.hpp"

#include "mechanics/inertia.hpp"
#include "mechanics/kinematics.hpp"

#include <algorithm>
#include <stdexcept>

namespace eomgen {

namespace {

std::size_t terms(const GiNaC::ex& e) {
    return GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1;
}

/// GiNaC has no trigonometric simplifier: of e, e with sin² → 1 − cos² and e with cos² → 1 − sin²
/// (expanded), keep the one with the fewest terms, so ½ m (l²/4)(sin²θ + cos²θ) θ̇² reads m l² θ̇²/8.
GiNaC::ex tidy(const GiNaC::ex& e) {
    const GiNaC::ex x = GiNaC::wild(0);
    const GiNaC::ex rules[2] = {GiNaC::pow(GiNaC::sin(x), 2) == 1 - GiNaC::pow(GiNaC::cos(x), 2),
                                GiNaC::pow(GiNaC::cos(x), 2) == 1 - GiNaC::pow(GiNaC::sin(x), 2)};
    GiNaC::ex best = e.expand();
    for (bool better = true; better;) {
        better = false;
        for (const GiNaC::ex& rule : rules) {
            const GiNaC::ex candidate = best.subs(rule, GiNaC::subs_options::algebraic).expand();
            if (terms(candidate) < terms(best)) {
                best = candidate;
                better = true;
            }
        }
    }
    return best;
}

}  // namespace

GiNaC::matrix body_inertia(const Body& body) {
    if (body.shape.empty()) return body.inertia;
    try {
        return shape_inertia(body.shape, body.mass, body.dimensions);
    } catch (const std::invalid_argument& error) {
        std::string message = std::string(error.what()) + " in body '" + body.name + "'";
        const std::vector<std::string> dims = shape_dimensions(body.shape);
        if (!dims.empty()) {
            message += " (" + body.shape + " takes dimensions = [";
            for (std::size_t i = 0; i < dims.size(); ++i) message += (i ? ", " : "") + dims[i];
            message += "])";
        } else {
            message += " (shapes:";
            for (const std::string& s : shape_names()) message += " " + s;
            message += ")";
        }
        throw ModelError(body.where, message);
    }
}

namespace {

void check_sequence(const Body& body) {
    if (body.rotations.empty() && !valid_euler_sequence(body.sequence))
        throw ModelError(body.where, "Euler sequence '" + body.sequence + "' of body '" + body.name +
                                         "' is not three of x, y, z with no axis twice in a row");
}

GiNaC::matrix column(const std::array<GiNaC::ex, 3>& v) {
    return GiNaC::matrix{{v[0]}, {v[1]}, {v[2]}};
}

GiNaC::matrix expanded(const GiNaC::matrix& m) {
    GiNaC::matrix out(m.rows(), m.cols());
    for (unsigned i = 0; i < m.rows(); ++i)
        for (unsigned j = 0; j < m.cols(); ++j) out(i, j) = m(i, j).expand();
    return out;
}

}  // namespace

std::vector<BodyEnergy> body_energies(const Model& model) {
    std::vector<BodyEnergy> out;
    for (const Body& body : model.bodies) {
        BodyEnergy e;
        e.name = body.name;
        e.inertia = body_inertia(body);
        check_sequence(body);
        const GiNaC::matrix r = column(body.centre);
        const GiNaC::matrix v = time_derivative(r, model);
        const GiNaC::matrix w = body_angular_velocity(body, model);
        GiNaC::ex v2 = 0, wIw = 0, gr = 0;
        for (unsigned i = 0; i < 3; ++i) {
            v2 += v(i, 0) * v(i, 0);
            gr += model.gravity[i] * body.centre[i];
            for (unsigned j = 0; j < 3; ++j) wIw += w(i, 0) * e.inertia(i, j) * w(j, 0);
        }
        e.T = tidy(body.mass * v2 / 2 + wIw / 2);
        e.V = tidy(-body.mass * gr);
        out.push_back(std::move(e));
    }
    return out;
}

BodyDynamics body_dynamics(const Model& model, const Body& body) {
    check_sequence(body);
    BodyDynamics d;
    d.name = body.name;
    const GiNaC::matrix I = body_inertia(body);
    d.rotation = body_rotation(body);
    d.omega_body = expanded(body_angular_velocity(body, model));
    d.omega_space = expanded(space_angular_velocity(body, model));
    const GiNaC::matrix r = column(body.centre);
    d.velocity = expanded(time_derivative(r, model));
    d.angular_momentum_body = expanded(I.mul(d.omega_body));
    const GiNaC::matrix spin = d.rotation.transpose().mul(d.angular_momentum_body);
    const GiNaC::matrix orbit = cross(r, d.velocity);
    for (unsigned i = 0; i < 3; ++i)
        d.angular_momentum_space(i, 0) = (spin(i, 0) + body.mass * orbit(i, 0)).expand();
    const GiNaC::matrix w_dot = time_derivative(d.omega_body, model);
    const GiNaC::matrix gyro = cross(d.omega_body, d.angular_momentum_body);
    const GiNaC::matrix Iw_dot = I.mul(w_dot);
    for (unsigned i = 0; i < 3; ++i) d.euler_torque(i, 0) = tidy(Iw_dot(i, 0) + gyro(i, 0));
    return d;
}

std::vector<GiNaC::ex> body_generalized_forces(const Model& model) {
    std::vector<GiNaC::ex> Q(model.dof(), GiNaC::ex(0));
    for (const Body& body : model.bodies) {
        const bool force = std::any_of(body.force.begin(), body.force.end(), [](const GiNaC::ex& e) { return !e.is_zero(); });
        const bool torque = std::any_of(body.torque.begin(), body.torque.end(), [](const GiNaC::ex& e) { return !e.is_zero(); });
        if (!force && !torque) continue;
        check_sequence(body);
        const GiNaC::matrix v = time_derivative(column(body.centre), model);
        const GiNaC::matrix w = body_angular_velocity(body, model);
        for (std::size_t i = 0; i < model.dof(); ++i) {
            const GiNaC::symbol& qd = model.coordinates[i].qd;
            for (unsigned k = 0; k < 3; ++k) {
                if (force) Q[i] += body.force[k] * GiNaC::diff(v(k, 0), qd);
                if (torque) Q[i] += body.torque[k] * GiNaC::diff(w(k, 0), qd);
            }
            Q[i] = Q[i].expand();
        }
    }
    return Q;
}

std::vector<SpringEnergy> spring_energies(const Model& model) {
    std::vector<SpringEnergy> out;
    for (const Spring& spring : model.springs) {
        auto end = [&](const SpringEnd& e) {
            if (e.body.empty()) return column(e.point);
            const auto body = std::find_if(model.bodies.begin(), model.bodies.end(),
                                           [&](const Body& b) { return b.name == e.body; });
            if (body == model.bodies.end())
                throw ModelError(spring.where, "spring '" + spring.name + "' is attached to body '" + e.body +
                                                   "', which the model does not have");
            check_sequence(*body);
            return point_position(column(body->centre), body_rotation(*body),
                                  column(e.point));
        };
        const GiNaC::matrix a = end(spring.from), b = end(spring.to);
        GiNaC::ex d2 = 0;
        for (unsigned i = 0; i < 3; ++i) d2 += GiNaC::pow(b(i, 0) - a(i, 0), 2);
        d2 = tidy(d2);
        SpringEnergy e;
        e.name = spring.name;
        e.length = GiNaC::sqrt(d2);
        e.V = spring.rest_length.is_zero()
                  ? tidy(spring.stiffness * d2 / 2)
                  : spring.stiffness * GiNaC::pow(e.length - spring.rest_length, 2) / 2;
        out.push_back(std::move(e));
    }
    return out;
}

}  // namespace eomgen
