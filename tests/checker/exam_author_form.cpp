/** @file exam_author_form.cpp  Differences and corrections in the author's form (issue 13): a double pendulum
 * whose model derives products of sines and cosines, checked against a textbook that writes cos(θ₁ − θ₂) and
 * (m₁ + m₂). The expected texts are pinned whole, so the form is. */
#include "checked_text.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <string>

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
        "m_{2} l_{1} l_{2} \\dot{\\theta_2}^{2} \\sin\\left(\\theta_1 - \\theta_2\\right) + m_{2} l_{1} "
        "l_{2} "
        "\\ddot{\\theta_2} \\cos\\left(\\theta_1 - \\theta_2\\right) + \\left(m_{1} + m_{2}\\right) l_{1} g "
        "\\sin \\theta_1 + \\left(m_{1} + m_{2}\\right) l_{1}^{2} \\ddot{\\theta_1} = 0");
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
        "m_{2} l_{1} l_{2} \\dot{\\theta_1}^{2} \\sin\\left(\\theta_2 - \\theta_1\\right) + m_{2} l_{1} "
        "l_{2} "
        "\\ddot{\\theta_1} \\cos\\left(\\theta_2 - \\theta_1\\right) + m_{2} l_{2} g \\sin \\theta_2 + m_{2} "
        "l_{2}^{2} \\ddot{\\theta_2} = 0");
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
