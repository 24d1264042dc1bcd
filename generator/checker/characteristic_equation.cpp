/** @file characteristic_equation.cpp  Exponential trial solutions and the characteristic equation about rest.
 */
#include "checker/characteristic_equation.hpp"

#include <exception>

namespace eomgen::checker {

namespace {

bool state_free(const GiNaC::ex& e, const Model& model) {
    for (const Coordinate& c : model.coordinates)
        if (e.has(c.q) || e.has(c.qd) || e.has(c.qdd)) return false;
    return !e.has(model.t);
}

}  // namespace

std::optional<ExponentialTrial> exponential_trial(const GiNaC::ex& left, const GiNaC::ex& right,
                                                  const Model& model, LatexContext& ctx) {
    for (const auto& [x, y] : {std::pair(left, right), std::pair(right, left)}) {
        bool coordinate = false;
        for (const Coordinate& c : model.coordinates) coordinate = coordinate || x.is_equal(c.q);
        if (!coordinate) continue;
        // y = e^{λ t} or A e^{λ t}.
        GiNaC::ex exponential = y, amplitude = 1;
        if (GiNaC::is_a<GiNaC::mul>(y) && y.nops() == 2)
            for (std::size_t k = 0; k < 2; ++k)
                if (GiNaC::is_the_function<GiNaC::exp_SERIAL>(y.op(k))) {
                    exponential = y.op(k);
                    amplitude = y.op(1 - k);
                }
        if (!GiNaC::is_the_function<GiNaC::exp_SERIAL>(exponential)) continue;
        if (!amplitude.is_equal(1)) {
            const FreeName* fa = ctx.free_name_of(amplitude);
            if (!fa || fa->kind != NameKind::Unknown) continue;
        }
        const GiNaC::ex power = exponential.op(0);
        if (!GiNaC::is_a<GiNaC::mul>(power) || power.nops() != 2) continue;
        for (std::size_t k = 0; k < 2; ++k) {
            if (!power.op(k).is_equal(ctx.time)) continue;
            const GiNaC::ex lambda = power.op(1 - k);
            const FreeName* f = ctx.free_name_of(lambda);
            if (!f || f->kind != NameKind::Unknown || f->name == "i" || lambda.is_equal(amplitude)) continue;
            ExponentialTrial t;
            t.exponent = lambda;
            return t;
        }
    }
    return std::nullopt;
}

std::optional<GiNaC::ex> characteristic_polynomial(const std::vector<GiNaC::ex>& motion, const Model& model,
                                                   const GiNaC::ex& lambda) {
    const std::size_t n = model.coordinates.size();
    if (motion.size() != n || n == 0) return std::nullopt;
    GiNaC::exmap rest;
    for (const Coordinate& c : model.coordinates) {
        rest[c.q] = 0;
        rest[c.qd] = 0;
        rest[c.qdd] = 0;
    }
    try {
        GiNaC::matrix a(static_cast<unsigned>(n), static_cast<unsigned>(n));
        for (std::size_t i = 0; i < n; ++i) {
            if (motion[i].has(model.t)) return std::nullopt;
            if (!GiNaC::normal(motion[i].subs(rest)).is_zero())
                return std::nullopt;  // rest is no equilibrium
            for (std::size_t k = 0; k < n; ++k) {
                const Coordinate& c = model.coordinates[k];
                a(unsigned(i), unsigned(k)) =
                    GiNaC::normal((lambda * lambda * motion[i].diff(c.qdd) + lambda * motion[i].diff(c.qd) +
                                   motion[i].diff(c.q))
                                      .subs(rest));
            }
        }
        return GiNaC::normal(a.determinant());
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

bool check_characteristic(const GiNaC::ex& a, const GiNaC::ex& b, const ExponentialTrial& trial,
                          const GiNaC::ex& p, Comparisons& cmp, EquationCheck& r) {
    const GiNaC::ex& lambda = trial.exponent;
    const std::string what =
        "the characteristic equation $\\det(\\lambda^2 M_0 + \\lambda C_0 + K_0) = 0$ about rest, " +
        std::string("$") + cmp.latex(p) + " = 0$, of the trial solution of line " +
        std::to_string(trial.line);
    // `\lambda = -\gamma \pm \sqrt{\gamma^2 - \omega_0^2}`: a root.
    for (const auto& [x, y] : {std::pair(a, b), std::pair(b, a)}) {
        if (!x.is_equal(lambda) || y.has(lambda)) continue;
        r.compared_with = what;
        try {
            const GiNaC::ex there = p.subs(lambda == y);
            if (cmp.same(there, 0, 1e-9)) {
                r.verdict = Verdict::Agrees;
                r.reason = "a root of it";
            } else {
                r.verdict = Verdict::Disagrees;
                r.reason = "not a root of it: it leaves $" + cmp.latex(GiNaC::normal(there)) + "$";
                r.difference = cmp.latex(GiNaC::normal(there));
                r.wrong_terms = {"not a root of the characteristic equation: put in, it leaves $" +
                                 r.difference + "$, not 0"};
            }
        } catch (const std::exception&) {
            return false;
        }
        return true;
    }
    // An equation in λ: p = 0 times a factor free of λ.
    const GiNaC::ex e = a - b;
    if (!e.has(lambda)) return false;
    try {
        const GiNaC::ex ratio = GiNaC::normal(e / p);
        r.compared_with = what;
        if (!ratio.has(lambda) && !cmp.same(ratio, 0, 1e-9)) {
            r.verdict = Verdict::Agrees;
            r.reason = ratio.is_equal(1)
                           ? "the same equation"
                           : "the same equation times $" + cmp.latex(GiNaC::normal(1 / ratio)) + "$";
            return true;
        }
        // Written monic in λ², as the text likely normalizes it: the correction in that form.
        const GiNaC::ex lead = p.expand().coeff(lambda, p.expand().degree(lambda));
        const GiNaC::ex monic = GiNaC::normal(p / lead).expand();
        r.verdict = Verdict::Disagrees;
        r.reason = "not the characteristic equation, nor a multiple of it";
        r.difference = cmp.latex(
            GiNaC::normal(e - GiNaC::normal(e.expand().coeff(lambda, e.expand().degree(lambda))) * monic));
        r.corrected = cmp.latex(monic) + " = 0";
        r.wrong_terms = {"not the characteristic equation $" + cmp.latex(p) +
                         " = 0$ times a factor free of $" + cmp.latex(lambda) + "$"};
        return true;
    } catch (const std::exception&) {
        return false;
    }
}

}  // namespace eomgen::checker
