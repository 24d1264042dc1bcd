/** @file exam_budget.cpp  The bound on expansion sizes that keeps `eomgen check` answering in bounded time. */
#include "checker/budget.hpp"

#include <catch2/catch.hpp>

#include <random>

namespace {

double terms(const GiNaC::ex& e) {
    return GiNaC::is_a<GiNaC::add>(e) ? double(e.nops()) : 1.0;
}

/// A random expression in a, b, c, sin(a): sums, products, small integer powers (negative too), quotients.
GiNaC::ex random_expression(std::mt19937& rng, int depth) {
    static const GiNaC::symbol a("a"), b("b"), c("c");
    const GiNaC::ex leaves[] = {a, b, c, GiNaC::sin(a), 2, GiNaC::numeric(1, 3)};
    if (depth == 0 || rng() % 4 == 0) return leaves[rng() % 6];
    const GiNaC::ex x = random_expression(rng, depth - 1), y = random_expression(rng, depth - 1);
    switch (rng() % 5) {
        case 0:
        case 1:
            return x + y;
        case 2:
            return x * y;
        case 3:
            return GiNaC::pow(x, int(rng() % 7) - 3);
        default:
            return y.is_zero() ? x : x / y;
    }
}

}  // namespace

TEST_CASE("budget: the bound is exact on powers of sums and never below the expansion", "[checker][budget]") {
    using eomgen::checker::expanded_terms;
    const GiNaC::symbol a("a"), b("b"), c("c"), d("d");
    CHECK(expanded_terms(a) == 1);
    CHECK(expanded_terms(a + b + c) == 3);
    CHECK(expanded_terms(GiNaC::pow(a + b + c + d, 6)) == 84);  // C(9, 6)
    CHECK(expanded_terms((a + b) * (c + d)) == 4);
    CHECK(expanded_terms(1 / (a + b) + 1 / (c + d)) == 4);      // (c + d + a + b) / ((a + b)(c + d))
    CHECK(expanded_terms(GiNaC::sin(GiNaC::pow(a + b, 3))) == 4);  // expand() expands arguments too
    CHECK(expanded_terms(GiNaC::pow(a + b + c, 100000)) == Approx(5000150001.0));  // C(100002, 2)
    CHECK(expanded_terms(GiNaC::pow(a + b, 10000000)) >= 1e18);  // saturates instead of counting on
    CHECK(expanded_terms(GiNaC::pow(a, 100000)) == 1);
    std::mt19937 rng(7);
    for (int k = 0; k < 300; ++k) {
        const GiNaC::ex e = random_expression(rng, 4);
        INFO(e);
        const double bound = expanded_terms(e);
        CHECK(terms(e.expand()) <= bound);
        const GiNaC::ex nd = GiNaC::normal(e).numer_denom();
        CHECK(terms(nd.op(0).expand()) <= bound);
        CHECK(terms(nd.op(1).expand()) <= bound);
    }
}
