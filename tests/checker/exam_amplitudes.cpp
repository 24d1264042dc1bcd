/** @file exam_amplitudes.cpp  A trial solution and the equations for its amplitudes (amplitude_equations.hpp),
 * on the triatomic molecule (linear, springs with rest lengths) and the double pendulum (about rest). */
#include "checked_text.hpp"
#include "checker/characteristic_equation.hpp"

#include <catch2/catch.hpp>

#include <optional>
#include <vector>

using eomgen::checker::CheckReport;
using eomgen::checker::EquationCheck;
using eomgen::checker::Verdict;

namespace {

const char* kTriatomic = "tests/checker/models/triatomic.toml";  // x1, x2, x3; masses m, M, m; springs k
const char* kDouble = "tests/checker/models/double_pendulum_equal.toml";

const std::string kAnsatz = "Try $x_j = A_j e^{i \\omega t}$.\n\n";

/// The verdict on the text's last equation (after its trial solution), kept with its report.
EquationCheck last(const CheckReport& r) {
    REQUIRE(!r.equations.empty());
    return r.equations.back();
}

}  // namespace

TEST_CASE("amplitudes: the rows of (K - w^2 M) A = 0 agree, with the frequency free and the factors in t",
          "[checker][amplitudes]") {
    const CheckReport r = eomgen::test::check_text(
        kTriatomic, kAnsatz + "$$\n\\begin{aligned}\n"
                              "m(-\\omega^2 A_1 e^{i\\omega t}) &= k (A_2 e^{i\\omega t} - A_1 e^{i\\omega t}) \\\\\n"
                              "(-M \\omega^2 + 2k)A_2 - kA_1 - kA_3 &= 0 \\\\\n"
                              "\\left(k - m\\omega^2\\right) A_3 &= k A_2\n"
                              "\\end{aligned}\n$$\n");
    REQUIRE(r.equations.size() == 4);
    CHECK(r.equations[0].reason.find("a trial solution") == 0);
    for (std::size_t k = 1; k < 4; ++k) {
        INFO(eomgen::test::describe(r.equations[k]));
        CHECK(r.equations[k].verdict == Verdict::Agrees);
        CHECK(r.equations[k].compared_with == "the amplitude equation for $x_{" + std::to_string(k) +
                                                  "}$ of the trial solution of line 1");
    }
}

TEST_CASE("amplitudes: a wrong coefficient, a wrong power and a term without its amplitude are named",
          "[checker][amplitudes]") {
    const EquationCheck sign = last(eomgen::test::check_text(kTriatomic, kAnsatz + "$$kA_1 + (-M \\omega^2 + 2k)A_2 - kA_3 = 0$$\n"))
    ;
    INFO(eomgen::test::describe(sign));
    CHECK(sign.verdict == Verdict::Disagrees);
    REQUIRE(sign.wrong_terms.size() == 1);
    CHECK(sign.wrong_terms[0] == "the coefficient of $A_{1}$ should be $-k$, not $k$");
    const EquationCheck cube =
        last(eomgen::test::check_text(kTriatomic, kAnsatz + "$$m(-\\omega^3 A_3) = -k (A_3 - A_2)$$\n"));
    INFO(eomgen::test::describe(cube));
    CHECK(cube.verdict == Verdict::Disagrees);
    CHECK(cube.compared_with.find("the amplitude equation for $x_{3}$") == 0);
    const EquationCheck lost =
        last(eomgen::test::check_text(kTriatomic, kAnsatz + "$$0 \\cdot A_1 - kA_2 + (-m \\omega^2 + k) = 0$$\n"));
    INFO(eomgen::test::describe(lost));
    CHECK(lost.verdict == Verdict::Disagrees);
    CHECK(lost.compared_with.find("the amplitude equation for $x_{3}$") == 0);  // A_1 is written (0 · A_1)
    REQUIRE(!lost.wrong_terms.empty());
    CHECK(lost.wrong_terms[0].find("without its amplitude $A_{3}$") != std::string::npos);
}

TEST_CASE("amplitudes: at the normal frequency the text states, rows and their combinations agree and a slip is "
          "corrected in the author's form",
          "[checker][amplitudes]") {
    // ω² = k/m: the outer masses opposite, the middle one at rest.
    const std::string text = kAnsatz + "For the second mode put $\\omega_2^2 = \\frac{k}{m}$ into the rows:\n"
                                       "$$\n\\begin{aligned}\n"
                                       "-kA_2 &= 0 \\\\\n"
                                       "-kA_1 + k\\left(2 - \\frac{M}{m}\\right)A_2 - kA_3 &= 0\n"
                                       "\\end{aligned}\n$$\n"
                                       "so $A_1 = -A_3$ and $A_1 = A_3$.\n";
    const CheckReport r = eomgen::test::check_text(kTriatomic, text);
    std::vector<const EquationCheck*> amplitude;
    for (const EquationCheck& e : r.equations)
        if (e.compared_with.find("of the trial solution of line 1 at") != std::string::npos) amplitude.push_back(&e);
    REQUIRE(amplitude.size() == 4);
    for (std::size_t k = 0; k < 3; ++k) {
        INFO(eomgen::test::describe(*amplitude[k]));
        CHECK(amplitude[k]->verdict == Verdict::Agrees);
        CHECK(amplitude[k]->compared_with.find("at the normal frequency $\\omega^2 = \\frac{k}{m}$") != std::string::npos);
    }
    const EquationCheck& wrong = *amplitude[3];
    INFO(eomgen::test::describe(wrong));
    CHECK(wrong.verdict == Verdict::Disagrees);
    CHECK(wrong.corrected == "A_1 = -A_{3}");
    REQUIRE(wrong.wrong_terms.size() == 1);
    CHECK(wrong.wrong_terms[0] == "in this mode $A_{1}$ is $-1$ times $A_{3}$, not $1$ times");
}

TEST_CASE("amplitudes: about rest, a nonlinear model's small oscillations", "[checker][amplitudes]") {
    const std::string ansatz = "Let $\\theta_1 = A_1 \\cos\\omega t$ and $\\theta_2 = A_2 \\cos\\omega t$.\n\n";
    // Linearized: 2 m l² θ̈₁ + m l² θ̈₂ + 2 m g l θ₁ = 0, m l² θ̈₁ + m l² θ̈₂ + m g l θ₂ = 0.
    const EquationCheck right =
        last(eomgen::test::check_text(kDouble, ansatz + "$$(2g - 2l\\omega^2) A_1 - l \\omega^2 A_2 = 0$$\n"));
    INFO(eomgen::test::describe(right));
    CHECK(right.verdict == Verdict::Agrees);
    const EquationCheck wrong =
        last(eomgen::test::check_text(kDouble, ansatz + "$$(g - l\\omega^2) A_2 - 2 l \\omega^2 A_1 = 0$$\n"));
    INFO(eomgen::test::describe(wrong));
    CHECK(wrong.verdict == Verdict::Disagrees);
    CHECK(wrong.compared_with.find("the amplitude equation for $\\theta_2$") == 0);
    // Without a trial solution the amplitudes are unknown names, as before.
    const EquationCheck none =
        last(eomgen::test::check_text(kDouble, "$$(2g - 2l\\omega^2) A_1 - l \\omega^2 A_2 = 0$$\n"));
    CHECK(none.verdict == Verdict::NotComparable);
}

TEST_CASE("amplitudes: a normal-mode derivation in the style of course notes, every line read, its one slip found",
          "[checker][amplitudes]") {
    const std::string text = eomgen::test::fixture("two_carts_planted.md");
    const std::map<int, std::string> planted = eomgen::test::planted_mistakes(text);
    REQUIRE(planted.size() == 1);
    const CheckReport r = eomgen::test::check_text("tests/checker/models/two_carts.toml", text);
    CHECK(eomgen::test::planted_found(r, planted) == 1);
    CHECK(r.count(Verdict::Agrees) >= 14);
}

TEST_CASE("amplitudes: the matrix form, the characteristic equation and a mode's shape", "[checker][amplitudes]") {
    const std::string matrix = "\\begin{bmatrix} k - m\\omega^2 & -k & 0 \\\\ -k & 2k - M\\omega^2 & -k \\\\ "
                               "0 & -k & k - m\\omega^2 \\end{bmatrix}";
    const std::string amplitudes = "\\begin{bmatrix} A_1 \\\\ A_2 \\\\ A_3 \\end{bmatrix}";
    const CheckReport r = eomgen::test::check_text(
        kTriatomic, kAnsatz + "$$" + matrix + amplitudes + " = 0$$\n\n$$det\\left(" + matrix + "\\right) = 0$$\n\n" +
                        "For the second mode, $\\omega^2 = \\frac{k}{m}$:\n\n$$e_2 = \\begin{bmatrix} 1 \\\\ 0 \\\\ -1 "
                        "\\end{bmatrix}$$\n");
    for (const EquationCheck& e : r.equations) INFO(eomgen::test::describe(e));
    REQUIRE(r.equations.size() == 5);
    // (K − ω²M)A = 0 row by row; det (written without its backslash) as the secular equation; e₂ as the shape.
    CHECK(r.equations[1].verdict == Verdict::Agrees);
    CHECK(r.equations[1].reason.find("row by row") == 0);
    CHECK(r.equations[2].verdict == Verdict::Agrees);
    CHECK(r.equations[2].compared_with.find("the secular equation") == 0);
    CHECK(r.equations[4].verdict == Verdict::Agrees);
    CHECK(r.equations[4].reason == "the mode's shape, a multiple of it");
    // A wrong entry of the matrix: the row it spoils is named; a wrong shape is corrected in the text's scale.
    std::string wrong_matrix = matrix;
    wrong_matrix.replace(wrong_matrix.find("2k - M"), 6, "2k - m");
    const CheckReport w = eomgen::test::check_text(
        kTriatomic, kAnsatz + "$$" + wrong_matrix + amplitudes + " = 0$$\n\nFor the second mode, $\\omega^2 = "
                              "\\frac{k}{m}$:\n\n$$e_2 = \\begin{bmatrix} 1 \\\\ 1 \\\\ -1 \\end{bmatrix}$$\n");
    for (const EquationCheck& e : w.equations) INFO(eomgen::test::describe(e));
    REQUIRE(w.equations.size() == 4);
    CHECK(w.equations[1].verdict == Verdict::Disagrees);
    REQUIRE(!w.equations[1].wrong_terms.empty());
    CHECK(w.equations[1].wrong_terms[0].rfind("row 2", 0) == 0);
    CHECK(w.equations[3].verdict == Verdict::Disagrees);
    CHECK(w.equations[3].corrected == "e_2 = \\begin{bmatrix} 1 \\\\ 0 \\\\ -1 \\end{bmatrix}");
}

TEST_CASE("amplitudes: an exponential trial's characteristic equation and roots, damping included",
          "[checker][amplitudes]") {
    // `\varphi = e^{\lambda t}` on the damped pendulum (models/damped_pendulum.toml, Rayleigh's R = ½ c φ̇²): the
    // equation in λ is det(λ² M₀ + λ C₀ + K₀) = 0 about rest, m l² λ² + c λ + m g l = 0, and each sign of the roots
    // solves it; the planted missing 2 and the root with + ω₀² disagree.
    const std::string text = eomgen::test::fixture("damped_pendulum_exponential_notes.md");
    const CheckReport r = eomgen::test::check_text("models/damped_pendulum.toml", text);
    CHECK(eomgen::test::planted_found(r, eomgen::test::planted_mistakes(text)) == 2);
    int characteristic = 0, roots = 0;
    for (const EquationCheck& e : r.equations) {
        INFO(eomgen::test::describe(e));
        if (e.where.line == 17 && e.equation.find("e^{") != std::string::npos)
            CHECK(e.role == eomgen::checker::Role::Trial);
        if (e.where.line == 19) {
            CHECK(e.verdict == Verdict::Agrees);
            CHECK(e.compared_with.find("the characteristic equation") != std::string::npos);
            ++characteristic;
        }
        if (e.where.line == 21) {
            CHECK(e.verdict == Verdict::Agrees);
            CHECK(e.reason == "with either sign of ±: a root of it");
            ++roots;
        }
        if (e.where.line == 25) CHECK(e.corrected.find("\\lambda^{2}") != std::string::npos);
        if (e.where.line == 13) CHECK(e.role == eomgen::checker::Role::Definition);  // γ, and ω₀² after "writing"
        // "weak damping, $\gamma < \omega_0$": an inequality defines nothing (it once read γ = ω₀ for line 29).
        CHECK_FALSE(eomgen::test::has_note(e, "using $\\gamma = \\omega_0$"));
    }
    CHECK(characteristic == 1);
    CHECK(roots == 1);
    CHECK(r.count(Verdict::Disagrees) == 2);
    // The polynomial itself: about rest, with the damping's λ term.
    const auto& [model, eq] = eomgen::test::derived_model("models/damped_pendulum.toml");
    std::vector<GiNaC::ex> motion;
    for (std::size_t i = 0; i < model.dof(); ++i)
        motion.push_back(eq.euler_lagrange[i] -
                         (i < eq.generalized_forces.size() ? eq.generalized_forces[i] : GiNaC::ex(0)));
    const GiNaC::symbol lambda("lambda");
    const std::optional<GiNaC::ex> p = eomgen::checker::characteristic_polynomial(motion, model, lambda);
    REQUIRE(p);
    const auto parameter = [&](const char* name) {
        for (const eomgen::Parameter& q : model.parameters)
            if (q.name == name) return GiNaC::ex(q.symbol);
        FAIL("no parameter " << name);
        return GiNaC::ex(0);
    };
    const GiNaC::ex m = parameter("m"), l = parameter("l"), g = parameter("g"), c = parameter("c");
    CHECK(GiNaC::expand(*p - (m * l * l * lambda * lambda + c * lambda + m * g * l)).is_zero());
}

TEST_CASE("amplitudes: a mode's ratio written without a trial solution, under the text's assumptions",
          "[checker][amplitudes]") {
    // Equal bobs and rods, the frequencies, then "for the slower mode the amplitudes are in the ratio A_2 = √2 A_1":
    // A_1, A_2 are read as the amplitudes of θ₁, θ₂ (their subscripts); the roots of a quadratic secular factor.
    const auto text = [](const std::string& ratio) {
        return "Take $m_1 = m_2 = m$ and $l_1 = l_2 = l$. The normal frequencies are\n\n"
               "$$\\omega^2 = (2 \\pm \\sqrt{2})\\frac{g}{l}$$\n\n"
               "For the slower mode the amplitudes are in the ratio\n\n$$" + ratio + "$$\n";
    };
    const auto last = [](const eomgen::checker::CheckReport& r) { return r.equations.back(); };
    const EquationCheck right = last(eomgen::test::check_text("examples/double_pendulum.toml", text("A_2 = \\sqrt{2} A_1")));
    INFO(eomgen::test::describe(right));
    CHECK(right.verdict == Verdict::Agrees);
    CHECK(right.compared_with.find("(no trial solution written)") != std::string::npos);
    CHECK(right.compared_with.find("\\omega^2 = \\frac{2 g - g \\sqrt{2}}{l}") != std::string::npos);
    const EquationCheck wrong = last(eomgen::test::check_text("examples/double_pendulum.toml", text("A_2 = 2 A_1")));
    INFO(eomgen::test::describe(wrong));
    CHECK(wrong.verdict == Verdict::Disagrees);
    // The secular equation on the matrices' plain names: \det takes a matrix, so K and M are the stiffness and mass
    // matrices at rest.
    const eomgen::checker::CheckReport det = eomgen::test::check_text(
        "examples/double_pendulum.toml", "The frequencies solve\n\n$$\\det(K - \\omega^2 M) = 0$$\n");
    REQUIRE(det.equations.size() == 1);
    INFO(eomgen::test::describe(det.equations[0]));
    CHECK(det.equations[0].verdict == Verdict::Agrees);
    CHECK(det.equations[0].compared_with.rfind("the secular equation", 0) == 0);
    // Names of one letter with the coordinates' subscripts, but no word of modes or amplitudes and no frequency
    // stated: not amplitudes.
    const eomgen::checker::CheckReport areas =
        eomgen::test::check_text("examples/double_pendulum.toml", "The two areas satisfy\n\n$$A_2 = 2 A_1$$\n");
    REQUIRE(areas.equations.size() == 1);
    CHECK(areas.equations[0].verdict == Verdict::NotComparable);
}

