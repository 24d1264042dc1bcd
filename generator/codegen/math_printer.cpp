/** @file math_printer.cpp  Plain-text and LaTeX rendering of the canonical DAG. */
#include "codegen/math_printer.hpp"

#include <algorithm>
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
    if (name == "max" || name == "min") return "\\" + name;
    if (name == "sign") return "\\operatorname{sgn}";
    if (name == "heaviside") return "\\operatorname{H}";
    return "\\operatorname{" + name + "}";
}

}  // namespace

MathPrinter::MathPrinter(const SymbolTable& table) : dag_(table.info, table.exprs, false) {}

std::string MathPrinter::print(const GiNaC::ex& e, MathStyle style) { return term(dag_.add(e), style); }

void MathPrinter::prefer_angles(const std::vector<GiNaC::ex>& angles) {
    for (const GiNaC::ex& u : angles) {
        const Term t = dag_.add(u);  // φ − θ is stored as −1·(θ − φ) when θ sorts first
        if (t.coeff.is_equal(-1) && t.node != kOne && dag_.node(t.node).op == Op::Add &&
            dag_.node(t.node).args.size() == 2 && dag_.node(t.node).value.is_zero())
            reversed_.insert(t.node);
    }
}

bool MathPrinter::parameters_only(NodeId id) const {
    if (id == kOne) return true;
    const Node& n = dag_.node(id);
    if (n.op == Op::Symbol) return dag_.symbol(n.symbol).kind == SymbolKind::Parameter;
    return std::all_of(n.args.begin(), n.args.end(), [this](NodeId a) { return parameters_only(a); });
}

bool MathPrinter::reversed(NodeId func) const {
    const Node& n = dag_.node(func);
    return in_term_ && n.op == Op::Func && (n.name == "sin" || n.name == "cos") && n.args.size() == 1 &&
           reversed_.count(n.args[0]) > 0;
}

int MathPrinter::flipped_sines(NodeId id) const {
    if (id == kOne || reversed_.empty()) return 0;
    const Node& n = dag_.node(id);
    auto sine = [&](NodeId f) {
        const Node& x = dag_.node(f);
        return x.op == Op::Func && x.name == "sin" && x.args.size() == 1 && reversed_.count(x.args[0]) > 0;
    };
    if (n.op == Op::Func) return sine(id) ? 1 : 0;
    int count = 0;
    if (n.op == Op::Mul)
        for (std::size_t i = 0; i < n.args.size(); ++i)
            if (sine(n.args[i]) && n.coeffs[i].is_integer() && n.coeffs[i].is_odd()) ++count;
    return count;
}

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

std::string MathPrinter::term(const Term& given, MathStyle style) {
    if (given.node == kOne) return numeric_string(given.coeff);
    // A sine printed with its angle reversed carries a sign: −k sin(θ − φ) reads k sin(φ − θ).
    const Term t{flipped_sines(given.node) % 2 ? GiNaC::numeric(-given.coeff) : given.coeff, given.node};
    struct Scope {
        bool& flag;
        bool saved;
        Scope(bool& f, bool v) : flag(f), saved(f) { flag = v; }
        ~Scope() { flag = saved; }
    } scope(in_term_, true);
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
            const bool flip = reversed(id);
            bool& flag = in_term_;
            const bool saved = flag;
            flag = false;  // inside a function's arguments, signs are the arguments' own
            std::vector<std::string> args;
            for (NodeId a : n.args) args.push_back(node(a, style, kSum));
            flag = saved;
            if (flip) {  // θ − φ printed as φ − θ: the two terms swapped, their signs flipped
                const Node& a = dag_.node(n.args[0]);
                args[0] = term(Term{-a.coeffs[1], a.args[1]}, style);
                const std::string second = term(Term{-a.coeffs[0], a.args[0]}, style);
                args[0] += second[0] == '-' ? " - " + second.substr(1) : " + " + second;
            }
            if (latex && n.name == "abs") {
                out = "\\left|" + args[0] + "\\right|";
            } else if (latex && n.name == "sqrt") {
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
            const std::size_t n_num = n.coeffs.size() - n_den;
            for (std::size_t i = 0; i < n.args.size(); ++i) {
                const GiNaC::numeric k = GiNaC::abs(n.coeffs[i]);
                // flipped_sines() counts integer powers only: a root of a sine keeps the canonical angle.
                const bool saved = in_term_;
                in_term_ = in_term_ && n.coeffs[i].is_integer();
                std::string f;
                if (k.is_equal(1)) {
                    const bool alone_in_frac =
                        latex && n_den > 0 && (n.coeffs[i].is_negative() ? n_den == 1 : n_num == 1);
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
                in_term_ = saved;
                // A sum of parameters leads its product, as people write it: (m + 3 M) l^2, not
                // l^2 (m + 3 M); a sum in the coordinates stays last: m g (w sin θ sin ψ + h cos θ).
                std::vector<std::string>& side = n.coeffs[i].is_negative() ? den : num;
                std::size_t& sums = n.coeffs[i].is_negative() ? den_sums : num_sums;
                const bool sum_factor = dag_.node(n.args[i]).op == Op::Add && parameters_only(n.args[i]);
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
