/** @file jacobian_terms.cpp  ∂(f − M q̈)/∂(q, q̇, p) at fixed q̈, for the generated analytic Jacobians. */
#include "mechanics/jacobian_terms.hpp"

#include <map>
#include <set>

namespace eomgen {
namespace {

/// The terms of r_i = f_i − Σ_j M_ij q̈_j, expanded once: ∂r_i/∂s is then the derivative of the few terms that hold s
/// (in an n-link chain a term holds two or three of the n angles), not of the whole of f_i and of every M_ij.
std::vector<std::vector<GiNaC::ex>> residual_terms(const Model& model, const Equations& eq) {
    const std::size_t n = model.dof();
    std::vector<std::vector<GiNaC::ex>> out(n);
    for (std::size_t i = 0; i < n; ++i) {
        GiNaC::ex r = eq.f[i];
        for (std::size_t j = 0; j < n; ++j)
            r -= eq.M(static_cast<unsigned>(i), static_cast<unsigned>(j)) * model.coordinates[j].qdd;
        r = r.expand();
        if (GiNaC::is_a<GiNaC::add>(r))
            for (const GiNaC::ex& term : r) out[i].push_back(term);
        else if (!r.is_zero())
            out[i].push_back(r);
    }
    return out;
}

/// ∂r/∂s for each symbol s (columns k), rows i: each term is read once for the symbols it holds and differentiated
/// by those of them that are asked for.
std::vector<std::vector<GiNaC::ex>> columns(const std::vector<std::vector<GiNaC::ex>>& terms,
                                            const std::vector<GiNaC::symbol>& symbols) {
    std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less> column;
    for (std::size_t k = 0; k < symbols.size(); ++k) column[symbols[k]] = k;
    std::vector<std::vector<GiNaC::ex>> out(terms.size(), std::vector<GiNaC::ex>(symbols.size()));
    for (std::size_t i = 0; i < terms.size(); ++i) {
        std::vector<GiNaC::exvector> parts(symbols.size());
        for (const GiNaC::ex& term : terms[i]) {
            std::set<std::size_t> held;
            for (auto it = term.preorder_begin(); it != term.preorder_end(); ++it)
                if (GiNaC::is_a<GiNaC::symbol>(*it)) {
                    const auto c = column.find(*it);
                    if (c != column.end()) held.insert(c->second);
                }
            for (std::size_t k : held) parts[k].push_back(term.diff(symbols[k]));
        }
        for (std::size_t k = 0; k < symbols.size(); ++k) out[i][k] = GiNaC::add(parts[k]);
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
    const std::vector<std::vector<GiNaC::ex>> terms = residual_terms(model, eq);
    return {columns(terms, q), columns(terms, qd), columns(terms, p)};
}

}  // namespace eomgen
