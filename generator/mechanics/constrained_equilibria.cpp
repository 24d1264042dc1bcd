/** @file constrained_equilibria.cpp  Rest and small oscillations on a constraint manifold (constrained_equilibria.hpp). */
#include "mechanics/constrained_equilibria.hpp"

#include "mechanics/small_oscillations.hpp"

#include <Eigen/Dense>

#include <algorithm>

namespace eomgen {

using GiNaC::ex;
using GiNaC::symbol;

ManifoldConstraints manifold_constraints(const Model& model, const Equations& eq, const std::vector<symbol>& q,
                                         const std::vector<std::string>& reduced) {
    ManifoldConstraints c;
    for (const ConstraintEquations& k : eq.constraints) {
        if (k.kind != ConstraintKind::Holonomic)
            throw ModesError("constraint '" + k.name +
                             "' is nonholonomic: rest under a velocity constraint is not an isolated equilibrium; "
                             "linearize about a steady motion instead, eomgen modes --steady q_dot=EXPR "
                             "(docs/steady_motions.md)");
        if (k.position.has(model.t))
            throw ModesError("constraint '" + k.name +
                             "' depends on t (a prescribed motion): the system has no equilibria in these "
                             "coordinates");
        for (const Coordinate& coordinate : model.coordinates)
            if (std::find(reduced.begin(), reduced.end(), coordinate.name) != reduced.end() &&
                k.position.has(coordinate.q))
                throw ModesError("constraint '" + k.name + "' involves " + coordinate.name +
                                 ", which --momentum reduces away: a cyclic coordinate cannot be constrained");
        c.names.push_back(k.name);
        c.g.push_back(k.position);
        c.lambda.emplace_back("lambda_" + k.name);
        std::vector<ex> row;
        std::vector<std::vector<ex>> hessian;
        for (const symbol& qi : q) {
            row.push_back(k.position.diff(qi));
            std::vector<ex> h;
            for (const symbol& qj : q) h.push_back(row.back().diff(qj));
            hessian.push_back(std::move(h));
        }
        c.jacobian.push_back(std::move(row));
        c.hessian.push_back(std::move(hessian));
    }
    return c;
}

void rest_conditions(const std::vector<ex>& G, const std::vector<std::vector<ex>>& dG, const ManifoldConstraints& c,
                     std::vector<ex>& F, std::vector<std::vector<ex>>& J) {
    const std::size_t n = G.size(), m = c.size();
    F.assign(n + m, 0);
    J.assign(n + m, std::vector<ex>(n + m, 0));
    for (std::size_t i = 0; i < n; ++i) {
        F[i] = G[i];
        for (std::size_t k = 0; k < m; ++k) F[i] -= c.lambda[k] * c.jacobian[k][i];
        for (std::size_t j = 0; j < n; ++j) {
            J[i][j] = dG[i][j];
            for (std::size_t k = 0; k < m; ++k) J[i][j] -= c.lambda[k] * c.hessian[k][i][j];
        }
        for (std::size_t k = 0; k < m; ++k) J[i][n + k] = -c.jacobian[k][i];
    }
    for (std::size_t k = 0; k < m; ++k) {
        F[n + k] = c.g[k];
        for (std::size_t j = 0; j < n; ++j) J[n + k][j] = c.jacobian[k][j];
    }
}

Eigen::MatrixXd tangent_basis(const Eigen::MatrixXd& A) {
    const Eigen::Index n = A.cols();
    if (A.rows() == 0) return Eigen::MatrixXd::Identity(n, n);
    // The right singular vectors of the zero singular values span A's null space, orthonormally.
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
    const Eigen::VectorXd& s = svd.singularValues();
    const double tol = std::max<double>(A.rows(), n) * std::numeric_limits<double>::epsilon() *
                       (s.size() ? s(0) : 0.0) * 1e3;
    Eigen::Index rank = 0;
    while (rank < s.size() && s(rank) > tol) ++rank;
    return svd.matrixV().rightCols(n - rank);
}

}  // namespace eomgen
