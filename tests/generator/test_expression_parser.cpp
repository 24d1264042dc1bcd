/** @file test_expression_parser.cpp  Expressions: exact numbers, precedence, velocities, errors. */
#include "model/expression_parser.hpp"
#include "model/nonsmooth.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <string>

namespace {

using Catch::Matchers::Contains;

/// Symbols of a two-coordinate system, as the model file reader would set them up.
struct Symbols {
    GiNaC::symbol m{"m"}, g{"g"}, l{"l"}, t{"t"};
    GiNaC::symbol psi{"psi"}, theta{"theta"}, psi_dot{"psi_dot"}, theta_dot{"theta_dot"};
    eomgen::SymbolTable table;

    Symbols() {
        table.symbols = {{"m", m}, {"g", g}, {"l", l}, {"t", t}, {"psi", psi}, {"theta", theta}};
        table.velocities = {{"psi", psi_dot}, {"theta", theta_dot}};
    }
    GiNaC::ex parse(const std::string& text, const eomgen::ParseOptions& options = {}) const {
        return eomgen::parse_expression(text, table, options);
    }
};

bool same(const GiNaC::ex& a, const GiNaC::ex& b) {
    return (a - b).expand().is_zero();
}

/// The error a text gives: its offset and message. Fails the test when it parses.
eomgen::ExpressionError error_of(const Symbols& s, const std::string& text,
                                 const eomgen::ParseOptions& options = {}) {
    try {
        const GiNaC::ex e = s.parse(text, options);
        FAIL_CHECK("'" << text << "' parsed as " << e << " instead of failing");
    } catch (const eomgen::ExpressionError& e) {
        return e;
    }
    return eomgen::ExpressionError(std::string::npos, "");
}

bool is_exact_rational(const GiNaC::ex& e) {
    return GiNaC::is_a<GiNaC::numeric>(e) && GiNaC::ex_to<GiNaC::numeric>(e).is_rational();
}

}  // namespace

TEST_CASE("decimal numbers are exact rationals, never floats", "[parser]") {
    const Symbols s;
    CHECK(same(s.parse("0.5*m"), s.m / 2));
    CHECK(GiNaC::ex_to<GiNaC::numeric>(s.parse("2.5e-3")).is_equal(GiNaC::numeric(1, 400)));
    const std::pair<const char*, GiNaC::numeric> cases[] = {
        {"0.5", GiNaC::numeric(1, 2)},
        {"2.5e-3", GiNaC::numeric(1, 400)},
        {"1e-3", GiNaC::numeric(1, 1000)},
        {".25", GiNaC::numeric(1, 4)},
        {"1.e2", GiNaC::numeric(100)},
        {"1E+2", GiNaC::numeric(100)},
        {"007", GiNaC::numeric(7)},
        {"0.000", GiNaC::numeric(0)},
        {"123.456e2", GiNaC::numeric(61728, 5)},
        {"9.81", GiNaC::numeric(981, 100)},
        {"0.1+0.2", GiNaC::numeric(3, 10)},
        {"1e20", GiNaC::numeric("100000000000000000000")},
    };
    for (const auto& [text, value] : cases) {
        INFO(text);
        const GiNaC::ex e = s.parse(text);
        REQUIRE(is_exact_rational(e));
        CHECK(GiNaC::ex_to<GiNaC::numeric>(e).is_equal(value));
    }
}

TEST_CASE("precedence and associativity", "[parser]") {
    const Symbols s;
    const std::pair<const char*, GiNaC::ex> numbers[] = {
        {"1+2*3", 7},
        {"2*3^2", 18},
        {"-2^2", -4},
        {"2^3^2", 512},
        {"2^-1", GiNaC::numeric(1, 2)},
        {"(1+2)*3", 9},
        {"8/4/2", 1},
        {"8-4-2", 2},
        {"2^-2^2", GiNaC::numeric(1, 16)},
        {"--3", 3},
        {"+3", 3},
        {"-3*-2", 6},
        {"2*-3", -6},
        {"(2^3)^2", 64},
        {"1 - -1", 2},
        {"6/2*3", 9},
        {"2^(1+1)", 4},
        {" \t\n 4 \n", 4},
    };
    for (const auto& [text, value] : numbers) {
        INFO(text);
        CHECK(same(s.parse(text), value));
    }
    CHECK(same(s.parse("-m^2"), -GiNaC::pow(s.m, 2)));
    CHECK(same(s.parse("m^l^g"), GiNaC::pow(s.m, GiNaC::pow(s.l, s.g))));
    CHECK(same(s.parse("m/g*l"), s.m * s.l / s.g));
    CHECK(same(s.parse("m - g + l"), s.m - s.g + s.l));
    CHECK(same(s.parse("m*g*l*(1 - cos(theta))"), s.m * s.g * s.l * (1 - GiNaC::cos(s.theta))));
}

TEST_CASE("names, constants and functions", "[parser]") {
    const Symbols s;
    CHECK(same(s.parse("pi"), GiNaC::Pi));
    CHECK(same(s.parse("t"), s.t));
    CHECK(same(s.parse("sin(theta)^2 + cos(theta)^2"),
               GiNaC::pow(GiNaC::sin(s.theta), 2) + GiNaC::pow(GiNaC::cos(s.theta), 2)));
    CHECK(same(s.parse("atan2(m, l)"), GiNaC::atan2(s.m, s.l)));
    CHECK(same(s.parse("sqrt(m)"), GiNaC::sqrt(s.m)));
    CHECK(same(s.parse("exp(t)*log(m)"), GiNaC::exp(s.t) * GiNaC::log(s.m)));
    CHECK(same(s.parse("tan(m)+sinh(m)+cosh(m)+tanh(m)+asin(m)+acos(m)+atan(m)"),
               GiNaC::tan(s.m) + GiNaC::sinh(s.m) + GiNaC::cosh(s.m) + GiNaC::tanh(s.m) + GiNaC::asin(s.m) +
                   GiNaC::acos(s.m) + GiNaC::atan(s.m)));
    CHECK(same(s.parse("sin(pi/6)"), GiNaC::numeric(1, 2)));
    CHECK(eomgen::expression_function_names().size() == 19);
}

TEST_CASE("non-smooth functions: abs, sign, heaviside, max, min, clamp, and roots of squares read for reals",
          "[parser][nonsmooth]") {
    const Symbols s;
    CHECK(same(s.parse("abs(-2*m)"), 2 * eomgen::real_abs(s.m)));
    CHECK(same(s.parse("abs(m^2)"), GiNaC::pow(s.m, 2)));
    CHECK(same(s.parse("abs(-3)"), 3));
    CHECK(same(s.parse("sign(-2*m)"), -eomgen::sign(s.m)));
    CHECK(same(s.parse("sign(-0.5) + heaviside(0) + heaviside(2)"), GiNaC::numeric(1, 2)));
    CHECK(same(s.parse("max(1, 2) + min(1, 2) + max(m, m)"), 3 + s.m));
    CHECK(same(s.parse("max(m, l) - max(l, m)"), 0));
    CHECK(same(s.parse("clamp(m, 0, 1)"), eomgen::real_min(eomgen::real_max(s.m, 0), 1)));
    // For real numbers sqrt(x^2) = |x|, (x^2)^(3/2) = |x|^3, x/sqrt(x^2) = sign(x); a root of a sum stays.
    CHECK(same(s.parse("sqrt(m^2)"), eomgen::real_abs(s.m)));
    CHECK(same(s.parse("(m^2)^(3/2)"), GiNaC::pow(eomgen::real_abs(s.m), 3)));
    CHECK(same(s.parse("sqrt(m^2*l^2)"), eomgen::real_abs(s.m) * eomgen::real_abs(s.l)));
    CHECK(same(s.parse("m/sqrt(m^2)"), eomgen::sign(s.m)));
    CHECK(same(s.parse("sqrt(m^2 + l^2)"), GiNaC::sqrt(GiNaC::pow(s.m, 2) + GiNaC::pow(s.l, 2))));
    // Derivatives where they exist: d|x| = sign x, d sign x = 0 away from 0, d max(a, b)/da = heaviside(a - b).
    CHECK(same(s.parse("abs(m)").diff(s.m), eomgen::sign(s.m)));
    CHECK(same(s.parse("sign(m)").diff(s.m), 0));
    CHECK(same(s.parse("max(m, l)").diff(s.m), eomgen::heaviside(s.m - s.l)));
    CHECK(same(s.parse("min(m, l)").diff(s.m), eomgen::heaviside(s.l - s.m)));
    CHECK_THROWS_WITH(s.parse("max(m)"), Catch::Contains("2 arguments"));
}

TEST_CASE("velocities: primes and dot()", "[parser]") {
    const Symbols s;
    CHECK(same(s.parse("psi'"), s.psi_dot));
    CHECK(same(s.parse("psi'^2"), GiNaC::pow(s.psi_dot, 2)));
    CHECK(same(s.parse("-psi'^2"), -GiNaC::pow(s.psi_dot, 2)));
    CHECK(same(s.parse("dot(psi)"), s.psi_dot));
    CHECK(same(s.parse("dot( theta )^2*2"), 2 * GiNaC::pow(s.theta_dot, 2)));
    CHECK(same(s.parse("1/2*m*(l*theta')^2"), s.m * GiNaC::pow(s.l * s.theta_dot, 2) / 2));
    CHECK(same(s.parse("psi'*dot(theta)*cos(psi - theta)"),
               s.psi_dot * s.theta_dot * GiNaC::cos(s.psi - s.theta)));
}

TEST_CASE("errors carry the offset of the offending character", "[parser]") {
    const Symbols s;
    struct Case {
        const char* text;
        std::size_t offset;
        const char* message;
    };
    const Case cases[] = {
        {"", 0, "empty expression"},
        {"   ", 0, "empty expression"},
        {"m*thta", 2, "unknown symbol 'thta'; did you mean 'theta'?"},
        {"m*x", 2, "unknown symbol 'x'"},
        {"m + #", 4, "unexpected character '#'"},
        {"m*ψ", 2, "unexpected character 'ψ'"},
        {"m*[l]", 2, "use parentheses"},
        {"m*(l + g", 2, "unclosed '('"},
        {"(m*(l + g)", 0, "unclosed '('"},
        {"sin(m", 3, "unclosed '('"},
        {"m + g)", 5, "unmatched ')'"},
        {")", 0, "unmatched ')'"},
        {"m +", 2, "missing operand after '+'"},
        {"m + * g", 4, "missing operand between '+' and '*'"},
        {"* m", 0, "missing operand before '*'"},
        {"(m+)", 3, "missing operand between '+' and ')'"},
        {"m^", 1, "missing operand after '^'"},
        {"()", 0, "empty parentheses"},
        {"m**2", 1, "use ^ for powers"},
        {"2m", 1, "missing operator before 'm': write 2*m"},
        {"m g", 2, "missing operator before 'g': write m*g"},
        {"2(m)", 1, "missing operator before '('"},
        {"(m)(g)", 3, "missing operator"},
        {"2e", 1, "missing operator before 'e'"},
        {"m'", 1, "'m' is not a coordinate"},
        {"t'", 1, "'t' is not a coordinate"},
        {"(psi)'", 5, "can only follow a coordinate name"},
        {"psi''", 4, "only one prime"},
        {"dot(m)", 4, "'m' is not a coordinate"},
        {"dot(pis)", 4, "unknown coordinate 'pis'; did you mean 'psi'?"},
        {"dot psi", 0, "dot needs a coordinate in parentheses"},
        {"dot(psi'", 7, "dot() takes one coordinate name"},
        {"dot(2)", 4, "dot() takes a coordinate name"},
        {"psi_dot", 0, "write psi' or dot(psi)"},
        {"sin(m, g)", 0, "sin takes 1 argument, not 2"},
        {"m + atan2(m)", 4, "atan2 takes 2 arguments (y, x), not 1"},
        {"cos()", 0, "cos takes 1 argument, not 0"},
        {"sin", 0, "'sin' is a function: write sin(...)"},
        {"m*sine(m)", 2, "unknown function 'sine'; did you mean 'sin'?"},
        {"m(g)", 0, "'m' is not a function"},
        {"m, g", 1, "unexpected ','"},
        {"sin(m,)", 6, "missing argument between ',' and ')'"},
        {"1/0", 1, "division by zero"},
        {"m + log(0)", 4, "division by zero"},
        {"0^0", 1, "undefined"},
        {"0^-3E03", 1, "division by zero (0 to a negative power)"},  // fuzz: GiNaC leaked the power
        {"1.5.2", 3, "a second '.'"},
        {"1e401", 0, "exponent of number out of range"},
        {"9^9^9", 1, "power too large"},
    };
    for (const auto& c : cases) {
        INFO("text: \"" << c.text << "\"");
        const auto e = error_of(s, c.text);
        CHECK(e.offset() == c.offset);
        CHECK_THAT(e.message(), Contains(c.message));
        CHECK(std::string(e.what()) == e.message());
    }
}

TEST_CASE("velocities can be forbidden, and constants can be required", "[parser]") {
    const Symbols s;
    eomgen::ParseOptions no_velocities;
    no_velocities.forbid_velocities = "V must not depend on velocities";
    CHECK(same(s.parse("m*g*l*cos(theta)", no_velocities), s.m * s.g * s.l * GiNaC::cos(s.theta)));
    auto e = error_of(s, "m*g*l*cos(theta) + theta'^2", no_velocities);
    CHECK(e.offset() == 19);
    CHECK_THAT(e.message(), Contains("theta'") && Contains("V must not depend on velocities"));
    e = error_of(s, "m*dot(psi)", no_velocities);
    CHECK(e.offset() == 2);

    CHECK(eomgen::evaluate_constant("pi/4") == Approx(0.7853981633974483));
    CHECK(eomgen::evaluate_constant("-2.5e-3") == -0.0025);
    CHECK(eomgen::evaluate_constant("sqrt(2)/2", s.table) == Approx(std::sqrt(2.0) / 2));
    try {
        eomgen::evaluate_constant("pi/4 + m", s.table);
        FAIL("a parameter in a constant expression was accepted");
    } catch (const eomgen::ExpressionError& x) {
        CHECK(x.offset() == 7);
        CHECK_THAT(x.message(), Contains("'m' is not a constant"));
    }
    CHECK_THROWS_AS(eomgen::evaluate_constant("psi'", s.table), eomgen::ExpressionError);
    CHECK_THROWS_AS(eomgen::evaluate_constant("dot(psi)", s.table), eomgen::ExpressionError);
    CHECK_THROWS_WITH(eomgen::evaluate_constant("sqrt(-1)"), Contains("not a real number"));
    CHECK_THROWS_WITH(eomgen::evaluate_constant("1e400"), Contains("not a finite number"));
    CHECK_THROWS_WITH(eomgen::evaluate_constant("exp(10^300)"), Contains("finite"));
}

// Found while writing the parser: "1.5.2" was read as 1.5 followed by the number .2, and the message
// was "missing operator before '.2'". A second decimal point is now a malformed number.
TEST_CASE("regression: second decimal point read as a new number", "[parser]") {
    const Symbols s;
    const auto e = error_of(s, "m*1.5.2");
    CHECK(e.offset() == 5);
    CHECK_THAT(e.message(), Contains("malformed number"));
}

TEST_CASE("nesting is bounded instead of overflowing the stack", "[parser]") {
    const Symbols s;
    CHECK(same(s.parse(std::string(50, '(') + "m" + std::string(50, ')')), s.m));
    const std::string deep = std::string(100000, '(') + "m" + std::string(100000, ')');
    CHECK_THAT(error_of(s, deep).message(), Contains("nested too deeply"));
    CHECK_THAT(error_of(s, std::string(100000, '-') + "m").message(), Contains("nested too deeply"));
}

TEST_CASE("random text never crashes the parser", "[parser]") {
    const Symbols s;
    std::mt19937 rng(20240611);
    const std::string alphabet = "0123456789.eE+-*/^(),' \tmglpsithetadotsincoxa_#\"\\\n\xce\xa8\xff";
    const std::string valid[] = {"1/6*m*l^2*psi'^2", "m*g*l*(1 - cos(theta))", "atan2(dot(psi), 2.5e-3)^-2",
                                 "-sqrt(m)^3^2/exp(t)"};
    auto check_one = [&](const std::string& text) {
        try {
            (void)s.parse(text);
        } catch (const eomgen::ExpressionError& e) {
            if (e.offset() > text.size()) FAIL("offset " << e.offset() << " beyond \"" << text << "\"");
            if (e.message().empty()) FAIL("empty message for \"" << text << "\"");
        }
    };
    for (int i = 0; i < 20000; ++i) {
        std::string text(std::uniform_int_distribution<int>(0, 24)(rng), ' ');
        for (char& c : text)
            c = alphabet[std::uniform_int_distribution<std::size_t>(0, alphabet.size() - 1)(rng)];
        check_one(text);
    }
    for (int i = 0; i < 20000; ++i) {  // near-valid text: a few characters of a valid one replaced or removed
        std::string text = valid[i % 4];
        const int edits = std::uniform_int_distribution<int>(1, 3)(rng);
        for (int k = 0; k < edits && !text.empty(); ++k) {
            const std::size_t at = std::uniform_int_distribution<std::size_t>(0, text.size() - 1)(rng);
            if (rng() % 2)
                text.erase(at, 1);
            else
                text[at] = alphabet[std::uniform_int_distribution<std::size_t>(0, alphabet.size() - 1)(rng)];
        }
        check_one(text);
    }
    SUCCEED();
}
