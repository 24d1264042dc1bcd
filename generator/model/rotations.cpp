/** @file rotations.cpp  A body's orientation as a chain of elementary rotations. */
#include "model/rotations.hpp"

#include <stdexcept>
#include <string>

namespace eomgen {

namespace {

void require_rates(const std::vector<Rotation>& chain, const std::vector<GiNaC::ex>& rates) {
    if (chain.size() != rates.size()) throw std::invalid_argument("one rate per rotation of the chain");
}

}  // namespace

GiNaC::matrix axis_vector(char axis) {
    GiNaC::matrix e(3, 1);
    e(static_cast<unsigned>(axis - 'x'), 0) = 1;
    return e;
}

GiNaC::ex dot(const GiNaC::matrix& a, const GiNaC::matrix& b) {
    return a(0, 0) * b(0, 0) + a(1, 0) * b(1, 0) + a(2, 0) * b(2, 0);
}

GiNaC::matrix cross(const GiNaC::matrix& a, const GiNaC::matrix& b) {
    return GiNaC::matrix{{a(1, 0) * b(2, 0) - a(2, 0) * b(1, 0)},
                         {a(2, 0) * b(0, 0) - a(0, 0) * b(2, 0)},
                         {a(0, 0) * b(1, 0) - a(1, 0) * b(0, 0)}};
}

std::vector<Rotation> euler_chain(const std::array<GiNaC::ex, 3>& angles, const std::string& sequence) {
    const bool valid = sequence.size() == 3 && sequence.find_first_not_of("xyz") == std::string::npos &&
                       sequence[0] != sequence[1] && sequence[1] != sequence[2];
    if (!valid)
        throw std::invalid_argument("Euler sequence '" + sequence +
                                    "' is not three of x, y, z with no axis twice in a row (e.g. \"zxz\", \"xyz\")");
    return {{sequence[0], angles[0]}, {sequence[1], angles[1]}, {sequence[2], angles[2]}};
}

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

GiNaC::matrix chain_rotation(const std::vector<Rotation>& chain) {
    GiNaC::matrix A{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const Rotation& r : chain) {
        if (r.angle.is_zero()) continue;
        A = axis_rotation(r.axis, r.angle).mul(A);
    }
    return A;
}

GiNaC::matrix chain_body_angular_velocity(const std::vector<Rotation>& chain, const std::vector<GiNaC::ex>& rates) {
    require_rates(chain, rates);
    GiNaC::matrix w(3, 1);
    for (std::size_t k = 0; k < chain.size(); ++k) {
        if (!chain[k].angle.is_zero()) w = axis_rotation(chain[k].axis, chain[k].angle).mul(w);
        w = w.add(axis_vector(chain[k].axis).mul_scalar(rates[k]));
    }
    for (unsigned i = 0; i < 3; ++i) w(i, 0) = w(i, 0).expand();
    return w;
}

GiNaC::matrix chain_space_angular_velocity(const std::vector<Rotation>& chain, const std::vector<GiNaC::ex>& rates) {
    require_rates(chain, rates);
    GiNaC::matrix w(3, 1);
    for (std::size_t k = chain.size(); k-- > 0;) {
        if (!chain[k].angle.is_zero()) w = axis_rotation(chain[k].axis, chain[k].angle).transpose().mul(w);
        w = w.add(axis_vector(chain[k].axis).mul_scalar(rates[k]));
    }
    for (unsigned i = 0; i < 3; ++i) w(i, 0) = w(i, 0).expand();
    return w;
}

}  // namespace eomgen
