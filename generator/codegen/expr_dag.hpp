/** @file expr_dag.hpp  Canonical hash-consed expression DAG: GiNaC expressions in an order of our own. */
#pragma once

#include <ginac/ginac.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace eomgen::codegen {

/// What a leaf symbol stands for; also the order leaves are listed in products and sums.
enum class SymbolKind : std::uint8_t { Parameter, Coordinate, Velocity, Acceleration, Time, Constant };

struct SymbolInfo {
    SymbolKind kind;
    int index = 0;       ///< position among coordinates or parameters
    std::string name;    ///< C identifier in the generated code
    std::string text;    ///< name in the model language, e.g. "psi'"
    std::string latex;   ///< LaTeX for `eomgen show --latex`
    std::string source;  ///< where generated code reads it from, e.g. "q_(0)", "p_.m"
};

enum class Op : std::uint8_t { Number, Symbol, Func, Pow, Mul, Add };

using NodeId = std::int32_t;
constexpr NodeId kOne = -1;  ///< the empty product: a Term {c, kOne} is the number c

/**
 * One distinct subexpression. Products carry no coefficient (it moves to the enclosing sum's term),
 * sums have their leading term's coefficient positive (the sign moves out), and children are sorted by
 * a structural order, so the same mathematical input gives the same DAG whatever order or sign GiNaC
 * happened to use in this process (its term order follows hash values that ASLR moves).
 */
struct Node {
    Op op;
    std::vector<NodeId> args;            ///< Add: terms; Mul: factors; Pow: {base}; Func: arguments
    std::vector<GiNaC::numeric> coeffs;  ///< Add: coefficient of each term; Mul: exponent (±1, or any
                                         ///< integer when powers are not lowered) of each factor
    GiNaC::numeric value;                ///< Number: the value; Add: the constant term; Pow: exponent
    std::string name;                    ///< Func: function name
    int symbol = -1;                     ///< Symbol: index into the symbol table
};

/// A coefficient times a node (kOne for a pure number).
struct Term {
    GiNaC::numeric coeff;
    NodeId node = kOne;
};

class ExprDag {
public:
    /// `lower_powers`: integer powers become Pow nodes with exponent 2 or 3 (x⁴ = (x²)², x⁵ = (x²)²·x) so
    /// that generated code multiplies and shares the squares; off for printing mathematics.
    ExprDag(std::vector<SymbolInfo> symbols, const std::vector<GiNaC::ex>& symbol_exprs, bool lower_powers);

    /// Converts a GiNaC expression (rational numbers only, functions by name). Throws std::runtime_error
    /// for something generated code cannot express.
    Term add(const GiNaC::ex& e);

    /// The node for a whole term (c·n becomes a one-term sum node when c ≠ 1).
    NodeId node_of(const Term& t);

    const Node& node(NodeId id) const { return nodes_[static_cast<std::size_t>(id)]; }
    const SymbolInfo& symbol(int index) const { return symbols_[static_cast<std::size_t>(index)]; }
    std::size_t size() const { return nodes_.size(); }

    /// Structural total order: <0, 0, >0. Deterministic across processes.
    int compare(NodeId a, NodeId b) const;

    /**
     * Rewrites a term (from add()) into a cheaper form with the same value, for generated code:
     *  1. expands it into a sum of monomials over atoms (symbols, function calls, powers and reciprocals
     *     of sums, kept whole), so that terms which cancel do cancel;
     *  2. sin and cos of a sum of up to four symbols become products of each symbol's sin and cos
     *     (sin(a−b) = sin a cos b − cos a sin b, ...) when the code computes sin or cos of each of those
     *     symbols anyway (see note_angles());
     *  3. sin²x·R + cos²x·R = R (equal coefficients);
     *  4. refactors by a greedy multivariate Horner scheme: the monomial common to all terms and the
     *     coefficient that saves most multiplications come out, then the atom in most terms (ties: atoms
     *     that depend on q, q̇ or t before parameters, then structural order) is factored out of those
     *     terms, recursively (Ceberio & Kreinovich, "Greedy algorithms for optimizing multivariate Horner
     *     schemes", ACM SIGSAM Bulletin 38(1), 2004); a node that every term of a resulting sum has as a
     *     factor comes out of the sum.
     * When the expansion would grow past an internal limit of monomials, or the result would take more
     * operations than the term as it is (counted once per distinct node), the term is returned as it is.
     * Deterministic: every choice depends on counts and compare(), never on node ids.
     */
    Term optimize(const Term& t);

    /// Records the symbols x whose sin(x) or cos(x) the terms (from add()) compute: optimize() expands
    /// sin/cos of sums of recorded symbols only, so that the addition theorems never add function calls.
    void note_angles(const std::vector<Term>& roots);

    /**
     * Shares partial sums and products between the nodes reachable from `roots`: a sum (product) whose terms
     * (factors) include all those of another reachable sum (product) of at least two is rewritten as that one
     * plus (times) the rest, largest first; roots are replaced by the rewritten nodes.
     */
    void share_partial(std::vector<Term>& roots);

private:
    NodeId intern(Node n);
    NodeId number(const GiNaC::numeric& v);
    Term make_add(std::vector<std::pair<NodeId, GiNaC::numeric>> terms, GiNaC::numeric constant);
    Term make_mul(std::map<NodeId, GiNaC::numeric> factors, GiNaC::numeric coeff);
    NodeId make_pow(NodeId base, long k);
    Term make_power(const Term& base, const GiNaC::numeric& exponent);
    Term make_func(const std::string& name, std::vector<Term> args);
    Term convert(const GiNaC::ex& e);

    // optimize(): polynomials over atoms (expr_dag.cpp).
    struct Poly;
    struct PolyBuilder;
    bool expand_node(NodeId id, std::shared_ptr<const Poly>& out);
    Term optimize_node(NodeId id);
    Term build(Poly p, const std::unordered_map<NodeId, int>& rank);
    void pythagoras(Poly& p, const std::unordered_map<NodeId, int>& rank);
    std::unordered_map<NodeId, int> atom_ranks(const Poly& p) const;
    bool depends_on_state(NodeId id, std::unordered_map<NodeId, char>& memo) const;
    NodeId find_func(const std::string& name, NodeId arg) const;
    Term mul_terms(const Term& a, const Term& b);
    Term add_terms(const Term& a, const Term& b);
    Term factor_common(const Term& sum);
    long cost(NodeId root) const;
    /// share_partial()'s tables, indexed by the node ids that existed when it started (ids are dense): vectors,
    /// not hash maps, which were a fifth of a 60-link chain's emission.
    struct SharePlan {
        std::vector<int> position;                 ///< preference order of reachable sums and products; -1 none
        std::vector<std::vector<NodeId>> sum_holders;      ///< per term: the sums holding it
        std::vector<std::vector<NodeId>> product_holders;  ///< per factor: the products holding it
        std::vector<int> arity;  ///< per candidate: its number of terms (factors); holders are sorted by it
        std::vector<NodeId> done;                  ///< rewritten node per original node; kNone when not yet
        std::vector<int> hits;                     ///< per candidate: scratch of rewrite_shared(), kept at 0
        std::vector<NodeId> touched;               ///< candidates whose hits are not 0
        static constexpr NodeId kNone = -2;
    };
    NodeId rewrite_shared(NodeId id, SharePlan& plan);

    struct NodeHash {
        std::size_t operator()(const Node& n) const;
    };
    struct NodeEqual {
        bool operator()(const Node& a, const Node& b) const;
    };

    std::vector<SymbolInfo> symbols_;
    GiNaC::exhashmap<int> symbol_index_;
    bool lower_powers_;
    std::vector<Node> nodes_;
    std::unordered_map<Node, NodeId, NodeHash, NodeEqual> interned_;
    GiNaC::exhashmap<Term> memo_;
    std::unordered_map<NodeId, Term> optimized_;  ///< optimize() of single nodes (arguments, opaque sums)
    std::unordered_map<NodeId, std::shared_ptr<const Poly>> expanded_;  ///< expansions, shared between outputs
    std::unordered_map<NodeId, bool> angles_;  ///< note_angles(): symbols with sin or cos computed
    std::vector<int> expansion_users_;         ///< note_angles(): how often each node's expansion is asked for
    std::vector<int> atom_count_;              ///< build()'s scratch, by node id: all 0 between calls
    std::size_t expansion_budget_ = 0;           ///< monomials optimize() may still create for this term
};

/// The terms of `values` in the form generated code computes: cheaper forms first (expansion, sin² + cos² = 1,
/// Horner: ExprDag::optimize), then partial sums and products shared (share_partial). What the C++ emitter prints
/// and the interpreter's tapes record (interpreter/tape.hpp), so that both do the same arithmetic.
std::vector<Term> code_roots(ExprDag& dag, const std::vector<GiNaC::ex>& values);

/// Name of a numeric for keys and messages: exact rationals as "p/q".
std::string numeric_string(const GiNaC::numeric& v);

}  // namespace eomgen::codegen
