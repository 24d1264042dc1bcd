/** @file test_codegen.cpp  The canonical DAG, CSE and the C++ emitter. */
#include "codegen/cpp_emitter.hpp"
#include "codegen/expr_dag.hpp"
#include "codegen/math_printer.hpp"
#include "codegen/switching_emitter.hpp"
#include "model/nonsmooth.hpp"
#include "model/expression_parser.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

namespace {

using namespace eomgen::codegen;

/// A symbol table of three "parameters" a, b, c and two "coordinates" x, y.
struct Fixture {
    GiNaC::symbol a{"a"}, b{"b"}, c{"c"}, x{"x"}, y{"y"}, t{"t"};
    SymbolTable table;
    Fixture() {
        auto put = [this](SymbolKind k, int i, const std::string& n, const GiNaC::symbol& s) {
            table.info.push_back({k, i, n, n, n, n});
            table.exprs.push_back(s);
        };
        put(SymbolKind::Parameter, 0, "a", a);
        put(SymbolKind::Parameter, 1, "b", b);
        put(SymbolKind::Parameter, 2, "c", c);
        put(SymbolKind::Coordinate, 0, "x", x);
        put(SymbolKind::Coordinate, 1, "y", y);
        put(SymbolKind::Time, 0, "t", t);
    }
    std::string body(const std::vector<Output>& outputs) {
        ExprDag dag(table.info, table.exprs, true);
        std::string s;
        for (const std::string& l : emit_body(dag, outputs).lines) s += l + "\n";
        return s;
    }
};

}  // namespace

TEST_CASE("GiNaC's sign choices do not change the emitted code", "[cse][determinism]") {
    Fixture f;
    // (c − a b)³ and −(a b − c)³ are the same number; GiNaC keeps them as different trees.
    const GiNaC::ex e1 = GiNaC::pow(f.c - f.a * f.b, 3);
    const GiNaC::ex e2 = -GiNaC::pow(f.a * f.b - f.c, 3);
    REQUIRE(f.body({{"r", e1}}) == f.body({{"r", e2}}));
    // sin(x − y) = −sin(y − x), cos(x − y) = cos(y − x).
    REQUIRE(f.body({{"r", GiNaC::sin(f.x - f.y)}}) == f.body({{"r", -GiNaC::sin(f.y - f.x)}}));
    REQUIRE(f.body({{"r", GiNaC::cos(f.x - f.y) * f.a}}) == f.body({{"r", f.a * GiNaC::cos(f.y - f.x)}}));
}

TEST_CASE("a header's switching surfaces do not depend on the order they were met in", "[switching][determinism]") {
    Fixture f;
    MathPrinter printer(f.table);
    // max(0, x − a) and heaviside(a − x) share the surface x = a; sign(y) is another one. GiNaC's stored order of
    // terms, which the walk meets them in, changes from one process to the next: met either way, the header is one.
    const GiNaC::ex kink = eomgen::real_max(0, f.x - f.a), jump = eomgen::heaviside(f.a - f.x), turn = eomgen::sign(f.y);
    using eomgen::SwitchingSurface;
    const std::vector<SwitchingSurface> one{{f.x - f.a, kink, {kink, jump}}, {f.y, turn, {turn}}};
    const std::vector<SwitchingSurface> other{{f.y, turn, {turn}}, {f.a - f.x, jump, {jump, kink}}};
    SwitchingCode a, b;
    canonical_switches(one, printer, a);
    canonical_switches(other, printer, b);
    REQUIRE(a.names == std::vector<std::string>{"heaviside(a - x)", "sign(y)"});
    REQUIRE(b.names == a.names);
    REQUIRE(a.surfaces.size() == 2);
    for (std::size_t k = 0; k < 2; ++k) {
        CHECK(a.surfaces[k].s.is_equal(b.surfaces[k].s));
        CHECK(a.surfaces[k].function.is_equal(b.surfaces[k].function));
    }
    // The surface's s is the named function's own argument (its sign says which side is which).
    CHECK((a.surfaces[0].s - (f.a - f.x)).expand().is_zero());
    CHECK(a.comment(printer) == b.comment(printer));
}

TEST_CASE("shared subexpressions are computed once, powers are products", "[cse]") {
    Fixture f;
    const GiNaC::ex s = GiNaC::sin(f.x);
    const std::string code = f.body({{"r0", f.a * s * GiNaC::pow(f.b + f.c, 2)}, {"r1", s * (f.b + f.c) + f.y}});
    INFO(code);
    // sin(x) once, named; b + c once, as a temporary; its square as a product.
    REQUIRE(code.find("const Scalar sin_x = sin(x);") != std::string::npos);
    REQUIRE(code.find("const Scalar t0 = b + c;") != std::string::npos);
    REQUIRE(code.find("t0*t0") != std::string::npos);
    REQUIRE(code.find("pow(") == std::string::npos);
    // x⁴ shares x² and is a square of it.
    const std::string quartic = f.body({{"r", GiNaC::pow(f.x, 4) + GiNaC::pow(f.x, 2)}});
    INFO(quartic);
    REQUIRE(quartic.find("x*x") != std::string::npos);
    REQUIRE(quartic.find("pow(") == std::string::npos);
}

TEST_CASE("rational coefficients and reciprocals are exact in the emitted code", "[cse]") {
    Fixture f;
    const std::string code = f.body({{"r", f.a / 6 - GiNaC::numeric(3, 4) * f.b / (f.x * f.y)}});
    INFO(code);
    REQUIRE(code.find("Scalar(1)/Scalar(6)") != std::string::npos);
    REQUIRE(code.find("Scalar(3)/Scalar(4)") != std::string::npos);
    REQUIRE(code.find("/(x*y)") != std::string::npos);
}

TEST_CASE("op counts count what the code does", "[cse]") {
    Fixture f;
    ExprDag dag(f.table.info, f.table.exprs, true);
    const FunctionBody body = emit_body(dag, {{"r", f.a * f.b + GiNaC::sin(f.x)}});
    REQUIRE(body.ops.multiplications == 1);
    REQUIRE(body.ops.additions == 1);
    REQUIRE(body.ops.function_calls == 1);
    REQUIRE(body.ops.divisions == 0);
}

TEST_CASE("the math printer writes the model language and LaTeX", "[printer]") {
    Fixture f;
    MathPrinter p(f.table);
    REQUIRE(p.print(GiNaC::numeric(1, 6) * f.a * GiNaC::pow(f.x, 2), MathStyle::Text) == "1/6*a*x^2");
    REQUIRE(p.print(GiNaC::numeric(1, 6) * f.a * GiNaC::pow(f.x, 2), MathStyle::Latex) == "\\frac{1}{6} a x^{2}");
    REQUIRE(p.print(f.a - f.b, MathStyle::Text) == "a - b");
    REQUIRE(p.print(f.a / (f.b * f.c), MathStyle::Text) == "a/(b*c)");
    REQUIRE(p.print(GiNaC::pow(GiNaC::sin(f.x), 2), MathStyle::Latex) == "\\sin^{2} x");
}

TEST_CASE("the math printer writes an angle difference the way the author does", "[printer]") {
    Fixture f;
    MathPrinter p(f.table);
    p.prefer_angles({f.y - f.x});
    // sin(x − y) = −sin(y − x): the sign moves into the coefficient; cos is even.
    REQUIRE(p.print(f.a * GiNaC::sin(f.x - f.y), MathStyle::Text) == "-a*sin(y - x)");
    REQUIRE(p.print(f.a * GiNaC::cos(f.x - f.y), MathStyle::Text) == "a*cos(y - x)");
    REQUIRE(p.print(f.a * GiNaC::pow(GiNaC::sin(f.x - f.y), 2), MathStyle::Text) == "a*sin(y - x)^2");
    REQUIRE(p.print(f.a * GiNaC::sin(f.y - f.x), MathStyle::Latex) == "a \\sin\\left(y - x\\right)");
    // Inside another function's argument the canonical angle stays (the sign could not move out).
    REQUIRE(p.print(GiNaC::exp(GiNaC::sin(f.x - f.y)), MathStyle::Text) == "exp(sin(x - y))");
}

TEST_CASE("printed with the author's angles, expressions parse back to the same value", "[printer]") {
    Fixture f;
    MathPrinter p(f.table);
    p.prefer_angles({f.y - f.x});
    eomgen::SymbolTable names;
    const std::vector<std::pair<std::string, GiNaC::symbol>> all = {
        {"a", f.a}, {"b", f.b}, {"c", f.c}, {"x", f.x}, {"y", f.y}, {"t", f.t}};
    for (const auto& [n, s] : all) names.symbols[n] = s;
    const GiNaC::ex u = f.x - f.y;
    const GiNaC::ex pieces[] = {GiNaC::sin(u), GiNaC::cos(u), GiNaC::pow(GiNaC::sin(u), 3), 1 / GiNaC::sin(u),
                                GiNaC::sqrt(1 + GiNaC::pow(GiNaC::sin(u), 2)), f.a + f.b * GiNaC::sin(u),
                                GiNaC::sin(f.x), f.c};
    unsigned state = 7;
    auto next = [&state]() { return (state = state * 1103515245u + 12345u) >> 16; };
    for (int n = 0; n < 200; ++n) {
        GiNaC::ex e = 0;
        for (unsigned k = next() % 4 + 1; k > 0; --k) {
            GiNaC::ex term = int(next() % 7) - 3;
            for (unsigned j = next() % 3 + 1; j > 0; --j) term *= pieces[next() % 8];
            e += term;
        }
        const std::string text = p.print(e, MathStyle::Text);
        INFO(e << "\n" << text);
        const GiNaC::ex back = eomgen::parse_expression(text, names);
        const GiNaC::exmap at{{f.a, 0.7}, {f.b, -1.3}, {f.c, 0.4}, {f.x, 1.1}, {f.y, -0.6}, {f.t, 0.2}};
        const double ve = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(at))).to_double();
        const double vb = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(back.subs(at))).to_double();
        CHECK(std::abs(ve - vb) <= 1e-12 * (1 + std::abs(ve)));
    }
}
