/** @file exam_latex_normalize.cpp  The LaTeX people publish: superscripts before subscripts, accents around
 * subscripted names, equation numbers, HTML entities and Unicode letters, continued displays. */
#include "test_paths.hpp"
#include "checker/checker.hpp"
#include "checker/latex_normalize.hpp"
#include "checker/latex_parser.hpp"
#include "checked_text.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

namespace {

using eomgen::checker::Chain;
using eomgen::checker::LatexContext;
using eomgen::checker::Side;
using eomgen::checker::Verdict;

struct Names {
    GiNaC::symbol th{"theta"}, thd{"theta_dot"}, thdd{"theta_ddot"}, m{"m"}, l{"l"}, g{"g"}, t{"t"};
    LatexContext ctx;
    Names() {
        ctx.names = {{"\\theta", th}, {"\\dot{\\theta}", thd}, {"\\ddot{\\theta}", thdd}, {"m", m},
                     {"l", l},        {"g", g},                {"t", t}};
        ctx.time = t;
    }
    GiNaC::ex parse(const std::string& latex) {
        const Side s = eomgen::checker::parse_expression(latex, ctx);
        INFO(latex << ": " << s.error << " at " << s.error_offset);
        REQUIRE(s.ok);
        return s.value;
    }
};

bool same(const GiNaC::ex& a, const GiNaC::ex& b) {
    return (a - b).expand().is_zero();
}

const std::string kSource = eomgen_test::source_dir();

eomgen::checker::CheckReport check(const std::string& model_path, const std::string& text) {
    return eomgen::test::check_text(model_path, text);
}

/// Each equation of a report with its reason, a line each (for INFO).
std::string reasons(const eomgen::checker::CheckReport& r) {
    std::string all;
    for (const auto& e : r.equations) all += e.equation + ": " + e.reason + "\n";
    return all;
}

}  // namespace

TEST_CASE("latex as published: a superscript before the subscript", "[checker][parser][normalize]") {
    Names n;
    // l^{2}_{1} is (l_1)^2, as MathJax pages and many editors write it; the same symbol as l_{1}.
    CHECK(same(n.parse("l^{2}_{1}"), n.parse("l_{1}^{2}")));
    CHECK(same(n.parse("m l^2_1 \\dot{\\theta}^{2}_{1}"), n.parse("m l_1^2 \\dot{\\theta}_1^2")));
    CHECK(same(n.parse("x^{\\prime 2}_{a}"), n.parse("x'_{a}^{2}")));
    // An exponent on an expression followed by a subscript is still refused.
    const Side s = eomgen::checker::parse_expression("(m l)^{2}_{1}", n.ctx);
    CHECK_FALSE(s.ok);
}

TEST_CASE("latex as published: dots around subscripted names", "[checker][parser][normalize]") {
    Names n;
    const GiNaC::ex a = n.parse("\\dot{\\theta_1}"), b = n.parse("\\dot\\theta_1"), c = n.parse("\\dot{\\theta}_{1}");
    CHECK(same(a, b));
    CHECK(same(a, c));
    CHECK(eomgen::checker::canonical_name("\\dot\\theta_1") == "\\dot{\\theta_{1}}");
}

TEST_CASE("latex as published: Unicode letters and HTML entities", "[checker][parser][normalize]") {
    Names n;
    const GiNaC::ex T = n.m * n.l * n.l * n.thd * n.thd / 2;
    // ½ m l² θ̇² with θ̇ as θ + U+0307 (a combining dot).
    CHECK(same(n.parse("\xC2\xBD m l\xC2\xB2 \xCE\xB8\xCC\x87\xC2\xB2"), T));
    CHECK(same(n.parse("&frac12; m l&sup2; &theta;&#775;&sup2;"), T));
    CHECK(same(n.parse("\\frac{1}{2} m l^2 \\dot{&#952;}^2"), T));
    CHECK(same(n.parse("\\frac{1}{2} m l^2 \\dot{&#x3b8;}^2"), T));
    // θ̈ (two combining dots), −, ·, ×
    CHECK(same(n.parse("\xCE\xB8\xCC\x88 \xE2\x88\x92 g \xC2\xB7 l \xC3\x97 m"), n.thdd - n.g * n.l * n.m));
    CHECK(same(n.parse("m g l \\cos &theta; &minus; m &middot; g"), n.m * n.g * n.l * GiNaC::cos(n.th) - n.m * n.g));
    // Relations: ≈ and &lt;
    std::vector<Chain> c = eomgen::checker::parse_math("\\ddot\\theta \xE2\x89\x88 -\\frac{g}{l}\\theta", n.ctx);
    REQUIRE(c.size() == 1);
    CHECK(c[0].relations.at(0) == eomgen::checker::Relation::Approx);
    c = eomgen::checker::parse_math("0 &lt; \\theta", n.ctx);
    CHECK(c[0].relations.at(0) == eomgen::checker::Relation::Inequality);
    // An unknown entity is not read, with a reason.
    CHECK_FALSE(eomgen::checker::parse_expression("&bogus; m", n.ctx).ok);
}

TEST_CASE("latex as published: implications split, brackets and products", "[checker][parser][normalize]") {
    Names n;
    for (const char* arrow : {"\\Longrightarrow", "\\Rightarrow", "\\implies", "\\quad\\Rightarrow\\quad"}) {
        const std::vector<Chain> c =
            eomgen::checker::parse_math(std::string("m \\ddot\\theta = - m g ") + arrow + " \\ddot\\theta = -g", n.ctx);
        INFO(arrow);
        CHECK(c.size() == 2);
    }
    CHECK(same(n.parse("\\left[ m + g \\right] l"), (n.m + n.g) * n.l));
    CHECK(same(n.parse("m \\cdot l \\times g"), n.m * n.l * n.g));
    CHECK(same(n.parse("\\mbox{m} l"), n.m * n.l));
}

TEST_CASE("latex as published: equation numbers, environments and continued displays", "[checker][normalize]") {
    using eomgen::checker::parse_derivation;
    auto rows = [](const std::string& text) {
        std::vector<std::string> out;
        for (const auto& r : parse_derivation(text, "x.md").rows) out.push_back(r.text);
        return out;
    };
    // Equation numbers are blanked; the offsets stay those of the file.
    for (const char* tail : {"\\quad (1)", "\\qquad (2.14)", "\\hfill (3)", "\\eqno(4)", "\\quad \\text{(5)}"}) {
        const std::string text = std::string("$$T = m l \\dot\\theta ") + tail + "$$";
        const auto d = parse_derivation(text, "x.md");
        REQUIRE(d.rows.size() == 1);
        INFO(tail);
        CHECK(d.rows[0].text.find('(') == std::string::npos);
        CHECK(d.rows[0].text.size() == text.size() - 4);
    }
    // Not an equation number: a condition in parentheses without a digit stays.
    CHECK(rows("$$T = 1 \\quad (x > a)$$")[0].find("(x > a)") != std::string::npos);
    // Three displays ending in = and + are one equation; a row starting with = or + continues the one above.
    auto joined = rows("$$L = a + b =$$\n$$= c +$$\n$$+ d$$");
    REQUIRE(joined.size() == 1);
    CHECK(std::count(joined[0].begin(), joined[0].end(), '=') == 2);  // L = a + b = c + d
    CHECK(std::count(joined[0].begin(), joined[0].end(), '+') == 2);
    // \\ rows of an aligned block: a row starting with a sign continues a row without a relation.
    joined = rows("$$\\begin{aligned} m l^2 \\ddot\\theta \\\\ + m g l \\sin\\theta &= 0 \\end{aligned}$$");
    CHECK(joined.size() == 1);
    // ... but a row that is an equation of its own is not joined: -y = 2 under x = 1.
    CHECK(rows("$$\\begin{aligned} x &= 1 \\\\ -y &= 2 \\end{aligned}$$").size() == 2);
    // Prose between two displays: not joined.
    CHECK(rows("$$L = a +$$ where $a$ is\n$$+ d$$").size() == 4 - 1);
    // eqnarray and align* rows, with &amp; as HTML writes the alignment mark.
    CHECK(rows("\\begin{eqnarray} a &=& b \\\\ c &=& d \\end{eqnarray}").size() == 2);
    const auto html = rows("\\begin{align*} a &amp;= b \\\\ c &amp;= &theta; \\end{align*}");
    REQUIRE(html.size() == 2);
    CHECK(html[0].find("amp") == std::string::npos);
    CHECK(html[1].find("&theta;") != std::string::npos);
}

TEST_CASE("latex as published: a MathJax page and a textbook solution agree line by line", "[checker][normalize]") {
    auto read = [](const std::string& name) {
        return eomgen::checker::read_derivation(kSource + "/tests/checker/fixtures/" + name).text;
    };
    const auto web = check("models/pendulum.toml", read("pendulum_web_page.md"));
    for (const auto& e : web.equations) {
        INFO(e.where.line << ": " << e.equation << " " << e.reason);
        CHECK(e.verdict == Verdict::Agrees);
    }
    CHECK(web.equations.size() == 17);
    const auto book = check("examples/double_pendulum.toml", read("double_pendulum_textbook.md"));
    for (const auto& e : book.equations) {
        INFO(e.where.line << ": " << e.equation << " " << e.reason);
        CHECK(e.verdict == Verdict::Agrees);
    }
    CHECK(book.equations.size() == 4);
}

TEST_CASE("latex as published: a slip in the last piece of a continued display is found", "[checker][normalize]") {
    // The regression: L split over three displays ending in = and +; the piece after the last + has m for M.
    const auto r = check("examples/double_pendulum.toml",
                         "$$L = \\frac{1}{2}(m_{1}+m_{2}) l^{2}_{1} \\dot{\\theta}^{2}_{1} + \\frac{1}{2} m_{2} l^{2}_{2} "
                         "\\dot{\\theta}^{2}_{2} +$$\n"
                         "$$+ m_{2} l_{1} l_{2} \\dot\\theta_1 \\dot\\theta_2 \\cos(\\theta_1 - \\theta_2) +$$\n"
                         "$$+ m_{1} g l_{1} \\cos \\theta_{1} + m_{2} g l_{2} \\cos \\theta_{2}$$\n");
    REQUIRE(r.equations.size() == 1);
    CHECK(r.equations[0].verdict == Verdict::Disagrees);
    CHECK(r.equations[0].where.line == 1);
    // An additive constant: agrees up to it, and a slip beside it still disagrees.
    const auto c = check("models/pendulum.toml", "$V = -m g l \\cos\\phi + \\text{const}$ and "
                                                 "$V = -m g l \\sin\\phi + \\mathrm{const}$");
    REQUIRE(c.equations.size() == 2);
    CHECK(c.equations[0].verdict == Verdict::Agrees);
    CHECK(c.equations[1].verdict == Verdict::Disagrees);
}

TEST_CASE("latex as published: a boxed result is read as if unboxed", "[checker][normalize]") {
    // \boxed{...} in math, \fbox{$...$} (its argument is text) in math and in prose; a slip in a box is found.
    const auto c = check("models/pendulum.toml",
                         "$$\\boxed{\\ddot\\phi = -\\frac{g}{l}\\sin\\phi}$$\n\n"
                         "$$\\fbox{$ \\ddot\\phi = -\\frac{g}{l}\\sin\\phi $}$$\n\n"
                         "so \\fbox{$\\ddot\\phi = -\\frac{g}{l}\\sin\\phi$} and\n\n"
                         "$$\\boxed{\\ddot\\phi = -\\frac{g}{l}\\cos\\phi}$$\n");
    INFO(reasons(c));
    REQUIRE(c.equations.size() == 4);
    CHECK(c.equations[0].verdict == Verdict::Agrees);
    CHECK(c.equations[1].verdict == Verdict::Agrees);
    CHECK(c.equations[2].verdict == Verdict::Agrees);
    CHECK(c.equations[3].verdict == Verdict::Disagrees);
}

TEST_CASE("latex as published: an indefinite integral holds up to a constant of integration", "[checker][normalize]") {
    // -\int F dx = V + c: the derivatives in the variable must agree; a name that drops out of them is the constant.
    const auto c = check("models/pendulum.toml",
                         "$$\\int m g l \\sin\\phi \\, d\\phi = -m g l \\cos\\phi + C$$\n\n"
                         "$$\\int m g l \\sin\\phi \\, d\\phi = m g l \\cos\\phi + C$$\n\n"
                         "$$- \\int (- m g l \\sin\\phi) \\, d\\phi = - m g l \\cos\\phi$$\n\n"
                         "$$\\int F \\, d\\phi = m g l \\cos\\phi$$\n\n"
                         "$$\\int m \\, d\\phi + \\int m \\, dt = m \\phi + m t$$\n\n"
                         "$$\\phi \\int m \\, d\\phi = \\frac{1}{2} m \\phi^2$$\n");
    REQUIRE(c.equations.size() == 6);
    INFO(reasons(c));
    CHECK(c.equations[0].verdict == Verdict::Agrees);
    CHECK(c.equations[0].reason.find("constant of integration ($C$)") != std::string::npos);
    CHECK(c.equations[1].verdict == Verdict::Disagrees);
    CHECK(c.equations[1].reason.find("differ by") != std::string::npos);
    CHECK(c.equations[2].verdict == Verdict::Agrees);
    CHECK(c.equations[3].verdict == Verdict::NotComparable);
    CHECK(c.equations[3].reason.find("$F$") != std::string::npos);
    CHECK(c.equations[4].verdict == Verdict::NotComparable);
    CHECK(c.equations[4].reason.find("different variables") != std::string::npos);
    CHECK(c.equations[5].verdict == Verdict::NotComparable);
    CHECK(c.equations[5].reason.find("times its own variable") != std::string::npos);
}

TEST_CASE("latex as published: a blank display continued by a sign (fuzz_latex: back() of an empty row)",
          "[checker][normalize]") {
    // `~` is a space, so the first display is blank; the second starts with a sign and continued it. The join
    // read the last character of the blank row (UBSan under fuzz_latex, 2026-11-25).
    for (const std::string text : {"$$~$$$$+$$", "$$ $$\n$$- x$$", "$$~$$\n$$+$$\n$$+ b$$"}) {
        INFO(text);
        const auto d = eomgen::checker::parse_derivation(text, "x.md");
        for (const auto& r : d.rows) {
            CHECK(r.offset + r.text.size() <= text.size());
            CHECK(r.text.find_first_not_of(" ~+-xb\n") == std::string::npos);
        }
    }
}
