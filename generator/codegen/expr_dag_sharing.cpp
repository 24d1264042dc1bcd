/**
 * @file expr_dag_sharing.cpp  ExprDag::share_partial(): sums and products that contain other sums and products are
 * rewritten to use them (expr_dag.hpp). A pass of its own over the optimized DAG, after optimize().
 */
#include "codegen/expr_dag.hpp"

#include <algorithm>
#include <unordered_map>

namespace eomgen::codegen {

void ExprDag::share_partial(std::vector<Term>& roots) {
    SharePlan plan;
    const std::size_t count = nodes_.size();
    plan.position.assign(count, -1);
    plan.sum_holders.resize(count);
    plan.product_holders.resize(count);
    plan.done.assign(count, SharePlan::kNone);
    plan.hits.assign(count, 0);
    // Reachable sums and products in a deterministic order (depth-first from the roots, children in their
    // canonical order): the order in which candidates are preferred.
    std::vector<NodeId> order;
    std::vector<char> seen(count, 0);
    std::vector<std::pair<NodeId, std::size_t>> stack;
    for (const Term& r : roots) {
        if (r.node == kOne || seen[std::size_t(r.node)]) continue;
        stack.emplace_back(r.node, 0);
        seen[std::size_t(r.node)] = 1;
        while (!stack.empty()) {
            auto& [id, next] = stack.back();
            const Node& n = node(id);
            if (next < n.args.size()) {
                const NodeId c = n.args[next++];
                if (c >= 0 && !seen[std::size_t(c)]) {
                    seen[std::size_t(c)] = 1;
                    stack.emplace_back(c, 0);
                }
                continue;
            }
            plan.position[std::size_t(id)] = static_cast<int>(order.size());
            order.push_back(id);
            stack.pop_back();
        }
    }
    // Candidate index: for each term (factor) node, the sums (products) holding it.
    for (NodeId id : order) {
        const Node& n = node(id);
        if ((n.op == Op::Add && n.value.is_zero()) || n.op == Op::Mul)
            if (n.args.size() >= 2)
                for (NodeId a : n.args)
                    if (a >= 0) (n.op == Op::Add ? plan.sum_holders : plan.product_holders)[std::size_t(a)].push_back(id);
    }
    // Smallest candidates first: a node looks only at candidates with fewer terms than its own (the rest cannot be
    // parts of it), and stops at the first that is not. Which candidate is taken does not depend on this order
    // (size, then the preference order decide).
    plan.arity.assign(count, 0);
    for (NodeId id : order) plan.arity[std::size_t(id)] = static_cast<int>(node(id).args.size());
    for (auto* holders : {&plan.sum_holders, &plan.product_holders})
        for (std::vector<NodeId>& h : *holders)
            std::sort(h.begin(), h.end(), [&plan](NodeId a, NodeId b) {
                return plan.arity[std::size_t(a)] != plan.arity[std::size_t(b)] ? plan.arity[std::size_t(a)] < plan.arity[std::size_t(b)]
                                                                                : a < b;
            });
    for (Term& r : roots)
        if (r.node != kOne) r.node = rewrite_shared(r.node, plan);
}

NodeId ExprDag::rewrite_shared(NodeId id, SharePlan& plan) {
    if (id < 0 || std::size_t(id) >= plan.done.size()) return id;  // a node made by this rewriting
    if (plan.done[std::size_t(id)] != SharePlan::kNone) return plan.done[std::size_t(id)];
    Node n = node(id);  // a copy: interning below may move nodes_
    const auto finish = [&](NodeId r) {
        plan.done[std::size_t(id)] = r;
        return r;
    };
    if ((n.op == Op::Add || n.op == Op::Mul) && n.args.size() >= 3) {
        // Greedily take the largest reachable sum (product) whose terms are all among ours with proportional
        // coefficients (equal exponents), then the largest among the rest, and so on.
        std::vector<bool> used(n.args.size(), false);
        std::unordered_map<NodeId, std::size_t> where;
        for (std::size_t i = 0; i < n.args.size(); ++i) where.emplace(n.args[i], i);
        std::vector<std::pair<NodeId, GiNaC::numeric>> parts;  // (sub-node, multiplier or exponent)
        // hits[c]: how many of our unused terms (factors) candidate c holds, counted once and then decremented as
        // terms are used, rather than recounted for every part taken (the same choices, byte-identical headers).
        // Only a candidate holding all of its terms among ours can be taken, and the count only falls: those are
        // kept. The counts live in plan.hits (indexed by node) and are set back to 0 before returning.
        // Candidates of our own kind only (sums for a sum, products for a product), indexed apart.
        const std::vector<std::vector<NodeId>>& holders = n.op == Op::Add ? plan.sum_holders : plan.product_holders;
        std::vector<NodeId>& touched = plan.touched;
        const std::size_t touched_from = touched.size();
        for (std::size_t i = 0; i < n.args.size(); ++i) {
            if (n.args[i] < 0 || std::size_t(n.args[i]) >= holders.size()) continue;
            for (NodeId cand : holders[std::size_t(n.args[i])]) {
                if (static_cast<std::size_t>(plan.arity[std::size_t(cand)]) >= n.args.size()) break;  // (id among them)
                if (plan.hits[std::size_t(cand)]++ == 0) touched.push_back(cand);
            }
        }
        std::vector<NodeId> whole;
        for (std::size_t k = touched_from; k < touched.size(); ++k) {
            const NodeId cand = touched[k];
            const Node& c = node(cand);
            if (static_cast<std::size_t>(plan.hits[std::size_t(cand)]) == c.args.size() && c.args.size() < n.args.size())
                whole.push_back(cand);
        }
        for (;;) {
            NodeId best = kOne;
            GiNaC::numeric best_factor;
            std::size_t best_size = 1;
            for (NodeId cand : whole) {
                const Node& c = node(cand);
                if (static_cast<std::size_t>(plan.hits[std::size_t(cand)]) != c.args.size()) continue;
                if (c.args.size() < best_size) continue;
                if (c.args.size() == best_size && best != kOne &&
                    plan.position[std::size_t(cand)] > plan.position[std::size_t(best)])
                    continue;
                GiNaC::numeric factor = n.op == Op::Add ? n.coeffs[where.at(c.args[0])] / c.coeffs[0] : 1;
                bool fits = true;
                for (std::size_t j = 0; j < c.args.size() && fits; ++j) {
                    const GiNaC::numeric mine = n.coeffs[where.at(c.args[j])];
                    fits = n.op == Op::Add ? mine.is_equal(factor * c.coeffs[j]) : mine.is_equal(c.coeffs[j]);
                }
                if (!fits) continue;
                best = cand;
                best_factor = factor;
                best_size = c.args.size();
            }
            if (best == kOne) break;
            for (NodeId a : node(best).args) {
                used[where.at(a)] = true;
                for (NodeId cand : holders[std::size_t(a)]) {
                    if (static_cast<std::size_t>(plan.arity[std::size_t(cand)]) >= n.args.size()) break;
                    --plan.hits[std::size_t(cand)];
                }
            }
            parts.emplace_back(best, best_factor);
        }
        for (std::size_t k = touched_from; k < touched.size(); ++k) plan.hits[std::size_t(touched[k])] = 0;
        touched.resize(touched_from);
        if (!parts.empty()) {
            if (n.op == Op::Add) {
                std::vector<std::pair<NodeId, GiNaC::numeric>> terms;
                for (const auto& [p, f] : parts) terms.emplace_back(rewrite_shared(p, plan), f);
                for (std::size_t i = 0; i < n.args.size(); ++i)
                    if (!used[i]) terms.emplace_back(rewrite_shared(n.args[i], plan), n.coeffs[i]);
                // Keep the sum as one node (no re-canonicalisation: it would split it up again).
                std::sort(terms.begin(), terms.end(),
                          [this](const auto& a, const auto& b) { return compare(a.first, b.first) < 0; });
                Node s{Op::Add, {}, {}, n.value, {}, -1};
                for (const auto& [a, c] : terms) {
                    s.args.push_back(a);
                    s.coeffs.push_back(c);
                }
                // (It may now lead with a negative coefficient; nothing matches on it any more.)
                return finish(intern(std::move(s)));
            }
            std::vector<std::pair<NodeId, GiNaC::numeric>> factors;
            for (const auto& [p, f] : parts) factors.emplace_back(rewrite_shared(p, plan), 1);
            for (std::size_t i = 0; i < n.args.size(); ++i)
                if (!used[i]) factors.emplace_back(rewrite_shared(n.args[i], plan), n.coeffs[i]);
            std::sort(factors.begin(), factors.end(),
                      [this](const auto& a, const auto& b) { return compare(a.first, b.first) < 0; });
            Node m{Op::Mul, {}, {}, GiNaC::numeric(0), {}, -1};
            for (const auto& [a, e] : factors) {
                m.args.push_back(a);
                m.coeffs.push_back(e);
            }
            return finish(intern(std::move(m)));
        }
    }
    bool changed = false;
    for (NodeId& a : n.args) {
        const NodeId b = rewrite_shared(a, plan);
        changed = changed || b != a;
        a = b;
    }
    return finish(changed ? intern(std::move(n)) : id);
}

}  // namespace eomgen::codegen
