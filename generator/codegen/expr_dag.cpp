/** @file expr_dag.cpp  Conversion of GiNaC expressions into the canonical DAG. */
#include "codegen/expr_dag.hpp"

#include <algorithm>
#include <set>
#include <sstream>
#include <stdexcept>

namespace eomgen::codegen {
namespace {

const std::set<std::string> kOddFunctions = {"sin", "tan", "sinh", "tanh", "asin", "atan"};
const std::set<std::string> kEvenFunctions = {"cos", "cosh"};

int compare_numeric(const GiNaC::numeric& a, const GiNaC::numeric& b) {
    // Real rationals only reach here; compare() orders them numerically.
    return a.compare(b);
}

}  // namespace

std::string numeric_string(const GiNaC::numeric& v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

ExprDag::ExprDag(std::vector<SymbolInfo> symbols, const std::vector<GiNaC::ex>& symbol_exprs, bool lower_powers)
    : symbols_(std::move(symbols)), lower_powers_(lower_powers) {
    if (symbols_.size() != symbol_exprs.size()) throw std::logic_error("ExprDag: symbol table sizes differ");
    for (std::size_t i = 0; i < symbol_exprs.size(); ++i) symbol_index_[symbol_exprs[i]] = static_cast<int>(i);
}

NodeId ExprDag::intern(Node n) {
    std::ostringstream key;
    key << static_cast<int>(n.op) << '|' << n.name << '|' << n.symbol << '|' << numeric_string(n.value);
    for (std::size_t i = 0; i < n.args.size(); ++i) {
        key << '|' << n.args[i];
        if (i < n.coeffs.size()) key << ':' << numeric_string(n.coeffs[i]);
    }
    const std::string k = key.str();
    auto it = interned_.find(k);
    if (it != interned_.end()) return it->second;
    const auto id = static_cast<NodeId>(nodes_.size());
    nodes_.push_back(std::move(n));
    interned_.emplace(k, id);
    return id;
}

NodeId ExprDag::number(const GiNaC::numeric& v) {
    Node n{Op::Number, {}, {}, v, {}, -1};
    return intern(std::move(n));
}

int ExprDag::compare(NodeId a, NodeId b) const {
    if (a == b) return 0;
    if (a == kOne || b == kOne) return a == kOne ? -1 : 1;
    const Node& x = node(a);
    const Node& y = node(b);
    if (x.op != y.op) return static_cast<int>(x.op) < static_cast<int>(y.op) ? -1 : 1;
    switch (x.op) {
        case Op::Number:
            return compare_numeric(x.value, y.value);
        case Op::Symbol: {
            const SymbolInfo& s = symbol(x.symbol);
            const SymbolInfo& t = symbol(y.symbol);
            if (s.kind != t.kind) return s.kind < t.kind ? -1 : 1;
            if (s.index != t.index) return s.index < t.index ? -1 : 1;
            return s.name.compare(t.name);
        }
        case Op::Func:
            if (x.name != y.name) return x.name < y.name ? -1 : 1;
            break;
        default:
            break;
    }
    if (int c = compare_numeric(x.value, y.value)) return c;
    const std::size_t n = std::min(x.args.size(), y.args.size());
    for (std::size_t i = 0; i < n; ++i) {
        if (int c = compare(x.args[i], y.args[i])) return c;
        if (i < x.coeffs.size() && i < y.coeffs.size())
            if (int c = compare_numeric(x.coeffs[i], y.coeffs[i])) return c;
    }
    if (x.args.size() != y.args.size()) return x.args.size() < y.args.size() ? -1 : 1;
    return 0;
}

NodeId ExprDag::node_of(const Term& t) {
    if (t.node == kOne) return number(t.coeff);
    if (t.coeff.is_equal(1)) return t.node;
    Node n{Op::Add, {t.node}, {t.coeff}, GiNaC::numeric(0), {}, -1};
    return intern(std::move(n));
}

Term ExprDag::make_add(std::vector<std::pair<NodeId, GiNaC::numeric>> terms, GiNaC::numeric constant) {
    // Merge equal nodes (our canonical forms can meet where GiNaC's did not), drop zeros, sort.
    std::map<NodeId, GiNaC::numeric> merged;
    for (auto& [id, c] : terms) {
        auto it = merged.find(id);
        if (it == merged.end())
            merged.emplace(id, c);
        else
            it->second = it->second + c;
    }
    std::vector<std::pair<NodeId, GiNaC::numeric>> sorted;
    for (auto& [id, c] : merged)
        if (!c.is_zero()) sorted.emplace_back(id, c);
    std::sort(sorted.begin(), sorted.end(),
              [this](const auto& a, const auto& b) { return compare(a.first, b.first) < 0; });
    if (sorted.empty()) return {constant, kOne};
    if (sorted.size() == 1 && constant.is_zero()) return {sorted[0].second, sorted[0].first};
    GiNaC::numeric sign(1);
    if (sorted[0].second.is_negative()) sign = GiNaC::numeric(-1);
    Node n{Op::Add, {}, {}, sign * constant, {}, -1};
    for (auto& [id, c] : sorted) {
        n.args.push_back(id);
        n.coeffs.push_back(sign * c);
    }
    return {sign, intern(std::move(n))};
}

NodeId ExprDag::make_pow(NodeId base, long k) {
    if (k == 1) return base;
    if (k == 2 || k == 3) {
        Node n{Op::Pow, {base}, {}, GiNaC::numeric(k), {}, -1};
        return intern(std::move(n));
    }
    // x^k = (x^(k/2))^2 · x^(k mod 2): the squares are shared between powers of the same base.
    const NodeId half = make_pow(base, k / 2);
    const NodeId square = make_pow(half, 2);
    if (k % 2 == 0) return square;
    std::map<NodeId, GiNaC::numeric> f{{square, GiNaC::numeric(1)}};
    auto it = f.find(base);
    if (it != f.end())
        it->second = it->second + 1;
    else
        f.emplace(base, GiNaC::numeric(1));
    return make_mul(std::move(f), GiNaC::numeric(1)).node;
}

Term ExprDag::make_mul(std::map<NodeId, GiNaC::numeric> factors, GiNaC::numeric coeff) {
    std::vector<std::pair<NodeId, GiNaC::numeric>> list;
    for (auto& [id, e] : factors) {
        if (e.is_zero()) continue;
        if (lower_powers_ && !(e.is_equal(1) || e.is_equal(-1))) {
            // Lowered: |e| ≥ 2 becomes a Pow node with exponent ±1 here.
            const long k = e.to_long();
            list.emplace_back(make_pow(id, k < 0 ? -k : k), GiNaC::numeric(k < 0 ? -1 : 1));
        } else {
            list.emplace_back(id, e);
        }
    }
    // Lowering may have produced equal factors again (x² · x² from x⁴ handled in make_pow); merge once more.
    std::map<NodeId, GiNaC::numeric> merged;
    for (auto& [id, e] : list) {
        auto it = merged.find(id);
        if (it == merged.end())
            merged.emplace(id, e);
        else
            it->second = it->second + e;
    }
    list.clear();
    for (auto& [id, e] : merged)
        if (!e.is_zero()) list.emplace_back(id, e);
    std::sort(list.begin(), list.end(), [this](const auto& a, const auto& b) { return compare(a.first, b.first) < 0; });
    if (list.empty()) return {coeff, kOne};
    if (list.size() == 1 && list[0].second.is_equal(1)) return {coeff, list[0].first};
    Node n{Op::Mul, {}, {}, GiNaC::numeric(0), {}, -1};
    for (auto& [id, e] : list) {
        n.args.push_back(id);
        n.coeffs.push_back(e);
    }
    return {coeff, intern(std::move(n))};
}

Term ExprDag::make_func(const std::string& name, std::vector<Term> args) {
    GiNaC::numeric sign(1);
    if (args.size() == 1 && args[0].coeff.is_negative() && args[0].node != kOne) {
        // f(−x): pull the sign out of odd functions, drop it in even ones, so f(a−b) and f(b−a) meet.
        if (kOddFunctions.count(name)) {
            sign = GiNaC::numeric(-1);
            args[0].coeff = -args[0].coeff;
        } else if (kEvenFunctions.count(name)) {
            args[0].coeff = -args[0].coeff;
        }
    }
    Node n{Op::Func, {}, {}, GiNaC::numeric(0), name, -1};
    for (const Term& a : args) n.args.push_back(node_of(a));
    return {sign, intern(std::move(n))};
}

Term ExprDag::make_power(const Term& base, const GiNaC::numeric& exponent) {
    if (exponent.is_integer()) {
        const GiNaC::numeric c = GiNaC::ex_to<GiNaC::numeric>(GiNaC::pow(base.coeff, exponent));
        if (base.node == kOne) return {c, kOne};
        // Splice a product's factors so that (x·y)^k stays a flat product.
        const Node& b = node(base.node);
        std::map<NodeId, GiNaC::numeric> f;
        if (b.op == Op::Mul && !lower_powers_) {
            for (std::size_t i = 0; i < b.args.size(); ++i) f[b.args[i]] = b.coeffs[i] * exponent;
        } else {
            f[base.node] = exponent;
        }
        return make_mul(std::move(f), c);
    }
    const NodeId b = node_of(base);
    const GiNaC::numeric two_e = exponent * 2;
    if (two_e.is_integer()) {
        // Half-integer powers through sqrt: x^(k/2) = sqrt(x)^k.
        Term root = make_func("sqrt", {Term{GiNaC::numeric(1), b}});
        std::map<NodeId, GiNaC::numeric> f{{root.node, two_e}};
        return make_mul(std::move(f), GiNaC::numeric(1));
    }
    Node n{Op::Func, {b, number(exponent)}, {}, GiNaC::numeric(0), "pow", -1};
    return {GiNaC::numeric(1), intern(std::move(n))};
}

Term ExprDag::add(const GiNaC::ex& e) { return convert(e); }

Term ExprDag::convert(const GiNaC::ex& e) {
    auto memo = memo_.find(e);
    if (memo != memo_.end()) return memo->second;
    Term result;
    if (GiNaC::is_a<GiNaC::numeric>(e)) {
        const GiNaC::numeric v = GiNaC::ex_to<GiNaC::numeric>(e);
        if (!v.is_rational())
            throw std::runtime_error("inexact or complex number " + numeric_string(v) + " in an expression");
        result = {v, kOne};
    } else if (GiNaC::is_a<GiNaC::symbol>(e) || GiNaC::is_a<GiNaC::constant>(e)) {
        auto it = symbol_index_.find(e);
        if (it == symbol_index_.end()) {
            std::ostringstream os;
            os << "symbol " << e << " is not part of the model";
            throw std::runtime_error(os.str());
        }
        Node n{Op::Symbol, {}, {}, GiNaC::numeric(0), {}, it->second};
        result = {GiNaC::numeric(1), intern(std::move(n))};
    } else if (GiNaC::is_a<GiNaC::add>(e)) {
        std::vector<std::pair<NodeId, GiNaC::numeric>> terms;
        GiNaC::numeric constant(0);
        for (const GiNaC::ex& op : e) {
            const Term t = convert(op);
            if (t.node == kOne)
                constant = constant + t.coeff;
            else if (node(t.node).op == Op::Add && node(t.node).args.size() == 1 && node(t.node).value.is_zero())
                terms.emplace_back(node(t.node).args[0], t.coeff * node(t.node).coeffs[0]);
            else
                terms.emplace_back(t.node, t.coeff);
        }
        result = make_add(std::move(terms), constant);
    } else if (GiNaC::is_a<GiNaC::mul>(e)) {
        GiNaC::numeric coeff(1);
        std::map<NodeId, GiNaC::numeric> factors;
        auto put = [&factors](NodeId id, const GiNaC::numeric& k) {
            auto it = factors.find(id);
            if (it == factors.end())
                factors.emplace(id, k);
            else
                it->second = it->second + k;
        };
        for (const GiNaC::ex& op : e) {
            const Term t = convert(op);
            coeff = coeff * t.coeff;
            if (t.node == kOne) continue;
            const Node& f = node(t.node);
            if (f.op == Op::Mul) {
                const std::vector<NodeId> args = f.args;
                const std::vector<GiNaC::numeric> exps = f.coeffs;
                for (std::size_t i = 0; i < args.size(); ++i) put(args[i], exps[i]);
            } else {
                put(t.node, GiNaC::numeric(1));
            }
        }
        result = make_mul(std::move(factors), coeff);
    } else if (GiNaC::is_a<GiNaC::power>(e)) {
        const GiNaC::ex expo = e.op(1);
        const Term base = convert(e.op(0));
        if (GiNaC::is_a<GiNaC::numeric>(expo) && GiNaC::ex_to<GiNaC::numeric>(expo).is_rational()) {
            result = make_power(base, GiNaC::ex_to<GiNaC::numeric>(expo));
        } else {
            Node n{Op::Func, {node_of(base), node_of(convert(expo))}, {}, GiNaC::numeric(0), "pow", -1};
            result = {GiNaC::numeric(1), intern(std::move(n))};
        }
    } else if (GiNaC::is_a<GiNaC::function>(e)) {
        const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
        static const std::set<std::string> known = {"sin",  "cos",  "tan",  "exp",  "log", "sinh", "cosh",
                                                    "tanh", "asin", "acos", "atan", "atan2", "abs"};
        if (!known.count(name)) throw std::runtime_error("function " + name + " cannot be emitted");
        std::vector<Term> args;
        for (const GiNaC::ex& op : e) args.push_back(convert(op));
        result = make_func(name, std::move(args));
    } else {
        std::ostringstream os;
        os << "expression " << e << " cannot be emitted";
        throw std::runtime_error(os.str());
    }
    memo_.emplace(e, result);
    return result;
}

}  // namespace eomgen::codegen
