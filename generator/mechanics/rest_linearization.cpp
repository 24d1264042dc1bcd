/** @file rest_linearization.cpp  Coefficients of the equations linearized about rest (rest_linearization.hpp). */
#include "mechanics/rest_linearization.hpp"

#include "mechanics/pole_free_subs.hpp"

#include <optional>
#include <sstream>

namespace eomgen {
namespace {

/// e at q̇ = 0. Where substituting divides by zero — ∂/∂θ' of θ' sqrt(θ'²), quadratic drag written without abs —
/// the limit along each velocity taken alone, from both sides: q̇_j = ±ε with ε a positive symbol, so that
/// sqrt(ε²) = ε and the quotient cancels. Both sides must agree; otherwise e has no value at rest and
/// NoValueAtRest names it.
GiNaC::ex at_rest(const GiNaC::ex& e, const std::vector<GiNaC::symbol>& qd, const GiNaC::exmap& rest) {
    if (const std::optional<GiNaC::ex> v = subs_unless_pole(e, rest, GiNaC::subs_options::no_pattern)) return *v;
    GiNaC::ex value = e;
    for (std::size_t j = 0; j < qd.size(); ++j) {
        if (!value.has(qd[j])) continue;
        const GiNaC::possymbol eps("eps");
        std::optional<GiNaC::ex> side[2];
        for (int s = 0; s < 2; ++s) {
            const GiNaC::ex along = GiNaC::normal(value.subs(GiNaC::exmap{{qd[j], (s == 0 ? 1 : -1) * eps}},
                                                             GiNaC::subs_options::no_pattern));
            side[s] = subs_unless_pole(along, GiNaC::exmap{{eps, 0}}, GiNaC::subs_options::no_pattern);
        }
        if (!side[0] || !side[1] || !GiNaC::normal(*side[0] - *side[1]).is_zero())
            throw NoValueAtRest(e, qd[j]);
        value = *side[0];
    }
    return value;
}

}  // namespace

NoValueAtRest::NoValueAtRest(const GiNaC::ex& e, const GiNaC::symbol& velocity)
    : std::runtime_error([&] {
          std::ostringstream os;
          os << e << " has no value at rest: it has no limit as " << velocity << " -> 0, or a different one from "
             << "either side";
          return os.str();
      }()) {}

RestLinearization linearize_about_rest(const GiNaC::ex& L, const std::vector<GiNaC::ex>& Q,
                                       const std::vector<GiNaC::symbol>& q, const std::vector<GiNaC::symbol>& qd) {
    const std::size_t n = q.size();
    GiNaC::exmap rest;
    for (const GiNaC::symbol& v : qd) rest[v] = 0;
    const auto at_rest = [&](const GiNaC::ex& e) { return eomgen::at_rest(e, qd, rest); };
    RestLinearization r;
    const GiNaC::ex L0 = at_rest(L);
    r.V_eff = -L0;
    r.beta.resize(n);
    r.gradient.resize(n);
    r.M.assign(n, std::vector<GiNaC::ex>(n));
    r.K.assign(n, std::vector<GiNaC::ex>(n));
    r.D.assign(n, std::vector<GiNaC::ex>(n));
    for (std::size_t i = 0; i < n; ++i) {
        const GiNaC::ex dL = L.diff(qd[i]);
        r.beta[i] = at_rest(dL);
        for (std::size_t j = 0; j < n; ++j) r.M[i][j] = at_rest(dL.diff(qd[j]));
        r.gradient[i] = -L0.diff(q[i]) - at_rest(Q[i]);
    }
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            r.K[i][j] = r.gradient[i].diff(q[j]);
            r.D[i][j] = r.beta[i].diff(q[j]) - r.beta[j].diff(q[i]) - at_rest(Q[i].diff(qd[j]));
        }
    return r;
}

}  // namespace eomgen
