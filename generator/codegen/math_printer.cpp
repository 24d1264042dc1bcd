/** @file math_printer.cpp  Plain-text and LaTeX rendering of the canonical DAG. */
#include "codegen/math_printer.hpp"

#include <sstream>

namespace eomgen::codegen {
namespace {

// Binding strength of what a node prints as; a child weaker than its context gets parentheses.
constexpr int kSum = 1, kProduct = 2, kPower = 3, kAtom = 4;

std::string latex_function(const std::string& name) {
    static const char* const known[] = {"sin", "cos", "tan", "exp", "log", "sinh", "cosh", "tanh"};
    for (const char* k : known)
        if (name == k) return "\\" + name;
    if (name == "asin") return "\\arcsin";
    if (name == "acos") return "\\arccos";
    if (name == "atan") return "\\arctan";
    return "\\operatorname{" + name + "}";
}

}  // namespace

MathPrinter::MathPrinter(const SymbolTable& table) : dag_(table.info, table.exprs, false) {}

std::string MathPrinter::print(const GiNaC::ex& e, MathStyle style) { return term(dag_.add(e), style); }

std::string MathPrinter::sum(const Node& n, const GiNaC::numeric& factor, MathStyle style) {
    std::string out;
    for (std::size_t i = 0; i < n.args.size(); ++i) {
        std::string t = term(Term{factor * n.coeffs[i], n.args[i]}, style);
        if (i == 0)
            out = t;
        else if (!t.empty() && t[0] == '-')
            out += " - " + t.substr(1);
        else
            out += " + " + t;
    }
    if (!n.value.is_zero()) {
        const GiNaC::numeric c = factor * n.value;
        out += (c.is_negative() ? " - " : " + ") + term(Term{GiNaC::abs(c), kOne}, style);
    }
    return out;
}

std::string MathPrinter::term(const Term& t, MathStyle style) {
    if (t.node == kOne) return numeric_string(t.coeff);
    // −(a + b) reads better as −a − b.
    if (t.coeff.is_equal(-1) && dag_.node(t.node).op == Op::Add && dag_.node(t.node).args.size() > 1)
        return sum(dag_.node(t.node), t.coeff, style);
    const std::string body = node(t.node, style, kProduct);
    if (t.coeff.is_equal(1)) return node(t.node, style, kSum);
    if (t.coeff.is_equal(-1)) return "-" + body;
    if (style == MathStyle::Latex && !t.coeff.is_integer()) {
        const GiNaC::numeric a = GiNaC::abs(t.coeff);
        return std::string(t.coeff.is_negative() ? "-" : "") + "\\frac{" + numeric_string(a.numer()) + "}{" +
               numeric_string(a.denom()) + "} " + body;
    }
    return numeric_string(t.coeff) + (style == MathStyle::Latex ? " " : "*") + body;
}

std::string MathPrinter::node(NodeId id, MathStyle style, int context) {
    const Node& n = dag_.node(id);
    const bool latex = style == MathStyle::Latex;
    std::string out;
    int strength = kAtom;
    switch (n.op) {
        case Op::Number:
            if (latex && !n.value.is_integer()) {
                out = "\\frac{" + numeric_string(n.value.numer()) + "}{" + numeric_string(n.value.denom()) + "}";
            } else {
                out = numeric_string(n.value);
                if (n.value.is_negative() || !n.value.is_integer()) strength = kSum;
            }
            break;
        case Op::Symbol: {
            const SymbolInfo& s = dag_.symbol(n.symbol);
            out = latex ? s.latex : s.text;
            break;
        }
        case Op::Func: {
            std::vector<std::string> args;
            for (NodeId a : n.args) args.push_back(node(a, style, kSum));
            if (latex && n.name == "sqrt") {
                out = "\\sqrt{" + args[0] + "}";
            } else if (latex && n.name == "pow") {
                out = "{" + node(n.args[0], style, kAtom) + "}^{" + args[1] + "}";
            } else if (latex && n.args.size() == 1 && dag_.node(n.args[0]).op == Op::Symbol) {
                // \sin \theta: functions sort after symbols in a product, so no parentheses are needed.
                out = latex_function(n.name) + " " + args[0];
            } else {
                std::string joined;
                for (std::size_t i = 0; i < args.size(); ++i) joined += (i ? ", " : "") + args[i];
                out = latex ? latex_function(n.name) + "\\left(" + joined + "\\right)" : n.name + "(" + joined + ")";
            }
            break;
        }
        case Op::Pow:  // only in lowered DAGs, which this printer does not build
        case Op::Mul: {
            std::vector<std::string> num, den;
            std::size_t n_den = 0, num_sums = 0, den_sums = 0;
            for (const GiNaC::numeric& k : n.coeffs) n_den += k.is_negative() ? 1 : 0;
            for (std::size_t i = 0; i < n.args.size(); ++i) {
                const GiNaC::numeric k = GiNaC::abs(n.coeffs[i]);
                std::string f;
                if (k.is_equal(1)) {
                    const bool alone_in_frac = latex && n.coeffs[i].is_negative() && n_den == 1;
                    f = node(n.args[i], style, alone_in_frac ? kSum : kProduct + 1);
                } else {
                    const Node& b = dag_.node(n.args[i]);
                    if (latex && b.op == Op::Func && b.args.size() == 1 && dag_.node(b.args[0]).op == Op::Symbol &&
                        b.name != "sqrt")
                        f = latex_function(b.name) + "^{" + numeric_string(k) + "} " + node(b.args[0], style, kAtom);
                    else
                        f = latex ? node(n.args[i], style, kAtom) + "^{" + numeric_string(k) + "}"
                                  : node(n.args[i], style, kAtom) + "^" + numeric_string(k);
                }
                // A sum factor leads its product, as people write it: (m + 3 M) l^2, not l^2 (m + 3 M).
                std::vector<std::string>& side = n.coeffs[i].is_negative() ? den : num;
                std::size_t& sums = n.coeffs[i].is_negative() ? den_sums : num_sums;
                const bool sum_factor = dag_.node(n.args[i]).op == Op::Add;
                side.insert(sum_factor ? side.begin() + long(sums++) : side.end(), f);
            }
            auto join = [&](const std::vector<std::string>& v) {
                std::string s;
                for (std::size_t i = 0; i < v.size(); ++i) s += (i ? (latex ? " " : "*") : "") + v[i];
                return s;
            };
            if (den.empty()) {
                out = join(num);
                strength = kProduct;
            } else if (latex) {
                out = "\\frac{" + (num.empty() ? std::string("1") : join(num)) + "}{" + join(den) + "}";
            } else {
                out = (num.empty() ? std::string("1") : join(num)) + "/" +
                      (den.size() > 1 ? "(" + join(den) + ")" : den[0]);
                strength = kProduct;
            }
            break;
        }
        case Op::Add:
            out = sum(n, GiNaC::numeric(1), style);
            strength = kSum;
            break;
    }
    if (strength < context) return latex ? "\\left(" + out + "\\right)" : "(" + out + ")";
    return out;
}

}  // namespace eomgen::codegen
