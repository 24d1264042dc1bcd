/** @file test_trig_rewrite.cpp  mechanics/trig_rewrite: angle sums both ways, sin² + cos² = 1 with
 * coefficients and powers, like terms collected, and (random consistency) the rewritten value always equals
 * the original. */
#include "mechanics/trig_rewrite.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

namespace {

using GiNaC::cos;
using GiNaC::ex;
using GiNaC::pow;
using GiNaC::sin;
using GiNaC::symbol;

bool same(const ex& a, const ex& b) {
    return (a - b).expand().is_zero();
}

std::size_t terms(const ex& e) {
    const ex x = e.expand();
    return GiNaC::is_a<GiNaC::add>(x) ? x.nops() : 1;
}

/// Every sine and cosine of e, as a list of their arguments.
bool has_trig_of(const ex& e, const ex& arg) {
    if ((GiNaC::is_the_function<GiNaC::sin_SERIAL>(e) || GiNaC::is_the_function<GiNaC::cos_SERIAL>(e)) &&
        e.op(0).is_equal(arg))
        return true;
    for (const ex& x : e)
        if (has_trig_of(x, arg)) return true;
    return false;
}

struct Syms {
    symbol a{"a"}, b{"b"}, m1{"m1"}, m2{"m2"}, l1{"l1"}, l2{"l2"}, R{"R"}, w{"w"}, t{"t"}, d1{"d1"}, d2{"d2"};
    GiNaC::exset constants() const { return {m1, m2, l1, l2, R, w}; }
};

}  // namespace

TEST_CASE("expand_sums splits sines and cosines of sums into products", "[trig]") {
    Syms s;
    CHECK(same(eomgen::trig::expand_sums(sin(s.a - s.b)), sin(s.a) * cos(s.b) - cos(s.a) * sin(s.b)));
    CHECK(same(eomgen::trig::expand_sums(cos(s.a + s.b)), cos(s.a) * cos(s.b) - sin(s.a) * sin(s.b)));
    // Three terms, nested: cos(a − b + wt) has only sines and cosines of a, b and wt left.
    const ex x = eomgen::trig::expand_sums(cos(s.a - s.b + s.w * s.t));
    CHECK_FALSE(has_trig_of(x, s.a - s.b + s.w * s.t));
    CHECK(has_trig_of(x, s.w * s.t));
    CHECK(terms(x) == 4);
}

TEST_CASE("contract_sums gives back the angle the author wrote, in the author's orientation", "[trig]") {
    Syms s;
    using eomgen::trig::contract_sums;
    const ex cc = cos(s.a) * cos(s.b), ss = sin(s.a) * sin(s.b), sc = sin(s.a) * cos(s.b),
             cs = cos(s.a) * sin(s.b);
    CHECK(contract_sums(cc + ss, {s.a - s.b}).is_equal(cos(s.a - s.b)));
    CHECK(contract_sums(cc - ss, {s.a + s.b}).is_equal(cos(s.a + s.b)));
    CHECK(contract_sums(sc - cs, {s.a - s.b}).is_equal(sin(s.a - s.b)));
    CHECK(contract_sums(sc + cs, {s.a + s.b}).is_equal(sin(s.a + s.b)));
    // Written b − a: sin a cos b − cos a sin b = −sin(b − a); the printed angle is the author's.
    const ex flipped = contract_sums(sc - cs, {s.b - s.a});
    CHECK(has_trig_of(flipped, s.b - s.a));
    CHECK(same(flipped, -sin(s.b - s.a)));
    // With a factor and numbers that differ: the common part pairs, the rest stays.
    const ex k = s.m2 * s.l1 * s.l2 * s.d1 * s.d2;
    CHECK(same(contract_sums(3 * k * cc + k * ss, {s.a - s.b}), k * cos(s.a - s.b) + 2 * k * cc));
    // Nothing to pair: unchanged.
    CHECK(same(contract_sums(cc + 2 * sin(s.a), {s.a - s.b}), cc + 2 * sin(s.a)));
    // cos²(a − b) expanded comes back whole.
    CHECK(contract_sums(eomgen::trig::expand_sums(pow(cos(s.a - s.b), 2)), {s.a - s.b})
              .is_equal(pow(cos(s.a - s.b), 2)));
}

TEST_CASE("angle_sums lists the sums and differences of the text's sines and cosines", "[trig]") {
    Syms s;
    const std::vector<ex> u =
        eomgen::trig::angle_sums(s.m1 * cos(s.b - s.a) + sin(s.a) + pow(sin(s.a + s.b), 2));
    REQUIRE(u.size() == 2);
    CHECK(((u[0].is_equal(s.b - s.a) && u[1].is_equal(s.a + s.b)) ||
           (u[1].is_equal(s.b - s.a) && u[0].is_equal(s.a + s.b))));
}

TEST_CASE("pythagoras applies sin^2 + cos^2 = 1 with coefficients and powers", "[trig]") {
    Syms s;
    using eomgen::trig::pythagoras;
    const ex sa = sin(s.a), ca = cos(s.a), sw = sin(s.w * s.t), cw = cos(s.w * s.t);
    CHECK(same(pythagoras(s.m1 + s.m2 * pow(sa, 2) + s.m2 * pow(ca, 2)), s.m1 + s.m2));
    CHECK(same(pythagoras(pow(sa, 4) + 2 * pow(sa, 2) * pow(ca, 2) + pow(ca, 4)), 1));
    CHECK(same(pythagoras(GiNaC::numeric(1, 2) * s.m2 * pow(s.l1 * s.d1, 2) * (pow(sa, 2) + pow(ca, 2))),
               GiNaC::numeric(1, 2) * s.m2 * pow(s.l1 * s.d1, 2)));
    // The bead on a spinning hoop written in Cartesian velocities: M = m R².
    CHECK(same(
        pythagoras(s.m1 * pow(s.R, 2) * (pow(ca, 2) * pow(cw, 2) + pow(ca, 2) * pow(sw, 2) + pow(sa, 2))),
        s.m1 * pow(s.R, 2)));
    // Unequal coefficients that do not shorten stay as they are.
    const ex kept = s.m1 * pow(ca, 2) + s.m2 * pow(sa, 2);
    CHECK(pythagoras(kept).is_equal(kept.expand()));
}

TEST_CASE("collect_like_terms sums the terms that differ in parameters and factors them", "[trig]") {
    Syms s;
    const ex e = s.m1 * pow(s.l1, 2) * s.d1 + s.m2 * pow(s.l1, 2) * s.d1 + s.m2 * s.l1 * s.l2 * s.d2;
    const ex c = eomgen::trig::collect_like_terms(e, s.constants());
    CHECK(same(c, e));
    REQUIRE(GiNaC::is_a<GiNaC::add>(c));
    CHECK(c.nops() == 2);
    // (m1 + m2) appears as a factor, not expanded.
    bool grouped = false;
    for (const ex& t : c)
        for (const ex& f : t) grouped = grouped || same(f, s.m1 + s.m2) || same(f, -s.m1 - s.m2);
    CHECK(grouped);
}

TEST_CASE("readable: the two-link chain from Cartesian velocities reads as the textbook T", "[trig]") {
    Syms s;
    const ex a = s.a, b = s.b;  // θ₁, θ₂; d1, d2 their rates
    // v₁ = l₁θ̇₁(cos θ₁, sin θ₁), v₂ = v₁ + l₂θ̇₂(cos θ₂, sin θ₂)
    const ex x1 = s.l1 * s.d1 * cos(a), y1 = s.l1 * s.d1 * sin(a);
    const ex x2 = x1 + s.l2 * s.d2 * cos(b), y2 = y1 + s.l2 * s.d2 * sin(b);
    const ex T = (s.m1 * (pow(x1, 2) + pow(y1, 2)) + s.m2 * (pow(x2, 2) + pow(y2, 2))) / 2;
    const ex textbook = (s.m1 + s.m2) * pow(s.l1 * s.d1, 2) / 2 +
                        s.m2 * s.l1 * s.l2 * s.d1 * s.d2 * cos(a - b) + s.m2 * pow(s.l2 * s.d2, 2) / 2;
    eomgen::trig::Hints hints;
    hints.angles = {a - b};
    hints.constants = s.constants();
    const ex r = eomgen::trig::readable(T, hints);
    CHECK(same(r, textbook));
    CHECK(has_trig_of(r, a - b));
    CHECK_FALSE(has_trig_of(r, a));
    CHECK(GiNaC::is_a<GiNaC::add>(r));
    CHECK(r.nops() == 3);
    // With no hint the pairing is found all the same (show has no author).
    hints.angles.clear();
    const ex r2 = eomgen::trig::readable(T, hints);
    CHECK(same(r2, textbook));
    CHECK(r2.nops() == 3);
}

TEST_CASE("readable never changes the value: random trigonometric polynomials at random points", "[trig]") {
    Syms s;
    std::mt19937 rng(20261124);
    std::uniform_int_distribution<int> small(-3, 3), pick(0, 5), count(1, 7);
    const ex atoms[] = {s.a, s.b, s.w * s.t, s.a - s.b, s.a + s.b, s.b - s.a};
    const ex coefficients[] = {s.m1, s.m2, s.l1 * s.l2, s.m2 * s.R, 1, s.d1 * s.d2};
    eomgen::trig::Hints hints;
    hints.constants = s.constants();
    hints.angles = {s.b - s.a};
    std::uniform_real_distribution<double> value(-2.0, 2.0);
    for (int n = 0; n < 150; ++n) {
        ex e = 0;
        for (int k = count(rng); k > 0; --k) {
            ex term = small(rng) * coefficients[pick(rng)];
            for (int f = pick(rng) % 4; f > 0; --f) {
                const ex u = atoms[pick(rng)];
                term *= pick(rng) % 2 ? sin(u) : cos(u);
            }
            e += term;
        }
        const ex r = eomgen::trig::readable(e, hints);
        CHECK(terms(r) <= terms(e));
        for (int point = 0; point < 3; ++point) {
            GiNaC::exmap at;
            for (const symbol& x : {s.a, s.b, s.m1, s.m2, s.l1, s.l2, s.R, s.w, s.t, s.d1, s.d2})
                at[x] = value(rng);
            const double ve = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(at))).to_double();
            const double vr = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(r.subs(at))).to_double();
            INFO("e = " << e << "\nr = " << r);
            CHECK(std::abs(ve - vr) <= 1e-10 * (1 + std::abs(ve)));
        }
    }
}

TEST_CASE("readable: terms over equal denominators written two ways meet, over a common denominator",
          "[trig]") {
    Syms s;
    eomgen::trig::Hints hints;
    hints.constants = s.constants();
    const ex s2 = pow(sin(s.a - s.b), 2);
    // The double pendulum's H: l1 (m1 l2 + m2 l2 s²) and m1 l1 l2 + m2 l1 l2 s² are one denominator.
    const ex e = s.d1 / (s.l1 * (s.m1 * s.l2 + s.m2 * s.l2 * s2)) +
                 s.d1 / (s.m1 * s.l1 * s.l2 + s.m2 * s.l1 * s.l2 * s2);
    const ex r = eomgen::trig::readable(e, hints);
    CHECK_FALSE(GiNaC::is_a<GiNaC::add>(r));  // one term
    CHECK(same(GiNaC::normal(r - 2 * s.d1 / (s.l1 * s.l2 * (s.m1 + s.m2 * s2))), 0));
    // A coefficient with denominators goes over a common one: (m1/(m2 l2²) + 1/l2²) d2 = (m1 + m2) d2/(m2
    // l2²).
    const ex c = eomgen::trig::collect_like_terms(s.m1 * s.d2 / (s.m2 * pow(s.l2, 2)) + s.d2 / pow(s.l2, 2),
                                                  s.constants());
    CHECK_FALSE(GiNaC::is_a<GiNaC::add>(c));
    CHECK(same(GiNaC::normal(c - (s.m1 + s.m2) * s.d2 / (s.m2 * pow(s.l2, 2))), 0));
    // Parameters alone over different denominators stay as written (k/m + 2 k/M).
    const ex k = s.R / s.m1 + 2 * s.R / s.m2;
    CHECK(eomgen::trig::collect_like_terms(k, s.constants()).is_equal(k));
}
