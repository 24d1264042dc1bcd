/** @file tree_emitter.cpp  rhs() through the particle tree's recursion (tree_emitter.hpp). */
#include "codegen/tree_emitter.hpp"

#include "mechanics/particle_tree.hpp"

#include <fmt/format.h>

#include <sstream>

namespace eomgen::codegen {
namespace {

std::string int_array(const std::vector<int>& v) {
    std::string s;
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + std::to_string(v[i]);
    return s;
}

}  // namespace

std::optional<std::string> emit_tree_rhs(const Model& model, const Equations& eq, const SymbolTable& table) {
    const std::size_t n = model.dof();
    if (n < kTreeMinN || !eq.constraints.empty()) return std::nullopt;
    const std::optional<ParticleTree> tree = find_particle_tree(model, eq);
    if (!tree) return std::nullopt;
    const std::size_t D = tree->components;
    std::vector<Output> terms;
    for (std::size_t k = 0; k < n; ++k) {
        for (std::size_t c = 0; c < D; ++c) {
            terms.push_back({fmt::format("terms_.lever({}, {})", c, k), tree->lever[k][c]});
            terms.push_back({fmt::format("terms_.bias({}, {})", c, k), tree->bias[k][c]});
            terms.push_back({fmt::format("terms_.weight({}, {})", c, k), tree->weight[k][c]});
        }
        terms.push_back({fmt::format("terms_.joint_inertia({})", k), tree->joint_inertia[k]});
        terms.push_back({fmt::format("terms_.force({})", k), tree->force[k]});
    }
    std::ostringstream os;
    os << "    /// T is a tree of point masses (generator/mechanics/particle_tree.hpp): coordinate k's parent (-1: the\n"
          "    /// ground), the coordinates parents first, and the components of the levers.\n";
    os << "    static constexpr int tree_components = " << D << ";\n";
    os << "    static constexpr std::array<int, nq> tree_parent = {" << int_array(tree->parent) << "};\n";
    os << "    static constexpr std::array<int, nq> tree_order = {" << int_array(tree->order) << "};\n";
    os << "    using TreeTerms = eomgen::ParticleTreeTerms<Scalar, nq, tree_components>;\n\n";
    const FunctionSpec spec{"The tree's levers a_k, their accelerations, the nodes' weights, J_k and Q_k "
                            "(eomgen/particle_tree.hpp).",
                            "void",
                            "tree_terms",
                            {{"Scalar", "t"}, {"Config", "q_"}, {"Config", "qd_"}, {"Params", "p_"}},
                            {{"TreeTerms", "terms_"}},
                            terms};
    os << emit_function(spec, table) << "\n";
    os << "    /// x' = [q', q''] with q'' from the tree's recursion in O(n) (eomgen::particle_tree_accelerations), M not\n"
          "    /// formed; a singular M throws eomgen::SingularMassMatrix.\n";
    os << "    static void rhs(const Scalar& t, const State& x_, const Params& p_, State& xdot_) {\n";
    os << "        const Config q_ = x_.template head<nq>();\n";
    os << "        const Config qd_ = x_.template tail<nq>();\n";
    os << "        TreeTerms terms_;\n        tree_terms(t, q_, qd_, p_, terms_);\n";
    os << "        Config qdd_;\n        eomgen::particle_tree_accelerations(tree_parent, tree_order, terms_, qdd_, t, x_);\n";
    os << "        xdot_.template head<nq>() = qd_;\n        xdot_.template tail<nq>() = qdd_;\n    }\n\n";
    return os.str();
}

}  // namespace eomgen::codegen
