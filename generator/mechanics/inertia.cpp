/** @file inertia.cpp  Symbolic inertia tensors: shapes, a density integrated over a region, parallel axes,
 * principal axes. */
#include "mechanics/inertia.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <map>
#include <stdexcept>

namespace eomgen {

namespace {

GiNaC::matrix diagonal(const GiNaC::ex& a, const GiNaC::ex& b, const GiNaC::ex& c) {
    return GiNaC::matrix{{a, 0, 0}, {0, b, 0}, {0, 0, c}};
}

GiNaC::matrix steiner_term(const GiNaC::ex& mass, const GiNaC::matrix& d) {
    const GiNaC::ex d2 = d(0, 0) * d(0, 0) + d(1, 0) * d(1, 0) + d(2, 0) * d(2, 0);
    GiNaC::matrix s(3, 3);
    for (unsigned j = 0; j < 3; ++j)
        for (unsigned k = 0; k < 3; ++k)
            s(j, k) = (mass * ((j == k ? d2 : GiNaC::ex(0)) - d(j, 0) * d(k, 0))).expand();
    return s;
}

bool has_integral(const GiNaC::ex& e) {
    if (GiNaC::is_a<GiNaC::integral>(e)) return true;
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (has_integral(e.op(i))) return true;
    return false;
}

GiNaC::ex integrate(GiNaC::ex f, const std::vector<Bound>& bounds) {
    for (const Bound& b : bounds) f = GiNaC::integral(b.variable, b.lower, b.upper, f.expand()).eval_integ();
    if (has_integral(f))
        throw std::invalid_argument(
            "cannot integrate the density symbolically (GiNaC integrates polynomials)");
    return f.expand();
}

GiNaC::matrix cross(const GiNaC::matrix& u, const GiNaC::matrix& v) {
    return GiNaC::matrix{{(u(1, 0) * v(2, 0) - u(2, 0) * v(1, 0)).normal()},
                         {(u(2, 0) * v(0, 0) - u(0, 0) * v(2, 0)).normal()},
                         {(u(0, 0) * v(1, 0) - u(1, 0) * v(0, 0)).normal()}};
}

bool is_null(const GiNaC::matrix& v) {
    for (unsigned i = 0; i < v.rows(); ++i)
        if (!v(i, 0).normal().is_zero()) return false;
    return true;
}

/// v scaled so its first non-zero component is 1, then normalised.
GiNaC::matrix unit(const GiNaC::matrix& v) {
    GiNaC::ex first = 1;
    for (unsigned i = 0; i < 3; ++i)
        if (!v(i, 0).normal().is_zero()) {
            first = v(i, 0);
            break;
        }
    GiNaC::matrix w(3, 1);
    GiNaC::ex n2 = 0;
    for (unsigned i = 0; i < 3; ++i) {
        w(i, 0) = (v(i, 0) / first).normal();
        n2 += w(i, 0) * w(i, 0);
    }
    const GiNaC::ex n = GiNaC::sqrt(n2.normal());
    for (unsigned i = 0; i < 3; ++i) w(i, 0) = (w(i, 0) / n).normal();
    return w;
}

/// An orthonormal basis of the null space of the symmetric 3×3 matrix A with `dimension` (1 to 3)
/// independent null vectors, built from cross products of its rows (generic values of the symbols).
std::vector<GiNaC::matrix> null_space(const GiNaC::matrix& A, unsigned dimension) {
    std::vector<GiNaC::matrix> rows;
    for (unsigned i = 0; i < 3; ++i) rows.push_back(GiNaC::matrix{{A(i, 0)}, {A(i, 1)}, {A(i, 2)}});
    const GiNaC::matrix e[3] = {GiNaC::matrix{{1}, {0}, {0}}, GiNaC::matrix{{0}, {1}, {0}},
                                GiNaC::matrix{{0}, {0}, {1}}};
    if (dimension == 1) {
        for (unsigned i = 0; i < 3; ++i)
            for (unsigned j = i + 1; j < 3; ++j) {
                const GiNaC::matrix c = cross(rows[i], rows[j]);
                if (!is_null(c)) return {unit(c)};
            }
        throw std::invalid_argument("principal axes: the tensor has no simple eigenvector");
    }
    if (dimension == 2) {
        for (const auto& n : rows) {
            if (is_null(n)) continue;
            for (const auto& ek : e) {
                const GiNaC::matrix v1 = cross(n, ek);
                if (is_null(v1)) continue;
                return {unit(v1), unit(cross(n, v1))};
            }
        }
        throw std::invalid_argument("principal axes: a double moment without a plane of axes");
    }
    return {e[0], e[1], e[2]};
}

/// The value used to order moments: every symbol set to 1.
double ordering_value(const GiNaC::ex& e) {
    GiNaC::exmap ones;
    struct Collect : GiNaC::visitor, GiNaC::symbol::visitor {
        GiNaC::exmap* map;
        void visit(const GiNaC::symbol& s) override { (*map)[s] = 1; }
    } collect;
    collect.map = &ones;
    e.traverse(collect);
    const GiNaC::ex v = GiNaC::evalf(e.subs(ones));
    return GiNaC::is_a<GiNaC::numeric>(v) ? GiNaC::ex_to<GiNaC::numeric>(v).to_double() : 0.0;
}

}  // namespace

GiNaC::matrix thin_rod_inertia(const GiNaC::ex& m, const GiNaC::ex& l) {
    return diagonal(m * l * l / 12, m * l * l / 12, 0);
}
GiNaC::matrix thin_disk_inertia(const GiNaC::ex& m, const GiNaC::ex& r) {
    return diagonal(m * r * r / 4, m * r * r / 4, m * r * r / 2);
}
GiNaC::matrix ring_inertia(const GiNaC::ex& m, const GiNaC::ex& r) {
    return diagonal(m * r * r / 2, m * r * r / 2, m * r * r);
}
GiNaC::matrix solid_sphere_inertia(const GiNaC::ex& m, const GiNaC::ex& r) {
    const GiNaC::ex i = GiNaC::numeric(2, 5) * m * r * r;
    return diagonal(i, i, i);
}
GiNaC::matrix hollow_sphere_inertia(const GiNaC::ex& m, const GiNaC::ex& r) {
    const GiNaC::ex i = GiNaC::numeric(2, 3) * m * r * r;
    return diagonal(i, i, i);
}
GiNaC::matrix solid_cone_inertia(const GiNaC::ex& m, const GiNaC::ex& r, const GiNaC::ex& h) {
    const GiNaC::ex i1 = GiNaC::numeric(3, 20) * m * r * r + GiNaC::numeric(3, 80) * m * h * h;
    return diagonal(i1, i1, GiNaC::numeric(3, 10) * m * r * r);
}
GiNaC::matrix cylinder_inertia(const GiNaC::ex& m, const GiNaC::ex& r, const GiNaC::ex& h) {
    const GiNaC::ex i1 = m * (3 * r * r + h * h) / 12;
    return diagonal(i1, i1, m * r * r / 2);
}
GiNaC::matrix box_inertia(const GiNaC::ex& m, const GiNaC::ex& a, const GiNaC::ex& b, const GiNaC::ex& c) {
    return diagonal(m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12);
}
GiNaC::matrix rectangular_plate_inertia(const GiNaC::ex& m, const GiNaC::ex& a, const GiNaC::ex& b) {
    return diagonal(m * b * b / 12, m * a * a / 12, m * (a * a + b * b) / 12);
}
GiNaC::matrix right_triangle_plate_inertia(const GiNaC::ex& m, const GiNaC::ex& a, const GiNaC::ex& b) {
    return GiNaC::matrix{{m * b * b / 18, m * a * b / 36, 0},
                         {m * a * b / 36, m * a * a / 18, 0},
                         {0, 0, m * (a * a + b * b) / 18}};
}

namespace {
const std::map<std::string, std::vector<std::string>>& shape_table() {
    static const std::map<std::string, std::vector<std::string>> table = {
        {"thin_rod", {"length"}},
        {"thin_disk", {"radius"}},
        {"ring", {"radius"}},
        {"solid_sphere", {"radius"}},
        {"hollow_sphere", {"radius"}},
        {"solid_cone", {"radius", "height"}},
        {"cylinder", {"radius", "height"}},
        {"box", {"a", "b", "c"}},
        {"rectangular_plate", {"a", "b"}},
        {"right_triangle_plate", {"a", "b"}},
    };
    return table;
}
}  // namespace

std::vector<std::string> shape_dimensions(const std::string& shape) {
    const auto it = shape_table().find(shape);
    return it == shape_table().end() ? std::vector<std::string>{} : it->second;
}

std::vector<std::string> shape_names() {
    std::vector<std::string> names;
    for (const auto& [name, dims] : shape_table()) names.push_back(name);
    return names;
}

GiNaC::matrix shape_inertia(const std::string& shape, const GiNaC::ex& m, const std::vector<GiNaC::ex>& d) {
    const std::vector<std::string> dims = shape_dimensions(shape);
    if (dims.empty()) throw std::invalid_argument("unknown shape '" + shape + "'");
    if (d.size() != dims.size())
        throw std::invalid_argument("shape '" + shape + "' takes " + std::to_string(dims.size()) +
                                    " dimension(s), not " + std::to_string(d.size()));
    if (shape == "thin_rod") return thin_rod_inertia(m, d[0]);
    if (shape == "thin_disk") return thin_disk_inertia(m, d[0]);
    if (shape == "ring") return ring_inertia(m, d[0]);
    if (shape == "solid_sphere") return solid_sphere_inertia(m, d[0]);
    if (shape == "hollow_sphere") return hollow_sphere_inertia(m, d[0]);
    if (shape == "solid_cone") return solid_cone_inertia(m, d[0], d[1]);
    if (shape == "cylinder") return cylinder_inertia(m, d[0], d[1]);
    if (shape == "box") return box_inertia(m, d[0], d[1], d[2]);
    if (shape == "rectangular_plate") return rectangular_plate_inertia(m, d[0], d[1]);
    return right_triangle_plate_inertia(m, d[0], d[1]);
}

MassProperties integrate_mass_properties(const GiNaC::ex& density, const GiNaC::symbol& x,
                                         const GiNaC::symbol& y, const GiNaC::symbol& z,
                                         const std::vector<Bound>& bounds) {
    // A coordinate without a bound is 0 on the body (plates and rods).
    GiNaC::ex r[3] = {x, y, z};
    for (auto& c : r) {
        const bool bounded = std::any_of(bounds.begin(), bounds.end(),
                                         [&](const Bound& b) { return GiNaC::ex(b.variable).is_equal(c); });
        if (!bounded) c = 0;
    }
    GiNaC::exmap flat;
    for (const GiNaC::symbol& s : {x, y, z})
        if (std::none_of(bounds.begin(), bounds.end(),
                         [&](const Bound& b) { return GiNaC::ex(b.variable).is_equal(s); }))
            flat[s] = 0;
    const GiNaC::ex rho = density.subs(flat);

    MassProperties p;
    p.mass = integrate(rho, bounds).normal();
    if (p.mass.is_zero()) throw std::invalid_argument("the body has zero mass");
    const GiNaC::ex r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    for (unsigned j = 0; j < 3; ++j) {
        p.centre(j, 0) = (integrate(rho * r[j], bounds) / p.mass).normal();
        for (unsigned k = j; k < 3; ++k) {
            const GiNaC::ex integrand = rho * ((j == k ? r2 : GiNaC::ex(0)) - r[j] * r[k]);
            p.inertia_origin(j, k) = p.inertia_origin(k, j) = integrate(integrand, bounds).normal();
        }
    }
    p.inertia_centre = shift_to_centre(p.inertia_origin, p.mass, p.centre);
    return p;
}

GiNaC::matrix parallel_axis(const GiNaC::matrix& inertia_centre, const GiNaC::ex& mass,
                            const GiNaC::matrix& d) {
    const GiNaC::matrix s = steiner_term(mass, d);
    GiNaC::matrix out(3, 3);
    for (unsigned j = 0; j < 3; ++j)
        for (unsigned k = 0; k < 3; ++k) out(j, k) = (inertia_centre(j, k) + s(j, k)).normal();
    return out;
}

GiNaC::matrix shift_to_centre(const GiNaC::matrix& inertia_point, const GiNaC::ex& mass,
                              const GiNaC::matrix& d) {
    const GiNaC::matrix s = steiner_term(mass, d);
    GiNaC::matrix out(3, 3);
    for (unsigned j = 0; j < 3; ++j)
        for (unsigned k = 0; k < 3; ++k) out(j, k) = (inertia_point(j, k) - s(j, k)).normal();
    return out;
}

PrincipalAxes principal_axes(const GiNaC::matrix& inertia, const GiNaC::exmap& values) {
    const GiNaC::symbol lambda("lambda");
    const GiNaC::ex p = GiNaC::factor(inertia.charpoly(lambda).expand());

    // Roots of the linear factors, with multiplicity; any factor of higher degree in λ → numeric.
    std::vector<std::pair<GiNaC::ex, unsigned>> roots;
    bool linear = true;
    auto take = [&](const GiNaC::ex& f, unsigned multiplicity) {
        if (!f.has(lambda)) return;
        if (f.degree(lambda) != 1) {
            linear = false;
            return;
        }
        const GiNaC::ex root = (-f.coeff(lambda, 0) / f.coeff(lambda, 1)).normal();
        for (auto& [r, m] : roots)
            if ((r - root).normal().is_zero()) {
                m += multiplicity;
                return;
            }
        roots.emplace_back(root, multiplicity);
    };
    auto take_power = [&](const GiNaC::ex& f) {
        if (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::numeric>(f.op(1)) &&
            f.op(1).info(GiNaC::info_flags::posint))
            take(f.op(0), static_cast<unsigned>(GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_int()));
        else
            take(f, 1);
    };
    if (GiNaC::is_a<GiNaC::mul>(p))
        for (std::size_t i = 0; i < p.nops(); ++i) take_power(p.op(i));
    else
        take_power(p);

    PrincipalAxes result;
    if (linear) {
        std::vector<std::pair<GiNaC::ex, GiNaC::matrix>> pairs;
        for (const auto& [root, multiplicity] : roots) {
            GiNaC::matrix A(3, 3);
            for (unsigned j = 0; j < 3; ++j)
                for (unsigned k = 0; k < 3; ++k)
                    A(j, k) = (inertia(j, k) - (j == k ? root : GiNaC::ex(0))).normal();
            for (const GiNaC::matrix& v : null_space(A, multiplicity)) pairs.emplace_back(root, v);
        }
        std::stable_sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) {
            return ordering_value(a.first) < ordering_value(b.first);
        });
        result.exact = true;
        for (const auto& [moment, axis] : pairs) {
            result.moments.push_back(moment);
            result.axes.push_back(axis);
        }
        return result;
    }

    Eigen::Matrix3d I;
    for (unsigned j = 0; j < 3; ++j)
        for (unsigned k = 0; k < 3; ++k) {
            const GiNaC::ex v = GiNaC::evalf(inertia(j, k).subs(values));
            if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real())
                throw std::invalid_argument(
                    "principal axes: the characteristic polynomial does not factor and the tensor is not "
                    "numeric after substituting the given values");
            I(j, k) = GiNaC::ex_to<GiNaC::numeric>(v).to_double();
        }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(I);  // ascending eigenvalues
    for (int i = 0; i < 3; ++i) {
        Eigen::Vector3d v = solver.eigenvectors().col(i);
        for (int k = 0; k < 3; ++k)
            if (std::abs(v(k)) > 1e-12) {
                if (v(k) < 0) v = -v;
                break;
            }
        result.moments.push_back(solver.eigenvalues()(i));
        result.axes.push_back(GiNaC::matrix{{v(0)}, {v(1)}, {v(2)}});
    }
    return result;
}

}  // namespace eomgen
