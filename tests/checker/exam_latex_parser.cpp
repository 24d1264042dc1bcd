/** @file exam_latex_parser.cpp  LaTeX → GiNaC: each construct derivations use, and where and why the rest is
 * refused. */
#include "checker/latex_parser.hpp"
#include "model/nonsmooth.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace {

using eomgen::checker::Chain;
using eomgen::checker::LatexContext;
using eomgen::checker::NameKind;
using eomgen::checker::Relation;
using eomgen::checker::Side;

/// A context with the pendulum's names: θ, φ with their dots, m, M, l, a, g and time.
struct Names {
    GiNaC::symbol th{"theta", "\\theta"}, thd{"theta_dot", "\\dot{\\theta}"},
        thdd{"theta_ddot", "\\ddot{\\theta}"};
    GiNaC::symbol ph{"phi", "\\phi"}, phd{"phi_dot", "\\dot{\\phi}"};
    GiNaC::symbol m{"m"}, M{"M"}, l{"l"}, a{"a"}, g{"g"}, t{"t"};
    LatexContext ctx;
    Names() {
        ctx.names = {{"\\theta", th},
                     {"\\dot{\\theta}", thd},
                     {"\\ddot{\\theta}", thdd},
                     {"\\phi", ph},
                     {"\\dot{\\phi}", phd},
                     {"m", m},
                     {"M", M},
                     {"l", l},
                     {"a", a},
                     {"g", g},
                     {"t", t}};
        ctx.time = t;
    }
    GiNaC::ex parse(const std::string& latex) {
        const Side s = eomgen::checker::parse_expression(latex, ctx);
        INFO(latex << ": " << s.error << " at " << s.error_offset);
        REQUIRE(s.ok);
        return s.value;
    }
    Side fail(const std::string& latex) {
        const Side s = eomgen::checker::parse_expression(latex, ctx);
        INFO(latex);
        REQUIRE_FALSE(s.ok);
        REQUIRE_FALSE(s.error.empty());
        return s;
    }
    GiNaC::ex free(const std::string& name) {
        auto it = ctx.free_names.find(name);
        REQUIRE(it != ctx.free_names.end());
        return it->second.symbol;
    }
};

bool same(const GiNaC::ex& a, const GiNaC::ex& b) {
    return (a - b).expand().is_zero() || GiNaC::normal(a - b).is_zero();
}

}  // namespace

TEST_CASE("latex: fractions, powers, dots and implicit multiplication", "[checker][parser]") {
    Names n;
    CHECK(same(n.parse("\\frac{1}{2} M l^{2} \\dot{\\theta}^{2}"), n.M * n.l * n.l * n.thd * n.thd / 2));
    CHECK(same(n.parse("\\frac12 m"), n.m / 2));
    CHECK(same(n.parse("\\dfrac{m}{2} + \\tfrac{M}{3}"), n.m / 2 + n.M / 3));
    CHECK(same(n.parse("m l^2/6"), n.m * n.l * n.l / 6));
    CHECK(same(n.parse("m l^{2} \\dot{\\theta}^{2} / 6"), n.m * n.l * n.l * n.thd * n.thd / 6));
    CHECK(same(n.parse("(1 / 2)(m / l)\\left(l^{3} / 3\\right)"), n.m * n.l * n.l / 6));
    CHECK(same(n.parse("\\ddot{\\theta} + \\ddot\\theta"), 2 * n.thdd));
    CHECK(same(n.parse("2 m l"), 2 * n.m * n.l));
    CHECK(same(n.parse("(m)(l)"), n.m * n.l));
    CHECK(same(n.parse("m \\cdot l"), n.m * n.l));
    CHECK(same(n.parse("2 \\times 3 \\times l"), 6 * n.l));
    CHECK(same(n.parse("M a l \\,\\dot{\\theta}\\; \\dot\\phi"), n.M * n.a * n.l * n.thd * n.phd));
    CHECK(same(n.parse("\\left( m + M \\right)^{2}"), GiNaC::pow(n.m + n.M, 2)));
    CHECK(same(n.parse("[m + M] l"), (n.m + n.M) * n.l));
    CHECK(same(n.parse("-\\frac{1}{2}(m+2 M) g l"), -(n.m + 2 * n.M) * n.g * n.l / 2));
    CHECK(same(n.parse("\\left|l\\right| + |m|"), eomgen::real_abs(n.l) + eomgen::real_abs(n.m)));
    CHECK(same(n.parse("\\operatorname{sgn}(l) + \\mathrm{sign}(m)"), eomgen::sign(n.l) + eomgen::sign(n.m)));
}

TEST_CASE("latex: functions with and without parentheses", "[checker][parser]") {
    Names n;
    CHECK(same(n.parse("\\sin \\theta"), GiNaC::sin(n.th)));
    CHECK(same(n.parse("\\sin \\theta \\cos \\phi"), GiNaC::sin(n.th) * GiNaC::cos(n.ph)));
    CHECK(same(n.parse("\\cos (\\phi-\\theta)"), GiNaC::cos(n.ph - n.th)));
    CHECK(same(n.parse("\\cos{\\theta}"), GiNaC::cos(n.th)));
    CHECK(same(n.parse("\\sin\\left(\\theta+\\phi\\right)"), GiNaC::sin(n.th + n.ph)));
    CHECK(same(n.parse("\\sin ^{2} \\theta+\\cos^2\\theta"),
               GiNaC::pow(GiNaC::sin(n.th), 2) + GiNaC::pow(GiNaC::cos(n.th), 2)));
    CHECK(same(n.parse("\\sin 2\\theta"), GiNaC::sin(2 * n.th)));
    CHECK(same(n.parse("g \\cos \\theta \\, l"), n.g * GiNaC::cos(n.th) * n.l));
    CHECK(same(n.parse("\\operatorname{sin} \\phi"), GiNaC::sin(n.ph)));
    CHECK(same(n.parse("\\tan\\theta + \\exp a + \\ln l"),
               GiNaC::tan(n.th) + GiNaC::exp(n.a) + GiNaC::log(n.l)));
    // \cos \Omega t: the argument runs over a following t.
    const GiNaC::ex v = n.parse("\\cos \\Omega t");
    CHECK(same(v, GiNaC::cos(n.free("\\Omega") * n.t)));
    CHECK(same(n.parse("\\sqrt{l}"), GiNaC::sqrt(n.l)));
    CHECK(same(n.parse("\\sqrt[3]{l}"), GiNaC::pow(n.l, GiNaC::numeric(1, 3))));
}

TEST_CASE("latex: numbers are exact, with their rounding recorded", "[checker][parser]") {
    Names n;
    Side s = eomgen::checker::parse_expression("0.5 m", n.ctx);
    REQUIRE(s.ok);
    CHECK(same(s.value, n.m / 2));
    CHECK(s.rounding == Approx(0.1));  // ±0.05 on 0.5
    s = eomgen::checker::parse_expression("1.51 \\sqrt{l}", n.ctx);
    REQUIRE(s.ok);
    CHECK(same(s.value, GiNaC::numeric(151, 100) * GiNaC::sqrt(n.l)));
    CHECK(s.rounding == Approx(0.005 / 1.51));
    CHECK(same(n.parse("3 \\times 10^{-3}"), GiNaC::numeric(3, 1000)));
    CHECK(same(n.parse("45^{\\circ}"), GiNaC::Pi / 4));
    CHECK(same(n.parse("2 \\pi"), 2 * GiNaC::Pi));
}

TEST_CASE("latex: names with subscripts, primes, fonts and Greek letters", "[checker][parser]") {
    Names n;
    const GiNaC::ex i3 = n.parse("I_{3} + I_3");
    CHECK(same(i3, 2 * n.free("I_{3}")));
    n.parse("T_{\\text {rod }}");
    CHECK(n.ctx.free_names.count("T_{rod}") == 1);
    n.parse("\\text { Trod }");
    CHECK(n.ctx.free_names.count("Trod") == 1);
    CHECK(same(n.parse("x' - x^{\\prime}"), 0));
    const GiNaC::ex r2 = n.parse("r^{\\prime 2}");
    CHECK(same(r2, GiNaC::pow(n.free("r'"), 2)));
    CHECK(same(n.parse("\\varphi"), n.ph));
    CHECK(same(n.parse("\\operatorname{dot} \\phi"), n.phd));  // OCR's way of writing \dot{\phi}
    n.parse("\\mathbf{r}_{0} + \\boldsymbol{\\omega}_{a} + \\hat{\\mathbf{k}}");
    CHECK(n.ctx.free_names.at("\\mathbf{r}_{0}").kind == NameKind::Vector);
    CHECK(n.ctx.free_names.at("\\boldsymbol{\\omega}_{a}").kind == NameKind::Vector);
    CHECK(n.ctx.free_names.at("\\hat{\\mathbf{k}}").kind == NameKind::Vector);
    n.parse("3 \\mathrm{~m} / \\mathrm{s}^{2}");
    CHECK(n.ctx.free_names.at("\\mathrm{m}").kind == NameKind::Unit);
    // \mathrm{ml}: letters that are all known names multiply (OCR's "2 \mathrm{ml}^{2}").
    CHECK(same(n.parse("\\mathrm{ml}"), n.m * n.l));
    CHECK(eomgen::checker::canonical_name("T_{\\text {rod }}") == "T_{rod}");
    CHECK(eomgen::checker::canonical_name("I_3") == "I_{3}");
    CHECK(eomgen::checker::canonical_name("x^{\\prime}") == "x'");
    CHECK(eomgen::checker::canonical_name("\\dot{\\theta}_{1}") == "\\dot{\\theta_{1}}");
    CHECK(eomgen::checker::canonical_name("\\dot{\\dot{\\theta}}") == "\\ddot{\\theta}");
    CHECK(eomgen::checker::canonical_name("\\varphi") == "\\phi");
    CHECK(eomgen::checker::canonical_name("a + b").empty());
}

TEST_CASE("latex: derivatives and definite integrals", "[checker][parser]") {
    Names n;
    const GiNaC::ex d = n.parse("\\frac{d}{d t}\\left(m l^{2} \\dot{\\theta}\\right)");
    CHECK(is_ex_the_function(d, eomgen::checker::ddt));
    CHECK(same(d.op(0), n.m * n.l * n.l * n.thd));
    CHECK(is_ex_the_function(n.parse("\\frac{d \\theta}{d t}"), eomgen::checker::ddt));
    const GiNaC::ex p = n.parse("\\frac{\\partial L}{\\partial \\dot{\\theta}}");
    CHECK(is_ex_the_function(p, eomgen::checker::pdiff));
    CHECK(p.op(1).is_equal(n.thd));
    CHECK(same(n.parse("\\int_{0}^{l} s^{2} \\, d s"), GiNaC::pow(n.l, 3) / 3));
    const GiNaC::ex plate =
        n.parse("\\frac{m}{w h} \\int_{0}^{w} x^{\\prime 2} d x^{\\prime} \\int_{0}^{h} d z^{\\prime}");
    CHECK(same(plate, n.m * GiNaC::pow(n.free("w"), 2) / 3));
    // The variable of integration is bound: it is not a free name of the side.
    const Side s = eomgen::checker::parse_expression("\\int_{0}^{l} u \\, du", n.ctx);
    REQUIRE(s.ok);
    CHECK(s.uses.empty());
}

TEST_CASE("latex: indefinite integrals, primes in braces, a doubled sign, a full stop after a space", "[checker][parser]") {
    Names n;
    // ∫ f dq without limits in a coordinate (or t): held, for the checker to judge up to a constant.
    n.ctx.coordinates = {n.th, n.ph};
    const GiNaC::ex I = n.parse("\\int m g l \\sin\\theta \\, d\\theta");
    REQUIRE(is_ex_the_function(I, eomgen::checker::antiderivative));
    CHECK(I.op(1).is_equal(n.th));
    CHECK(same(I.op(0), n.m * n.g * n.l * sin(n.th)));
    CHECK(is_ex_the_function(n.parse("\\int \\dot{\\theta} \\, dt"), eomgen::checker::antiderivative));
    // Over a body (∫ v² dm), over a region (two differentials), or what does not parse: not read, as before.
    CHECK(n.fail("\\int v^{2} d m").error.find("indefinite integral") != std::string::npos);
    CHECK(n.fail("\\int m \\, d\\theta \\, d\\phi").error.find("indefinite integral") != std::string::npos);
    CHECK(n.fail("\\int ( m ? ) d\\theta").error.find("indefinite integral") != std::string::npos);
    // r_{1}^{'} and r_{1}^{''} are r_{1}' and r_{1}'' (as word processors write primes), like r_{1}^{\\prime}.
    CHECK(eomgen::checker::canonical_name("r_{1}^{'}") == eomgen::checker::canonical_name("r_{1}^{\\prime}"));
    CHECK(eomgen::checker::canonical_name("r_{1}^{''}") == eomgen::checker::canonical_name("r_{1}''"));
    CHECK(same(n.parse("m + + l"), n.m + n.l));
    CHECK(same(n.parse("\\frac{m l}{m + l \\,. }"), n.m * n.l / (n.m + n.l)));
    CHECK(same(n.parse("2."), GiNaC::numeric(2)));
    // |x|^2 = x^2 for a real x (a speed's square written with bars, a space after the bar).
    CHECK(same(n.parse("\\left|~\\dot{\\theta}\\right|^2"), n.thd * n.thd));
}

TEST_CASE("latex: what is not read gets a reason and the place", "[checker][parser]") {
    Names n;
    Side s = n.fail("\\omega_{3}\\left(I_{3} ? I\\right) / I");
    CHECK(s.error_offset == std::string("\\omega_{3}\\left(I_{3} ").size());
    CHECK(s.error.find("'?'") != std::string::npos);
    CHECK(n.fail("\\int_{A} \\sigma d A").error.find("region") != std::string::npos);
    CHECK(n.fail("l(\\cos \\theta, \\sin \\theta, 0)").error.find("vector or tuple") != std::string::npos);
    CHECK(n.fail("2 F(\\pi / 4,2)").error.find("unknown function F") != std::string::npos);
    CHECK(n.fail("\\frac{1}{0}").error.find("division by zero") != std::string::npos);
    CHECK(n.fail("\\left[\\begin{array}{cc} 1 & 2 \\end{array}\\right]").error.find("matrix") !=
          std::string::npos);
    CHECK(n.fail("\\sum_{i} x_{i}").error.find("sums") != std::string::npos);
    CHECK(n.fail("l^{1000}").error.find("too large") != std::string::npos);
    // By a known name other than t: not read; by a name the text introduces (a new time τ = t/T), the checker
    // reads its definition (exam_definitions.cpp).
    CHECK(n.fail("\\frac{d y}{d \\theta}").error.find("with respect to \\theta") != std::string::npos);
    CHECK(is_ex_the_function(n.parse("\\frac{d y}{d x}"), eomgen::checker::dby));
    s = n.fail("m + ");
    CHECK(s.error_offset == 3);  // the end of the formula
    n.fail("\\frac{1}{2");
    n.fail("\\left( m");
    n.fail("\\sqrt");
    n.fail("x_");
    n.fail("}");
}

TEST_CASE("latex: rows split into chains of relations", "[checker][parser]") {
    Names n;
    std::vector<Chain> c = eomgen::checker::parse_math("T = \\frac{1}{2} m l^{2} = T_{1} .", n.ctx);
    REQUIRE(c.size() == 1);
    REQUIRE(c[0].sides.size() == 3);
    CHECK(c[0].relations == std::vector<Relation>{Relation::Equal, Relation::Equal});
    CHECK(c[0].relation_offsets[0] == 2);
    CHECK(c[0].sides[2].source == "T_{1}");  // the sentence's full stop is not part of it
    c = eomgen::checker::parse_math("n_{1 x}=n_{1 y}, n_{1 z}=0 \\rightarrow x = 2", n.ctx);
    CHECK(c.size() == 3);
    c = eomgen::checker::parse_math("-\\pi / 2<\\psi<0", n.ctx);
    REQUIRE(c.size() == 1);
    CHECK(c[0].relations[0] == Relation::Inequality);
    c = eomgen::checker::parse_math("\\Delta t \\approx 1.51", n.ctx);
    CHECK(c[0].relations[0] == Relation::Approx);
    c = eomgen::checker::parse_math("f(a, b) = 1", n.ctx);  // commas inside parentheses do not split
    CHECK(c.size() == 1);
    // Two lists of as many entries, names on the left: one chain a name, each relation at its own place.
    const std::string tuple = "x, y, z = 0, l, 2a.";
    c = eomgen::checker::parse_math(tuple, n.ctx);
    REQUIRE(c.size() == 3);
    for (std::size_t k = 0; k < 3; ++k) {
        REQUIRE(c[k].sides.size() == 2);
        CHECK(c[k].sides[0].source == std::string(1, char('x' + k)));
        CHECK(c[k].relation_offsets[0] == tuple.find(char('x' + k)) + 1);
    }
    CHECK(c[1].sides[1].source == "l");
    CHECK(same(c[2].sides[1].value, 2 * n.a));
    c = eomgen::checker::parse_math("\\left(x, y\\right) = (l\\sin\\theta, -l\\cos\\theta)", n.ctx);
    REQUIRE(c.size() == 2);
    CHECK(same(c[1].sides[1].value, -n.l * GiNaC::cos(n.th)));
    // Not tuples: a left entry that is no name, lists of different lengths, a function's arguments.
    CHECK(eomgen::checker::parse_math("(x - a, y) = (1, 2)", n.ctx).size() == 1);
    CHECK(eomgen::checker::parse_math("x, y = 1, 2, 3", n.ctx).size() == 1);
    CHECK(eomgen::checker::parse_math("(a)(b) = 1, 2", n.ctx).size() == 1);
    // A vector set to a list: its components along the axes' unit vectors.
    c = eomgen::checker::parse_math("\\mathbf{r} = (l\\sin\\theta, -l\\cos\\theta)", n.ctx);
    REQUIRE(c.size() == 1);
    REQUIRE(c[0].sides.size() == 2);
    REQUIRE(c[0].sides[1].ok);
    CHECK(c[0].sides[1].source == "(l\\sin\\theta, -l\\cos\\theta)");
    CHECK(same(c[0].sides[1].value,
               n.l * GiNaC::sin(n.th) * n.free("\\hat{x}") - n.l * GiNaC::cos(n.th) * n.free("\\hat{y}")));
    c = eomgen::checker::parse_math("\\vec{r}_2 = (l, a)", n.ctx);
    REQUIRE(c.size() == 1);
    CHECK(c[0].sides[1].ok);
    // Other vectors and lists of other names in parentheses are left to linear_algebra.hpp, which reads them whole.
    c = eomgen::checker::parse_math("\\mathbf{u} = (1, 0, 0)", n.ctx);
    REQUIRE(c.size() == 1);
    CHECK_FALSE(c[0].sides[1].ok);
    CHECK(eomgen::checker::parse_math("(I_1, I_2) = (a, l)", n.ctx).size() == 1);
    CHECK(eomgen::checker::parse_math("I_1, I_2 = a, l", n.ctx).size() == 2);
    c = eomgen::checker::parse_math("=\\dot{\\phi}", n.ctx);
    REQUIRE(c.size() == 1);
    CHECK(c[0].sides[0].empty());
    // Math inside the display's text, `\text{where $c = d$}`: a chain of its own, at its place in the row.
    const std::string with_text = "a = g \\qquad \\text{where $m = l$}";
    c = eomgen::checker::parse_math(with_text, n.ctx);
    REQUIRE(c.size() == 2);
    REQUIRE(c[1].sides.size() == 2);
    CHECK(c[1].sides[0].source == "m");
    CHECK(c[1].sides[0].begin == with_text.find("m = l"));
    CHECK(c[1].relation_offsets[0] == with_text.find("= l"));
    CHECK(eomgen::checker::has_relation("a = b"));
    CHECK_FALSE(eomgen::checker::has_relation("\\left(a = b\\right)"));
}

// Regression (shared/repro/check_hang_*.md): "Fig. 1" in prose read as math made the parser multiply by a
// number it never consumed, forever. A full stop before a spaced digit is a full stop.
TEST_CASE("latex: a full stop before a spaced number ends the parse instead of looping", "[checker][parser]") {
    Names n;
    const Side s = n.fail("a m . 1 g");
    CHECK(s.error.find("'.'") != std::string::npos);
    CHECK(same(n.parse(".5 m"), n.m / 2));
    n.fail("m . 5");  // a spaced ". 5" is not 0.5
}

TEST_CASE("latex: functions written without their backslash", "[checker][parser]") {
    Names n;
    // As pages pasted from a word processor, and Q&A posts, write them.
    CHECK(same(n.parse("mglsin\\theta"), n.m * n.g * n.l * GiNaC::sin(n.th)));
    CHECK(same(n.parse("m l^2\\dot{\\phi}sin\\theta cos\\theta"),
               n.m * n.l * n.l * n.phd * GiNaC::sin(n.th) * GiNaC::cos(n.th)));
    CHECK(same(n.parse("cos(\\phi - \\theta) + tan^2\\theta"),
               GiNaC::cos(n.ph - n.th) + GiNaC::pow(GiNaC::tan(n.th), 2)));
    CHECK(same(n.parse("ln(l)"), GiNaC::log(n.l)));
    // Letters that only begin like a function stay letters: "sine", "cost", and ln without a bracket (l n).
    n.parse("a cost");
    CHECK(n.ctx.free_names.count("c") == 1);
    n.parse("ln a");
    CHECK(n.ctx.free_names.count("n") == 1);
}

TEST_CASE("latex: notation variants of notes and notebooks", "[checker][parser]") {
    Names n;
    // (\partial with its variable in braces and dx/dt as plain text: exam_roles.cpp, against a model.)
    // Macros of course notes: \Ddot is \ddot, \Vec is \vec.
    CHECK(same(n.parse("m l^2 \\Ddot{\\theta}"), n.m * n.l * n.l * n.thdd));
    // A struck-out factor is still a factor; a brace's note is not part of the formula.
    CHECK(same(n.parse("\\cancel{m} g \\sin\\theta"), n.m * n.g * GiNaC::sin(n.th)));
    CHECK(same(n.parse("\\overbrace{m l^2\\ddot\\theta}^{a} + \\underbrace{m g l \\sin\\theta}_{\\text{gravity}}"),
               n.m * n.l * n.l * n.thdd + n.m * n.g * n.l * GiNaC::sin(n.th)));
    // \{ … \} used as brackets (no comma: no Poisson bracket).
    CHECK(same(n.parse("\\frac{m}{2}\\{l^2\\dot\\theta^2 + a^2\\}"), n.m / 2 * (n.l * n.l * n.thd * n.thd + n.a * n.a)));
    // Markdown's escaped underscore is a subscript.
    n.parse("m\\_1 g");
    CHECK(n.ctx.free_names.count("m_{1}") == 1);
    // The sentence's full stop at the end of a formula, bare or in \text.
    CHECK(same(n.parse("\\frac{m}{a + l \\,. }"), n.m / (n.a + n.l)));
    CHECK(same(n.parse("g \\sin\\theta \\text{. }"), n.g * GiNaC::sin(n.th)));
    n.fail("\\left. g \\right|");  // a delimiter's '.' is not a full stop
    // Pasted from a word processor: a combining dot after a bracketed power dots its base (`(θ^2 ) ̇` is θ̇²).
    CHECK(same(n.parse("\\frac{m}{2}(\\theta^2 ) \xCC\x87"), n.m / 2 * n.thd * n.thd));
    // (A dot after a ')' that no '(' opens: refused, and read within bounds — the sanitized fuzz test found it.)
    n.fail("a ) \xCC\x87");
    n.fail(") \xCC\x87");
    // The ordinal sign typed for degrees; a number's large power of ten; a backslash ending a line is a space.
    CHECK(same(n.parse("120\xC2\xBA"), 120 * GiNaC::Pi / 180));
    CHECK(same(n.parse("1.993 \\cdot 10^{-26} m"), GiNaC::numeric(1993, 1000) * GiNaC::pow(10, -26) * n.m));
    CHECK(same(n.parse("a \\\n \\sin\\theta"), n.a * GiNaC::sin(n.th)));
    n.fail("(g + l)^{20}");  // large powers of sums are still refused
    // A unit in bare letters after a number, one of them no known name (k here), is a unit; known letters are a
    // product as before.
    n.parse("3628 N/k");  // not a unit: N/k is no unit
    n.parse("2.66 \\cdot 10^{-26} kg");
    bool unit = false;
    for (const auto& [name, f] : n.ctx.free_names) unit = unit || f.kind == eomgen::checker::NameKind::Unit;
    CHECK(unit);
    CHECK(same(n.parse("2 m g"), 2 * n.m * n.g));
    // ∂L/∂θ written with a slash, as plain text and some notes do: the fraction; an operand in brackets too.
    CHECK(same(n.parse("\\partial (m l^2 \\theta)/\\partial \\theta"),
               n.parse("\\frac{\\partial (m l^2 \\theta)}{\\partial \\theta}")));
    CHECK(same(n.parse("\\partial (m \\theta^2)/\\partial\\theta + g"),
               n.parse("\\frac{\\partial (m \\theta^2)}{\\partial\\theta} + g")));
    n.fail("\\partial m");  // no slash: still refused
    // e to a power is the exponential.
    CHECK(same(n.parse("a e^{-g t}"), n.a * GiNaC::exp(-n.g * n.t)));
    CHECK(same(n.parse("\\mathrm{e}^{g t}"), GiNaC::exp(n.g * n.t)));
}
