/** @file jacobian_emitter.cpp  Generated ∂ẋ/∂x and ∂ẋ/∂p: the symbolic terms CSE'd, one factorization of M. */
#include "codegen/jacobian_emitter.hpp"

#include "mechanics/jacobian_terms.hpp"
#include "model/nonsmooth.hpp"

#include <fmt/format.h>

#include <sstream>

namespace eomgen::codegen {
namespace {

/// The member template `name` that the runtime's `solver` computes from the header's terms.
std::string combine(const std::string& doc, const std::string& name, const std::string& mat, const std::string& out,
                    const std::string& solver) {
    std::ostringstream os;
    os << doc;
    os << "    template <class Mat" << out << " = " << mat << ">\n";
    os << "    static void " << name << "(const Scalar& t, const State& x_, const Params& p_, Mat" << out << "& " << out
       << "_) {\n";
    os << "        eomgen::" << solver << "<Model>(t, x_, p_, " << out << "_);\n";
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
    // With abs, sign, max … in the dynamics, the derivatives are the ones away from the switching surfaces.
    std::vector<GiNaC::ex> dynamics(eq.f.begin(), eq.f.end());
    for (unsigned i = 0; i < eq.M.rows(); ++i)
        for (unsigned j = 0; j < eq.M.cols(); ++j) dynamics.push_back(eq.M(i, j));
    const std::string kinks = switching_surfaces(dynamics).empty()
                                  ? ""
                                  : "    /// On a switching surface (switch_names, switching()) f has a kink or a jump and J is not defined\n"
                                    "    /// there: the value is the derivative on the side the code's branch takes (sign(0) = 0).\n";
    std::ostringstream os;
    os << emit_function(state_terms, table) << "\n" << emit_function(param_terms, table) << "\n";
    os << combine("    /// J = dx'/dx = [[0, I], [M^-1 dr/dq, M^-1 dr/dq']] at (t, x), analytic (jacobian_terms()), with one\n"
                  "    /// factorization of M; a singular M throws as in rhs(). A member template: compiled only where called.\n" +
                      kinks,
                  "state_jacobian", "StateJacobian", "J", "analytic_state_jacobian");
    os << "\n";
    os << combine("    /// Jp = dx'/dp = [[0], [M^-1 dr/dp]] at (t, x), columns in param_names order, analytic\n"
                  "    /// (parameter_jacobian_terms()), with one factorization of M. A member template: compiled only where called.\n",
                  "parameter_jacobian", "ParameterJacobian", "Jp", "analytic_parameter_jacobian");
    return os.str();
}

std::string emit_recursion_jacobian() {
    return "    /// J = dx'/dx at (t, x) by forward differentiation through rhs(), the tree's O(n) recursion\n"
           "    /// (eomgen::state_jacobian); exact to round-off; for Model<double>. A member template: compiled only where\n"
           "    /// called. A singular M throws as in rhs().\n"
           "    template <class MatJ = StateJacobian>\n"
           "    static void state_jacobian(const Scalar& t, const State& x_, const Params& p_, MatJ& J_) {\n"
           "        static_assert(std::is_same_v<Scalar, double>, \"state_jacobian() of a tree is for Model<double>\");\n"
           "        eomgen::state_jacobian<Model>(t, x_, p_, J_);\n"
           "    }\n\n"
           "    /// Jp = dx'/dp at (t, x), columns in param_names order, by forward differentiation through rhs()\n"
           "    /// (eomgen::linearize); for Model<double>. A member template: compiled only where called.\n"
           "    template <class MatJp = ParameterJacobian>\n"
           "    static void parameter_jacobian(const Scalar& t, const State& x_, const Params& p_, MatJp& Jp_) {\n"
           "        static_assert(std::is_same_v<Scalar, double>, \"parameter_jacobian() of a tree is for Model<double>\");\n"
           "        StateJacobian A_;\n"
           "        eomgen::linearize<Model>(t, x_, p_, A_, Jp_);\n"
           "    }\n\n";
}

}  // namespace eomgen::codegen
