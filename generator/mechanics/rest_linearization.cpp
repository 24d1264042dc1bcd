/** @file rest_linearization.cpp  Coefficients of the equations linearized about rest (rest_linearization.hpp). */
#include "mechanics/rest_linearization.hpp"

namespace eomgen {

RestLinearization linearize_about_rest(const GiNaC::ex& L, const std::vector<GiNaC::ex>& Q,
                                       const std::vector<GiNaC::symbol>& q, const std::vector<GiNaC::symbol>& qd) {
    const std::size_t n = q.size();
    GiNaC::exmap rest;
    for (const GiNaC::symbol& v : qd) rest[v] = 0;
    const auto at_rest = [&](const GiNaC::ex& e) { return e.subs(rest, GiNaC::subs_options::no_pattern); };
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
