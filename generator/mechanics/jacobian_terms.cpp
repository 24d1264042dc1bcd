/** @file jacobian_terms.cpp  ∂(f − M q̈)/∂(q, q̇, p) at fixed q̈, for the generated analytic Jacobians. */
#include "mechanics/jacobian_terms.hpp"

namespace eomgen {
namespace {

/// ∂r_i/∂s for every i, r = f − M q̈: ∂f_i/∂s − Σ_j ∂M_ij/∂s q̈_j (the M terms only where M involves s).
std::vector<GiNaC::ex> residual_derivative(const Model& model, const Equations& eq, const GiNaC::symbol& s) {
    const std::size_t n = model.dof();
    std::vector<GiNaC::ex> out(n);
    for (std::size_t i = 0; i < n; ++i) {
        GiNaC::ex d = eq.f[i].diff(s);
        for (std::size_t j = 0; j < n; ++j) {
            const GiNaC::ex& Mij = eq.M(static_cast<unsigned>(i), static_cast<unsigned>(j));
            if (Mij.has(s)) d -= Mij.diff(s) * model.coordinates[j].qdd;
        }
        out[i] = d;
    }
    return out;
}

/// Columns (one per symbol) of ∂r/∂s as rows i, columns k.
std::vector<std::vector<GiNaC::ex>> columns(const Model& model, const Equations& eq,
                                            const std::vector<GiNaC::symbol>& symbols) {
    std::vector<std::vector<GiNaC::ex>> out(model.dof(), std::vector<GiNaC::ex>(symbols.size()));
    for (std::size_t k = 0; k < symbols.size(); ++k) {
        const std::vector<GiNaC::ex> col = residual_derivative(model, eq, symbols[k]);
        for (std::size_t i = 0; i < col.size(); ++i) out[i][k] = col[i];
    }
    return out;
}

}  // namespace

JacobianTerms jacobian_terms(const Model& model, const Equations& eq) {
    std::vector<GiNaC::symbol> q, qd, p;
    for (const Coordinate& c : model.coordinates) {
        q.push_back(c.q);
        qd.push_back(c.qd);
    }
    for (const Parameter& par : model.parameters) p.push_back(par.symbol);
    return {columns(model, eq, q), columns(model, eq, qd), columns(model, eq, p)};
}

}  // namespace eomgen
