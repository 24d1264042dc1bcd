/** @file bodies.cpp  Kinetic and potential energy of the rigid bodies of a body-based model. */
#include "mechanics/bodies.hpp"

#include "mechanics/inertia.hpp"
#include "mechanics/kinematics.hpp"

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

std::vector<BodyEnergy> body_energies(const Model& model) {
    std::vector<BodyEnergy> out;
    for (const Body& body : model.bodies) {
        BodyEnergy e;
        e.name = body.name;
        try {
            e.inertia =
                body.shape.empty() ? body.inertia : shape_inertia(body.shape, body.mass, body.dimensions);
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
        if (!valid_euler_sequence(body.sequence))
            throw ModelError(body.where, "Euler sequence '" + body.sequence + "' of body '" + body.name +
                                             "' is not three of x, y, z with no axis twice in a row");
        const GiNaC::matrix r{{body.centre[0]}, {body.centre[1]}, {body.centre[2]}};
        const GiNaC::matrix v = time_derivative(r, model);
        const GiNaC::matrix w = body_angular_velocity(body.angles, model, body.sequence);
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

}  // namespace eomgen
