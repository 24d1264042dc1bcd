/** @file expansion_bound.cpp  The expansion-size bound of expansion_bound.hpp. */
#include "mechanics/expansion_bound.hpp"

#include <algorithm>
#include <vector>

namespace eomgen {
namespace {

constexpr double kSaturated = 1e18;

/// Term counts of the expression brought over a common denominator and expanded (what normal() and
/// expand() make of it): numerator and denominator, and the largest expansion anywhere inside it.
struct Size {
    double num = 1, den = 1;
    double most = 1;
};

double capped(double x) {
    return std::min(x, kSaturated);
}

/// C(k + n − 1, n): the monomials of degree n in k variables, the most terms (t₁ + … + t_k)^n expands to.
double multisets(double k, const GiNaC::numeric& power) {
    if (k <= 1) return k;                             // a monomial's power is one term
    if (power > 1000000) return kSaturated;           // at least n + 1 terms: past any budget
    const long n = power.to_long();
    double c = 1;
    for (long i = 1; i <= n && c < kSaturated; ++i) c = c * (k + double(i) - 1) / double(i);
    return capped(c);
}

Size size_of(const GiNaC::ex& e) {
    Size s;
    if (GiNaC::is_a<GiNaC::add>(e)) {  // a/b + c/d = (a d + c b) / (b d)
        std::vector<Size> terms;
        for (std::size_t i = 0; i < e.nops(); ++i) terms.push_back(size_of(e.op(i)));
        s.num = 0;
        for (std::size_t i = 0; i < terms.size(); ++i) {
            double n = terms[i].num;
            for (std::size_t j = 0; j < terms.size(); ++j)
                if (j != i) n = capped(n * terms[j].den);
            s.num = capped(s.num + n);
            s.den = capped(s.den * terms[i].den);
            s.most = std::max(s.most, terms[i].most);
        }
    } else if (GiNaC::is_a<GiNaC::mul>(e)) {
        for (std::size_t i = 0; i < e.nops(); ++i) {
            const Size o = size_of(e.op(i));
            s.num = capped(s.num * o.num);
            s.den = capped(s.den * o.den);
            s.most = std::max(s.most, o.most);
        }
    } else if (GiNaC::is_a<GiNaC::power>(e)) {
        const Size base = size_of(e.op(0));
        s.most = base.most;
        const GiNaC::ex n = e.op(1);
        if (n.info(GiNaC::info_flags::integer)) {
            const GiNaC::numeric power = GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(n));
            s.num = multisets(base.num, power);
            s.den = multisets(base.den, power);
            if (n.info(GiNaC::info_flags::negative)) std::swap(s.num, s.den);
        }
    } else {  // a symbol, a number, or a function whose arguments are expanded inside it
        for (std::size_t i = 0; i < e.nops(); ++i) s.most = std::max(s.most, size_of(e.op(i)).most);
    }
    s.most = std::max({s.most, s.num, s.den});
    return s;
}

}  // namespace

double expanded_terms(const GiNaC::ex& e) {
    return size_of(e).most;
}

}  // namespace eomgen
