/**
 * @file stored_terms.hpp  The terms and factors of GiNaC's sums and products as it stores them.
 *
 * GiNaC keeps a sum Σ c_k x_k + c and a product Π x_k^e_k · c as pairs (x_k, c_k) and an overall coefficient, and
 * e.op(k) builds a new node c_k·x_k (x_k^e_k) for every term it is asked for. A walk that only needs the x_k (which
 * symbols or functions a tree holds, its value at a point) reads the pairs instead: no allocation, and the x_k are
 * the shared nodes, so a walk that remembers nodes by address meets each once. The pairs are protected members,
 * reached through a derived class, as the language allows.
 */
#pragma once

#include <ginac/ginac.h>

namespace eomgen {

struct StoredTerms : GiNaC::expairseq {
    /// The pairs (x_k, c_k) of a sum or product (e must be exactly an add or a mul).
    static const GiNaC::epvector& pairs(const GiNaC::ex& e) {
        return GiNaC::ex_to<GiNaC::expairseq>(e).*(&StoredTerms::seq);
    }
    /// The constant term of a sum, the numeric factor of a product.
    static const GiNaC::ex& overall_coefficient(const GiNaC::ex& e) {
        return GiNaC::ex_to<GiNaC::expairseq>(e).*(&StoredTerms::overall_coeff);
    }
    /// Calls visit(child) for each node below e: the x_k of a sum's or product's pairs (their coefficients are
    /// numbers), the operands of anything else.
    template <class Visit>
    static void for_each_child(const GiNaC::ex& e, Visit&& visit) {
        if (GiNaC::is_exactly_a<GiNaC::add>(e) || GiNaC::is_exactly_a<GiNaC::mul>(e)) {
            for (const GiNaC::expair& p : pairs(e)) visit(p.rest);
        } else {
            for (std::size_t i = 0; i < e.nops(); ++i) visit(e.op(i));
        }
    }
};

}  // namespace eomgen
