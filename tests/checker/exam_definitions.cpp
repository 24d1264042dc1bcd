/** @file exam_definitions.cpp  Derivatives of quantities the text defines use the definition; a symbol the
 * text does not define is never differentiated to 0. */
#include "checked_text.hpp"

#include <catch2/catch.hpp>

#include <cstring>
#include <string>

namespace {

using eomgen::checker::EquationCheck;
using eomgen::checker::Role;
using eomgen::checker::Verdict;

const char* const kSpherical = "tests/checker/models/spherical_pendulum.toml";

std::string describe(const EquationCheck& e) {
    std::string s = std::to_string(e.where.line) + ": " + eomgen::checker::verdict_name(e.verdict) + ": " +
                    e.equation + " — " + e.reason;
    for (const std::string& n : e.notes) s += "\n  note: " + n;
    return s;
}

bool has_note(const EquationCheck& e, const std::string& part) {
    for (const std::string& n : e.notes)
        if (n.find(part) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST_CASE("definitions: the derivative of a quantity the text defines uses its definition", "[checker][definitions]") {
    // The lecture notes: {\mbox K} defined two lines before it is differentiated.
    const auto r = eomgen::test::check_text(kSpherical,
                                            "$${\\mbox K} = \\frac{1}{2} m \\ell^2 \\left( \\dot\\theta^2 + \\sin^2\\theta \\, "
                                            "\\dot\\phi^2 \\right)$$\n"
                                            "$$\\frac{\\partial {\\mbox K}}{\\partial \\dot{\\phi}} = m l^2 \\sin^2\\theta \\, \\dot\\phi$$\n"
                                            "$$\\frac{\\partial K}{\\partial \\dot{\\phi}} = m l^2 \\sin\\theta \\, \\dot\\phi$$\n"
                                            "$$\\frac{d}{dt} \\frac{\\partial K}{\\partial \\dot{\\theta}} = m l^2 \\ddot\\theta$$\n");
    REQUIRE(r.equations.size() == 4);
    INFO(describe(r.equations[1]));
    CHECK(r.equations[1].verdict == Verdict::Agrees);
    CHECK(has_note(r.equations[1], "uses $K$ as the text defines it at line 1"));
    INFO(describe(r.equations[2]));
    CHECK(r.equations[2].verdict == Verdict::Disagrees);  // sin θ where sin² θ belongs
    INFO(describe(r.equations[3]));
    CHECK(r.equations[3].verdict == Verdict::Agrees);
    // The defining line itself is not a claim: the text names K, which is not a quantity of the model.
    CHECK(r.equations[0].verdict == Verdict::NotJudged);
    CHECK(r.equations[0].role == Role::Definition);
}

TEST_CASE("definitions: a later definition of the same name applies from its place on", "[checker][definitions]") {
    const auto r = eomgen::test::check_text(kSpherical, "$$K = m l^2 \\dot\\theta^2$$\n"
                                                        "$$\\frac{\\partial K}{\\partial \\dot\\theta} = 2 m l^2 \\dot\\theta$$\n"
                                                        "$$K = m l^2 \\dot\\phi^2$$\n"
                                                        "$$\\frac{\\partial K}{\\partial \\dot\\theta} = 0$$\n");
    REQUIRE(r.equations.size() == 4);
    CHECK(r.equations[1].verdict == Verdict::Agrees);
    CHECK(has_note(r.equations[3], "line 3"));
    CHECK(r.equations[3].verdict == Verdict::Agrees);
}

TEST_CASE("definitions: an unknown symbol is never differentiated to 0", "[checker][definitions]") {
    // Before: ∂W/∂θ was 0 (W a constant), so "∂W/∂θ = 0" agreed and the right line disagreed. (U is read as
    // the potential energy now.)
    const auto r = eomgen::test::check_text(kSpherical, "$$\\frac{\\partial W}{\\partial \\theta} = m g l \\sin\\theta$$\n"
                                                        "$$\\frac{\\partial W}{\\partial \\theta} = 0$$\n"
                                                        "$$\\frac{d}{dt}\\left(I_0 \\dot\\phi\\right) = 0$$\n"
                                                        "$$\\frac{\\partial L}{\\partial x} = 0$$\n"
                                                        "$$\\frac{d}{dt}\\left(\\text{const}\\right) = 0$$\n");
    REQUIRE(r.equations.size() == 5);
    for (std::size_t k = 0; k < 4; ++k) {
        INFO(describe(r.equations[k]));
        CHECK(r.equations[k].verdict == Verdict::NotComparable);
    }
    CHECK(r.equations[0].reason.find("partial derivative of $W$ (1:") != std::string::npos);
    CHECK(r.equations[1].reason.find("$W$") != std::string::npos);
    CHECK(r.equations[2].reason.find("time derivative of $I_{0}$") != std::string::npos);
    CHECK(r.equations[3].reason.find("with respect to $x$") != std::string::npos);
    // An additive constant is a constant.
    CHECK(r.equations[4].verdict == Verdict::Agrees);
}

TEST_CASE("definitions: a quantity of the motion set equal to a name the text introduces", "[checker][definitions]") {
    // `m r^2\dot\theta = \ell`: conserved, so it agrees, and ℓ stands for m r²θ̇ in what follows; `r\dot\theta =
    // v_\perp` is not conserved: the text's name for it, not judged.
    const std::string text = eomgen::test::fixture("central_force_notes.md");
    const std::map<int, std::string> planted = eomgen::test::planted_mistakes(text);
    REQUIRE(planted.size() == 2);
    const eomgen::checker::CheckReport r = eomgen::test::check_text("tests/checker/models/central_force.toml", text);
    CHECK(eomgen::test::planted_found(r, planted) == 2);
    int constants = 0, named = 0, times_velocity = 0;
    for (const EquationCheck& e : r.equations) {
        INFO(describe(e));
        if (e.reason.find("a constant of the motion") != std::string::npos) {
            CHECK(e.verdict == Verdict::Agrees);
            ++constants;
        }
        if (e.reason.find("the text's name $v_{\\perp}$") != std::string::npos) {
            CHECK(e.verdict == Verdict::NotComparable);
            ++named;
        }
        if (has_note(e, "read as $\\dot{r}$ times an equation")) ++times_velocity;
        if (e.where.line == 8 || e.where.line == 13) CHECK(e.verdict == Verdict::Agrees);  // ℓ put in
    }
    CHECK(constants == 3);  // ℓ, E_0 and the areal velocity A
    CHECK(named == 1);
    CHECK(times_velocity == 2);
    CHECK(r.count(Verdict::Disagrees) == 2);
}

TEST_CASE("definitions: the square of a name set to a constant defines the name", "[checker][definitions]") {
    // Notes on the damped pendulum written here: "Define ω₀² = g/l and γ = c/(2 m l²)", then the equation in them.
    const std::string text = eomgen::test::fixture("damped_pendulum_notes.md");
    const eomgen::checker::CheckReport r = eomgen::test::check_text("models/damped_pendulum.toml", text);
    CHECK(r.count(Verdict::Disagrees) == 0);
    bool found = false;
    for (const EquationCheck& e : r.equations) {
        INFO(describe(e));
        if (e.where.line == 10) {
            CHECK(e.verdict == Verdict::Agrees);
            CHECK(has_note(e, "using $\\omega_{0} = \\sqrt{g/l}$ (line 9)"));
            found = true;
        }
    }
    CHECK(found);
    // A square set to something that moves is not a definition of a constant.
    const eomgen::checker::CheckReport moving = eomgen::test::check_text(
        "models/damped_pendulum.toml", "Let $u^2 = \\dot\\varphi^2$, so that $u^2 + 1 = \\dot\\varphi^2 + 1$.\n");
    for (const EquationCheck& e : moving.equations) CHECK(e.reason.find("\\sqrt") == std::string::npos);
}

TEST_CASE("definitions: a speed squared written out names the speed, and its uses blame it", "[checker][definitions]") {
    // A spherical pendulum's bob: v² as the text writes it, then T = ½ m v² and L in v.
    const char* const model = "models/damped_spherical_pendulum.toml";
    const auto text = [](const std::string& v2) {
        return "The bob's speed squared is\n\n$$v^2 = " + v2 +
               "$$\n\nso that\n\n$$T = \\frac{1}{2} m v^2$$\n\nand\n\n$$L = \\frac{1}{2} m v^2 + mgl\\cos\\theta$$\n";
    };
    const eomgen::checker::CheckReport right =
        eomgen::test::check_text(model, text("l^2\\dot\\theta^2 + l^2\\sin^2\\theta\\,\\dot\\phi^2"));
    REQUIRE(right.equations.size() == 3);
    for (const EquationCheck& e : right.equations) INFO(describe(e));
    CHECK(right.equations[0].verdict == Verdict::Agrees);  // the definition, through its uses
    CHECK(right.equations[0].compared_with == "its uses on lines 7, 11");
    CHECK(right.equations[1].verdict == Verdict::Agrees);
    CHECK(right.equations[2].verdict == Verdict::Agrees);
    // cos where sin belongs: the definition disagrees, corrected in its own square; its uses hold with the correction.
    const eomgen::checker::CheckReport wrong =
        eomgen::test::check_text(model, text("l^2\\dot\\theta^2 + l^2\\cos^2\\theta\\,\\dot\\phi^2"));
    REQUIRE(wrong.equations.size() == 3);
    for (const EquationCheck& e : wrong.equations) INFO(describe(e));
    CHECK(wrong.equations[0].verdict == Verdict::Disagrees);
    CHECK(wrong.equations[0].corrected.rfind("v^2 = ", 0) == 0);
    CHECK(wrong.equations[0].corrected.find("\\sin^{2} \\theta") != std::string::npos);
    CHECK(wrong.equations[1].verdict == Verdict::NotComparable);
    CHECK(wrong.equations[1].reason.find("the text's $v$ of line 3 is what disagrees") != std::string::npos);
    // The square of one quantity (a velocity with a sign) names nothing: `l^2\dot\theta^2` stays the text's unknown.
    const eomgen::checker::CheckReport single = eomgen::test::check_text(model, text("l^2\\dot\\theta^2"));
    for (const EquationCheck& e : single.equations) {
        INFO(describe(e));
        CHECK(e.verdict == Verdict::NotComparable);
    }
}

TEST_CASE("definitions: the positions a text defines agree through the rows that use them", "[checker][definitions]") {
    const char* const pendulum = "tests/checker/models/plane_pendulum.toml";
    // x, y used in T and V that agree with eomgen's; ẋ defined from x (an identity) and then used in T: the rows
    // that confirm ẋ confirm x.
    const eomgen::checker::CheckReport r = eomgen::test::check_text(
        pendulum,
        "Let $x = l\\sin\\theta$ and $y = -l\\cos\\theta$, and $k = g/l$.\n\n"
        "$$\\dot x = l\\cos\\theta\\,\\dot\\theta$$\n\n"
        "$$T = \\frac12 m (\\dot x^2 + \\dot y^2)$$\n\n$$V = m g y$$\n\n$$\\ddot\\theta = -k\\sin\\theta$$\n");
    REQUIRE(r.equations.size() == 7);
    for (const EquationCheck& e : r.equations) INFO(describe(e));
    CHECK(r.equations[0].verdict == Verdict::Agrees);  // x: through ẋ (line 3) into T (line 5)
    CHECK(r.equations[0].compared_with == "its use on line 5");
    CHECK(r.equations[1].verdict == Verdict::Agrees);  // y: in T and in V
    CHECK(r.equations[1].compared_with == "its uses on lines 5, 7");
    CHECK(r.equations[1].role == Role::Definition);
    // k is a constant the text names: used in an equation that agrees, it is still only a name.
    CHECK(r.equations[2].verdict == Verdict::NotJudged);
    CHECK(r.equations[2].role == Role::Definition);
    CHECK(r.count(Verdict::Disagrees) == 0);
    // Used only in identities of the text's own, nothing confirms them.
    const eomgen::checker::CheckReport alone = eomgen::test::check_text(
        pendulum, "Let $x = l\\sin\\theta$.\n\n$$\\dot x = l\\cos\\theta\\,\\dot\\theta$$\n");
    REQUIRE(alone.equations.size() == 2);
    CHECK(alone.equations[0].verdict == Verdict::NotJudged);
    // A use that disagrees confirms nothing either (y with the wrong sign; one use: the use is flagged).
    const eomgen::checker::CheckReport wrong =
        eomgen::test::check_text(pendulum, "Let $y = l\\cos\\theta$.\n\n$$V = m g y$$\n");
    REQUIRE(wrong.equations.size() == 2);
    CHECK(wrong.equations[0].verdict == Verdict::NotJudged);
    CHECK(wrong.equations[1].verdict == Verdict::Disagrees);
}

TEST_CASE("definitions: a label written as a function of its arguments is the label", "[checker][definitions]") {
    const char* const pendulum = "tests/checker/models/plane_pendulum.toml";
    for (const char* text : {"$$L\\left(\\theta, \\dot\\theta\\right) = \\frac12 m l^2 \\dot\\theta^2 + m g l \\cos\\theta$$\n",
                             "$$L(\\theta, \\dot\\theta) = \\frac12 m l^2 \\dot\\theta^2 + m g l \\cos\\theta$$\n",
                             "$$V\\left(\\theta\\right) = -m g l\\cos\\theta$$\n"}) {
        const eomgen::checker::CheckReport r = eomgen::test::check_text(pendulum, text);
        REQUIRE(r.equations.size() == 1);
        INFO(describe(r.equations[0]));
        CHECK(r.equations[0].verdict == Verdict::Agrees);
    }
    const eomgen::checker::CheckReport wrong = eomgen::test::check_text(
        pendulum, "$$L\\left(\\theta, \\dot\\theta\\right) = \\frac12 m l^2 \\dot\\theta^2 - m g l \\cos\\theta$$\n");
    REQUIRE(wrong.equations.size() == 1);
    CHECK(wrong.equations[0].verdict == Verdict::Disagrees);
}

TEST_CASE("definitions: a definition after 'where' holds in the formula it explains", "[checker][definitions]") {
    const char* const spherical = "tests/checker/models/spherical_pendulum.toml";
    // In the same display (`\text{where $...$}`) and in the display after "where ... is:".
    const eomgen::checker::CheckReport same = eomgen::test::check_text(
        spherical, "$$\\ddot\\theta = \\sin\\theta\\cos\\theta\\,\\dot\\phi^2 - \\omega^2\\sin\\theta, \\quad "
                   "\\text{where } \\omega^2 = g/l$$\n");
    REQUIRE(same.equations.size() == 2);
    for (const EquationCheck& e : same.equations) INFO(describe(e));
    CHECK(same.equations[0].verdict == Verdict::Agrees);
    CHECK(has_note(same.equations[0], "using $\\omega = \\sqrt{g/l}$"));
    const eomgen::checker::CheckReport after = eomgen::test::check_text(
        spherical, "$$m l^2 \\ddot\\theta + m g l \\sin\\theta = Q$$\n\nwhere $Q$ is the centrifugal term:\n\n"
                   "$$Q = m l^2 \\sin\\theta\\cos\\theta\\,\\dot\\phi^2$$\n");
    REQUIRE(after.equations.size() == 2);
    for (const EquationCheck& e : after.equations) INFO(describe(e));
    CHECK(after.equations[0].verdict == Verdict::Agrees);
    // Without the cue, a value the text gives later in the section is taken where it makes the link agree ...
    const eomgen::checker::CheckReport plain = eomgen::test::check_text(
        spherical, "$$m l^2 \\ddot\\theta + m g l \\sin\\theta = Q$$\n\nThe centrifugal term:\n\n"
                   "$$Q = m l^2 \\sin\\theta\\cos\\theta\\,\\dot\\phi^2$$\n");
    REQUIRE(plain.equations.size() == 2);
    CHECK(plain.equations[0].verdict == Verdict::Agrees);
    CHECK(has_note(plain.equations[0], "with a value the text gives the name only later in its section"));
    // ... and only there: with a wrong later value the earlier link is not judged by it (no false alarm on it).
    const eomgen::checker::CheckReport wrong = eomgen::test::check_text(
        spherical, "$$m l^2 \\ddot\\theta + m g l \\sin\\theta = Q$$\n\nThe centrifugal term:\n\n"
                   "$$Q = m l^2 \\sin\\theta\\,\\dot\\phi^2$$\n");
    REQUIRE(wrong.equations.size() == 2);
    CHECK(wrong.equations[0].verdict == Verdict::NotComparable);
}

TEST_CASE("definitions: a constant of the motion is held fixed where the text differentiates by a coordinate",
          "[checker][definitions]") {
    // The effective potential in J = p_φ / m: -∂V_eff/∂θ at fixed J is the θ equation; with J's value put in before
    // differentiating, the sign of the centrifugal term would flip.
    const char* const spherical = "tests/checker/models/spherical_pendulum.toml";
    const std::string text = "The momentum $J = l^2\\sin^2\\theta\\,\\dot\\phi$ is conserved.\n\n"
                             "$$V_{eff}(\\theta) = -\\frac{g}{l}\\cos\\theta + \\frac{J^2}{2 l^4 \\sin^2\\theta}$$\n\n"
                             "$$\\ddot\\theta = -\\frac{\\partial V_{eff}}{\\partial\\theta}$$\n\n"
                             "$$\\ddot\\theta = -\\frac{\\partial}{\\partial\\theta}\\left(\\frac{J^2}{2 l^4 \\sin^2\\theta}\\right) - "
                             "\\frac{g}{l}\\sin\\theta$$\n";
    const eomgen::checker::CheckReport r = eomgen::test::check_text(spherical, text);
    for (const EquationCheck& e : r.equations) INFO(describe(e));
    CHECK(r.count(Verdict::Disagrees) == 0);
    int held = 0;
    for (const EquationCheck& e : r.equations)
        if (e.where.line == 5 || e.where.line == 7) {
            CHECK(e.verdict == Verdict::Agrees);
            held += has_note(e, "holds $J$ fixed in the derivative by a coordinate: a constant of the motion (line 1)");
        }
    CHECK(held == 2);
    // A wrong sign is still one.
    std::string wrong = text;
    wrong.replace(wrong.find("= -\\frac{\\partial V_{eff}}"), 3, "= ");
    const eomgen::checker::CheckReport w = eomgen::test::check_text(spherical, wrong);
    CHECK(w.count(Verdict::Disagrees) == 1);
}

TEST_CASE("definitions: a function of a coordinate, f(theta), and its derivative f'(theta)", "[checker][definitions]") {
    const char* const pendulum = "tests/checker/models/plane_pendulum.toml";
    const eomgen::checker::CheckReport r = eomgen::test::check_text(
        pendulum, "Let $y(\\theta) = -l\\cos\\theta$ be the height.\n\n$$V = m g y(\\theta)$$\n\n"
                  "$$y'(\\theta) = l\\sin\\theta$$\n\n$$V'(\\theta) = m g l \\sin\\theta$$\n\n"
                  "$$m l^2\\ddot\\theta = -V'(\\theta)$$\n\n$$y''(\\theta) = l\\sin\\theta$$\n");
    for (const EquationCheck& e : r.equations) INFO(describe(e));
    REQUIRE(r.equations.size() == 6);
    for (std::size_t k = 1; k < 5; ++k) CHECK(r.equations[k].verdict == Verdict::Agrees);
    CHECK(r.equations[5].verdict == Verdict::Disagrees);  // y'' = l cos θ
    // A parameter before a bracket is a product, as before: m(g l) is m g l.
    const eomgen::checker::CheckReport product =
        eomgen::test::check_text(pendulum, "$$V = -m(\\theta)g l\\cos\\theta$$\n");
    REQUIRE(product.equations.size() == 1);
    CHECK(product.equations[0].verdict == Verdict::Disagrees);
}

TEST_CASE("definitions: notes on the Kepler problem's effective potential, written here, raise no alarm",
          "[checker][definitions]") {
    // Written after the readings above (a generic q, V'(r), ℓ held fixed in ∂U_eff/∂r, a value given later);
    // first run at 94068ee: no false alarm.
    const std::string text = eomgen::test::fixture("kepler_effective_potential_notes.md");
    const eomgen::checker::CheckReport r = eomgen::test::check_text("tests/checker/models/central_force.toml", text);
    for (const EquationCheck& e : r.equations) INFO(describe(e));
    CHECK(r.count(Verdict::Disagrees) == 0);
    CHECK(r.count(Verdict::Agrees) == 12);
    CHECK(r.count(Verdict::NotComparable) == 1);  // U_eff''(r_0): a derivative at a point
    // "for q = r, θ": the generic coordinate's meaning, a definition.
    CHECK(r.equations[3].verdict == Verdict::NotJudged);
    CHECK(r.equations[3].reason == "a definition: the text's $q$ stands for each of $r$, $\\theta$ in turn");
    // A slip in V' is flagged at its line; one in U_eff makes its uses disagree.
    std::string wrong = text;
    wrong.replace(wrong.find("V'(r) = \\frac{k}{r^2}"), std::strlen("V'(r) = \\frac{k}{r^2}"), "V'(r) = -\\frac{k}{r^2}");
    const eomgen::checker::CheckReport w = eomgen::test::check_text("tests/checker/models/central_force.toml", wrong);
    REQUIRE(w.count(Verdict::Disagrees) == 1);
    for (const EquationCheck& e : w.equations)
        if (e.verdict == Verdict::Disagrees) CHECK(e.corrected == "V'(r) = \\frac{k}{r^{2}}");
}

TEST_CASE("definitions: a coordinate as a function of another along the motion, r'(theta)", "[checker][definitions]") {
    // An orbit r(θ): dr/dθ = ṙ/θ̇ on the motion, each prime one more (1/θ̇) d/dt.
    const eomgen::checker::CheckReport r = eomgen::test::check_text(
        "tests/checker/models/central_force.toml",
        "$$r'(\\theta) = \\frac{\\dot r}{\\dot\\theta}$$\n\n"
        "$$r''(\\theta) = \\frac{\\ddot r \\dot\\theta - \\dot r \\ddot\\theta}{\\dot\\theta^3}$$\n\n$$r'(\\theta) = \\dot r$$\n");
    REQUIRE(r.equations.size() == 3);
    for (const EquationCheck& e : r.equations) INFO(describe(e));
    CHECK(r.equations[0].verdict == Verdict::Agrees);
    CHECK(r.equations[1].verdict == Verdict::Agrees);
    CHECK(r.equations[2].verdict != Verdict::Agrees);
    CHECK(has_note(r.equations[0], "$r'(\\theta)$ read as the derivative by it along the motion"));
}

TEST_CASE("definitions: derivatives by a new time tau = c t",
          "[checker][definitions]") {
    const eomgen::checker::CheckReport r = eomgen::test::check_text(
        "tests/checker/models/plane_pendulum.toml",
        "With the time $\\tau = t\\sqrt{g/l}$,\n\n$$\\frac{d^2\\theta}{d\\tau^2} = -\\sin\\theta$$\n\n"
        "$$\\frac{d^2\\theta}{d\\tau^2} = \\sin\\theta$$\n\n"
        "$$\\frac{d^2\\theta}{d s^2} = -\\sin\\theta$$\n");
    REQUIRE(r.equations.size() == 4);
    for (const EquationCheck& e : r.equations) INFO(describe(e));
    CHECK(r.equations[0].verdict == Verdict::NotJudged);  // a new time is a definition, not a quantity of the motion
    CHECK(r.equations[1].verdict == Verdict::Agrees);
    CHECK(r.equations[2].verdict == Verdict::Disagrees);
    CHECK(r.equations[2].compared_with == "the Euler–Lagrange equation for $\\theta$");
    CHECK(r.equations[3].verdict == Verdict::NotComparable);  // s: not defined by the text
    CHECK(r.equations[3].reason.find("which the text does not define") != std::string::npos);
}

TEST_CASE("definitions: one derived with an implication sign is the relation before it solved for the name",
          "[checker][definitions][implication]") {
    // The double Atwood machine of the corpus: `\frac{1}{2}(y_1+y_2) = l_2-y_3 \Rightarrow y_3 = l_2 - \frac{1}{2}
    // (y_1 - y_2)`, a sign slipped in the solving.
    const char* const model = "tests/checker/models/two_carts.toml";
    const auto verdict_of_s = [&](const std::string& text) -> const EquationCheck {
        const auto r = eomgen::test::check_text(model, text);
        for (const EquationCheck& e : r.equations)
            if (e.equation.rfind("s = ", 0) == 0) return e;
        FAIL("no verdict on s = …");
        return {};
    };
    const EquationCheck right =
        verdict_of_s("The midpoint: $x_1 + x_2 = 2 s$ $\\Rightarrow$ $s = \\frac{1}{2}(x_1 + x_2)$.\n");
    INFO(describe(right));
    CHECK(right.verdict == Verdict::Agrees);
    CHECK(right.compared_with.rfind("the relation it follows from (line 1)", 0) == 0);
    const EquationCheck wrong =
        verdict_of_s("The midpoint: $x_1 + x_2 = 2 s$ $\\Rightarrow$ $s = \\frac{1}{2}(x_1 - x_2)$.\n");
    INFO(describe(wrong));
    CHECK(wrong.verdict == Verdict::Disagrees);
    CHECK(wrong.reason.rfind("it does not follow from", 0) == 0);
    CHECK(wrong.corrected == "s = \\frac{1}{2} x_{1} + \\frac{1}{2} x_{2}");
    // Without the sign, or where solving would divide by a quantity of the motion, it stays a definition.
    const EquationCheck apart = verdict_of_s("$x_1 + x_2 = 2 s$ and, for later, $s = \\frac{1}{2}(x_1 - x_2)$.\n");
    CHECK(apart.verdict == Verdict::NotJudged);
    const EquationCheck divided = verdict_of_s("$x_1 s = 1$ $\\Rightarrow$ $s = 2/x_1$.\n");
    CHECK(divided.verdict == Verdict::NotJudged);
}

TEST_CASE("definitions: after a definition that does not follow, the lines are read with its correction",
          "[checker][definitions][implication]") {
    // One slip does not make every later line that uses the name disagree, and a later line that is right about
    // the system is not flagged for carrying the text's slip; one that carries it forward is.
    const char* const model = "tests/checker/models/two_carts.toml";
    const std::string head = "The midpoint: $x_1 + x_2 = 2 s$ $\\Rightarrow$ $s = \\frac{1}{2}(x_1 - x_2)$.\n\n";
    const auto verdict_on_line = [&](const std::string& text, int line) -> const EquationCheck {
        const auto r = eomgen::test::check_text(model, text);
        for (const EquationCheck& e : r.equations) {
            INFO(describe(e));
            if (e.where.line == line) return e;
        }
        FAIL("no verdict on line " << line);
        return {};
    };
    const EquationCheck right = verdict_on_line(head + "$$\\dot s = \\frac{1}{2}(\\dot x_1 + \\dot x_2)$$\n", 3);
    INFO(describe(right));
    CHECK(right.verdict == Verdict::Agrees);
    CHECK(eomgen::test::has_note(right, "corrected (the text's does not follow)"));
    const EquationCheck carried = verdict_on_line(head + "$$\\dot s = \\frac{1}{2}(\\dot x_1 - \\dot x_2)$$\n", 3);
    INFO(describe(carried));
    CHECK(carried.verdict != Verdict::Agrees);
    // A definition that follows is used as the text gives it, with no such note.
    const EquationCheck plain = verdict_on_line(
        "The midpoint: $x_1 + x_2 = 2 s$ $\\Rightarrow$ $s = \\frac{1}{2}(x_1 + x_2)$.\n\n"
        "$$\\dot s = \\frac{1}{2}(\\dot x_1 + \\dot x_2)$$\n",
        3);
    CHECK(plain.verdict == Verdict::Agrees);
    CHECK(!eomgen::test::has_note(plain, "corrected"));
}

TEST_CASE("definitions: a wrong value given only after its uses is blamed at its line when the uses agree on another",
          "[checker][definitions]") {
    // The yo-yo of the corpus: I used in L and in the equation of motion, then "defined by I = m(kR)^2".
    const char* const model = "tests/checker/models/plane_pendulum.toml";
    const std::string text = "$$L = \\frac{1}{2} I \\dot\\theta^2 + m g l \\cos\\theta$$\n"
                             "\n"
                             "$$I \\ddot\\theta = -m g l \\sin\\theta$$\n"
                             "\n"
                             "where the moment of inertia about the pivot is $I = m l$.\n";
    const auto r = eomgen::test::check_text(model, text);
    bool blamed = false;
    for (const EquationCheck& e : r.equations) {
        INFO(describe(e));
        if (e.where.line == 5) {
            CHECK(e.verdict == Verdict::Disagrees);
            CHECK(e.corrected == "I = m l^{2}");
            blamed = true;
        } else {
            CHECK(e.verdict == Verdict::NotComparable);
            CHECK(e.reason.find("the text's $I$ of line 5 is what disagrees") != std::string::npos);
        }
    }
    CHECK(blamed);
    // Right, it makes them agree (a value given later, taken where it does).
    std::string right = text;
    right.replace(right.find("I = m l$"), 8, "I = m l^2$");
    for (const EquationCheck& e : eomgen::test::check_text(model, right).equations) {
        INFO(describe(e));
        CHECK(e.verdict != Verdict::Disagrees);
    }
}

TEST_CASE("definitions: a name the symbol map gives is compared with the map's value", "[checker][definitions]") {
    eomgen::checker::CheckOptions options;
    options.map.push_back({"\\omega_{0}", "\\sqrt{g/l}", "--map", 0, 0});
    const char* const model = "tests/checker/models/plane_pendulum.toml";
    const auto wrong = eomgen::test::check_text(model, "The frequency is $\\omega_0 = \\sqrt{l/g}$.\n", options);
    REQUIRE(wrong.equations.size() == 1);
    INFO(describe(wrong.equations[0]));
    CHECK(wrong.equations[0].verdict == Verdict::Disagrees);
    CHECK(wrong.equations[0].compared_with.rfind("the symbol map's $\\omega_{0} = \\sqrt{g/l}$", 0) == 0);
    const auto right = eomgen::test::check_text(model, "The frequency is $\\omega_0 = \\sqrt{g/l}$.\n", options);
    REQUIRE(right.equations.size() == 1);
    CHECK(right.equations[0].verdict == Verdict::Agrees);
    // A number the text picks for it is its choice, not compared with the map.
    const auto picked = eomgen::test::check_text(model, "Take $\\omega_0 = 2$.\n", options);
    REQUIRE(picked.equations.size() == 1);
    CHECK(picked.equations[0].verdict != Verdict::Disagrees);
}

TEST_CASE("definitions: solving by dividing by a quantity that vanishes on the motion is a slip",
          "[checker][definitions][implication]") {
    // The double Atwood machine of the corpus: with m_1 = m_2 = m the motion has ÿ₁ = ÿ₂, and the asker divides
    // m(ÿ₁ − ÿ₂) = −m₃/4 (ÿ₁ − ÿ₂) by ÿ₁ − ÿ₂ to get m = −m₃/4.
    const char* const model = "tests/checker/corpus/atwood_double_mse/model.toml";
    const std::string head = "For equal masses, with $m_1 = m_2 = m$,\n"
                             "$$\nm(\\ddot{y_1} - \\ddot{y_2}) = -\\frac{m_3}{4} ( \\ddot{y_1} - \\ddot{y_2})\n$$\n";
    const auto r = eomgen::test::check_text(model, head + "$$\n\\Rightarrow m = -\\frac{m_3}{4}\n$$\n");
    int judged = 0;
    for (const EquationCheck& e : r.equations) {
        INFO(describe(e));
        if (e.where.line == 1) CHECK(e.verdict == Verdict::NotJudged);  // the assumption, naming m
        if (e.where.line == 3) CHECK(e.verdict == Verdict::Agrees);     // on the motion, with the masses equal
        if (e.where.line == 6) {
            CHECK(e.verdict == Verdict::Disagrees);
            CHECK(e.reason.find("which is 0 on the motion") != std::string::npos);
            CHECK(e.corrected == "\\ddot{y_{1}} - \\ddot{y_{2}} = 0");
            ++judged;
        }
    }
    CHECK(judged == 1);
    // Without the assumption the factor does not vanish on the motion: the step is not judged a slip.
    const auto apart = eomgen::test::check_text(
        model, "$$\nm_1(\\ddot{y_1} - \\ddot{y_2}) = -\\frac{m_3}{4} ( \\ddot{y_1} - \\ddot{y_2})\n$$\n"
               "$$\n\\Rightarrow m = -\\frac{m_3}{4}\n$$\n");
    for (const EquationCheck& e : apart.equations) {
        INFO(describe(e));
        if (e.where.line == 5) CHECK(e.reason.find("which is 0 on the motion") == std::string::npos);
    }
}

TEST_CASE("definitions: a name times a factor at the end of a chain names the quantity before it",
          "[checker][definitions]") {
    // `p_\psi = I_3(\dot\psi + \dot\phi\cos\theta) = I_3\omega_3`: ω₃ is the spin, in the rows after it too.
    const std::string text = eomgen::test::fixture("heavy_top_steady_notes.md");
    const eomgen::checker::CheckReport r = eomgen::test::check_text("models/heavy_symmetric_top.toml", text);
    bool named = false;
    int used = 0;
    for (const EquationCheck& e : r.equations) {
        INFO(describe(e));
        if (e.where.line == 14 && e.reason.find("the text names its value $\\omega_{3}$") != std::string::npos) {
            CHECK(e.verdict == Verdict::Agrees);  // the spin is conserved
            named = true;
        }
        if (has_note(e, "using $\\omega_{3} = \\dot{\\psi} + \\dot{\\phi} \\cos \\theta$ (line 14)")) ++used;
        CHECK(e.reason.find("unknown symbol") == std::string::npos);
    }
    CHECK(named);
    CHECK(used >= 4);  // p_φ, the θ equation, steady precession, the energy
    // A name the text wrote before is not introduced there: "a circular orbit of radius $r_0$ … $\ell^2 = m k r_0$"
    // (with ℓ = m r² θ̇ conserved) is a claim about that radius, not the text's name for ℓ²/(mk).
    const eomgen::checker::CheckReport orbit = eomgen::test::check_text(
        "tests/checker/models/central_force.toml",
        "With $m r^2\\dot\\theta = \\ell$, a circular orbit of radius $r_0$ satisfies $\\ell^2 = m k r_0$.\n");
    for (const EquationCheck& e : orbit.equations) {
        INFO(describe(e));
        if (e.equation.find("r_0") != std::string::npos) CHECK(e.verdict == Verdict::NotComparable);
    }
}
