/** @file exam_normal_modes.cpp  A text's secular equation and normal frequencies against the model's
 * det(K₀ − ω² M₀) = 0 (normal_modes_check.hpp): the double pendulum for equal and for general masses and
 * lengths, the bead on a spinning hoop off its bottom, and the models whose modes cannot be compared. */
#include "checked_text.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <string>

namespace {

using eomgen::checker::CheckReport;
using eomgen::checker::EquationCheck;
using eomgen::checker::Role;
using eomgen::checker::Verdict;
using eomgen::test::describe;

/// Every planted line disagrees, naming its mistake, and every other line agrees with the model's modes.
/// Returns the number of agreements.
int check_fixture(const std::string& model, const std::string& name) {
    const std::string text = eomgen::test::fixture(name);
    const CheckReport r = eomgen::test::check_text(model, text);
    const auto planted = eomgen::test::planted_mistakes(text);
    REQUIRE(planted.size() == 3);
    int found = 0, agree = 0;
    for (const EquationCheck& e : r.equations) {
        INFO(name << ":" << describe(e));
        CHECK(e.compared_with.rfind("the secular equation $\\det(K_0 - \\omega^2 M_0) = 0$ at the equilibrium "
                                    "$\\theta_1 = 0$, $\\theta_2 = 0$", 0) == 0);
        if (planted.count(e.where.line)) {
            CHECK(e.verdict == Verdict::Disagrees);
            std::string all;
            for (const std::string& w : e.wrong_terms) all += w + "\n";
            CHECK(all.find(planted.at(e.where.line)) != std::string::npos);
            // A single equation's correction is checked by the checker itself before it is printed.
            if (e.equation.find("\\pm") == std::string::npos) {
                CHECK_FALSE(e.corrected.empty());
                CHECK(e.notes.empty());
            }
            ++found;
            continue;
        }
        CHECK(e.verdict == Verdict::Agrees);
        ++agree;
    }
    CHECK(found == 3);
    return agree;
}

}  // namespace

TEST_CASE("normal modes: the double pendulum with equal masses and lengths", "[checker][modes]") {
    CHECK(check_fixture("tests/checker/models/double_pendulum_equal.toml", "normal_modes_equal.md") == 6);
    // The verdicts, pinned.
    const CheckReport r = eomgen::test::check_text(
        "tests/checker/models/double_pendulum_equal.toml",
        "# Modes\n\n$$\\omega^2 = \\frac{g}{l}\\left(2 \\mp \\sqrt{2}\\right)$$\n\n"
        "$$l^2 \\omega^4 - 4 g l \\omega^2 + 2 g^2 = 0$$\n\n$\\omega_2^2 = \\frac{2 g}{l}$\n");
    REQUIRE(r.equations.size() == 3);
    for (const EquationCheck& e : r.equations)
        CHECK(e.compared_with == "the secular equation $\\det(K_0 - \\omega^2 M_0) = 0$ at the equilibrium "
                                 "$\\theta_1 = 0$, $\\theta_2 = 0$");
    CHECK(r.equations[0].reason ==
          "both signs give normal frequencies of the model (modes 1 and 2 of 2, $\\omega^{2} = 5.746564953$ and "
          "$\\omega^{2} = 33.49343505$ at the model's parameter values), exactly");
    CHECK(r.equations[1].reason ==
          "the secular equation (the same polynomial in $\\omega^{2}$ up to a factor), exactly");
    const EquationCheck& wrong = r.equations[2];
    CHECK(wrong.verdict == Verdict::Disagrees);
    CHECK(wrong.reason == "its roots are not the model's normal frequencies there, $\\omega_{2}^{2} = 2 \\frac{g}{l} - "
                          "\\frac{g \\sqrt{2}}{l}$ or $\\omega_{2}^{2} = 2 \\frac{g}{l} + \\frac{g \\sqrt{2}}{l}$");
    REQUIRE(wrong.wrong_terms.size() == 1);
    CHECK(wrong.wrong_terms[0] == "$\\omega_{2}^{2}$ is not a normal frequency of the model: at the model's parameter "
                                  "values it is 19.62, the nearest mode (2 of 2) has $\\omega^{2} = 33.49343505$");
    CHECK(wrong.difference == "-\\frac{g \\sqrt{2}}{l}");
    CHECK(wrong.corrected == "\\omega_{2}^{2} = 2 \\frac{g}{l} + \\frac{g \\sqrt{2}}{l}");
}

TEST_CASE("normal modes: where normal() cannot decide, random parameter values do, and the verdict says so",
          "[checker][modes]") {
    // √(g/l) √(g l) = g for positive g, l, which normal() does not know.
    const CheckReport r = eomgen::test::check_text(
        "tests/checker/models/double_pendulum_equal.toml",
        "# N\n\n$$\\omega^2 = (2 - \\sqrt{2}) \\frac{\\sqrt{g/l} \\sqrt{g l}}{l}$$\n\n"
        "$$\\omega^2 = (2 - \\sqrt{3}) \\frac{\\sqrt{g/l} \\sqrt{g l}}{l}$$\n");
    REQUIRE(r.equations.size() == 2);
    CHECK(r.equations[0].verdict == Verdict::Agrees);
    CHECK(r.equations[0].reason == "a normal frequency of the model (mode 1 of 2, $\\omega^{2} = 5.746564953$ at the "
                                   "model's parameter values), numerically, at random parameter values to a relative "
                                   "1e-10");
    CHECK(r.equations[1].verdict == Verdict::Disagrees);
}

TEST_CASE("normal modes: the double pendulum for any masses and lengths", "[checker][modes]") {
    CHECK(check_fixture("examples/double_pendulum.toml", "normal_modes_general.md") == 4);
}

TEST_CASE("normal modes: numbers, --map, and ω that is not a frequency", "[checker][modes]") {
    eomgen::checker::CheckOptions o;
    o.map.push_back({"\\nu", "\\omega", "test"});
    const CheckReport r = eomgen::test::check_text(
        "tests/checker/models/double_pendulum_equal.toml",
        "# D\n\n$\\omega^2 = 5.7466$, $\\omega = 2.3972$, $\\omega^2 = 5.76$, $\\nu^2 = \\frac{g}{l}(2-\\sqrt{2})$, "
        "$\\omega = \\dot\\theta_1$, $\\omega_3 = \\frac{g}{l}$\n",
        o);
    REQUIRE(r.equations.size() == 6);
    for (const EquationCheck& e : r.equations) INFO(describe(e));
    // ω² = 5.7466 within its rounding (the model's g = 9.81: ω² = 5.746564953).
    CHECK(r.equations[0].verdict == Verdict::Agrees);
    CHECK(r.equations[0].reason.find("in numbers, at the model's parameter values within the text's rounding") !=
          std::string::npos);
    CHECK(r.equations[1].verdict == Verdict::Agrees);
    CHECK(r.equations[2].verdict == Verdict::Disagrees);  // 5.76 is off by 0.2 %, beyond its rounding
    CHECK(r.equations[3].verdict == Verdict::Agrees);     // ν is ω by the map
    // ω = θ̇₁ is an angular velocity, not a frequency: the text's definition of ω.
    CHECK(r.equations[4].verdict == Verdict::NotJudged);
    CHECK(r.equations[4].role == Role::Definition);
    CHECK(r.equations[4].compared_with.find("secular") == std::string::npos);
    // ω equal to a rational expression is not how a frequency is written (ω = √(…)): an angular velocity.
    CHECK(r.equations[5].verdict == Verdict::NotJudged);
    CHECK(r.equations[5].role == Role::Definition);
    CHECK(r.equations[5].compared_with.find("secular") == std::string::npos);
}

TEST_CASE("normal modes: an abbreviation the text defines, \\omega_0^2 = g/l", "[checker][modes]") {
    const CheckReport r = eomgen::test::check_text(
        "tests/checker/models/double_pendulum_equal.toml",
        "# A\n\n$\\omega_0^2 = \\frac{g}{l}$\n\n$$\\omega^2 = \\omega_0^2(2 \\mp \\sqrt{2})$$\n\n"
        "$$\\omega_2^2 = \\omega_0^2 (2 + \\sqrt{3})$$\n");
    REQUIRE(r.equations.size() == 3);
    for (const EquationCheck& e : r.equations) INFO(describe(e));
    // The definition is not a claim about the modes: the text's name ω₀, with a note.
    CHECK(r.equations[0].verdict == Verdict::NotJudged);
    CHECK(r.equations[0].role == Role::Definition);
    REQUIRE(r.equations[0].notes.size() == 1);
    CHECK(r.equations[0].notes[0] ==
          "read as an abbreviation, not as a normal frequency: the text uses $\\omega_{0}$ in the frequency at line 7");
    CHECK(r.equations[1].verdict == Verdict::Agrees);
    REQUIRE(r.equations[1].notes.size() == 1);
    CHECK(r.equations[1].notes[0] == "uses $\\omega_{0}^{2} = \\frac{g}{l}$ as the text defines it at line 3");
    CHECK(r.equations[2].verdict == Verdict::Disagrees);
}

TEST_CASE("normal modes: the linear triatomic molecule, with its zero mode (Goldstein 6.4)", "[checker][modes]") {
    const CheckReport r = eomgen::test::check_text(
        "tests/checker/models/triatomic.toml",
        "# Triatomic\n\n$$\\omega^2 (k - m\\omega^2)(k(M + 2m) - M m \\omega^2) = 0$$\n\n"
        "$\\omega_1 = 0$, $\\omega_2 = \\sqrt{\\frac{k}{m}}$, "
        "$\\omega_3 = \\sqrt{\\frac{k}{m}\\left(1 + \\frac{2m}{M}\\right)}$, "
        "$\\omega_3 = \\sqrt{\\frac{k}{m}\\left(1 + \\frac{m}{M}\\right)}$, "
        "$\\omega^2 (k - m\\omega^2) = 0$\n");
    REQUIRE(r.equations.size() == 6);
    for (const EquationCheck& e : r.equations) INFO(describe(e));
    CHECK(r.equations[0].verdict == Verdict::Agrees);  // the secular equation, of degree 3
    CHECK(r.equations[1].verdict == Verdict::Agrees);  // the translation
    CHECK(r.equations[1].reason.rfind("a normal frequency of the model (mode 1 of 3", 0) == 0);
    CHECK(r.equations[2].verdict == Verdict::Agrees);
    CHECK(r.equations[3].verdict == Verdict::Agrees);
    CHECK(r.equations[4].verdict == Verdict::Disagrees);  // 1 + m/M for 1 + 2m/M
    CHECK(r.equations[4].corrected == "\\omega_{3}^{2} = \\frac{k}{m} + 2 \\frac{k}{M}");
    // Two of the three roots: a factor of the characteristic polynomial.
    CHECK(r.equations[5].verdict == Verdict::Agrees);
    CHECK(r.equations[5].reason.rfind("a factor of the characteristic polynomial", 0) == 0);
}

TEST_CASE("normal modes: the bead on a spinning hoop, off its bottom", "[checker][modes]") {
    // ω is the hoop's spin rate (a parameter); the frequency is ω₀. At ω² > g/R the bottom is unstable and the
    // bead rests at cos α₀ = g/(Rω²), where ω₀² = ω² sin²α₀ = ω² − g²/(R²ω²).
    const CheckReport r = eomgen::test::check_text(
        "examples/bead_on_hoop.toml",
        "# Bead\n\n$$\\omega_0^2 = \\omega^2 - \\frac{g^2}{R^2 \\omega^2}$$\n\n$$\\omega_0^2 = \\frac{g}{R} - \\omega^2$$\n");
    REQUIRE(r.equations.size() == 2);
    for (const EquationCheck& e : r.equations) INFO(describe(e));
    CHECK(r.equations[0].verdict == Verdict::Agrees);
    CHECK(r.equations[0].compared_with.find("\\arccos\\left(\\frac{g}{R \\omega^{2}}\\right)$") != std::string::npos);
    CHECK(r.equations[0].reason.rfind("the normal frequency of the model (mode 1 of 1", 0) == 0);
    // The bottom's frequency, where the bottom is unstable.
    CHECK(r.equations[1].verdict == Verdict::Disagrees);
    CHECK(r.equations[1].reason.find("(nor at its other stable equilibrium)") != std::string::npos);
}

TEST_CASE("normal modes: an equilibrium known in numbers only", "[checker][modes]") {
    // k x + a sin x = 0 has no closed form: x = 0 is found in numbers, ω² = (k + a)/m = 4 there.
    const CheckReport r = eomgen::test::check_text(
        "tests/checker/models/pendulum_spring.toml",
        "# S\n\n$\\omega^2 = \\frac{k + a}{m}$, $\\omega^2 = 4$, $\\omega^2 = 4.5$\n");
    REQUIRE(r.equations.size() == 3);
    for (const EquationCheck& e : r.equations) INFO(describe(e));
    // In the parameters: not compared with numbers (values of 1 would let wrong powers pass).
    CHECK(r.equations[0].verdict == Verdict::NotComparable);
    REQUIRE(r.equations[0].notes.size() == 1);
    CHECK(r.equations[0].notes[0].find("known in numbers only") != std::string::npos);
    CHECK(r.equations[1].verdict == Verdict::Agrees);
    CHECK(r.equations[1].reason.find("in numbers, at the model's parameter values") != std::string::npos);
    CHECK(r.equations[2].verdict == Verdict::Disagrees);
    CHECK(r.equations[2].corrected == "\\omega^{2} = 4");
    // On a constraint (the pendulum in x, y): the mode on the tangent space, in numbers, within the rounding of
    // 9.81 but not of 9.9 (±0.05).
    const CheckReport c = eomgen::test::check_text("models/pendulum_cartesian.toml",
                                                   "# C\n\n$\\omega^2 = 9.81$, $\\omega^2 = 9.9$\n");
    REQUIRE(c.equations.size() == 2);
    CHECK(c.equations[0].verdict == Verdict::Agrees);
    CHECK(c.equations[0].compared_with.find("at the equilibrium $x = 0$, $y = -1$") != std::string::npos);
    CHECK(c.equations[1].verdict == Verdict::Disagrees);
}

TEST_CASE("normal modes: models whose modes are not compared", "[checker][modes]") {
    // Read as a frequency, a claim that is not compared: ω stays an unknown symbol, with why it is not compared.
    auto only = [](const std::string& model, const std::string& text) {
        const CheckReport r = eomgen::test::check_text(model, text);
        REQUIRE(r.equations.size() == 1);
        INFO(describe(r.equations[0]));
        CHECK(r.equations[0].verdict == Verdict::NotComparable);
        CHECK(r.equations[0].reason.rfind("unknown symbol $\\omega$", 0) == 0);
        REQUIRE(r.equations[0].notes.size() == 1);
        return r.equations[0].notes[0];
    };
    CHECK(only("models/damped_pendulum.toml", "# D\n\n$\\omega^2 = \\frac{g}{l}$\n")
              .find("read as a normal frequency, $\\omega$ is not compared: at the model's stable equilibria damping or "
                    "gyroscopic terms act") == 0);
    CHECK(only("models/rolling_disc.toml", "# D\n\n$\\omega^2 = \\frac{g}{R}$\n")
              .find("read as a normal frequency, $\\omega$ is not compared: the model's normal modes cannot be "
                    "computed: constraint 'roll_x' is nonholonomic") == 0);
}
