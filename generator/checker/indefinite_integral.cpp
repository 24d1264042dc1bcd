/** @file indefinite_integral.cpp  Equal up to a constant of integration: the derivatives in the variable agree. */
#include "checker/indefinite_integral.hpp"

#include <algorithm>

#include <string>

namespace eomgen::checker {

namespace {

/// Every antiderivative(f, x) in e, each once.
void collect(const GiNaC::ex& e, GiNaC::exset& out) {
    if (is_ex_the_function(e, antiderivative)) {
        out.insert(e);
        return;
    }
    for (std::size_t i = 0; i < e.nops(); ++i) collect(e.op(i), out);
}

}  // namespace

bool has_antiderivative(const GiNaC::ex& e) {
    GiNaC::exset found;
    collect(e, found);
    return !found.empty();
}

void check_antiderivative(const GiNaC::ex& a, const GiNaC::ex& b, const std::vector<const FreeName*>& unknown,
                          Comparisons& cmp, double tol, EquationCheck& r) {
    GiNaC::exset integrals;
    collect(a - b, integrals);
    GiNaC::ex x;
    for (const GiNaC::ex& I : integrals) {
        if (x.is_zero()) {
            x = I.op(1);
        } else if (!I.op(1).is_equal(x)) {
            r.reason = "indefinite integrals in different variables ($" + cmp.latex(x) + "$, $" + cmp.latex(I.op(1)) +
                       "$) are not compared";
            return;
        }
    }
    if (!GiNaC::is_a<GiNaC::symbol>(x)) {  // a definition put in for the variable: not an antiderivative any more
        r.reason = "the variable of the indefinite integral is not a coordinate or the time here";
        return;
    }
    const GiNaC::symbol& var = GiNaC::ex_to<GiNaC::symbol>(x);
    // Each integral a symbol of its own; the difference must be linear in them with coefficients free of x.
    GiNaC::exmap as_symbols;
    std::vector<std::pair<GiNaC::symbol, GiNaC::ex>> named;  // A, its integrand
    for (const GiNaC::ex& I : integrals) {
        const GiNaC::symbol A("A");
        as_symbols[I] = A;
        named.emplace_back(A, I.op(0));
    }
    GiNaC::ex D = 0;
    try {
        const GiNaC::ex d = (a - b).subs(as_symbols).expand();
        GiNaC::ex linear = 0;
        for (const auto& [A, f] : named) {
            const GiNaC::ex c = d.coeff(A, 1);
            if (c.has(var) ||
                std::any_of(named.begin(), named.end(), [&](const auto& other) { return c.has(other.first); })) {
                r.reason = "an indefinite integral times its own variable, or a power of one, is not compared";
                return;
            }
            linear += c * A;
            D += c * f;
        }
        // Linear in the integrals: nothing of them left once their terms are taken away (not inside a function).
        const GiNaC::ex rest = (d - linear).expand();
        for (const auto& [A, f] : named)
            if (rest.has(A)) {
                r.reason = "an indefinite integral times its own variable, or a power of one, is not compared";
                return;
            }
        D += GiNaC::diff(rest, var);
    } catch (const std::exception& e) {
        r.reason = std::string("cannot evaluate the derivative of an indefinite integral: ") + e.what();
        return;
    }
    std::string constants, still;
    GiNaC::exset seen;
    int stay = 0;
    for (const FreeName* f : unknown) {
        if (!seen.insert(f->symbol).second) continue;
        std::string& list = D.has(f->symbol) ? still : constants;
        list += (list.empty() ? "" : ", ") + std::string("$") + f->name + "$";
        stay += D.has(f->symbol) ? 1 : 0;
    }
    if (stay > 0) {
        r.reason = std::string(stay == 1 ? "unknown symbol " : "unknown symbols ") + still + " in the derivative in $" +
                   cmp.latex(x) + "$: not " + (stay == 1 ? "a symbol" : "symbols") +
                   " of the model (--map can say what " + (stay == 1 ? "it stands" : "they stand") + " for)";
        return;
    }
    r.compared_with = "the derivatives in $" + cmp.latex(x) + "$ (an indefinite integral)";
    if (cmp.same(D, 0, tol)) {
        r.verdict = Verdict::Agrees;
        r.reason = "the two sides' derivatives in $" + cmp.latex(x) + "$ are equal: they differ by a constant of integration" +
                   (constants.empty() ? std::string() : " (" + constants + ")");
    } else {
        r.verdict = Verdict::Disagrees;
        r.reason = "the two sides' derivatives in $" + cmp.latex(x) + "$ differ by $" + cmp.latex(D.expand()) +
                   "$: no constant of integration makes them equal";
    }
}

}  // namespace eomgen::checker
