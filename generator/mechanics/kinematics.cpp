/** @file kinematics.cpp  Rigid-body kinematics: Euler-angle rotations, angular velocity, positions and
 * velocities of points. */
#include "mechanics/kinematics.hpp"

#include "mechanics/lagrangian.hpp"

#include <stdexcept>

namespace eomgen {

bool valid_euler_sequence(const std::string& sequence) {
    if (sequence.size() != 3) return false;
    for (char c : sequence)
        if (c != 'x' && c != 'y' && c != 'z') return false;
    return sequence[0] != sequence[1] && sequence[1] != sequence[2];
}

GiNaC::matrix euler_rotation(const std::array<GiNaC::ex, 3>& angles, const std::string& sequence) {
    return chain_rotation(euler_chain(angles, sequence));
}

GiNaC::matrix body_angular_velocity(const std::array<GiNaC::ex, 3>& angles,
                                    const std::array<GiNaC::ex, 3>& rates, const std::string& sequence) {
    return chain_body_angular_velocity(euler_chain(angles, sequence), {rates[0], rates[1], rates[2]});
}

GiNaC::matrix space_angular_velocity(const std::array<GiNaC::ex, 3>& angles,
                                     const std::array<GiNaC::ex, 3>& rates, const std::string& sequence) {
    return chain_space_angular_velocity(euler_chain(angles, sequence), {rates[0], rates[1], rates[2]});
}

namespace {
std::array<GiNaC::ex, 3> rates_of(const std::array<GiNaC::ex, 3>& angles, const Model& model) {
    return {time_derivative(angles[0], model), time_derivative(angles[1], model),
            time_derivative(angles[2], model)};
}
}  // namespace

GiNaC::matrix body_angular_velocity(const std::array<GiNaC::ex, 3>& angles, const Model& model,
                                    const std::string& sequence) {
    return body_angular_velocity(angles, rates_of(angles, model), sequence);
}

GiNaC::matrix space_angular_velocity(const std::array<GiNaC::ex, 3>& angles, const Model& model,
                                     const std::string& sequence) {
    return space_angular_velocity(angles, rates_of(angles, model), sequence);
}

namespace {
const std::vector<Rotation>& chain_of(const Body& body, std::vector<Rotation>& scratch) {
    if (!body.rotations.empty()) return body.rotations;
    scratch = euler_chain(body.angles, body.sequence);
    return scratch;
}
std::vector<GiNaC::ex> chain_rates(const std::vector<Rotation>& chain, const Model& model) {
    std::vector<GiNaC::ex> rates;
    for (const Rotation& r : chain) rates.push_back(time_derivative(r.angle, model));
    return rates;
}
}  // namespace

GiNaC::matrix body_rotation(const Body& body) {
    std::vector<Rotation> scratch;
    return chain_rotation(chain_of(body, scratch));
}

GiNaC::matrix body_angular_velocity(const Body& body, const Model& model) {
    std::vector<Rotation> scratch;
    const std::vector<Rotation>& chain = chain_of(body, scratch);
    return chain_body_angular_velocity(chain, chain_rates(chain, model));
}

GiNaC::matrix space_angular_velocity(const Body& body, const Model& model) {
    std::vector<Rotation> scratch;
    const std::vector<Rotation>& chain = chain_of(body, scratch);
    return chain_space_angular_velocity(chain, chain_rates(chain, model));
}

GiNaC::matrix skew(const GiNaC::matrix& v) {
    return GiNaC::matrix{{0, -v(2, 0), v(1, 0)}, {v(2, 0), 0, -v(0, 0)}, {-v(1, 0), v(0, 0), 0}};
}

GiNaC::matrix body_angular_velocity_from_rotation(const GiNaC::matrix& A, const GiNaC::matrix& A_dot) {
    const GiNaC::matrix W = A.mul(A_dot.transpose());
    // W is skew up to sin² + cos² identities; average the two halves.
    return GiNaC::matrix{{((W(2, 1) - W(1, 2)) / 2).expand()},
                         {((W(0, 2) - W(2, 0)) / 2).expand()},
                         {((W(1, 0) - W(0, 1)) / 2).expand()}};
}

GiNaC::matrix point_position(const GiNaC::matrix& centre, const GiNaC::matrix& A, const GiNaC::matrix& rho) {
    return centre.add(A.transpose().mul(rho));
}

GiNaC::matrix time_derivative(const GiNaC::matrix& m, const Model& model) {
    GiNaC::matrix d(m.rows(), m.cols());
    for (unsigned i = 0; i < m.rows(); ++i)
        for (unsigned j = 0; j < m.cols(); ++j) d(i, j) = time_derivative(m(i, j), model);
    return d;
}

}  // namespace eomgen
