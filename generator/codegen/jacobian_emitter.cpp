/** @file jacobian_emitter.cpp  Generated ∂ẋ/∂x and ∂ẋ/∂p: the symbolic terms CSE'd, one factorization of M. */
#include "codegen/jacobian_emitter.hpp"

#include "mechanics/jacobian_terms.hpp"

#include <fmt/format.h>

#include <sstream>

namespace eomgen::codegen {
namespace {

/// The member template that solves for q'' and the columns `columns` of R_ (filled by `terms`), then writes `out`.
std::string combine(const std::string& doc, const std::string& name, const std::string& mat, const std::string& out,
                    const std::string& columns, const std::string& terms, const std::string& write) {
    std::ostringstream os;
    os << doc;
    os << "    template <class Mat" << out << " = " << mat << ">\n";
    os << "    static void " << name << "(const Scalar& t, const State& x_, const Params& p_, Mat" << out << "& " << out
       << "_) {\n";
    os << "        const Config q_ = x_.template head<nq>();\n";
    os << "        const Config qd_ = x_.template tail<nq>();\n";
    os << "        MassMatrix M_;\n        Config f_;\n        dynamics(t, q_, qd_, p_, M_, f_);\n";
    os << "        Config qdd_;\n        Eigen::Matrix<Scalar, nq, " << columns << "> R_;\n";
    os << "        eomgen::solve_jacobian_columns(M_, f_, qdd_, R_, t, x_, [&](const Config& a_, auto& r_) {\n";
    os << "            " << terms << "(t, q_, qd_, a_, p_, r_);\n        });\n";
    os << "        " << out << "_.resize(nx, " << columns << ");\n";
    os << write;
    os << "    }\n";
    return os.str();
}

}  // namespace

std::string emit_analytic_jacobian(const Model& model, const Equations& eq, const SymbolTable& table) {
    const JacobianTerms terms = jacobian_terms(model, eq);
    const std::size_t n = model.dof();
    std::vector<Output> state, params;
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t k = 0; k < n; ++k) state.push_back({fmt::format("R_({}, {})", i, k), terms.dq[i][k]});
        for (std::size_t k = 0; k < n; ++k) state.push_back({fmt::format("R_({}, {})", i, n + k), terms.dqd[i][k]});
        for (std::size_t j = 0; j < model.parameters.size(); ++j)
            params.push_back({fmt::format("Rp_({}, {})", i, j), terms.dp[i][j]});
    }
    const std::pair<std::string, std::string> t_in{"Scalar", "t"}, q_in{"Config", "q_"}, qd_in{"Config", "qd_"},
        qdd_in{"Config", "qdd_"}, p_in{"Params", "p_"};
    const FunctionSpec state_terms{
        "R = [dr/dq, dr/dq'] of r = f - M q'' at fixed q'' (the solved accelerations): M dq''/dq = dr/dq, "
        "M dq''/dq' = dr/dq'.\n"
        "    /// R_ is nq x nx; a member template, compiled only where called.",
        "void", "jacobian_terms", {t_in, q_in, qd_in, qdd_in, p_in}, {{"MatR", "R_"}}, state, {}, "template <class MatR>"};
    const FunctionSpec param_terms{
        "Rp = dr/dp of r = f - M q'' at fixed q'', columns in param_names order: M dq''/dp = dr/dp. Rp_ is\n"
        "    /// nq x n_params; a member template, compiled only where called.",
        "void", "parameter_jacobian_terms", {t_in, q_in, qd_in, qdd_in, p_in}, {{"MatRp", "Rp_"}}, params, {},
        "template <class MatRp>"};
    std::ostringstream os;
    os << emit_function(state_terms, table) << "\n" << emit_function(param_terms, table) << "\n";
    os << combine("    /// J = dx'/dx = [[0, I], [M^-1 dr/dq, M^-1 dr/dq']] at (t, x), analytic (jacobian_terms()), with one\n"
                  "    /// factorization of M; a singular M throws as in rhs(). A member template: compiled only where called.\n",
                  "state_jacobian", "StateJacobian", "J", "nx", "jacobian_terms",
                  "        J_.template topLeftCorner<nq, nq>().setZero();\n"
                  "        J_.template topRightCorner<nq, nq>().setIdentity();\n"
                  "        J_.template bottomRows<nq>() = R_;\n");
    os << "\n";
    os << combine("    /// Jp = dx'/dp = [[0], [M^-1 dr/dp]] at (t, x), columns in param_names order, analytic\n"
                  "    /// (parameter_jacobian_terms()), with one factorization of M. A member template: compiled only where called.\n",
                  "parameter_jacobian", "ParameterJacobian", "Jp", "n_params", "parameter_jacobian_terms",
                  "        Jp_.template topRows<nq>().setZero();\n"
                  "        Jp_.template bottomRows<nq>() = R_;\n");
    return os.str();
}

}  // namespace eomgen::codegen
