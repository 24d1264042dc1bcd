/** @file noether.cpp  Affine symmetries of L by linear algebra at random states, verified symbolically. */
#include "mechanics/noether.hpp"

#include "mechanics/double_evaluator.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>

namespace eomgen {
namespace {

/// x as p/d with d ≤ 12 when it is one within 1e-7; nothing otherwise.
std::optional<GiNaC::numeric> small_rational(double x) {
    for (int d = 1; d <= 12; ++d) {
        const double r = std::round(x * d);
        if (std::abs(x * d - r) < 1e-7 * d) return GiNaC::numeric(static_cast<long>(r), d);
    }
    return std::nullopt;
}

/// The rows of `basis` (k × u) brought to reduced row echelon form, pivots 1.
Eigen::MatrixXd reduced_echelon(Eigen::MatrixXd a) {
    Eigen::Index row = 0;
    for (Eigen::Index col = 0; col < a.cols() && row < a.rows(); ++col) {
        Eigen::Index best = row;
        for (Eigen::Index r = row; r < a.rows(); ++r)
            if (std::abs(a(r, col)) > std::abs(a(best, col))) best = r;
        if (std::abs(a(best, col)) < 1e-9) continue;
        a.row(row).swap(a.row(best));
        a.row(row) /= a(row, col);
        for (Eigen::Index r = 0; r < a.rows(); ++r)
            if (r != row) a.row(r) -= a(r, col) * a.row(row);
        ++row;
    }
    return a.topRows(row);
}

/// A generator ξ_i = c_i + Σ_j B_ij q_j with exact coefficients.
struct Generator {
    std::vector<GiNaC::ex> c;
    std::vector<std::vector<GiNaC::ex>> B;
};

std::string join_terms(const std::vector<std::pair<GiNaC::ex, std::string>>& terms) {
    std::ostringstream os;
    bool first = true;
    for (const auto& [k, name] : terms) {
        if (k.is_zero()) continue;
        const bool negative = GiNaC::is_a<GiNaC::numeric>(k) && GiNaC::ex_to<GiNaC::numeric>(k).is_negative();
        const GiNaC::ex size = negative ? GiNaC::ex(-k) : k;
        os << (first ? (negative ? "-" : "") : (negative ? " - " : " + "));
        if (name.empty()) os << size;
        else if (size.is_equal(1)) os << name;
        else os << size << "*" << name;
        first = false;
    }
    return first ? "0" : os.str();
}

/// The generator in words: "δx = -y, δy = x".
std::string describe(const Generator& g, const Model& model) {
    std::string out;
    for (std::size_t i = 0; i < model.dof(); ++i) {
        std::vector<std::pair<GiNaC::ex, std::string>> terms{{g.c[i], ""}};
        for (std::size_t j = 0; j < model.dof(); ++j) terms.emplace_back(g.B[i][j], model.coordinates[j].name);
        const std::string s = join_terms(terms);
        if (s != "0") out += (out.empty() ? "δ" : ", δ") + model.coordinates[i].name + " = " + s;
    }
    return out;
}

bool is_translation(const Generator& g) {
    for (const auto& row : g.B)
        if (std::any_of(row.begin(), row.end(), [](const GiNaC::ex& b) { return !b.is_zero(); })) return false;
    return true;
}

/// The pair (i, j), i < j, when ξ is the rotation δq_i = ∓q_j, δq_j = ±q_i and nothing else.
std::optional<std::pair<std::size_t, std::size_t>> plane_rotation(const Generator& g) {
    const std::size_t n = g.c.size();
    if (std::any_of(g.c.begin(), g.c.end(), [](const GiNaC::ex& c) { return !c.is_zero(); })) return std::nullopt;
    std::optional<std::pair<std::size_t, std::size_t>> pair;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
            if (g.B[i][j].is_zero() && g.B[j][i].is_zero()) continue;
            if (pair || !(g.B[i][j] + g.B[j][i]).is_zero()) return std::nullopt;
            pair = std::make_pair(i, j);
        }
    for (std::size_t i = 0; i < n; ++i)
        if (!g.B[i][i].is_zero()) return std::nullopt;
    return pair;
}

}  // namespace

std::vector<ConservedQuantity> noether_symmetries(const Model& model, const Equations& eq) {
    const std::size_t n = model.dof();
    if (n == 0 || n > kTranslationCoordinates) return {};
    const bool affine = n <= kAffineCoordinates;
    const std::size_t unknowns = affine ? n + n * n : n;  // c, then B row by row
    const bool forced = std::any_of(eq.generalized_forces.begin(), eq.generalized_forces.end(),
                                    [](const GiNaC::ex& Q) { return !Q.is_zero(); });

    // δL, Q·ξ and A ξ at random states: rows of a linear system in (c, B).
    std::vector<Eigen::VectorXd> rows;
    auto add_row = [&](const std::vector<double>& a, const std::vector<double>& b, const std::vector<double>& q) {
        // a_i multiplies ξ_i = c_i + Σ_j B_ij q_j; b_i multiplies ξ̇_i = Σ_j B_ij q̇_j (the q̇ are in `q`'s second half)
        Eigen::VectorXd row = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(unknowns));
        for (std::size_t i = 0; i < n; ++i) {
            row(Eigen::Index(i)) = a[i];
            if (!affine) continue;
            for (std::size_t j = 0; j < n; ++j)
                row(Eigen::Index(n + i * n + j)) = a[i] * q[j] + (b.empty() ? 0.0 : b[i] * q[n + j]);
        }
        const double size = row.cwiseAbs().maxCoeff();
        if (std::isfinite(size) && size > 0) rows.push_back(row / size);
    };
    const std::size_t points = unknowns + 8;
    for (unsigned seed = 0; rows.size() < points && seed < 3 * points; ++seed) {
        DoubleEvaluator value = DoubleEvaluator::at(random_point(model, 7001 + seed));
        auto number = [&value](const GiNaC::ex& e) { return value(e).value_or(std::nan("")); };
        std::vector<double> state(2 * n), dLdq(n), p(n);
        for (std::size_t i = 0; i < n; ++i) {
            state[i] = number(model.coordinates[i].q);
            state[n + i] = number(model.coordinates[i].qd);
            dLdq[i] = number(eq.dLdq[i]);
            p[i] = number(eq.momenta[i]);
        }
        add_row(dLdq, p, state);
        if (forced) {
            std::vector<double> Q(n);
            for (std::size_t i = 0; i < n; ++i) Q[i] = number(eq.generalized_forces[i]);
            add_row(Q, {}, state);
        }
        for (const ConstraintEquations& k : eq.constraints) {
            std::vector<double> A(n);
            for (std::size_t i = 0; i < n; ++i) A[i] = number(k.jacobian[i]);
            add_row(A, {}, state);
        }
    }
    if (rows.size() < unknowns) return {};
    Eigen::MatrixXd S(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(unknowns));
    for (std::size_t r = 0; r < rows.size(); ++r) S.row(Eigen::Index(r)) = rows[r].transpose();
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(S, Eigen::ComputeFullV);
    const Eigen::VectorXd sigma = svd.singularValues();
    Eigen::Index rank = 0;
    while (rank < sigma.size() && sigma(rank) > 1e-9 * std::max(1.0, sigma(0))) ++rank;
    if (rank == static_cast<Eigen::Index>(unknowns)) return {};
    const Eigen::MatrixXd basis = reduced_echelon(svd.matrixV().rightCols(Eigen::Index(unknowns) - rank).transpose());

    std::vector<ConservedQuantity> out;
    int unnamed = 0;
    for (Eigen::Index r = 0; r < basis.rows(); ++r) {
        Generator g{std::vector<GiNaC::ex>(n, 0), std::vector<std::vector<GiNaC::ex>>(n, std::vector<GiNaC::ex>(n, 0))};
        bool rational = true;
        for (std::size_t k = 0; k < unknowns && rational; ++k) {
            const std::optional<GiNaC::numeric> x = small_rational(basis(r, Eigen::Index(k)));
            if (!x) rational = false;
            else if (k < n) g.c[k] = *x;
            else g.B[(k - n) / n][(k - n) % n] = *x;
        }
        if (!rational) continue;

        // The exact test: δL, Q·ξ and A ξ vanish identically.
        GiNaC::ex dL = 0, work = 0, J = 0;
        std::vector<GiNaC::ex> xi(n), xi_dot(n);
        for (std::size_t i = 0; i < n; ++i) {
            xi[i] = g.c[i];
            xi_dot[i] = 0;
            for (std::size_t j = 0; j < n; ++j) {
                xi[i] += g.B[i][j] * model.coordinates[j].q;
                xi_dot[i] += g.B[i][j] * model.coordinates[j].qd;
            }
            dL += eq.dLdq[i] * xi[i] + eq.momenta[i] * xi_dot[i];
            work += eq.generalized_forces[i] * xi[i];
            J += eq.momenta[i] * xi[i];
        }
        if (!is_zero(dL, model) || !is_zero(work, model)) continue;
        if (std::any_of(eq.constraints.begin(), eq.constraints.end(), [&](const ConstraintEquations& k) {
                GiNaC::ex a = 0;
                for (std::size_t i = 0; i < n; ++i) a += k.jacobian[i] * xi[i];
                return !is_zero(a, model);
            }))
            continue;
        J = J.expand();
        if (is_zero(J, model)) continue;
        // Already known (a cyclic coordinate's momentum, or a multiple of one found here).
        auto known = [&](const ConservedQuantity& c) {
            return is_zero(J - c.value, model) || is_zero(J + c.value, model);
        };
        if (std::any_of(eq.conserved.begin(), eq.conserved.end(), known) ||
            std::any_of(out.begin(), out.end(), known))
            continue;

        ConservedQuantity c;
        auto flip = [&] {
            J = -J;
            for (GiNaC::ex& x : g.c) x = -x;
            for (auto& row : g.B)
                for (GiNaC::ex& x : row) x = -x;
        };
        if (const auto pair = plane_rotation(g)) {
            const auto [i, j] = *pair;
            // Oriented as δq_i = −q_j, δq_j = q_i, so that the x-y rotation gives L_z = x p_y − y p_x.
            if (GiNaC::ex_to<GiNaC::numeric>(g.B[i][j]).is_positive()) flip();
            const std::string a = model.coordinates[i].name, b = model.coordinates[j].name;
            std::string axis;
            if (a == "x" && b == "y") axis = "z";
            if (a == "y" && b == "z") axis = "x";
            if (a == "x" && b == "z") {
                axis = "y";  // δz = −x, δx = z
                flip();
            }
            const std::string words = describe(g, model);
            c.name = axis.empty() ? "J_" + a + "_" + b : "L_" + axis;
            c.latex = axis.empty() ? "J_{" + model.coordinates[i].latex + " " + model.coordinates[j].latex + "}"
                                   : "L_{" + axis + "}";
            c.reason = "Noether: L, the forces and the constraints are unchanged by the rotation " + words;
        } else if (is_translation(g)) {
            const std::string words = describe(g, model);
            std::string names, latex;
            for (std::size_t i = 0; i < n; ++i)
                if (!g.c[i].is_zero()) {
                    names += "_" + model.coordinates[i].name;
                    latex += (latex.empty() ? "" : " ") + model.coordinates[i].latex;
                }
            c.name = "P" + names;
            c.latex = "P_{" + latex + "}";
            c.reason = "Noether: L, the forces and the constraints are unchanged by the translation " + words;
        } else {
            const std::string words = describe(g, model);
            c.name = "N" + std::to_string(++unnamed);
            c.latex = "N_{" + std::to_string(unnamed) + "}";
            c.reason = "Noether: L, the forces and the constraints are unchanged by " + words;
        }
        c.value = J;
        out.push_back(std::move(c));
    }

    // A name that the model uses already (a parameter called L_z) gets a suffix.
    auto taken = [&](const std::string& name) {
        return std::any_of(model.parameters.begin(), model.parameters.end(), [&](const Parameter& p) { return p.name == name; }) ||
               std::any_of(model.coordinates.begin(), model.coordinates.end(), [&](const Coordinate& q) { return q.name == name; }) ||
               std::any_of(eq.conserved.begin(), eq.conserved.end(), [&](const ConservedQuantity& q) { return q.name == name; });
    };
    for (ConservedQuantity& c : out)
        while (taken(c.name)) c.name += "_noether";
    return out;
}

}  // namespace eomgen
