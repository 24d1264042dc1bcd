/**
 * @file test_differentiator.cpp  mechanics/differentiator and the float evaluators against GiNaC's own diff() and
 * evalf(): the same expressions from the remembered, support-skipping derivatives; the same values in double and
 * long double; is_zero's first look in both precisions never taking a symbolic zero for a number; h = T + V.
 */
#include "mechanics/differentiator.hpp"
#include "mechanics/double_evaluator.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model_file.hpp"
#include "model/nonsmooth.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using GiNaC::ex;

/// A random expression over the symbols: sums, products, integer and rational powers, sin, cos, exp, atan, the
/// model language's abs and sign,
/// with shared subexpressions (a node is reused from the ones made before).
ex random_expression(std::mt19937& rng, const std::vector<ex>& leaves, int depth, std::vector<ex>& made) {
    std::uniform_int_distribution<int> pick(0, 9);
    if (depth == 0 || pick(rng) < 2) {
        if (!made.empty() && pick(rng) < 3) return made[std::uniform_int_distribution<std::size_t>(0, made.size() - 1)(rng)];
        const int k = std::uniform_int_distribution<int>(0, static_cast<int>(leaves.size()))(rng);
        return k == static_cast<int>(leaves.size()) ? ex(GiNaC::numeric(pick(rng) + 1, 3)) : leaves[std::size_t(k)];
    }
    const ex a = random_expression(rng, leaves, depth - 1, made), b = random_expression(rng, leaves, depth - 1, made);
    ex out;
    switch (pick(rng)) {
        case 0: case 1: out = a + 3 * b; break;
        case 2: case 3: out = a * b; break;
        case 4: out = GiNaC::pow(a, 2) - GiNaC::numeric(1, 2) * b; break;
        case 5: out = GiNaC::sin(a) * b; break;
        case 6: out = GiNaC::cos(a + b); break;
        case 7: out = GiNaC::exp(a / 5) + GiNaC::atan(b); break;
        case 8: out = a / (GiNaC::pow(b, 2) + 1); break;
        default: out = eomgen::real_abs(a) + eomgen::sign(b) * b; break;
    }
    made.push_back(out);
    return out;
}

}  // namespace

TEST_CASE("the Differentiator gives GiNaC's diff(), with and without the support's skipping", "[mechanics]") {
    const GiNaC::symbol x("x"), y("y"), z("z"), p("p");  // p: a parameter the support does not list
    const std::vector<ex> leaves{x, y, z, p};
    eomgen::install_chain_rule();
    // The same value at two points (expanding the differences of these trees would take minutes).
    const std::vector<GiNaC::exmap> points{
        {{x, GiNaC::numeric(7, 10)}, {y, GiNaC::numeric(-13, 10)}, {z, GiNaC::numeric(1, 3)}, {p, GiNaC::numeric(11, 10)}},
        {{x, GiNaC::numeric(-3, 7)}, {y, GiNaC::numeric(9, 10)}, {z, GiNaC::numeric(5, 4)}, {p, GiNaC::numeric(-2, 3)}}};
    auto same = [&points](const ex& a, const ex& b) {
        if (a.is_equal(b)) return true;
        int evaluated = 0;
        for (const GiNaC::exmap& at : points) {
            ex d, s;
            try {
                d = GiNaC::evalf((a - b).subs(at));
                s = GiNaC::evalf(GiNaC::abs(b.subs(at)) + 1);
            } catch (const std::exception&) {
                continue;  // a pole of both there (1/(b² + 1) is none; atan'(u) or sign at 0 may be)
            }
            if (!GiNaC::is_a<GiNaC::numeric>(d) || !GiNaC::is_a<GiNaC::numeric>(s)) return false;
            if (GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(d)).to_double() > 1e-9 * GiNaC::ex_to<GiNaC::numeric>(s).to_double())
                return false;
            ++evaluated;
        }
        return evaluated > 0;
    };
    std::mt19937 rng(42);
    int compared = 0;
    for (int trial = 0; trial < 40; ++trial) {
        std::vector<ex> made;
        std::vector<ex> exprs;
        for (int k = 0; k < 4; ++k) exprs.push_back(random_expression(rng, leaves, 3, made));
        eomgen::SymbolSupport support({x, y, z});
        for (const GiNaC::symbol& s : {x, y, z, p}) {
            eomgen::Differentiator plain(s), skipping(s, &support);
            for (const ex& e : exprs) {
                const ex expected = e.diff(s);
                INFO("d/d" << s << " of " << e);
                CHECK(same(plain(e), expected));
                CHECK(same(skipping(e), expected));
                ++compared;
            }
        }
        // The directional derivative Σ v_k ∂/∂x_k.
        eomgen::Differentiator along(GiNaC::exmap{{x, y}, {z, 2}}, &support);
        for (const ex& e : exprs) CHECK(same(along(e), e.diff(x) * y + e.diff(z) * 2));
    }
    CHECK(compared == 40 * 4 * 4);
}

TEST_CASE("SymbolSupport: which listed symbols a node holds", "[mechanics]") {
    const GiNaC::symbol x("x"), y("y"), k("k");
    eomgen::SymbolSupport support({x, y});
    const std::vector<std::uint64_t> only_x = support.mask(std::vector<ex>{x}), only_y = support.mask(std::vector<ex>{y});
    const ex e = k * GiNaC::sin(x) + GiNaC::pow(k, 2);
    CHECK(support.holds(e, only_x));
    CHECK_FALSE(support.holds(e, only_y));
    CHECK_FALSE(support.holds(GiNaC::pow(k, 3) + 1, only_x));
    bool indexed = true;
    static_cast<void>(support.mask(GiNaC::exmap{{k, 1}}, indexed));
    CHECK_FALSE(indexed);  // k is not listed: a Differentiator seeded with it must not skip
}

TEST_CASE("the float evaluators agree with evalf() in double and long double", "[mechanics]") {
    const GiNaC::symbol x("x"), y("y"), z("z"), p("p");
    const std::vector<ex> leaves{x, y, z, p};
    const GiNaC::exmap at{{x, GiNaC::numeric(7, 10)}, {y, GiNaC::numeric(-13, 10)}, {z, GiNaC::numeric(1, 3)},
                          {p, GiNaC::numeric(11, 10)}};
    std::mt19937 rng(7);
    int compared = 0;
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<ex> made;
        const ex e = random_expression(rng, leaves, 4, made);
        const ex exact = GiNaC::evalf(e.subs(at));
        if (!GiNaC::is_a<GiNaC::numeric>(exact) || !GiNaC::ex_to<GiNaC::numeric>(exact).is_real()) continue;
        const double want = GiNaC::ex_to<GiNaC::numeric>(exact).to_double();
        if (!std::isfinite(want) || std::abs(want) > 1e12) continue;
        const std::optional<double> d = eomgen::DoubleEvaluator::at(at)(e);
        const std::optional<long double> l = eomgen::LongDoubleEvaluator::at(at)(e);
        REQUIRE(d);
        REQUIRE(l);
        INFO(e);
        CHECK(std::abs(*d - want) <= 1e-9 * (1 + std::abs(want)));
        CHECK(std::abs(static_cast<double>(*l) - want) <= 1e-9 * (1 + std::abs(want)));
        ++compared;
    }
    CHECK(compared > 100);
}

TEST_CASE("is_zero: zeros that round-off hides, and small values that are not zero", "[mechanics]") {
    const eomgen::Model md = eomgen::parse_model(
        "name = \"z\"\n[[coordinates]]\nname = \"x\"\n[[coordinates]]\nname = \"y\"\n[[parameters]]\nname = \"m\"\n"
        "value = 1.0\n[lagrangian]\nT = \"1/2*m*(x'^2 + y'^2)\"\nV = \"0\"\n",
        "z.toml");
    const ex x = md.coordinates[0].q, y = md.coordinates[1].q, m = md.parameters[0].symbol;
    const ex big = GiNaC::pow(x + y + m, 12);
    // Zero, though its double evaluation is round-off of terms of size 10^3 or so.
    CHECK(eomgen::is_zero(big * (GiNaC::pow(GiNaC::sin(x - y), 2) + GiNaC::pow(GiNaC::cos(x - y), 2) - 1), md));
    CHECK(eomgen::is_zero(big - big.expand(), md));
    CHECK(eomgen::is_zero(GiNaC::sin(x + y) - GiNaC::sin(x) * GiNaC::cos(y) - GiNaC::cos(x) * GiNaC::sin(y), md));
    // Not zero, though small beside its terms.
    CHECK_FALSE(eomgen::is_zero(big - big.expand() + GiNaC::numeric(1, 1000000000) * x, md));
    CHECK_FALSE(eomgen::is_zero(GiNaC::numeric(1, 1000000) * GiNaC::sin(x), md));
}

TEST_CASE("h = T + V where T is homogeneous quadratic in the velocities, else Σ q' p − L expanded", "[mechanics]") {
    auto model = [](const std::string& T, const std::string& V) {
        return eomgen::parse_model("name = \"h\"\n[[coordinates]]\nname = \"th\"\n[[coordinates]]\nname = \"ph\"\n"
                                   "[[parameters]]\nname = \"m\"\nvalue = 1.0\n[[parameters]]\nname = \"w\"\nvalue = 2.0\n"
                                   "[lagrangian]\nT = \"" + T + "\"\nV = \"" + V + "\"\n",
                                   "h.toml");
    };
    const eomgen::Equations natural = eomgen::derive_equations(model("m/2*((cos(th)*th')^2 + (sin(th)*th' + ph')^2)", "m*cos(th)"));
    CHECK(natural.natural);
    CHECK((natural.energy - (natural.T + natural.V)).is_zero());  // T as the model wrote it, not expanded
    // A rotating frame: T has T₁ and T₀ terms, and h = T₂ − T₀ + V.
    const eomgen::Model md = model("m/2*(th'^2 + (ph' + w)^2)", "0");
    const eomgen::Equations rotating = eomgen::derive_equations(md);
    CHECK_FALSE(rotating.natural);
    const ex m = md.parameters[0].symbol, w = md.parameters[1].symbol;
    const ex th_dot = md.coordinates[0].qd, ph_dot = md.coordinates[1].qd;
    CHECK((rotating.energy - (m / 2 * (GiNaC::pow(th_dot, 2) + GiNaC::pow(ph_dot, 2)) - m * GiNaC::pow(w, 2) / 2))
              .expand()
              .is_zero());
}

TEST_CASE("contains_nonsmooth over several expressions sharing nodes", "[mechanics]") {
    const GiNaC::symbol x("x"), y("y");
    const ex shared = GiNaC::pow(GiNaC::sin(x) + y, 3);
    CHECK_FALSE(eomgen::contains_nonsmooth(std::vector<ex>{shared, shared * x, shared + y}));
    CHECK(eomgen::contains_nonsmooth(std::vector<ex>{shared, shared * eomgen::sign(y - x)}));
    CHECK(eomgen::contains_nonsmooth(GiNaC::sin(eomgen::real_abs(x) + 1)));
}
