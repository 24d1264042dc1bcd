/** @file exam_published_notation.cpp  Notation from the corpus' newer texts (docs/checker.md, "The LaTeX people
 * publish"): an accent over a power, a colon ending the math, norms and the other bars, plain TeX's \cases, a
 * coordinate at an instant, ∂/∂t for the Euler–Lagrange d/dt, a letter whose square is written in velocities, and
 * a potential with its zero elsewhere. Each against the plane pendulum (models/pendulum.toml: φ; m, l, g). */
#include "checked_text.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace {

using eomgen::checker::CheckReport;
using eomgen::checker::EquationCheck;
using eomgen::checker::Role;
using eomgen::checker::Verdict;

const char* const kModel = "models/pendulum.toml";

}  // namespace

TEST_CASE("published notation: an accent over a power, a final colon, norms and \\cases", "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text(kModel, R"(# Pendulum

$$T = \frac12 m l^2 \dot{\phi^2}$$

At the top, $\phi = \pi:$

$$\|\dot\phi\|^2 = \lvert\dot\phi\rvert^2 = \left\Vert \dot\phi \right\Vert^2 = \dot\phi^2$$

$$\cases{ T = \frac12 m l^2\dot\phi^2 \\ V = -mgl\cos\phi }$$
)");
    INFO(eomgen::test::describe_all(r));
    REQUIRE(r.equations.size() == 7);
    CHECK(r.equations[0].verdict == Verdict::Agrees);
    CHECK(eomgen::test::has_note(r.equations[0], "as $\\dot{\\phi}^{2}$ (the accent written over the power)"));
    CHECK(r.equations[1].verdict == Verdict::NotJudged);
    CHECK(r.equations[1].role == Role::Condition);
    for (std::size_t k = 2; k < 7; ++k) CHECK(r.equations[k].verdict == Verdict::Agrees);
    CHECK(r.equations[5].compared_with == "$T$");
    CHECK(r.equations[6].compared_with == "$V$");
}

TEST_CASE("published notation: a coordinate at an instant is its initial value, not a product",
          "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text(kModel, "$$\\phi(0) = 0.1$$ and $\\dot\\phi(0) = 0$; also $\\phi(0) = 0$.\n");
    INFO(eomgen::test::describe_all(r));
    REQUIRE(r.equations.size() == 3);
    for (const EquationCheck& e : r.equations) {
        CHECK(e.verdict == Verdict::NotJudged);
        CHECK(e.role == Role::ChosenValue);
    }
    CHECK(r.equations[1].reason == "a value the text chooses: the initial value of $\\dot{\\phi}$");
}

TEST_CASE("published notation: d/dt written as a partial derivative in the Euler-Lagrange equation",
          "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text(
        kModel, "$$\\frac{\\partial L}{\\partial \\phi} - \\frac{\\partial}{\\partial t}\\left(\\frac{\\partial L}{\\partial "
                "\\dot\\phi}\\right) = 0$$\n\n$$\\frac{\\partial}{\\partial t} l = 0$$\n");
    INFO(eomgen::test::describe_all(r));
    REQUIRE(r.equations.size() == 2);
    CHECK(r.equations[0].verdict == Verdict::Agrees);
    CHECK(r.equations[0].compared_with == "the Euler–Lagrange equation for $\\phi$");
    CHECK(eomgen::test::has_note(r.equations[0], "as the Euler–Lagrange equation's $\\frac{d}{dt}$"));
    // Anything else by t stays a partial derivative.
    CHECK(!eomgen::test::has_note(r.equations[1], "Euler–Lagrange"));
}

TEST_CASE("published notation: a label letter whose square is written in the velocities is the text's speed",
          "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text(kModel, R"(# Pendulum

The bob is at $X = l\sin\phi$, $Y = -l\cos\phi$; its speed squared is $V^2 = \dot{X}^2 + \dot{Y}^2 = l^2\dot\phi^2$.

The potential energy is $U = -mgl\cos\phi$.
)");
    INFO(eomgen::test::describe_all(r));
    bool speed = false;
    for (const EquationCheck& e : r.equations) {
        CHECK(e.verdict != Verdict::Disagrees);
        if (e.equation.rfind("V^2 = \\dot{X}^2", 0) == 0) {
            CHECK(e.verdict == Verdict::NotJudged);
            CHECK(e.reason.find("the text's $V$ is the speed") != std::string::npos);
            speed = true;
        }
    }
    CHECK(speed);
}

TEST_CASE("published notation: a potential with its zero elsewhere agrees, a constant term written wrong does not",
          "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text(
        kModel, "The potential energy: $V = mgl(1-\\cos\\phi)$, $U = -mgl\\cos\\phi + mgl$ and $V = 2mgl - mgl\\cos\\phi$.\n");
    INFO(eomgen::test::describe_all(r));
    REQUIRE(r.equations.size() == 3);
    CHECK(r.equations[0].verdict == Verdict::Agrees);
    CHECK(r.equations[0].reason.find("up to the constant") != std::string::npos);
    CHECK(r.equations[1].verdict == Verdict::Agrees);
    // V = 2mgl − mgl cos φ vanishes nowhere a reader would take for its zero, and writes a constant: flagged, and told
    // that the constant changes no equation of motion.
    CHECK(r.equations[2].verdict == Verdict::Disagrees);
    CHECK(eomgen::test::has_note(r.equations[2], "changes no equation of motion"));
}

TEST_CASE("published notation: a letter introduced for the quantity its sentence names is compared with it",
          "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text(kModel, R"(# Pendulum

The kinetic energy of the bob is

$$K = \frac12 m l^2\dot\phi^2$$

and, written again with a slip, the kinetic energy is

$$K = \frac12 m l\dot\phi^2$$

with $\Omega = \dot\phi$ a plain abbreviation.
)");
    INFO(eomgen::test::describe_all(r));
    REQUIRE(r.equations.size() == 3);
    CHECK(r.equations[0].verdict == Verdict::Agrees);
    CHECK(r.equations[0].compared_with == "$T$");
    CHECK(eomgen::test::has_note(r.equations[0], "the text's $K$, introduced here for the quantity its sentence names (“The kinetic energy”, line 3)"));
    CHECK(r.equations[1].verdict == Verdict::Disagrees);
    CHECK(r.equations[1].corrected == "K = \\frac{1}{2} m l^{2} \\dot{\\phi}^{2}");
    CHECK(r.equations[2].verdict == Verdict::NotJudged);
}

TEST_CASE("published notation: a split into parts is judged at the parts, unless every part is right",
          "[checker][readings]") {
    // An Atwood machine whose pulley turns: T = ½ m₁ẋ² + ½ m₂ẋ² + ½ I ẋ²/a².
    const char* atwood = "tests/checker/corpus/atwood_pulley_inertia_farside/model.toml";
    const CheckReport wrong_part = eomgen::test::check_text(
        atwood, "$$T = T_1 + T_2$$\n\n$$T_1 = \\frac12 m_1\\dot x^2$$\n\n"
                "$$T_2 = \\frac12 m_2\\dot x^2 + I\\frac{\\dot x^2}{a^2}$$\n");
    INFO(eomgen::test::describe_all(wrong_part));
    REQUIRE(wrong_part.equations.size() == 3);
    CHECK(wrong_part.equations[0].verdict == Verdict::NotJudged);
    CHECK(wrong_part.equations[0].reason.find("each judged where the text gives its value") != std::string::npos);
    CHECK(wrong_part.equations[2].verdict == Verdict::Disagrees);
    // Both parts right, the pulley's left out: the split is the slip.
    const CheckReport missing = eomgen::test::check_text(
        atwood, "$$T = T_1 + T_2$$\n\n$$T_1 = \\frac12 m_1\\dot x^2$$\n\n$$T_2 = \\frac12 m_2\\dot x^2$$\n");
    INFO(eomgen::test::describe_all(missing));
    REQUIRE(missing.equations.size() == 3);
    CHECK(missing.equations[0].verdict == Verdict::Disagrees);
    CHECK(missing.equations[1].verdict == Verdict::Agrees);
    CHECK(missing.equations[2].verdict == Verdict::Agrees);
}

TEST_CASE("published notation: font switches, a braced partial, capitals for a point, the rate of a defined name",
          "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text(kModel, R"(# Pendulum

$$V = -mgl\cos\phi + {\rm const}$$

$$\frac{{\partial}{L}}{\partial{\dot\phi}} = m l^2 \dot\phi$$

The bob is at $(X, Y) = (l\sin\phi, -l\cos\phi)$, and with $u = l\sin\phi$,

$$\frac{d}{dt}(m\dot u) = m l\ddot\phi\cos\phi - m l\dot\phi^2\sin\phi$$
)");
    INFO(eomgen::test::describe_all(r));
    REQUIRE(r.equations.size() == 6);
    CHECK(r.equations[0].verdict == Verdict::Agrees);
    CHECK(r.equations[1].verdict == Verdict::Agrees);
    CHECK(r.equations[2].verdict == Verdict::Agrees);
    CHECK(r.equations[2].compared_with.find("the position of the model's point") != std::string::npos);
    CHECK(r.equations[3].verdict == Verdict::Agrees);
    CHECK(r.equations[5].verdict == Verdict::Agrees);
    CHECK(eomgen::test::has_note(r.equations[5], "$\\dot{u}$ is the time derivative of $u$"));
}

TEST_CASE("published notation: approximating a sine in the prose makes the angle small from there on",
          "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text(kModel, R"(# Pendulum

With the Euler-Lagrange equation, and approximating $sin(\phi)=\phi$, one gets

$$\ddot{\phi} + \frac{g}{l}\phi = 0$$

and with a slip

$$\ddot{\phi} + \frac{g}{2l}\phi = 0$$
)");
    INFO(eomgen::test::describe_all(r));
    REQUIRE(r.equations.size() == 3);
    CHECK(r.equations[0].verdict == Verdict::Agrees);
    CHECK(r.equations[0].reason == "agrees to first order in $\\phi$");
    CHECK(r.equations[1].verdict == Verdict::Agrees);
    CHECK(r.equations[2].verdict == Verdict::Disagrees);
    CHECK(r.equations[2].compared_with.find("expanded about $\\phi = 0$") != std::string::npos);
}

TEST_CASE("published notation: a name the sentence introduces on the right of = is defined by the left side",
          "[checker][definitions]") {
    // "let $\ddot\phi = \alpha$": α is the text's name for the angular acceleration from there on; an equation in
    // it is compared (and a wrong one flagged), and a value stated for it later is a claim, not a new definition.
    const CheckReport r = eomgen::test::check_text(kModel, R"(# Pendulum

We let $\ddot\phi = \alpha$, so that

$$m l^2 \alpha = -m g l \sin\phi$$

$$m l \alpha = -m g \cos\phi$$

At the bottom, $\phi = 0$, we get $\alpha = 0$.

Elsewhere $\gamma$ is a number of the text's, and we let $\ddot\phi = \gamma$.
)");
    INFO(eomgen::test::describe_all(r));
    REQUIRE(r.equations.size() >= 5);
    CHECK(r.equations[0].verdict == Verdict::NotJudged);
    CHECK(r.equations[0].role == Role::Definition);
    CHECK(r.equations[0].reason == "a definition: the text's abbreviation $\\alpha = \\ddot\\phi$ for the rest of its section");
    CHECK(r.equations[1].verdict == Verdict::Agrees);
    CHECK(r.equations[2].verdict == Verdict::Disagrees);
    CHECK(r.equations[4].verdict == Verdict::Agrees);
    CHECK(eomgen::test::has_note(r.equations[4], "using $\\alpha = \\ddot\\phi$ (line 3)"));
    // (γ was written before the sentence that "lets" it: no definition there.)
    REQUIRE(r.equations.size() == 6);
    CHECK(r.equations[5].role != Role::Definition);
    CHECK(r.equations[5].verdict == Verdict::NotComparable);
}
