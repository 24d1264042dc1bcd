/** @file kinematics.cpp  Rigid-body kinematics: Euler-angle rotations, angular velocity, positions and
 * velocities of points. */
#include "mechanics/kinematics.hpp"

#include "mechanics/lagrangian.hpp"

#include <stdexcept>

namespace eomgen {

namespace {

GiNaC::matrix unit_vector(char axis) {
    GiNaC::matrix e(3, 1);
    e(static_cast<unsigned>(axis - 'x'), 0) = 1;
    return e;
}

GiNaC::matrix add(const GiNaC::matrix& a, const GiNaC::matrix& b) {
    return a.add(b);
}

}  // namespace

GiNaC::matrix axis_rotation(char axis, const GiNaC::ex& angle) {
    const GiNaC::ex c = GiNaC::cos(angle), s = GiNaC::sin(angle);
    switch (axis) {
        case 'x':
            return GiNaC::matrix{{1, 0, 0}, {0, c, s}, {0, -s, c}};
        case 'y':
            return GiNaC::matrix{{c, 0, -s}, {0, 1, 0}, {s, 0, c}};
        case 'z':
            return GiNaC::matrix{{c, s, 0}, {-s, c, 0}, {0, 0, 1}};
        default:
            throw std::invalid_argument(std::string("rotation axis must be x, y or z, not '") + axis + "'");
    }
}

bool valid_euler_sequence(const std::string& sequence) {
    if (sequence.size() != 3) return false;
    for (char c : sequence)
        if (c != 'x' && c != 'y' && c != 'z') return false;
    return sequence[0] != sequence[1] && sequence[1] != sequence[2];
}

namespace {
void require_sequence(const std::string& sequence) {
    if (!valid_euler_sequence(sequence))
        throw std::invalid_argument(
            "Euler sequence '" + sequence +
            "' is not three of x, y, z with no axis twice in a row (e.g. \"zxz\", \"xyz\")");
}
}  // namespace

GiNaC::matrix euler_rotation(const std::array<GiNaC::ex, 3>& angles, const std::string& sequence) {
    require_sequence(sequence);
    return axis_rotation(sequence[2], angles[2])
        .mul(axis_rotation(sequence[1], angles[1]))
        .mul(axis_rotation(sequence[0], angles[0]));
}

GiNaC::matrix body_angular_velocity(const std::array<GiNaC::ex, 3>& angles,
                                    const std::array<GiNaC::ex, 3>& rates, const std::string& sequence) {
    require_sequence(sequence);
    GiNaC::matrix w =
        axis_rotation(sequence[1], angles[1]).mul(unit_vector(sequence[0])).mul_scalar(rates[0]);
    w = add(w, unit_vector(sequence[1]).mul_scalar(rates[1]));
    w = add(axis_rotation(sequence[2], angles[2]).mul(w), unit_vector(sequence[2]).mul_scalar(rates[2]));
    for (unsigned i = 0; i < 3; ++i) w(i, 0) = w(i, 0).expand();
    return w;
}

GiNaC::matrix space_angular_velocity(const std::array<GiNaC::ex, 3>& angles,
                                     const std::array<GiNaC::ex, 3>& rates, const std::string& sequence) {
    // ω = Aᵀ ω' composed the other way round, so no sin² + cos² is left to simplify:
    // ω = φ̇ e_a + R_aᵀ(φ) (θ̇ e_b + R_bᵀ(θ) ψ̇ e_c).
    require_sequence(sequence);
    GiNaC::matrix w =
        axis_rotation(sequence[1], angles[1]).transpose().mul(unit_vector(sequence[2])).mul_scalar(rates[2]);
    w = add(w, unit_vector(sequence[1]).mul_scalar(rates[1]));
    w = add(axis_rotation(sequence[0], angles[0]).transpose().mul(w),
            unit_vector(sequence[0]).mul_scalar(rates[0]));
    for (unsigned i = 0; i < 3; ++i) w(i, 0) = w(i, 0).expand();
    return w;
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
