/** @file hamiltonian.cpp  Legendre transform L(q, q̇, t) → H(q, p, t), block by block of the mass matrix. */
#include "mechanics/hamiltonian.hpp"

#include "mechanics/expansion_bound.hpp"

#include <algorithm>
#include <optional>
#include <sstream>

namespace eomgen {
namespace {

/// The blocks of coordinates M couples (connected components of its non-zero entries), in coordinate order.
std::vector<std::vector<unsigned>> coupled_blocks(const GiNaC::matrix& M, const Model& model) {
    const unsigned n = M.rows();
    std::vector<int> block(n, -1);
    std::vector<std::vector<unsigned>> out;
    for (unsigned s = 0; s < n; ++s) {
        if (block[s] >= 0) continue;
        out.push_back({});
        std::vector<unsigned> stack{s};
        block[s] = int(out.size() - 1);
        while (!stack.empty()) {
            const unsigned i = stack.back();
            stack.pop_back();
            out.back().push_back(i);
            for (unsigned j = 0; j < n; ++j)
                if (block[j] < 0 && !is_zero(M(i, j), model)) {
                    block[j] = block[s];
                    stack.push_back(j);
                }
        }
        std::sort(out.back().begin(), out.back().end());
    }
    return out;
}

/// The most terms det of a block of M may expand to for its inverse to be formed symbolically (as for det M's
/// factorization in lagrangian.cpp): beyond it normal() on the inverse runs for minutes.
constexpr double kMaxInverseDetTerms = 4000;

/// An upper bound on the terms of det(sub) expanded: Σ over permutations of Π expanded_terms(entries).
double det_terms(const GiNaC::matrix& sub) {
    const unsigned k = sub.rows();
    std::vector<unsigned> perm(k);
    for (unsigned i = 0; i < k; ++i) perm[i] = i;
    double total = 0;
    do {
        double product = 1;
        for (unsigned r = 0; r < k && product > 0; ++r)
            product = sub(r, perm[r]).is_zero() ? 0 : product * expanded_terms(sub(r, perm[r]));
        total += product;
    } while (std::next_permutation(perm.begin(), perm.end()));
    return total;
}

/// The most variables det of a block of M may hold, as a polynomial (every symbol, and every sin, cos or other
/// function of the coordinates counted as one variable), for its inverse to be simplified by normal(): GiNaC's
/// multivariate gcd is exponential in them. A 3×3 block of 65 terms in 18 variables (a fuzzed model) ran for
/// 160 s in normal(); the shipped models' largest block, the triangle plate's, has 11.
constexpr std::size_t kMaxSimplifyVariables = 12;

/// The number of variables of e as a polynomial (GiNaC::to_polynomial's symbols and the symbols it introduces).
std::size_t polynomial_variables(const GiNaC::ex& e) {
    GiNaC::exmap introduced;
    const GiNaC::ex poly = e.expand().to_polynomial(introduced);
    GiNaC::exset symbols;
    for (GiNaC::const_preorder_iterator it = poly.preorder_begin(); it != poly.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it)) symbols.insert(*it);
    return symbols.size();
}

/// The inverse of a small block (k ≤ 3) as adj/det, each entry normal(cofactor / det) over the expanded
/// polynomials. GiNaC's matrix::inverse() eliminates with normal() after every step, whose gcds of growing
/// rational functions are far slower: a 3×3 block of two bodies turned by chains of the same angles, with a
/// product of inertia (11 polynomial variables, a fuzzed model, seed 35009), took 22 s there and 0.1 s here.
/// Empty where the block's determinant vanishes identically.
std::optional<GiNaC::matrix> inverse_by_cofactors(const GiNaC::matrix& sub) {
    const unsigned k = sub.rows();
    const GiNaC::ex det = sub.determinant(GiNaC::determinant_algo::laplace).expand();
    if (det.is_zero()) return std::nullopt;
    GiNaC::matrix inv(k, k);
    for (unsigned r = 0; r < k; ++r)
        for (unsigned c = 0; c < k; ++c) {
            GiNaC::ex cofactor = 1;
            if (k > 1) {  // the minor without row c and column r, for entry (r, c) of adj = cofactorsᵀ
                GiNaC::matrix minor(k - 1, k - 1);
                for (unsigned i = 0, mi = 0; i < k; ++i) {
                    if (i == c) continue;
                    for (unsigned j = 0, mj = 0; j < k; ++j)
                        if (j != r) minor(mi, mj++) = sub(i, j);
                    ++mi;
                }
                cofactor = minor.determinant(GiNaC::determinant_algo::laplace).expand();
                if ((r + c) % 2) cofactor = -cofactor;
            }
            inv(r, c) = GiNaC::normal(cofactor / det);
        }
    return inv;
}

}  // namespace

GiNaC::ex shorter_trig(const GiNaC::ex& e) {
    const GiNaC::ex w = GiNaC::wild(0);
    auto length = [](const GiNaC::ex& x) {
        std::ostringstream os;
        os << x;
        return os.str().size();
    };
    GiNaC::ex best = e;
    for (const GiNaC::ex& rule : {GiNaC::ex(GiNaC::pow(GiNaC::cos(w), 2) == 1 - GiNaC::pow(GiNaC::sin(w), 2)),
                                  GiNaC::ex(GiNaC::pow(GiNaC::sin(w), 2) == 1 - GiNaC::pow(GiNaC::cos(w), 2))}) {
        try {
            const GiNaC::ex x = GiNaC::normal(e.subs(rule, GiNaC::subs_options::algebraic));
            if (length(x) < length(best)) best = x;
            const GiNaC::ex f = GiNaC::factor(x);  // (I1 + M l²) sin²θ rather than its expansion
            if (length(f) < length(best)) best = f;
        } catch (const std::exception&) {
        }
    }
    return best;
}

Hamiltonian derive_hamiltonian(const Model& model, const Equations& eq) {
    Hamiltonian h;
    const unsigned n = unsigned(model.dof());
    GiNaC::exmap rest;  // q̇ = 0
    for (const Coordinate& c : model.coordinates) rest[c.qd] = 0;
    for (const Coordinate& c : model.coordinates)
        h.p.emplace_back("p_" + c.name, "p_{" + c.latex + "}");
    for (const ConstraintEquations& k : eq.constraints) h.lambda.emplace_back("lambda_" + k.name);
    h.momenta = eq.momenta;
    h.M = eq.M;
    for (unsigned i = 0; i < n; ++i) h.b.push_back(eq.momenta[i].subs(rest).expand());
    h.L0 = eq.L.subs(rest).expand();

    const std::vector<std::vector<unsigned>> blocks = coupled_blocks(h.M, model);
    for (const std::vector<unsigned>& blk : blocks)
        if (blk.size() > 3) {
            std::string names;
            for (unsigned i : blk) names += (names.empty() ? "" : ", ") + model.coordinates[i].name;
            h.why_not_symbolic = "the mass matrix couples " + std::to_string(blk.size()) + " coordinates (" + names +
                                 "): its inverse is not formed symbolically";
            return h;
        }
    std::vector<GiNaC::matrix> subs;
    for (const std::vector<unsigned>& blk : blocks) {
        const unsigned k = unsigned(blk.size());
        GiNaC::matrix sub(k, k);
        for (unsigned r = 0; r < k; ++r)
            for (unsigned c = 0; c < k; ++c) sub(r, c) = h.M(blk[r], blk[c]);
        if (const double terms = det_terms(sub); terms > kMaxInverseDetTerms) {
            std::string names;
            for (unsigned i : blk) names += (names.empty() ? "" : ", ") + model.coordinates[i].name;
            std::ostringstream why;
            why << "the mass matrix's entries are too large to invert symbolically within the budget (the determinant"
                << " of the block of " << names << " expands to up to " << terms << " terms, more than "
                << kMaxInverseDetTerms << ")";
            h.why_not_symbolic = why.str();
            return h;
        }
        if (k > 1) {
            const std::size_t vars = polynomial_variables(sub.determinant(GiNaC::determinant_algo::laplace));
            if (vars > kMaxSimplifyVariables) {
                std::string names;
                for (unsigned i : blk) names += (names.empty() ? "" : ", ") + model.coordinates[i].name;
                h.why_not_symbolic = "the determinant of the mass matrix's block of " + names + " is a polynomial in " +
                                     std::to_string(vars) + " variables (symbols, sines, cosines), more than " +
                                     std::to_string(kMaxSimplifyVariables) +
                                     ": its inverse is not simplified within the budget";
                return h;
            }
        }
        subs.push_back(sub);
    }
    h.Minv = GiNaC::matrix(n, n);
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        const std::vector<unsigned>& blk = blocks[b];
        const unsigned k = unsigned(blk.size());
        const std::optional<GiNaC::matrix> inv = inverse_by_cofactors(subs[b]);
        if (!inv) {
            h.why_not_symbolic = "a block of the mass matrix is singular for every value of the coordinates";
            return h;
        }
        for (unsigned r = 0; r < k; ++r)
            for (unsigned c = 0; c < k; ++c) h.Minv(blk[r], blk[c]) = shorter_trig((*inv)(r, c));
    }
    std::vector<GiNaC::ex> shifted(n);  // p − b
    for (unsigned i = 0; i < n; ++i) shifted[i] = h.p[i] - h.b[i];
    GiNaC::ex H = -h.L0;
    for (unsigned i = 0; i < n; ++i) {
        GiNaC::ex v = 0;
        for (unsigned j = 0; j < n; ++j) v += h.Minv(i, j) * shifted[j];
        h.velocities.push_back(v);
        for (unsigned j = 0; j < n; ++j)
            if (!h.Minv(i, j).is_zero()) H += h.Minv(i, j) * shifted[i] * shifted[j] / 2;
    }
    h.H = H;
    GiNaC::exmap qdot_of_p;
    for (unsigned i = 0; i < n; ++i) qdot_of_p[model.coordinates[i].qd] = h.velocities[i];
    for (unsigned i = 0; i < n; ++i) {
        h.qdot.push_back(GiNaC::diff(H, h.p[i]));
        GiNaC::ex pdot = -GiNaC::diff(H, model.coordinates[i].q);
        if (i < eq.generalized_forces.size()) pdot += eq.generalized_forces[i].subs(qdot_of_p);
        // The constraint forces: without them a particle held on a sphere would have ṗ_x = −∂H/∂x = 0.
        for (std::size_t k = 0; k < eq.constraints.size(); ++k)
            pdot += eq.constraints[k].jacobian[i].subs(qdot_of_p) * h.lambda[k];
        h.pdot.push_back(pdot);
    }
    h.symbolic = true;
    return h;
}

GiNaC::ex in_velocities(const GiNaC::ex& e, const Hamiltonian& h) {
    GiNaC::exmap m;
    for (std::size_t i = 0; i < h.p.size(); ++i) m[h.p[i]] = h.momenta[i];
    return e.subs(m);
}

}  // namespace eomgen
