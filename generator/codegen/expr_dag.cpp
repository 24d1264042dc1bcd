/** @file expr_dag.cpp  Conversion of GiNaC expressions into the canonical DAG. */
#include "codegen/expr_dag.hpp"

#include <algorithm>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

namespace eomgen::codegen {
namespace {

const std::set<std::string> kOddFunctions = {"sin", "tan", "sinh", "tanh", "asin", "atan", "sign"};
const std::set<std::string> kEvenFunctions = {"cos", "cosh", "abs"};

int compare_numeric(const GiNaC::numeric& a, const GiNaC::numeric& b) {
    // Real rationals only reach here; compare() orders them numerically.
    return a.compare(b);
}

}  // namespace

std::vector<Term> code_roots(ExprDag& dag, const std::vector<GiNaC::ex>& values) {
    std::vector<Term> roots;
    for (const GiNaC::ex& v : values) roots.push_back(dag.add(v));
    dag.note_angles(roots);
    for (Term& r : roots) r = dag.optimize(r);
    dag.share_partial(roots);
    return roots;
}

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

std::size_t ExprDag::NodeHash::operator()(const Node& n) const {
    // Only for lookup: the order of anything emitted never depends on these values.
    std::size_t h = static_cast<std::size_t>(n.op) * 0x9e3779b97f4a7c15ULL;
    auto mix = [&h](std::size_t v) { h = (h ^ v) * 0x100000001b3ULL + (h >> 29); };
    if (!n.name.empty()) mix(std::hash<std::string>()(n.name));
    mix(static_cast<std::size_t>(n.symbol + 1));
    mix(n.value.gethash());
    for (NodeId a : n.args) mix(static_cast<std::size_t>(a + 2));
    for (const GiNaC::numeric& c : n.coeffs) mix(c.gethash());
    return h;
}

bool ExprDag::NodeEqual::operator()(const Node& a, const Node& b) const {
    if (a.op != b.op || a.symbol != b.symbol || a.args != b.args || a.name != b.name) return false;
    if (!a.value.is_equal(b.value) || a.coeffs.size() != b.coeffs.size()) return false;
    for (std::size_t i = 0; i < a.coeffs.size(); ++i)
        if (!a.coeffs[i].is_equal(b.coeffs[i])) return false;
    return true;
}

NodeId ExprDag::intern(Node n) {
    auto it = interned_.find(n);
    if (it != interned_.end()) return it->second;
    const auto id = static_cast<NodeId>(nodes_.size());
    nodes_.push_back(n);
    interned_.emplace(std::move(n), id);
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
                                                    "tanh", "asin", "acos", "atan", "atan2", "abs",
                                                    "sign", "heaviside", "max", "min"};
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


// ---- optimize(): expansion over atoms, sin² + cos² = 1, greedy Horner ---------------------------------------

namespace {

/// Atoms with non-zero integer exponents, sorted by node id (an id order is only used for hashing and
/// merging; every decision about the emitted code goes through ExprDag::compare()).
using Monomial = std::vector<std::pair<NodeId, int>>;

struct MonomialHash {
    std::size_t operator()(const Monomial& m) const {
        std::size_t h = 0xcbf29ce484222325ULL;
        for (const auto& [a, e] : m) h = (h ^ (static_cast<std::size_t>(a) * 131 + static_cast<std::size_t>(e + 64))) *
                                         0x100000001b3ULL;
        return h;
    }
};

Monomial multiply(const Monomial& a, const Monomial& b) {
    Monomial out;
    out.reserve(a.size() + b.size());
    std::size_t i = 0, j = 0;
    while (i < a.size() || j < b.size()) {
        if (j == b.size() || (i < a.size() && a[i].first < b[j].first)) {
            out.push_back(a[i++]);
        } else if (i == a.size() || b[j].first < a[i].first) {
            out.push_back(b[j++]);
        } else {
            const int e = a[i].second + b[j].second;
            if (e != 0) out.emplace_back(a[i].first, e);
            ++i, ++j;
        }
    }
    return out;
}

int exponent_of(const Monomial& m, NodeId atom) {
    auto it = std::lower_bound(m.begin(), m.end(), std::make_pair(atom, std::numeric_limits<int>::min()));
    return it != m.end() && it->first == atom ? it->second : 0;
}

/// m with atom's exponent changed by delta.
Monomial shift(const Monomial& m, NodeId atom, int delta) {
    Monomial out;
    out.reserve(m.size() + 1);
    bool placed = false;
    for (const auto& [a, e] : m) {
        if (!placed && atom < a) {
            out.emplace_back(atom, delta);
            placed = true;
        }
        if (a == atom) {
            placed = true;
            if (e + delta != 0) out.emplace_back(a, e + delta);
        } else {
            out.emplace_back(a, e);
        }
    }
    if (!placed) out.emplace_back(atom, delta);
    return out;
}

// Terms the expansion of one output may create before optimize() gives up and keeps the term as it is.
constexpr std::size_t kExpansionBudget = 400000;
// Sums of more symbols than this inside sin/cos stay as they are (the expansion doubles per symbol).
constexpr std::size_t kMaxTrigSymbols = 4;

}  // namespace

struct ExprDag::Poly {
    std::vector<std::pair<Monomial, GiNaC::numeric>> terms;  ///< distinct monomials, non-zero coefficients
};

/// Accumulates c·monomial terms, merging equal monomials.
struct ExprDag::PolyBuilder {
    std::unordered_map<Monomial, std::size_t, MonomialHash> index;
    std::vector<std::pair<Monomial, GiNaC::numeric>> terms;

    void add(const Monomial& m, const GiNaC::numeric& c) {
        auto [it, fresh] = index.emplace(m, terms.size());
        if (fresh)
            terms.emplace_back(m, c);
        else
            terms[it->second].second = terms[it->second].second + c;
    }
    Poly finish() {
        Poly p;
        p.terms.reserve(terms.size());
        for (auto& t : terms)
            if (!t.second.is_zero()) p.terms.push_back(std::move(t));
        return p;
    }
};

NodeId ExprDag::find_func(const std::string& name, NodeId arg) const {
    Node probe{Op::Func, {arg}, {}, GiNaC::numeric(0), name, -1};
    auto it = interned_.find(probe);
    return it == interned_.end() ? kOne : it->second;
}

long ExprDag::cost(NodeId root) const {
    // Operations of the code for root with every distinct node computed once, counted as BodyEmitter does.
    long ops = 0;
    std::vector<NodeId> stack{root};
    std::unordered_map<NodeId, bool> seen{{root, true}};
    while (!stack.empty()) {
        const Node& n = node(stack.back());
        stack.pop_back();
        switch (n.op) {
            case Op::Func:
                ops += 1;
                break;
            case Op::Pow:
                ops += n.value.to_long() - 1;
                break;
            case Op::Mul:
                ops += static_cast<long>(n.args.size()) - 1;
                break;
            case Op::Add:
                ops += static_cast<long>(n.args.size()) - 1 + (n.value.is_zero() ? 0 : 1);
                for (const GiNaC::numeric& c : n.coeffs) ops += GiNaC::abs(c).is_equal(1) ? 0 : 1;
                break;
            default:
                break;
        }
        for (NodeId a : n.args)
            if (seen.emplace(a, true).second) stack.push_back(a);
    }
    return ops;
}

Term ExprDag::optimize_node(NodeId id) {
    auto it = optimized_.find(id);
    if (it != optimized_.end()) return it->second;
    const std::size_t saved = expansion_budget_;
    expansion_budget_ = kExpansionBudget;
    Term result{GiNaC::numeric(1), id};
    std::shared_ptr<const Poly> p;
    if (expand_node(id, p)) {
        Poly q = *p;
        const auto rank = atom_ranks(q);
        pythagoras(q, rank);
        const Term built = build(std::move(q), rank);
        // Keep the original form where the rewriting does not pay (nothing cancelled or factored better).
        if (built.node == kOne || cost(built.node) <= cost(id)) result = built;
    }
    expansion_budget_ = saved;
    optimized_.emplace(id, result);
    return result;
}

void ExprDag::note_angles(const std::vector<Term>& roots) {
    std::vector<NodeId> stack;
    std::vector<char> seen(nodes_.size(), 0);
    // Expansions asked for more than once: a root, a child of several nodes, or a child whose parent expands
    // it twice (the base of a power, a sum in a denominator: expand_node(), then optimize_node()).
    expansion_users_.assign(nodes_.size(), 0);
    auto use = [this](NodeId id, int k) { expansion_users_[static_cast<std::size_t>(id)] += k; };
    for (const Term& r : roots)
        if (r.node != kOne) {
            use(r.node, 1);
            if (!seen[static_cast<std::size_t>(r.node)]) {
                seen[static_cast<std::size_t>(r.node)] = 1;
                stack.push_back(r.node);
            }
        }
    while (!stack.empty()) {
        const Node& n = node(stack.back());
        stack.pop_back();
        if (n.op == Op::Func && (n.name == "sin" || n.name == "cos") && n.args.size() == 1 &&
            node(n.args[0]).op == Op::Symbol)
            angles_.emplace(n.args[0], true);
        for (std::size_t i = 0; i < n.args.size(); ++i) {
            const NodeId a = n.args[i];
            if (a < 0) continue;
            use(a, n.op == Op::Pow || (n.op == Op::Mul && !n.coeffs[i].is_equal(1)) ? 2 : 1);
            if (!seen[static_cast<std::size_t>(a)]) {
                seen[static_cast<std::size_t>(a)] = 1;
                stack.push_back(a);
            }
        }
    }
}

Term ExprDag::optimize(const Term& t) {
    if (t.node == kOne) return t;
    const Term r = optimize_node(t.node);
    return {r.coeff * t.coeff, r.node};
}

bool ExprDag::expand_node(NodeId id, std::shared_ptr<const Poly>& out) {
    auto memo = expanded_.find(id);
    if (memo != expanded_.end()) {
        out = memo->second;
        return true;
    }
    const Node n = node(id);  // a copy: interning below may move nodes_
    auto atom = [](const Term& t) {
        Poly p;
        if (t.node == kOne)
            p.terms.push_back({Monomial{}, t.coeff});
        else
            p.terms.push_back({Monomial{{t.node, 1}}, t.coeff});
        return p;
    };
    auto charge = [this](std::size_t k) {
        if (k > expansion_budget_) return false;
        expansion_budget_ -= k;
        return true;
    };
    auto product = [&](const Poly& a, const Poly& b, Poly& r) {
        if (!charge(a.terms.size() * b.terms.size())) return false;
        PolyBuilder pb;
        for (const auto& [ma, ca] : a.terms)
            for (const auto& [mb, cb] : b.terms) pb.add(multiply(ma, mb), ca * cb);
        r = pb.finish();
        return true;
    };
    Poly result;
    switch (n.op) {
        case Op::Number:
            result.terms.push_back({Monomial{}, n.value});
            break;
        case Op::Symbol:
            result = atom({GiNaC::numeric(1), id});
            break;
        case Op::Func: {
            // sin/cos of ±x ± y ± … (symbols): the addition theorems, down to each symbol's sin and cos.
            const Node* arg = n.args.size() == 1 ? &node(n.args[0]) : nullptr;
            bool trig = (n.name == "sin" || n.name == "cos") && arg && arg->op == Op::Add && arg->value.is_zero() &&
                        arg->args.size() <= kMaxTrigSymbols;
            if (trig)
                for (std::size_t i = 0; i < arg->args.size(); ++i)
                    trig = trig && node(arg->args[i]).op == Op::Symbol && angles_.count(arg->args[i]) &&
                           (arg->coeffs[i].is_equal(1) || arg->coeffs[i].is_equal(-1));
            if (trig) {
                const std::vector<NodeId> xs = arg->args;
                const std::vector<GiNaC::numeric> signs = arg->coeffs;
                Poly S, C;  // sin and cos of the partial sum so far: 0 and 1
                C.terms.push_back({Monomial{}, GiNaC::numeric(1)});
                for (std::size_t i = 0; i < xs.size(); ++i) {
                    const Term s = make_func("sin", {Term{GiNaC::numeric(1), xs[i]}});
                    const Term c = make_func("cos", {Term{GiNaC::numeric(1), xs[i]}});
                    Poly sp = atom({s.coeff * signs[i], s.node}), cp = atom(c);
                    Poly sc, cs, cc, ss;
                    if (!product(S, cp, sc) || !product(C, sp, cs) || !product(C, cp, cc) || !product(S, sp, ss))
                        return false;
                    PolyBuilder ns, nc;
                    for (const auto& t : sc.terms) ns.add(t.first, t.second);
                    for (const auto& t : cs.terms) ns.add(t.first, t.second);
                    for (const auto& t : cc.terms) nc.add(t.first, t.second);
                    for (const auto& t : ss.terms) nc.add(t.first, -t.second);
                    S = ns.finish();
                    C = nc.finish();
                }
                result = n.name == "sin" ? std::move(S) : std::move(C);
                break;
            }
            std::vector<Term> args;
            for (NodeId a : n.args) args.push_back(optimize_node(a));
            result = atom(make_func(n.name, std::move(args)));
            break;
        }
        case Op::Pow: {
            std::shared_ptr<const Poly> base;
            if (!expand_node(n.args[0], base)) return false;
            const int k = n.value.to_int();
            if (base->terms.size() == 1) {
                const auto& [m, c] = base->terms[0];
                Monomial mk = m;
                for (auto& f : mk) f.second *= k;
                result.terms.push_back({mk, GiNaC::ex_to<GiNaC::numeric>(GiNaC::pow(c, k))});
            } else {
                // A power of a sum stays a power (of the optimized sum): expanding it would only add work.
                const Term b = optimize_node(n.args[0]);
                Monomial m;
                if (b.node != kOne) m.emplace_back(b.node, k);
                result.terms.push_back({m, GiNaC::ex_to<GiNaC::numeric>(GiNaC::pow(b.coeff, k))});
            }
            break;
        }
        case Op::Mul: {
            result.terms.push_back({Monomial{}, GiNaC::numeric(1)});
            for (std::size_t i = 0; i < n.args.size(); ++i) {
                const int e = n.coeffs[i].to_int();
                std::shared_ptr<const Poly> f;
                if (!expand_node(n.args[i], f)) return false;
                Poly factor;
                if (e == 1) {
                    factor = *f;
                } else if (f->terms.size() == 1) {
                    const auto& [m, c] = f->terms[0];
                    Monomial me = m;
                    for (auto& x : me) x.second *= e;
                    factor.terms.push_back({me, GiNaC::ex_to<GiNaC::numeric>(GiNaC::pow(c, e))});
                } else {
                    // 1/(sum): the optimized sum, as one atom.
                    const Term b = optimize_node(n.args[i]);
                    Monomial m;
                    if (b.node != kOne) m.emplace_back(b.node, e);
                    factor.terms.push_back({m, GiNaC::ex_to<GiNaC::numeric>(GiNaC::pow(b.coeff, e))});
                }
                Poly next;
                if (!product(result, factor, next)) return false;
                result = std::move(next);
            }
            break;
        }
        case Op::Add: {
            PolyBuilder pb;
            if (!n.value.is_zero()) pb.add(Monomial{}, n.value);
            std::size_t total = 0;
            for (std::size_t i = 0; i < n.args.size(); ++i) {
                std::shared_ptr<const Poly> t;
                if (!expand_node(n.args[i], t)) return false;
                total += t->terms.size();
                for (const auto& [m, c] : t->terms) pb.add(m, c * n.coeffs[i]);
            }
            if (!charge(total)) return false;
            result = pb.finish();
            break;
        }
    }
    out = std::make_shared<const Poly>(std::move(result));
    // Kept only where it will be asked for again: the expansions of the 60-link pendulum's M and f, every
    // intermediate product kept, were 1.5 million monomials (200 MB) for a function that needs its roots'.
    if (static_cast<std::size_t>(id) >= expansion_users_.size() || expansion_users_[static_cast<std::size_t>(id)] > 1)
        expanded_.emplace(id, out);
    return true;
}

std::unordered_map<NodeId, int> ExprDag::atom_ranks(const Poly& p) const {
    std::vector<NodeId> atoms;
    std::unordered_map<NodeId, int> rank;
    for (const auto& t : p.terms)
        for (const auto& f : t.first)
            if (rank.emplace(f.first, 0).second) atoms.push_back(f.first);
    // Atoms that depend on the state (q, q̇, t) first, then parameters: on a tie in build(), factoring out a
    // velocity or an angle's sine keeps sums over bodies together (Σ_k m_k stays a partial sum), where a mass
    // first would split a quadratic form into one per body.
    std::vector<char> state(atoms.size());
    std::unordered_map<NodeId, char> on_state;
    for (std::size_t i = 0; i < atoms.size(); ++i) state[i] = depends_on_state(atoms[i], on_state);
    std::vector<std::size_t> order(atoms.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        if (state[a] != state[b]) return state[a] > state[b];
        return compare(atoms[a], atoms[b]) < 0;
    });
    for (std::size_t i = 0; i < order.size(); ++i) rank[atoms[order[i]]] = static_cast<int>(i);
    return rank;
}

bool ExprDag::depends_on_state(NodeId id, std::unordered_map<NodeId, char>& memo) const {
    auto it = memo.find(id);
    if (it != memo.end()) return it->second;
    const Node& n = node(id);
    bool state = false;
    if (n.op == Op::Symbol) {
        const SymbolKind k = symbol(n.symbol).kind;
        state = k != SymbolKind::Parameter && k != SymbolKind::Constant;
    }
    for (NodeId a : n.args) state = state || depends_on_state(a, memo);
    memo.emplace(id, state);
    return state;
}

void ExprDag::pythagoras(Poly& p, const std::unordered_map<NodeId, int>& rank) {
    // c·cos²x·R + c·sin²x·R → c·R, repeated until nothing pairs up; candidates in a structural order so that
    // the pairing (when several are possible) is the same in every process.
    std::vector<std::pair<NodeId, NodeId>> cos_sin;  // (cos x, sin x) atoms present
    for (const auto& [atom, r] : rank) {
        const Node& a = node(atom);
        if (a.op == Op::Func && a.name == "cos" && a.args.size() == 1) {
            const NodeId s = find_func("sin", a.args[0]);
            if (s != kOne && rank.count(s)) cos_sin.emplace_back(atom, s);
        }
    }
    if (cos_sin.empty()) return;
    std::sort(cos_sin.begin(), cos_sin.end(),
              [&rank](const auto& a, const auto& b) { return rank.at(a.first) < rank.at(b.first); });
    auto key = [&rank](const Monomial& m) {
        std::vector<std::pair<int, int>> k;
        for (const auto& [a, e] : m) k.emplace_back(rank.at(a), e);
        std::sort(k.begin(), k.end());
        return k;
    };
    for (bool changed = true; changed;) {
        changed = false;
        std::unordered_map<Monomial, GiNaC::numeric, MonomialHash> terms;
        for (auto& t : p.terms) terms.emplace(t.first, t.second);
        std::vector<std::pair<std::vector<std::pair<int, int>>, Monomial>> order;
        for (const auto& t : p.terms) order.emplace_back(key(t.first), t.first);
        std::sort(order.begin(), order.end());
        for (const auto& [k, m] : order) {
            auto it = terms.find(m);
            if (it == terms.end()) continue;
            for (const auto& [c, s] : cos_sin) {
                if (exponent_of(m, c) < 2) continue;
                const Monomial partner = shift(shift(m, c, -2), s, 2);
                auto jt = terms.find(partner);
                if (jt == terms.end() || !jt->second.is_equal(it->second)) continue;
                const GiNaC::numeric coeff = it->second;
                terms.erase(jt);
                terms.erase(terms.find(m));
                const Monomial reduced = shift(m, c, -2);
                auto [rt, fresh] = terms.emplace(reduced, coeff);
                if (!fresh) {
                    rt->second = rt->second + coeff;
                    if (rt->second.is_zero()) terms.erase(rt);
                }
                changed = true;
                break;
            }
        }
        if (changed) {
            // Rebuild in the previous order, new monomials last (their order is fixed by key() in build()).
            Poly q;
            for (const auto& [k, m] : order) {
                auto it = terms.find(m);
                if (it != terms.end()) {
                    q.terms.emplace_back(m, it->second);
                    terms.erase(it);
                }
            }
            std::vector<std::pair<std::vector<std::pair<int, int>>, Monomial>> rest;
            for (const auto& [m, c] : terms) rest.emplace_back(key(m), m);
            std::sort(rest.begin(), rest.end());
            std::unordered_map<Monomial, GiNaC::numeric, MonomialHash> left = std::move(terms);
            for (const auto& [k, m] : rest) q.terms.emplace_back(m, left.at(m));
            p = std::move(q);
        }
    }
}

Term ExprDag::mul_terms(const Term& a, const Term& b) {
    std::map<NodeId, GiNaC::numeric> f;
    auto put = [&](const Term& t) {
        if (t.node == kOne) return;
        const Node& n = node(t.node);
        if (n.op == Op::Mul) {
            for (std::size_t i = 0; i < n.args.size(); ++i) f[n.args[i]] = f[n.args[i]] + n.coeffs[i];
        } else {
            f[t.node] = f[t.node] + 1;
        }
    };
    put(a);
    put(b);
    return make_mul(std::move(f), a.coeff * b.coeff);
}

Term ExprDag::add_terms(const Term& a, const Term& b) {
    std::vector<std::pair<NodeId, GiNaC::numeric>> terms;
    GiNaC::numeric constant(0);
    auto put = [&](const Term& t) {
        if (t.node == kOne) {
            constant = constant + t.coeff;
            return;
        }
        const Node& n = node(t.node);
        if (n.op == Op::Add) {
            for (std::size_t i = 0; i < n.args.size(); ++i) terms.emplace_back(n.args[i], n.coeffs[i] * t.coeff);
            constant = constant + n.value * t.coeff;
        } else {
            terms.emplace_back(t.node, t.coeff);
        }
    };
    put(a);
    put(b);
    return make_add(std::move(terms), constant);
}

Term ExprDag::factor_common(const Term& sum) {
    // a·S + b·S → S·(a + b) for a node S (often a sum itself) that every term of the sum has as a factor.
    if (sum.node == kOne || node(sum.node).op != Op::Add || !node(sum.node).value.is_zero()) return sum;
    const Node s = node(sum.node);
    auto factors_of = [this](NodeId id) {
        std::map<NodeId, GiNaC::numeric> f;
        const Node& n = node(id);
        if (n.op == Op::Mul)
            for (std::size_t i = 0; i < n.args.size(); ++i) f.emplace(n.args[i], n.coeffs[i]);
        else
            f.emplace(id, GiNaC::numeric(1));
        return f;
    };
    std::map<NodeId, GiNaC::numeric> common = factors_of(s.args[0]);
    for (std::size_t i = 1; i < s.args.size() && !common.empty(); ++i) {
        const auto f = factors_of(s.args[i]);
        for (auto it = common.begin(); it != common.end();) {
            auto jt = f.find(it->first);
            if (jt == f.end() || !jt->second.is_equal(it->second))
                it = common.erase(it);
            else
                ++it;
        }
    }
    if (common.empty()) return sum;
    std::vector<std::pair<NodeId, GiNaC::numeric>> terms;
    GiNaC::numeric constant(0);
    for (std::size_t i = 0; i < s.args.size(); ++i) {
        auto f = factors_of(s.args[i]);
        for (const auto& c : common) f.erase(c.first);
        const Term t = make_mul(std::move(f), s.coeffs[i]);
        if (t.node == kOne)
            constant = constant + t.coeff;
        else
            terms.emplace_back(t.node, t.coeff);
    }
    const Term rest = make_add(std::move(terms), constant);
    const Term c = make_mul(std::move(common), GiNaC::numeric(1));
    return mul_terms(c, {rest.coeff * sum.coeff, rest.node});
}

Term ExprDag::build(Poly p, const std::unordered_map<NodeId, int>& rank) {
    auto& terms = p.terms;
    if (terms.empty()) return {GiNaC::numeric(0), kOne};
    auto monomial_term = [this](const Monomial& m, const GiNaC::numeric& c) {
        std::map<NodeId, GiNaC::numeric> f;
        for (const auto& [a, e] : m) f[a] = GiNaC::numeric(e);
        return make_mul(std::move(f), c);
    };
    if (terms.size() == 1) return monomial_term(terms[0].first, terms[0].second);

    // The monomial common to every term (same sign of exponent, smallest magnitude) comes out.
    Monomial common = terms[0].first;
    for (std::size_t i = 1; i < terms.size() && !common.empty(); ++i) {
        Monomial keep;
        for (const auto& [a, e] : common) {
            const int f = exponent_of(terms[i].first, a);
            if (f != 0 && (f > 0) == (e > 0)) keep.emplace_back(a, e > 0 ? std::min(e, f) : std::max(e, f));
        }
        common = std::move(keep);
    }
    if (!common.empty()) {
        Monomial inverse = common;
        for (auto& f : inverse) f.second = -f.second;
        for (auto& t : terms) t.first = multiply(t.first, inverse);
    }
    // The coefficient that leaves the fewest multiplications by constants comes out (2a + 2b = 2(a + b),
    // a/2 + b/2 + c = (a + b + 2c)/2); ties keep the terms as they are, then prefer the smaller number.
    std::vector<std::pair<GiNaC::numeric, long>> magnitudes;  // distinct |coefficient| of non-constant terms
    for (const auto& t : terms) {
        if (t.first.empty()) continue;
        const GiNaC::numeric c = GiNaC::abs(t.second);
        auto m = std::find_if(magnitudes.begin(), magnitudes.end(), [&c](const auto& x) { return x.first.is_equal(c); });
        if (m == magnitudes.end())
            magnitudes.emplace_back(c, 1);
        else
            ++m->second;
    }
    if (magnitudes.size() > 16) magnitudes.clear();  // many different coefficients: leave them
    auto constant_muls = [&magnitudes](const GiNaC::numeric& c) {
        long k = c.is_equal(1) ? 0 : 1;
        for (const auto& [v, count] : magnitudes) k += (v / c).is_equal(1) ? 0 : count;
        return k;
    };
    GiNaC::numeric content(1);
    long best_muls = constant_muls(content);
    for (const auto& m : magnitudes) {
        const GiNaC::numeric& c = m.first;
        const long k = constant_muls(c);
        if (k < best_muls || (k == best_muls && !content.is_equal(1) && c < content)) {
            content = c;
            best_muls = k;
        }
    }
    if (!content.is_equal(1))
        for (auto& t : terms) t.second = t.second / content;

    // The atom in most terms (ties: structural order) comes out of those terms: a·Q + R. Counted in a vector by
    // node id (a hash map per call was 4 % of generating the 60-link pendulum), set back to 0 after.
    std::vector<NodeId> counted;
    for (const auto& t : terms)
        for (const auto& [a, e] : t.first)
            if (e > 0) {
                if (static_cast<std::size_t>(a) >= atom_count_.size()) atom_count_.resize(nodes_.size(), 0);
                if (atom_count_[static_cast<std::size_t>(a)]++ == 0) counted.push_back(a);
            }
    NodeId best = kOne;
    int best_count = 1;
    for (NodeId a : counted) {
        const int c = atom_count_[static_cast<std::size_t>(a)];
        if (c > best_count || (c == best_count && best != kOne && rank.at(a) < rank.at(best))) {
            best = a;
            best_count = c;
        }
    }
    for (NodeId a : counted) atom_count_[static_cast<std::size_t>(a)] = 0;
    Term inner;
    if (best != kOne) {
        Poly q, r;
        q.terms.reserve(static_cast<std::size_t>(best_count));
        r.terms.reserve(terms.size() - static_cast<std::size_t>(best_count));
        for (auto& t : terms) {
            if (exponent_of(t.first, best) > 0)
                q.terms.emplace_back(shift(t.first, best, -1), t.second);
            else
                r.terms.emplace_back(std::move(t.first), t.second);
        }
        inner = add_terms(mul_terms({GiNaC::numeric(1), best}, build(std::move(q), rank)), build(std::move(r), rank));
        inner = factor_common(inner);
    } else {
        std::vector<std::pair<NodeId, GiNaC::numeric>> sum;
        GiNaC::numeric constant(0);
        for (const auto& [m, c] : terms) {
            const Term t = monomial_term(m, c);
            if (t.node == kOne)
                constant = constant + t.coeff;
            else
                sum.emplace_back(t.node, t.coeff);
        }
        inner = make_add(std::move(sum), constant);
    }
    return mul_terms(monomial_term(common, content), inner);
}

}  // namespace eomgen::codegen
