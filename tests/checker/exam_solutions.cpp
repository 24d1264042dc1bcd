/** @file exam_solutions.cpp  A solution the text claims for a coordinate (claimed_solution.hpp), and `q(t)` read as
 * the coordinate as a function of time, not q times t. */
#include "checked_text.hpp"

#include <catch2/catch.hpp>

using eomgen::checker::CheckReport;
using eomgen::checker::EquationCheck;
using eomgen::checker::Role;
using eomgen::checker::Verdict;

namespace {

const char* kPendulum = "tests/checker/models/plane_pendulum.toml";
const char* kRod = "tests/checker/corpus/bead_rotating_rod/model.toml";  // s along a rod turned at phi = omega t

EquationCheck one(const char* model, const std::string& text) {
    const CheckReport r = eomgen::test::check_text(model, text);
    REQUIRE(r.equations.size() == 1);
    INFO(eomgen::test::describe(r.equations[0]));
    return r.equations[0];
}

}  // namespace

TEST_CASE("solutions: q(t) is the coordinate as a function of time", "[checker][solutions]") {
    CHECK(one(kPendulum, "$$\\theta(t) = \\theta$$\n").verdict == Verdict::Agrees);
    CHECK(one(kPendulum, "$$\\dot\\theta(t) = \\dot\\theta$$\n").verdict == Verdict::Agrees);
    // Spaced, it stays a product.
    CHECK(one(kPendulum, "$$\\theta (t) = \\theta$$\n").verdict == Verdict::NotComparable);
}

TEST_CASE("solutions: a claimed solution is put into the equation of motion, with the constraints that fix the "
          "other coordinates in time",
          "[checker][solutions]") {
    // s'' = ω² s − g sin ωt on the rod: s_0 cos ωt is no solution for any s_0.
    const EquationCheck wrong = one(kRod, "$$s(t) = s_0 \\cos(\\omega t)$$\n");
    CHECK(wrong.verdict == Verdict::Disagrees);
    CHECK(wrong.compared_with == "the equation of motion for $s$ on the constraints, with this as its solution");
    REQUIRE(wrong.wrong_terms.size() == 1);
    CHECK(wrong.wrong_terms[0].find("it is not a solution") != std::string::npos);
    // s_0 cosh ωt + g/(2ω²) sin ωt is one.
    const EquationCheck right =
        one(kRod, "$$s(t) = s_0 \\cosh(\\omega t) + \\frac{g}{2\\omega^2}\\sin(\\omega t)$$\n");
    CHECK(right.verdict == Verdict::Agrees);
    CHECK(right.reason == "it solves the equation of motion for $s$ at every $t$");
}

TEST_CASE("solutions: a small oscillation holds to first order, and a name inside the function of t is not judged",
          "[checker][solutions]") {
    const EquationCheck small =
        one(kPendulum, "$$\\theta(t) = A \\cos\\left(\\sqrt{\\frac{g}{l}}\\, t\\right)$$\n");
    CHECK(small.verdict == Verdict::Agrees);
    CHECK(small.reason.find("to first order") != std::string::npos);
    const EquationCheck wrong = one(kPendulum, "$$\\theta(t) = A \\cos\\left(\\frac{g}{l} t\\right)$$\n");
    CHECK(wrong.verdict == Verdict::Disagrees);
    // Ω unknown: a trial solution (the right Ω would make it one), not judged.
    const EquationCheck trial = one(kPendulum, "$$\\theta(t) = A \\cos(\\Omega t)$$\n");
    CHECK(trial.verdict == Verdict::NotJudged);
    CHECK(trial.role == Role::Trial);
}

TEST_CASE("solutions: with the frequency the text has stated, x = A cos(omega t) is a solution it claims, not a trial",
          "[checker][solutions]") {
    const CheckReport r = eomgen::test::check_text(
        kPendulum, "For small oscillations $\\omega^2 = g/l$ and $\\theta(t) = \\theta_0 \\cos(\\omega t)$.\n");
    REQUIRE(r.equations.size() == 2);
    INFO(eomgen::test::describe(r.equations[1]));
    CHECK(r.equations[1].verdict == Verdict::Agrees);
    CHECK(r.equations[1].reason.find("to first order") != std::string::npos);
    const CheckReport wrong = eomgen::test::check_text(
        kPendulum, "For small oscillations $\\omega^2 = g l$ and $\\theta(t) = \\theta_0 \\cos(\\omega t)$.\n");
    REQUIRE(wrong.equations.size() == 2);
    CHECK(wrong.equations[1].verdict == Verdict::Disagrees);
}

TEST_CASE("solutions: the rows after a claimed solution that use its constants are read on that motion",
          "[checker][solutions]") {
    // A solution: its rate agrees on it, a wrong rate disagrees there; the multiplier (the drive's torque, the φ
    // equation on φ = ωt: λ = 2 m s ṡ ω + m g s cos ωt) at s = s_0 cosh ωt + … agrees.
    const CheckReport right = eomgen::test::check_text(
        kRod, "$$s(t) = s_0 \\cosh(\\omega t) + \\frac{g}{2\\omega^2}\\sin(\\omega t)$$\n\n"
              "$$\\dot s = s_0\\omega\\sinh(\\omega t) + \\frac{g}{2\\omega}\\cos(\\omega t)$$\n\n"
              "$$\\dot s = s_0\\omega\\cosh(\\omega t)$$\n\n"
              "$$2 m \\omega^2 s_0^2\\cosh(\\omega t)\\sinh(\\omega t) + 2 m g s_0 \\cosh(\\omega t)\\cos(\\omega t) + "
              "m g s_0 \\sinh(\\omega t)\\sin(\\omega t) + \\frac{m g^2}{\\omega^2}\\sin(\\omega t)\\cos(\\omega t) "
              "= \\lambda$$\n");
    REQUIRE(right.equations.size() == 4);
    INFO(eomgen::test::describe(right.equations[3]));
    CHECK(right.equations[0].verdict == Verdict::Agrees);
    CHECK(right.equations[1].verdict == Verdict::Agrees);
    CHECK(right.equations[1].compared_with.find("the motion $s(t) = s_0 \\cosh") != std::string::npos);
    CHECK(right.equations[2].verdict == Verdict::Disagrees);
    CHECK(right.equations[3].verdict == Verdict::Agrees);
    // Not a solution: a row that holds on it carries its error, and says so.
    const CheckReport wrong = eomgen::test::check_text(
        kRod, "$$s(t) = s_0 \\cos(\\omega t)$$\n\n$$\\dot s = -s_0\\omega\\sin(\\omega t)$$\n\n"
              "$$-2ms_0^2\\omega^2\\cos(\\omega t)\\sin(\\omega t) +mgs_0\\cos^2(\\omega t)=\\lambda$$\n");
    REQUIRE(wrong.equations.size() == 3);
    for (const std::size_t k : {1u, 2u}) {
        INFO(eomgen::test::describe(wrong.equations[k]));
        CHECK(wrong.equations[k].verdict == Verdict::Disagrees);
        REQUIRE(wrong.equations[k].wrong_terms.size() == 1);
        CHECK(wrong.equations[k].wrong_terms[0].find("it carries that error") != std::string::npos);
    }
    // Without the claim, s_0 is a name the text never gave a meaning.
    const EquationCheck alone = one(kRod, "$$\\dot s = -s_0\\omega\\sin(\\omega t)$$\n");
    CHECK(alone.verdict == Verdict::NotComparable);
}
