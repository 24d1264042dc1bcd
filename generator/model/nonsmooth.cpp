/** @file nonsmooth.cpp  abs, sign, heaviside, max and min for real arguments (nonsmooth.hpp). */
#include "model/nonsmooth.hpp"

#include "model/stored_terms.hpp"

#include <algorithm>
#include <unordered_set>

namespace eomgen {
namespace {

using GiNaC::ex;
using GiNaC::numeric;

/// x = c·y with c a real number other than 1: c and y, else nothing. (Not a − b against b − a: GiNaC's order of
/// a sum's terms varies from run to run, and the generated code would with it; the code generator's DAG merges
/// those.)
bool scaled(const ex& x, numeric& c, ex& y) {
    if (!GiNaC::is_exactly_a<GiNaC::mul>(x)) return false;
    const ex last = x.op(x.nops() - 1);
    if (!GiNaC::is_exactly_a<numeric>(last) || !GiNaC::ex_to<numeric>(last).is_real() || last.is_equal(1) ||
        last.is_zero())
        return false;
    c = GiNaC::ex_to<numeric>(last);
    y = x / c;
    return true;
}

/// An even integer power: x = b^(2k).
bool even_power(const ex& x) {
    if (!GiNaC::is_exactly_a<GiNaC::power>(x) || !GiNaC::is_exactly_a<numeric>(x.op(1))) return false;
    const numeric k = GiNaC::ex_to<numeric>(x.op(1));
    return k.is_integer() && k.is_even();
}

bool real_number(const ex& x) {
    return GiNaC::is_exactly_a<numeric>(x) && GiNaC::ex_to<numeric>(x).is_real();
}

ex abs_eval(const ex& x) {
    if (real_number(x)) return GiNaC::abs(GiNaC::ex_to<numeric>(x));
    if (x.info(GiNaC::info_flags::nonnegative) || even_power(x)) return x;
    if (x.info(GiNaC::info_flags::negative)) return -x;
    if (is_nonsmooth_function(x) && GiNaC::ex_to<GiNaC::function>(x).get_name() == "abs") return x;
    numeric c;
    ex y;
    if (scaled(x, c, y)) return GiNaC::abs(c) * real_abs(y);
    return GiNaC::function(GiNaC::function::current_serial, x).hold();
}
ex abs_evalf(const ex& x) {
    if (real_number(x)) return GiNaC::abs(GiNaC::ex_to<numeric>(x));
    return GiNaC::function(GiNaC::function::current_serial, x).hold();
}
ex abs_deriv(const ex& x, unsigned) { return sign(x); }
/// |x|^(2k) = x^(2k) for real x (a velocity's squared magnitude written |v|^2); other powers stay powers of |x|.
ex abs_power(const ex& x, const ex& p) {
    if (GiNaC::is_exactly_a<numeric>(p) && GiNaC::ex_to<numeric>(p).is_even()) return GiNaC::pow(x, p);
    return GiNaC::power(real_abs(x), p).hold();
}

ex sign_eval(const ex& x) {
    if (real_number(x)) return numeric(GiNaC::ex_to<numeric>(x).csgn());
    if (x.info(GiNaC::info_flags::positive)) return 1;
    if (x.info(GiNaC::info_flags::negative)) return -1;
    if (is_nonsmooth_function(x) && GiNaC::ex_to<GiNaC::function>(x).get_name() == "sign") return x;
    numeric c;
    ex y;
    if (scaled(x, c, y)) return c.csgn() * sign(y);
    return GiNaC::function(GiNaC::function::current_serial, x).hold();
}
ex sign_evalf(const ex& x) {
    if (real_number(x)) return numeric(GiNaC::ex_to<numeric>(x).csgn());
    return GiNaC::function(GiNaC::function::current_serial, x).hold();
}
ex zero_deriv(const ex&, unsigned) { return 0; }

ex heaviside_eval(const ex& x) {
    if (real_number(x)) {
        const int s = GiNaC::ex_to<numeric>(x).csgn();
        return s > 0 ? ex(1) : s < 0 ? ex(0) : ex(numeric(1, 2));
    }
    if (x.info(GiNaC::info_flags::positive)) return 1;
    if (x.info(GiNaC::info_flags::negative)) return 0;
    return GiNaC::function(GiNaC::function::current_serial, x).hold();
}
ex heaviside_evalf(const ex& x) { return heaviside_eval(x); }
ex heaviside_deriv(const ex&, unsigned) { return 0; }

ex max_eval(const ex& a, const ex& b) {
    if (real_number(a) && real_number(b))
        return GiNaC::ex_to<numeric>(a) < GiNaC::ex_to<numeric>(b) ? b : a;
    if (a.is_equal(b)) return a;
    const ex d = a - b;
    if (d.info(GiNaC::info_flags::nonnegative)) return a;
    if (d.info(GiNaC::info_flags::negative)) return b;
    // max is symmetric: one order of the arguments (GiNaC's), so that max(a, b) and max(b, a) are one expression.
    if (b.compare(a) < 0) return real_max(b, a);
    return GiNaC::function(GiNaC::function::current_serial, a, b).hold();
}
ex max_evalf(const ex& a, const ex& b) { return max_eval(a, b); }
ex max_deriv(const ex& a, const ex& b, unsigned which) { return which == 0 ? heaviside(a - b) : heaviside(b - a); }

ex min_eval(const ex& a, const ex& b) {
    if (real_number(a) && real_number(b))
        return GiNaC::ex_to<numeric>(b) < GiNaC::ex_to<numeric>(a) ? b : a;
    if (a.is_equal(b)) return a;
    const ex d = a - b;
    if (d.info(GiNaC::info_flags::nonnegative)) return b;
    if (d.info(GiNaC::info_flags::negative)) return a;
    if (b.compare(a) < 0) return real_min(b, a);
    return GiNaC::function(GiNaC::function::current_serial, a, b).hold();
}
ex min_evalf(const ex& a, const ex& b) { return min_eval(a, b); }
ex min_deriv(const ex& a, const ex& b, unsigned which) { return which == 0 ? heaviside(b - a) : heaviside(a - b); }

// GiNaC has an abs of its own, for complex arguments: overloaded(2) says the second function of that name is meant.
const unsigned abs_serial = GiNaC::function::register_new(GiNaC::function_options("abs", 1)
                                                              .overloaded(2)
                                                              .eval_func(abs_eval)
                                                              .evalf_func(abs_evalf)
                                                              .derivative_func(abs_deriv)
                                                              .power_func(abs_power));
const unsigned sign_serial = GiNaC::function::register_new(GiNaC::function_options("sign", 1)
                                                               .eval_func(sign_eval)
                                                               .evalf_func(sign_evalf)
                                                               .derivative_func(zero_deriv));
const unsigned heaviside_serial = GiNaC::function::register_new(GiNaC::function_options("heaviside", 1)
                                                                    .eval_func(heaviside_eval)
                                                                    .evalf_func(heaviside_evalf)
                                                                    .derivative_func(heaviside_deriv));
const unsigned max_serial = GiNaC::function::register_new(
    GiNaC::function_options("max", 2).eval_func(max_eval).evalf_func(max_evalf).derivative_func(max_deriv));
const unsigned min_serial = GiNaC::function::register_new(
    GiNaC::function_options("min", 2).eval_func(min_eval).evalf_func(min_evalf).derivative_func(min_deriv));

bool has_serial(const ex& e, unsigned serial) {
    return GiNaC::is_exactly_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_serial() == serial;
}

}  // namespace

ex real_abs(const ex& x) { return GiNaC::function(abs_serial, x); }
ex sign(const ex& x) { return GiNaC::function(sign_serial, x); }
ex heaviside(const ex& x) { return GiNaC::function(heaviside_serial, x); }
ex real_max(const ex& a, const ex& b) { return GiNaC::function(max_serial, a, b); }
ex real_min(const ex& a, const ex& b) { return GiNaC::function(min_serial, a, b); }

bool nonsmooth_value(const std::string& name, const double* a, std::size_t n, double& out) {
    if (n == 1 && name == "abs") out = a[0] < 0 ? -a[0] : a[0];
    else if (n == 1 && name == "sign") out = a[0] > 0 ? 1.0 : a[0] < 0 ? -1.0 : 0.0;
    else if (n == 1 && name == "heaviside") out = a[0] > 0 ? 1.0 : a[0] < 0 ? 0.0 : 0.5;
    else if (n == 2 && name == "max") out = a[0] < a[1] ? a[1] : a[0];
    else if (n == 2 && name == "min") out = a[1] < a[0] ? a[1] : a[0];
    else return false;
    return true;
}

bool is_nonsmooth_function(const ex& e) {
    return has_serial(e, abs_serial) || has_serial(e, sign_serial) || has_serial(e, heaviside_serial) ||
           has_serial(e, max_serial) || has_serial(e, min_serial);
}

namespace {
ex signs_of_quotients(const ex& product);
}  // namespace

bool contains_nonsmooth(const ex& e) { return contains_nonsmooth(std::vector<ex>{e}); }

bool contains_nonsmooth(const std::vector<ex>& exprs) {
    // Each distinct node once, through the stored children (a preorder walk by op() built a node per term and
    // met a shared subexpression once per occurrence: a tenth of emitting the 60-link pendulum).
    std::unordered_set<const GiNaC::basic*> seen;
    std::vector<ex> stack(exprs.rbegin(), exprs.rend());
    while (!stack.empty()) {
        const ex x = std::move(stack.back());
        stack.pop_back();
        if (is_nonsmooth_function(x)) return true;
        StoredTerms::for_each_child(x, [&](const ex& child) {
            if (child.nops() > 0 && seen.insert(&GiNaC::ex_to<GiNaC::basic>(child)).second) stack.push_back(child);
        });
    }
    return false;
}

ex real_roots(const ex& e) {
    if (GiNaC::is_exactly_a<GiNaC::power>(e) && GiNaC::is_exactly_a<numeric>(e.op(1))) {
        const numeric r = GiNaC::ex_to<numeric>(e.op(1));
        const ex base = real_roots(e.op(0));
        if (!r.is_integer() && r.is_rational()) {
            // (Π f_i^(2k_i))^r = Π |f_i|^(2k_i r) when every factor is an even power (or a positive number).
            const auto split = [&](const ex& f, ex& out) {
                if (even_power(f)) {
                    const numeric k = GiNaC::ex_to<numeric>(f.op(1)) * r;
                    out = (k.is_integer() && k.is_even()) ? GiNaC::pow(f.op(0), k) : GiNaC::pow(real_abs(f.op(0)), k);
                    return true;
                }
                if (real_number(f) && GiNaC::ex_to<numeric>(f).is_positive()) {
                    out = GiNaC::pow(f, r);
                    return true;
                }
                return false;
            };
            ex out = 1;
            if (GiNaC::is_exactly_a<GiNaC::mul>(base)) {
                bool all = true;
                for (const ex& f : base) {
                    ex g;
                    if (!split(f, g)) {
                        all = false;
                        break;
                    }
                    out *= g;
                }
                if (all) return out;
            } else if (split(base, out)) {
                return out;
            }
        }
        return GiNaC::pow(base, e.op(1));
    }
    if (GiNaC::is_exactly_a<GiNaC::mul>(e)) return signs_of_quotients(e.map([](const ex& x) { return real_roots(x); }));
    if (GiNaC::is_exactly_a<GiNaC::add>(e) || GiNaC::is_exactly_a<GiNaC::function>(e) ||
        GiNaC::is_exactly_a<GiNaC::power>(e))
        return e.map([](const ex& x) { return real_roots(x); });
    return e;
}

namespace {

/// x·|x|^(-1) (or x^(-1)·|x|) as sign(x), in one product: how a unit vector's sign is written without sign().
ex signs_of_quotients(const ex& product) {
    if (!GiNaC::is_exactly_a<GiNaC::mul>(product)) return product;
    GiNaC::exvector factors(product.begin(), product.end());
    bool changed = false;
    for (std::size_t i = 0; i < factors.size(); ++i)
        for (std::size_t j = 0; j < factors.size(); ++j) {
            if (i == j) continue;
            // factors[i] = x^p with p = ±1, factors[j] = |x|^(-p)
            const ex& a = factors[i];
            const ex& b = factors[j];
            const ex base = GiNaC::is_exactly_a<GiNaC::power>(a) ? a.op(0) : a;
            const ex p = GiNaC::is_exactly_a<GiNaC::power>(a) ? a.op(1) : ex(1);
            if (!(p.is_equal(1) || p.is_equal(-1))) continue;
            if (!GiNaC::is_exactly_a<GiNaC::power>(b) || !b.op(1).is_equal(-p)) continue;
            if (!is_nonsmooth_function(b.op(0)) || GiNaC::ex_to<GiNaC::function>(b.op(0)).get_name() != "abs" ||
                !b.op(0).op(0).is_equal(base))
                continue;
            factors[i] = sign(base);
            factors[j] = 1;
            changed = true;
        }
    if (!changed) return product;
    ex out = 1;
    for (const ex& f : factors) out *= f;
    return out;
}

/// Children before their parent, each distinct node once (`walked`: by address, through the stored children; the
/// surfaces found are in the order of a walk by op(), which met shared nodes again and built a node per term).
void collect_surfaces(const ex& e, std::vector<SwitchingSurface>& out, std::unordered_set<const GiNaC::basic*>& walked) {
    if (e.nops() == 0 || !walked.insert(&GiNaC::ex_to<GiNaC::basic>(e)).second) return;
    StoredTerms::for_each_child(e, [&](const ex& child) { collect_surfaces(child, out, walked); });
    if (!is_nonsmooth_function(e)) return;
    const ex s = surface_of(e);
    if (GiNaC::is_exactly_a<numeric>(s)) return;
    const auto seen = std::find_if(out.begin(), out.end(), [&](const SwitchingSurface& x) {
        return (x.s - s).expand().is_zero() || (x.s + s).expand().is_zero();
    });
    if (seen == out.end())
        out.push_back({s, e, {e}});
    else if (std::none_of(seen->functions.begin(), seen->functions.end(), [&](const ex& f) { return f.is_equal(e); }))
        seen->functions.push_back(e);
}

}  // namespace

ex surface_of(const ex& function) { return function.nops() == 2 ? ex(function.op(0) - function.op(1)) : function.op(0); }

std::vector<SwitchingSurface> switching_surfaces(const std::vector<ex>& exprs) {
    std::vector<SwitchingSurface> out;
    std::unordered_set<const GiNaC::basic*> seen;
    for (const ex& e : exprs) collect_surfaces(e, out, seen);
    return out;
}

ex one_sided(const ex& e, const ex& s, int side) {
    if (e.nops() == 0) return e;
    struct Each : GiNaC::map_function {
        const ex& s;
        int side;
        Each(const ex& surface, int which) : s(surface), side(which) {}
        ex operator()(const ex& x) override { return one_sided(x, s, side); }
    } each(s, side);
    const ex inner = e.map(each);  // the arguments first: they may hold functions of the same surface
    if (!is_nonsmooth_function(inner)) return inner;
    const bool two = has_serial(inner, max_serial) || has_serial(inner, min_serial);
    const ex a = two ? inner.op(0) - inner.op(1) : inner.op(0);
    int sigma = 0;  // the sign of the function's own argument on this side
    if ((a - s).expand().is_zero()) sigma = side > 0 ? 1 : -1;
    else if ((a + s).expand().is_zero()) sigma = side > 0 ? -1 : 1;
    if (sigma == 0) return inner;
    if (has_serial(inner, sign_serial)) return sigma;
    if (has_serial(inner, heaviside_serial)) return sigma > 0 ? 1 : 0;
    if (has_serial(inner, abs_serial)) return sigma * inner.op(0);
    if (has_serial(inner, max_serial)) return sigma > 0 ? inner.op(0) : inner.op(1);
    return sigma > 0 ? inner.op(1) : inner.op(0);  // min
}

bool nonsmooth_in(const ex& e, const std::vector<GiNaC::symbol>& symbols) {
    for (const SwitchingSurface& s : switching_surfaces({e}))
        for (const GiNaC::symbol& x : symbols)
            if (s.s.has(x)) return true;
    return false;
}

}  // namespace eomgen
