/** @file exam_author_form.cpp  Differences and corrections in the author's form (issue 13): a double pendulum
 * whose model derives products of sines and cosines, checked against a textbook that writes cos(θ₁ − θ₂) and
 * (m₁ + m₂). The expected texts are pinned whole, so the form is. A slip in one written term (a flipped sign) is
 * corrected in the text's own line; others from the reference, grouped as the author groups. */
#include "checked_text.hpp"
#include "checker/correction_check.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <string>
#include <vector>

using eomgen::checker::CheckReport;
using eomgen::checker::EquationCheck;
using eomgen::checker::Verdict;

namespace {

const char* const kModel = "tests/checker/models/double_pendulum_cartesian.toml";

std::map<int, EquationCheck> by_line(const CheckReport& r) {
    std::map<int, EquationCheck> out;
    for (const EquationCheck& e : r.equations) out[e.where.line] = e;
    return out;
}

/// The fixture's verdicts by line.
std::map<int, EquationCheck> checked_lines() {
    return by_line(eomgen::test::check_text(kModel, eomgen::test::fixture("double_pendulum_author_form.md")));
}

/// A disagreement pinned as text: its one wrong-term line and its correction.
void check_pinned(const EquationCheck& e, const std::string& wrong, const std::string& corrected) {
    INFO(eomgen::test::describe(e));
    REQUIRE(e.verdict == Verdict::Disagrees);
    REQUIRE(e.wrong_terms.size() == 1);
    CHECK(e.wrong_terms[0] == wrong);
    CHECK(e.corrected == corrected);
}

}  // namespace

TEST_CASE("author form: agreeing equations show no factor that is 1 (sin^2 + cos^2)",
          "[checker][author_form]") {
    std::map<int, EquationCheck> lines = checked_lines();
    for (int line : {11, 15, 21, 25, 43}) {
        INFO(eomgen::test::describe(lines[line]));
        CHECK(lines[line].verdict == Verdict::Agrees);
    }
    // Was "the same equation times 1/(sin(θ₁)² + cos(θ₁)²)".
    CHECK(lines[21].reason == "the same equation");
    CHECK(lines[25].reason == "the same equation");
    CHECK(lines[43].reason == "the same equation times $\\frac{1}{l_{1}}$");
}

TEST_CASE("author form: a sign slip in the angle-difference term, corrected in cos(th1 - th2)",
          "[checker][author_form]") {
    const std::string text = eomgen::test::fixture("double_pendulum_author_form.md");
    const CheckReport r = eomgen::test::check_text(kModel, text);
    std::map<int, EquationCheck> lines = by_line(r);
    // Every planted mistake found at its line, nothing else disagrees.
    const std::map<int, std::string> planted = eomgen::test::planted_mistakes(text);
    for (const EquationCheck& e : r.equations) {
        INFO(eomgen::test::describe(e));
        CHECK((e.verdict == Verdict::Disagrees) == (planted.count(e.where.line) > 0));
    }
    check_pinned(
        lines[31],
        "the $\\dot{\\theta_2}^{2}$ terms: $-m_{2} l_{1} l_{2} \\dot{\\theta_2}^{2} \\sin\\left(\\theta_1 - "
        "\\theta_2\\right)$ where $m_{2} l_{1} l_{2} \\dot{\\theta_2}^{2} \\sin\\left(\\theta_1 - "
        "\\theta_2\\right)$ belongs (a flipped sign)",
        // The text's own line, the one term's sign flipped (authors_form.cpp).
        "(m_{1}+m_{2}) l_{1}^{2} \\ddot{\\theta}_{1}+m_{2} l_{1} l_{2} \\ddot{\\theta}_{2} \\cos (\\theta_{1}-\\theta_{2})"
        "+m_{2} l_{1} l_{2} \\dot{\\theta}_{2}^{2} \\sin (\\theta_{1}-\\theta_{2})+(m_{1}+m_{2}) g l_{1} \\sin "
        "\\theta_{1} = 0");
}

TEST_CASE("author form: k sin(th1 - th2) where k cos(th1 - th2) belongs", "[checker][author_form]") {
    std::map<int, EquationCheck> lines = checked_lines();
    check_pinned(
        lines[37],
        "the $\\ddot{\\theta_1}$ terms: $m_{2} l_{1} l_{2} \\ddot{\\theta_1} \\sin\\left(\\theta_1 - "
        "\\theta_2\\right)$ where $m_{2} l_{1} l_{2} \\ddot{\\theta_1} \\cos\\left(\\theta_1 - "
        "\\theta_2\\right)$ belongs ($\\sin$ where $\\cos$ belongs)",
        "-m_{2} l_{1} l_{2} \\dot{\\theta_1}^{2} \\sin\\left(\\theta_1 - \\theta_2\\right) + m_{2} l_{1} "
        "l_{2} \\ddot{\\theta_1} \\cos\\left(\\theta_1 - \\theta_2\\right) + m_{2} l_{2} g \\sin "
        "\\theta_2 + m_{2} l_{2}^{2} \\ddot{\\theta_2} = 0");
}

TEST_CASE("author form: the angle difference in the author's orientation, sin(th2 - th1)",
          "[checker][author_form]") {
    std::map<int, EquationCheck> lines = checked_lines();
    // The model and the other lines write θ₁ − θ₂; this line's own θ₂ − θ₁ is what its correction uses.
    check_pinned(
        lines[49],
        "the $\\dot{\\theta_1}^{2}$ terms: $-m_{2} l_{1} l_{2} \\dot{\\theta_1}^{2} \\sin\\left(\\theta_2 - "
        "\\theta_1\\right)$ where $m_{2} l_{1} l_{2} \\dot{\\theta_1}^{2} \\sin\\left(\\theta_2 - "
        "\\theta_1\\right)$ belongs (a flipped sign)",
        "m_{2} l_{2}^{2} \\ddot{\\theta}_{2}+m_{2} l_{1} l_{2} \\ddot{\\theta}_{1} \\cos (\\theta_{2}-\\theta_{1})"
        "+m_{2} l_{1} l_{2} \\dot{\\theta}_{1}^{2} \\sin (\\theta_{2}-\\theta_{1})+m_{2} g l_{2} \\sin \\theta_{2} = 0");
}

TEST_CASE("author form: a corrected T with sin^2 + cos^2 = 1 applied and (m1 + m2) grouped",
          "[checker][author_form]") {
    std::map<int, EquationCheck> lines = checked_lines();
    // Was ½ m₁ l₁² θ̇₁² cos² θ₁ + ½ m₁ l₁² θ̇₁² sin² θ₁ + m₂ l₁ l₂ θ̇₁ θ̇₂ cos θ₁ cos θ₂ + … (eight terms).
    check_pinned(
        lines[55],
        "the $\\dot{\\theta_1} \\dot{\\theta_2}$ terms: $2 m_{2} l_{1} l_{2} \\dot{\\theta_1} "
        "\\dot{\\theta_2} "
        "\\cos\\left(\\theta_1 - \\theta_2\\right)$ where $m_{2} l_{1} l_{2} \\dot{\\theta_1} "
        "\\dot{\\theta_2} "
        "\\cos\\left(\\theta_1 - \\theta_2\\right)$ belongs (off by a factor $2$)",
        "T = m_{2} l_{1} l_{2} \\dot{\\theta_1} \\dot{\\theta_2} \\cos\\left(\\theta_1 - \\theta_2\\right) + "
        "\\frac{1}{2} m_{2} l_{2}^{2} \\dot{\\theta_2}^{2} + \\frac{1}{2} \\left(m_{1} + m_{2}\\right) "
        "l_{1}^{2} "
        "\\dot{\\theta_1}^{2}");
}

TEST_CASE("author form: one term of the text's line flipped, in the text's own names", "[checker][author_form]") {
    // The top's θ equation and energy in the text's I = I₁ + M l² and ω₃ (tests/checker/fixtures/
    // heavy_top_steady_notes.md): the correction is the line as written, one sign changed, not the model's expansion.
    std::map<int, EquationCheck> lines =
        by_line(eomgen::test::check_text("models/heavy_symmetric_top.toml",
                                         eomgen::test::fixture("heavy_top_steady_notes.md")));
    INFO(eomgen::test::describe(lines[20]));
    CHECK(lines[20].corrected ==
          "I\\ddot\\theta = I\\dot\\phi^2\\sin\\theta\\cos\\theta - I_3\\omega_3\\dot\\phi\\sin\\theta + Mgl\\sin\\theta");
    CHECK(eomgen::test::has_note(lines[20], "one term changed: $I_3\\omega_3\\dot\\phi\\sin\\theta$"));
    INFO(eomgen::test::describe(lines[28]));
    CHECK(lines[28].corrected == "E = \\frac{1}{2} I(\\dot\\theta^2 + \\dot\\phi^2\\sin^2\\theta) + \\frac{1}{2} "
                                 "I_3\\omega_3^2 + Mgl\\cos\\theta");
    // A term that should not be there is left out of the text's line (a fixture of one line).
    const CheckReport extra = eomgen::test::check_text(
        "tests/checker/models/plane_pendulum.toml", "$$T = \\frac{1}{2} m l^2 \\dot\\theta^2 + m g l\\cos\\theta$$\n");
    REQUIRE(extra.equations.size() == 1);
    INFO(eomgen::test::describe(extra.equations[0]));
    CHECK(extra.equations[0].corrected == "T = \\frac{1}{2} m l^2 \\dot\\theta^2");
}

TEST_CASE("author form: the edits of one written term", "[checker][author_form]") {
    using eomgen::checker::one_term_edits;
    const auto sides = [](const std::string& side) {
        std::vector<std::string> out;
        for (const eomgen::checker::TermEdit& e : one_term_edits(side)) out.push_back(e.side);
        return out;
    };
    // Three terms: three flips, then three left out; the minus inside \frac and the parentheses is no split.
    CHECK(sides("a + \\frac{b - c}{2} - (d + e)^2") ==
          std::vector<std::string>{"-a + \\frac{b - c}{2} - (d + e)^2", "a - \\frac{b - c}{2} - (d + e)^2",
                                   "a + \\frac{b - c}{2} + (d + e)^2", "\\frac{b - c}{2} - (d + e)^2",
                                   "a - (d + e)^2", "a + \\frac{b - c}{2}"});
    CHECK(one_term_edits("a + \\frac{b - c}{2} - (d + e)^2").back().term == "(d + e)^2");
    // A leading minus is the first term's sign; a unary minus in an exponent is not a split.
    CHECK(sides("-x^{-1} + y") == std::vector<std::string>{"x^{-1} + y", "-x^{-1} - y", "y", "-x^{-1}"});
    // One term: its sign only.
    CHECK(sides("m g l") == std::vector<std::string>{"-m g l"});
    // Refused: ±, an alignment mark, unbalanced braces.
    CHECK(one_term_edits("a \\pm b").empty());
    CHECK(one_term_edits("a & + b").empty());
    CHECK(one_term_edits("a + {b").empty());
}
