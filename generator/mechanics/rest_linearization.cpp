/** @file rest_linearization.cpp  Coefficients of the equations linearized about rest (rest_linearization.hpp). */
#include "mechanics/rest_linearization.hpp"

#include "mechanics/differentiator.hpp"
#include "mechanics/pole_free_subs.hpp"
#include "model/nonsmooth.hpp"

#include <algorithm>
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

/// e with each non-smooth function whose switching surface does not pass through rest (sign(v − x') with the belt's
/// speed v) replaced by its first-order Taylor polynomial about rest, F(a₀) + Σ ∂F/∂a_i(a₀)·(a_i − a₀_i): smooth there,
/// so the one-sided quotients below see only the surfaces that do pass through rest.
GiNaC::ex linearize_off_surface(const GiNaC::ex& e, const std::vector<GiNaC::symbol>& qd, const GiNaC::exmap& rest) {
    if (is_nonsmooth_function(e) && nonsmooth_in(e, qd)) {
        const GiNaC::ex s = switching_surfaces({e}).front().s;
        if (!GiNaC::normal(at_rest(s, qd, rest)).is_zero()) {
            const GiNaC::function& f = GiNaC::ex_to<GiNaC::function>(e);
            GiNaC::exvector args, args0;
            for (const GiNaC::ex& a : e) {
                args.push_back(a);
                args0.push_back(at_rest(a, qd, rest));
            }
            GiNaC::exvector dummies;
            GiNaC::exmap at0;
            for (std::size_t i = 0; i < args.size(); ++i) {
                dummies.push_back(GiNaC::symbol());
                at0[dummies[i]] = args0[i];
            }
            const GiNaC::ex generic = GiNaC::function(f.get_serial(), dummies);
            GiNaC::ex out = generic.subs(at0, GiNaC::subs_options::no_pattern);
            for (std::size_t i = 0; i < args.size(); ++i)
                out += generic.diff(GiNaC::ex_to<GiNaC::symbol>(dummies[i])).subs(at0, GiNaC::subs_options::no_pattern) *
                       (args[i] - args0[i]);
            return out;
        }
    }
    struct Recurse : GiNaC::map_function {
        const std::vector<GiNaC::symbol>& qd;
        const GiNaC::exmap& rest;
        Recurse(const std::vector<GiNaC::symbol>& v, const GiNaC::exmap& r) : qd(v), rest(r) {}
        GiNaC::ex operator()(const GiNaC::ex& x) override { return linearize_off_surface(x, qd, rest); }
    } recurse(qd, rest);
    if (GiNaC::is_exactly_a<GiNaC::add>(e) || GiNaC::is_exactly_a<GiNaC::mul>(e) ||
        GiNaC::is_exactly_a<GiNaC::power>(e) || GiNaC::is_exactly_a<GiNaC::function>(e))
        return e.map(recurse);
    return e;
}

/// Whether e has a switching surface, in the velocities, that passes through rest (|v| or sign(v), not sign(v − x')).
bool switches_at_rest(const GiNaC::ex& e, const std::vector<GiNaC::symbol>& qd, const GiNaC::exmap& rest) {
    for (const SwitchingSurface& w : switching_surfaces({e}))
        if (std::any_of(qd.begin(), qd.end(), [&](const GiNaC::symbol& v) { return w.s.has(v); }) &&
            GiNaC::normal(at_rest(w.s, qd, rest)).is_zero())
            return true;
    return false;
}

/// ∂e/∂v at q̇ = 0. Where a switching surface of e in the velocities passes through rest (abs, sign of a
/// velocity), GiNaC's derivative is the one away from it (d sign/dx = 0), which at rest may be wrong: the
/// one-sided difference quotients along v, (e(v = ±ε) − e(0))/(±ε) as ε → 0⁺, are taken instead, and must agree.
/// Empty where they do not (dry friction: sign(v) jumps at rest) or do not exist.
std::optional<GiNaC::ex> derivative_at_rest(const GiNaC::ex& e, const GiNaC::symbol& v,
                                            const std::vector<GiNaC::symbol>& qd, const GiNaC::exmap& rest) {
    if (!switches_at_rest(e, qd, rest)) return at_rest(e.diff(v), qd, rest);
    const GiNaC::ex smooth_elsewhere = linearize_off_surface(e, qd, rest);
    GiNaC::exmap others = rest;
    others.erase(v);
    const GiNaC::ex e0 = at_rest(smooth_elsewhere, qd, rest);
    const GiNaC::possymbol eps("eps");
    std::optional<GiNaC::ex> side[2];
    for (int s = 0; s < 2; ++s) {
        const GiNaC::ex step = (s == 0 ? 1 : -1) * eps;
        GiNaC::exmap at = others;
        at[v] = step;
        // Not subs(): GiNaC throws on a zero denominator from inside the product it builds, and leaks it.
        const std::optional<GiNaC::ex> along = subs_unless_pole(smooth_elsewhere, at, GiNaC::subs_options::no_pattern);
        if (!along) continue;
        side[s] = subs_unless_pole(GiNaC::normal((*along - e0) / step), GiNaC::exmap{{eps, 0}},
                                   GiNaC::subs_options::no_pattern);
        if (side[s] && side[s]->has(eps)) side[s].reset();
    }
    if (!side[0] || !side[1] || !GiNaC::normal(*side[0] - *side[1]).is_zero()) return std::nullopt;
    return *side[0];
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
    // One remembered Differentiator per variable over every expression, skipping the parts without it
    // (mechanics/differentiator.hpp): GiNaC's diff() of L and its n derivatives, n² walks of whole trees, was
    // the 60-link pendulum's 19–30 s here.
    install_chain_rule();
    std::vector<GiNaC::ex> variables(q.begin(), q.end());
    variables.insert(variables.end(), qd.begin(), qd.end());
    SymbolSupport support(variables);
    std::vector<Differentiator> d_dq, d_dqd;
    for (std::size_t j = 0; j < n; ++j) {
        d_dq.emplace_back(q[j], &support);
        d_dqd.emplace_back(qd[j], &support);
    }
    for (std::size_t i = 0; i < n; ++i) {
        const GiNaC::ex dL = d_dqd[i](L);
        r.beta[i] = at_rest(dL);
        for (std::size_t j = 0; j < n; ++j) r.M[i][j] = at_rest(d_dqd[j](dL));
        r.gradient[i] = -d_dq[i](L0) - at_rest(Q[i]);
    }
    r.D_defined.assign(n, std::vector<bool>(n, true));
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            r.K[i][j] = d_dq[j](r.gradient[i]);
            const std::optional<GiNaC::ex> dQ = derivative_at_rest(Q[i], qd[j], qd, rest);
            if (!dQ) {
                r.D_defined[i][j] = false;
                // Named by coordinates, not printed: GiNaC's order of terms varies from run to run.
                const std::string qi = q[i].get_name(), vj = q[j].get_name() + "'";
                r.undefined.push_back("the generalized force on " + qi + " has no derivative in " + vj +
                                      " at rest (its one-sided limits at " + vj +
                                      " = 0 differ: a sign, or a kink, there)");
            }
            r.D[i][j] = d_dq[j](r.beta[i]) - d_dq[i](r.beta[j]) - (dQ ? *dQ : GiNaC::ex(0));
        }
    return r;
}

}  // namespace eomgen
