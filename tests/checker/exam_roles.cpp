/** @file exam_roles.cpp  Rows that are not claims of the general motion: a value the text chooses for a
 * parameter, the conditions of a particular point, an approximation announced in the problem's statement, and
 * an acceleration solved from the equations. */
#include "checked_text.hpp"

#include <catch2/catch.hpp>

#include <cstring>

using eomgen::checker::CheckReport;
using eomgen::checker::EquationCheck;
using eomgen::checker::Role;
using eomgen::checker::Verdict;

namespace {

const char* kAtwood = "tests/checker/corpus/atwood_double_pf/model.toml";
const char* kPendulum = "tests/checker/models/plane_pendulum.toml";

std::vector<const EquationCheck*> on_line(const CheckReport& r, int line) {
    std::vector<const EquationCheck*> out;
    for (const EquationCheck& e : r.equations)
        if (e.where.line == line) out.push_back(&e);
    return out;
}

/// The verdict on a text of one equation.
Verdict one_verdict(const char* model, const std::string& text) {
    const CheckReport r = eomgen::test::check_text(model, text);
    REQUIRE(r.equations.size() == 1);
    INFO(eomgen::test::describe(r.equations[0]));
    return r.equations[0].verdict;
}

}  // namespace

TEST_CASE("roles: a parameter the text sets holds for the rest of its paragraph, in the text and in eomgen's "
          "equations",
          "[checker][roles]") {
    const std::string text = "For $m_1 = 0$ it reduces to $\\ddot{l_2} = 0$, and $\\ddot{l_1} = -g$.\n"
                             "\n"
                             "In general $\\ddot{l_1} = -g$ does not hold.\n";
    const CheckReport r = eomgen::test::check_text(kAtwood, text);
    const auto first = on_line(r, 1);
    REQUIRE(first.size() == 3);
    for (const EquationCheck* e : first) INFO(eomgen::test::describe(*e));
    CHECK(first[0]->verdict == Verdict::NotJudged);
    CHECK(first[0]->role == Role::ChosenValue);
    CHECK(first[0]->reason.find("a value the text chooses") == 0);
    for (int k : {1, 2}) {
        INFO(eomgen::test::describe(*first[std::size_t(k)]));
        CHECK(first[std::size_t(k)]->verdict == Verdict::Agrees);
        CHECK(eomgen::test::has_note(*first[std::size_t(k)], "with $m_{1} = 0$, the value the text chose on line 1"));
    }
    // The next paragraph is back to the model's m_1.
    const auto later = on_line(r, 3);
    REQUIRE(later.size() == 1);
    INFO(eomgen::test::describe(*later[0]));
    CHECK(later[0]->verdict == Verdict::Disagrees);
}

TEST_CASE("roles: an acceleration with the others eliminated is compared with its solution, and corrected to it",
          "[checker][roles]") {
    const CheckReport wrong = eomgen::test::check_text(
        kAtwood, "$$\\ddot{l_2} = \\frac{ 2m_1(m_2 - M) }{m_1M + m_1 m_2 + 2 M m_2}g$$\n");
    REQUIRE(wrong.equations.size() == 1);
    const EquationCheck& w = wrong.equations[0];
    INFO(eomgen::test::describe(w));
    CHECK(w.verdict == Verdict::Disagrees);
    CHECK(w.compared_with == "$\\ddot{l_{2}}$ solved from the Euler–Lagrange equations");
    CHECK(w.corrected.find("\\ddot{l_2} = ") == 0);  // the author's left side, then eomgen's solution
    CHECK(w.corrected.find("4 m_{2} M") != std::string::npos);
    CHECK(w.corrected.find("\\ddot{l_{1}}") == std::string::npos);  // no other acceleration in the correction
    CHECK(one_verdict(kAtwood, "$$\\ddot{l_2} = \\frac{ 2m_1(m_2 - M) }{m_1M + m_1 m_2 + 4 M m_2}g$$\n") ==
          Verdict::Agrees);
}

TEST_CASE("roles: a coordinate set to a value is a condition, and what the paragraph names there holds only in it",
          "[checker][roles]") {
    const std::string text = "At the side,\n"
                             "$$\n"
                             "u = \\theta = \\frac{\\pi}{2},\\\\\n"
                             "y = l \\cos\\theta = 0\n"
                             "$$\n"
                             "\n"
                             "The potential energy is $V = -m g y$.\n";
    const CheckReport r = eomgen::test::check_text(kPendulum, text);
    for (const EquationCheck& e : r.equations) {
        INFO(eomgen::test::describe(e));
        CHECK(e.verdict != Verdict::Disagrees);
    }
    const auto cond = on_line(r, 3);
    REQUIRE(cond.size() == 2);
    CHECK(cond[1]->reason.find("a condition: the point or motion the text considers, where $\\theta$") == 0);
    // y = 0 at θ = π/2 is not the definition of y: V = −m g y is not judged with y = 0.
    const auto v = on_line(r, 7);
    REQUIRE(v.size() == 1);
    CHECK(v[0]->verdict == Verdict::NotComparable);
    CHECK(v[0]->reason.find("unknown symbol $y$") == 0);
}

TEST_CASE("roles: small oscillations stated with the problem make a later linear equation an approximation",
          "[checker][roles]") {
    const std::string eq = "$$\\ddot\\theta + \\frac{g}{l}\\theta = 0$$\n";
    const CheckReport stated =
        eomgen::test::check_text(kPendulum, "The pendulum makes small oscillations.\n\nIts equation:\n\n" + eq);
    REQUIRE(stated.equations.size() == 1);
    INFO(eomgen::test::describe(stated.equations[0]));
    CHECK(stated.equations[0].verdict == Verdict::Agrees);
    CHECK(stated.equations[0].reason == "agrees to first order in $\\theta$");
    CHECK(stated.equations[0].compared_with.find("the text says on line 1 that the motion is small") !=
          std::string::npos);
    // Without it, θ for sin θ is a slip.
    CHECK(one_verdict(kPendulum, "The pendulum swings.\n\nIts equation:\n\n" + eq) == Verdict::Disagrees);
}

TEST_CASE("roles: the derivative macros of the physics package and of course notes are read as the fractions they "
          "typeset",
          "[checker][roles]") {
    for (const char* text : {"$$\\dv{t}\\pdv{L}{\\dot\\theta} = \\pdv{L}{\\theta}$$\n",
                             "$$\\diff{}{t}\\pdiff{\\Lagr}{\\dot{\\theta}} - \\pdiff{\\Lagr}{\\theta} = 0$$\n",
                             "$$\\dv{t}\\left(\\pdv{L}{\\dot\\theta}\\right) = \\pdv{L}{\\theta}$$\n",
                             "$$\\pdv{L}{\\dot\\theta} = m l^2 \\dv{\\theta}{t}$$\n"}) {
        const CheckReport r = eomgen::test::check_text(kPendulum, text);
        REQUIRE(r.equations.size() == 1);
        INFO(text << "\n" << eomgen::test::describe(r.equations[0]));
        CHECK(r.equations[0].verdict == Verdict::Agrees);
        CHECK(r.equations[0].equation.find("\\pd") != std::string::npos);  // shown as the text writes it
    }
    // A slip inside a macro is still one.
    CHECK(one_verdict(kPendulum, "$$\\pdv{L}{\\dot\\theta} = m l \\dot\\theta$$\n") == Verdict::Disagrees);
}

TEST_CASE("roles: a momentum set equal to a one-letter label names it with that letter for the rest of the section",
          "[checker][roles]") {
    const std::string text = "$$\n"
                             "p_\\theta = L = \\pdv{L}{\\dot{\\theta}} = m l^2 \\dot{\\theta}, \\qquad\n"
                             "\\dot{L} = \\pdv{L}{\\theta}\n"
                             "$$\n";
    const CheckReport r = eomgen::test::check_text(kPendulum, text);
    REQUIRE(r.equations.size() == 4);
    for (const EquationCheck& e : r.equations) INFO(eomgen::test::describe(e));
    CHECK(r.equations[0].verdict == Verdict::NotJudged);
    CHECK(r.equations[0].role == Role::Definition);
    CHECK(r.equations[0].reason.find("a definition: the text names $p_\\theta$ $L$ here") == 0);
    for (std::size_t k = 1; k < 4; ++k) {
        INFO(eomgen::test::describe(r.equations[k]));
        CHECK(r.equations[k].verdict == Verdict::Agrees);
    }
    CHECK(r.equations[1].compared_with == "$p_{\\theta}$");
    CHECK(eomgen::test::has_note(r.equations[3], "reads $L$ as $p_\\theta$, as the text names it on line 2"));
    // Without the naming, L = ∂L/∂θ̇ is wrong.
    CHECK(one_verdict(kPendulum, "$$L = \\pdv{L}{\\dot{\\theta}}$$\n") == Verdict::Disagrees);
}

TEST_CASE("roles: U is the potential energy, KE and PE the energies, as many texts write them", "[checker][roles]") {
    CHECK(one_verdict(kPendulum, "$$\\mathcal{L} = T - U$$\n") == Verdict::Agrees);
    CHECK(one_verdict(kPendulum, "$$U = -m g l \\cos\\theta$$\n") == Verdict::Agrees);
    CHECK(one_verdict(kPendulum, "$$U = m g l \\cos\\theta$$\n") == Verdict::Disagrees);
    CHECK(one_verdict(kPendulum, "$$KE = \\frac12 m l^2 \\dot\\theta^2$$\n") == Verdict::Agrees);
    CHECK(one_verdict(kPendulum, "$$\\text{PE} = -m g l \\cos\\theta$$\n") == Verdict::Agrees);
    CHECK(one_verdict(kPendulum, "$$PE = m g l$$\n") == Verdict::Disagrees);
    // K alone is the text's own name (a spring constant as often as a kinetic energy); K E with a space is a
    // product.
    CHECK(one_verdict(kPendulum, "$$K = \\frac12 m l^2 \\dot\\theta^2$$\n") == Verdict::NotJudged);
    CHECK(one_verdict(kPendulum, "$$K E = \\frac12 m l^2 \\dot\\theta^2$$\n") == Verdict::NotComparable);
}

TEST_CASE("roles: the Lagrangian of the coordinates a text keeps, when eomgen's separates (a two-body problem's "
          "relative motion)",
          "[checker][roles]") {
    const char* two_body = "tests/checker/corpus/central_two_body_one_body/model.toml";
    const EquationCheck rel = [&] {
        const CheckReport r = eomgen::test::check_text(
            two_body, "$$L = \\frac{1}{2}\\frac{m_1 m_2}{m_1 + m_2}(\\dot{r}^{2} + r^{2}\\dot{\\theta}^{2}) + \\frac{k}{r}$$\n");
        REQUIRE(r.equations.size() == 1);
        return r.equations[0];
    }();
    INFO(eomgen::test::describe(rel));
    CHECK(rel.verdict == Verdict::Agrees);
    CHECK(rel.reason.find("the Lagrangian of $r$, $\\theta$ alone: eomgen's L separates, and the part in $X$, $Y$") == 0);
    // A slip in the part it keeps is still one.
    CHECK(one_verdict(two_body, "$$L = \\frac{1}{2}\\frac{m_1 m_2}{m_1 + m_2}(\\dot{r}^{2} + r\\dot{\\theta}^{2}) + "
                                "\\frac{k}{r}$$\n") == Verdict::Disagrees);
    // A double pendulum's L without θ₂'s own terms is no such part: θ₂ is coupled to θ₁.
    CHECK(one_verdict("tests/checker/models/double_pendulum_equal.toml",
                      "$$L = m l^2 \\dot\\theta_1^2 + 2 m g l \\cos\\theta_1$$\n") == Verdict::Disagrees);
}

TEST_CASE("roles: an equation that holds only on a holonomic constraint is checked at states on it",
          "[checker][roles]") {
    // x² + y² = a z in (ρ, z, φ): ρ² φ̈ + 2 ρ ρ̇ φ̇ = 0 is a (ż φ̇ + z φ̈) = 0 where ρ² = a z.
    const char* paraboloid = "tests/checker/corpus/central_paraboloid_multiplier_mathse/model.toml";
    CHECK(one_verdict(paraboloid, "$$\\dot z\\dot\\varphi+z\\ddot\\varphi=0$$\n") == Verdict::Agrees);
    CHECK(one_verdict(paraboloid, "$$\\dot z\\dot\\varphi+2z\\ddot\\varphi=0$$\n") == Verdict::Disagrees);
}

TEST_CASE("roles: an equation with the multiplier, written on the constraint, and a constraint's name as its "
          "function",
          "[checker][roles]") {
    // The rod turned at φ = ωt (constraint f = φ − ωt): the φ equation with λ, φ = ωt put in.
    const char* rod = "tests/checker/corpus/bead_rotating_rod/model.toml";
    const CheckReport r = eomgen::test::check_text(
        rod, "$$2ms\\dot s \\omega + mgs\\cos(\\omega t) = \\lambda\\frac {\\partial f}{\\partial\\varphi} = \\lambda$$\n");
    REQUIRE(r.equations.size() == 2);
    for (const EquationCheck& e : r.equations) {
        INFO(eomgen::test::describe(e));
        CHECK(e.verdict == Verdict::Agrees);
    }
    CHECK(r.equations[0].compared_with == "the equations of motion with the constraint forces");
    CHECK(one_verdict(rod, "$$2ms\\dot s \\omega + mgs\\cos(\\omega t) = 2\\lambda$$\n") != Verdict::Agrees);
    CHECK(one_verdict(rod, "$$ms\\dot s \\omega + mgs\\cos(\\omega t) = \\lambda$$\n") != Verdict::Agrees);
}

TEST_CASE("roles: a definition that two uses make wrong is the slip, not the uses", "[checker][roles]") {
    // The height is y = −l cos θ; the text defines y = l sin θ and uses it twice with eomgen's V and L.
    const std::string wrong_def = "Let $y = l\\sin\\theta$ be the height of the bob.\n\n"
                                  "$$V = m g y$$\n\n"
                                  "$$L = \\frac12 m l^2 \\dot\\theta^2 - m g y$$\n";
    const CheckReport r = eomgen::test::check_text(kPendulum, wrong_def);
    REQUIRE(r.equations.size() == 3);
    for (const EquationCheck& e : r.equations) INFO(eomgen::test::describe(e));
    CHECK(r.equations[0].verdict == Verdict::Disagrees);
    CHECK(r.equations[0].corrected == "y = -l \\cos \\theta");
    for (std::size_t k = 1; k < 3; ++k) {
        INFO(eomgen::test::describe(r.equations[k]));
        CHECK(r.equations[k].verdict == Verdict::NotComparable);
        CHECK(r.equations[k].reason.find("the text's $y$ of line 1 is what disagrees") != std::string::npos);
    }
    // A bare use and one inside ∂/∂θ: the value the bare use needs makes the other agree, so they blame it alike.
    const CheckReport derivative = eomgen::test::check_text(
        kPendulum, "Let $y = l\\cos\\theta$ be the height of the bob.\n\n$$V = m g y$$\n\n"
                   "$$m l^2 \\ddot\\theta = -m g \\frac{\\partial y}{\\partial \\theta}$$\n");
    REQUIRE(derivative.equations.size() == 3);
    for (const EquationCheck& e : derivative.equations) INFO(eomgen::test::describe(e));
    CHECK(derivative.equations[0].verdict == Verdict::Disagrees);
    CHECK(derivative.equations[0].corrected == "y = -l \\cos \\theta");
    CHECK(derivative.equations[2].reason.find("the text's $y$ of line 1 is what disagrees") != std::string::npos);
    // One use alone does not say which of the two is wrong: the use disagrees, the definition stands.
    const CheckReport once = eomgen::test::check_text(kPendulum, "Let $y = l\\sin\\theta$ be the height.\n\n$$V = m g y$$\n");
    REQUIRE(once.equations.size() == 2);
    CHECK(once.equations[0].verdict == Verdict::NotJudged);
    CHECK(once.equations[0].role == Role::Definition);
    CHECK(once.equations[1].verdict == Verdict::Disagrees);
}

TEST_CASE("roles: T_0 set to a constant is a period, not a part of T", "[checker][roles]") {
    const CheckReport r = eomgen::test::check_text(kPendulum, "The period is $T_0 = 2\\pi\\sqrt{l/g}$.\n\n"
                                                              "$$T_{1} = \\frac12 m l^2 \\dot\\theta^2$$\n");
    REQUIRE(r.equations.size() == 2);
    CHECK(r.equations[0].verdict == Verdict::NotJudged);
    CHECK(r.equations[0].role == Role::Definition);
    CHECK(r.equations[0].reason.find("a definition: the text's abbreviation $T_{0} = ") != std::string::npos);
    INFO(eomgen::test::describe(r.equations[1]));
    CHECK(r.equations[1].compared_with.find("a part of $T$") != std::string::npos);
}

TEST_CASE("roles: a bare const is the additive constant, and a label (E_1): before a row is no part of it",
          "[checker][roles]") {
    CHECK(one_verdict(kPendulum, "$$V = -m g l \\cos\\theta + const.$$\n") == Verdict::Agrees);
    CHECK(one_verdict(kPendulum, "$$V = -m g l \\cos\\theta + \\text{constant}$$\n") == Verdict::Agrees);
    // `constraint` stays letters (here unknown names).
    CHECK(one_verdict(kPendulum, "$$V = constraint$$\n") == Verdict::NotComparable);
    const CheckReport r = eomgen::test::check_text(
        kPendulum, "$$\\begin{aligned}(E_1):& \\; m l^2 \\ddot\\theta + m g l \\sin\\theta = 0\\end{aligned}$$\n");
    REQUIRE(r.equations.size() == 1);
    INFO(eomgen::test::describe(r.equations[0]));
    CHECK(r.equations[0].verdict == Verdict::Agrees);
}

TEST_CASE("roles: math as word processors and course notes paste it: K.E., \\ds, frac{ without its backslash, a "
          "dot after a space",
          "[checker][roles]") {
    CHECK(one_verdict(kPendulum, "$\\ds L = K.E. - P.E.$\n") == Verdict::Agrees);
    CHECK(one_verdict(kPendulum, "$K.E. = frac{1}{2} m l^2 \\dot\\theta^2$\n") == Verdict::Agrees);
    CHECK(one_verdict(kPendulum, "$\\theta ̈ = -frac{g}{l} \\sin\\theta$\n") == Verdict::Agrees);
    CHECK(one_verdict(kPendulum, "$T = frac{1}{2} m l^2 \\theta ̇^2$\n") == Verdict::Agrees);
    CHECK(one_verdict(kPendulum, "$\\theta ̈ = frac{g}{l} \\sin\\theta$\n") == Verdict::Disagrees);
    // d/dt in plain text, bare or in parentheses, is the operator.
    CHECK(one_verdict(kPendulum, "$(d/dt) [m l^2 \\dot\\theta] = -m g l \\sin\\theta$\n") == Verdict::Agrees);
    CHECK(one_verdict(kPendulum, "$d/dt (m l^2 \\dot\\theta) = -m g l \\sin\\theta$\n") == Verdict::Agrees);
}

TEST_CASE("roles: a name the prose gives a quantity, and the conditions of a steady motion with their consequence",
          "[checker][roles]") {
    // Written here, not from the corpus: "… is conserved; call it $\ell$", then θ̇ = 0 and θ̈ = 0 for a conical motion.
    const CheckReport r = eomgen::test::check_text("tests/checker/models/spherical_pendulum.toml",
                                                   eomgen::test::fixture("spherical_conical_notes.md"));
    for (const EquationCheck& e : r.equations) {
        INFO(eomgen::test::describe(e));
        CHECK(e.verdict != Verdict::Disagrees);
    }
    CHECK(r.count(Verdict::Agrees) == 8);
    const auto last = r.equations.back();
    CHECK(last.compared_with == "the Euler–Lagrange equation for $\\theta$ on the motion the text considers");
    // A wrong steady-motion relation is not excused.
    const CheckReport wrong = eomgen::test::check_text(
        "tests/checker/models/spherical_pendulum.toml",
        "For a conical motion $\\dot\\theta = 0$ and $\\ddot\\theta = 0$, so $\\dot\\phi^2 = \\frac{g}{l}$.\n");
    REQUIRE(wrong.equations.size() == 3);
    CHECK(wrong.equations[1].verdict == Verdict::NotJudged);
    CHECK(wrong.equations[1].role == Role::Condition);
    CHECK(wrong.equations[2].verdict == Verdict::Disagrees);
}

TEST_CASE("roles: at equilibrium x'' = 0 is a condition, and a derivation written here has its one slip found",
          "[checker][roles]") {
    const std::string text = eomgen::test::fixture("incline_spring_notes.md");
    const std::map<int, std::string> planted = eomgen::test::planted_mistakes(text);
    REQUIRE(planted.size() == 1);
    const CheckReport r = eomgen::test::check_text("tests/checker/models/incline_spring.toml", text);
    CHECK(eomgen::test::planted_found(r, planted) == 1);
    for (const EquationCheck& e : r.equations)
        if (e.equation == "\\ddot x = 0") CHECK(e.reason.find("a condition") == 0);
}

TEST_CASE("roles: an assumption on the parameters (m_1 = m_2) holds for its paragraph, and equations with the multiplier",
          "[checker][roles]") {
    const std::string text = eomgen::test::fixture("atwood_lambda_notes.md");
    const std::map<int, std::string> planted = eomgen::test::planted_mistakes(text);
    REQUIRE(planted.size() == 1);
    const CheckReport r = eomgen::test::check_text("tests/checker/models/atwood_lambda.toml", text);
    CHECK(eomgen::test::planted_found(r, planted) == 1);
    const EquationCheck& last = r.equations.back();
    INFO(eomgen::test::describe(last));
    CHECK(last.verdict == Verdict::Agrees);  // ÿ₁ = 0 with m₁ = m₂
    CHECK(eomgen::test::has_note(last, "with $m_{1} = m_{2}$, as the text assumes on line"));
    // Outside the paragraph the assumption does not hold.
    CHECK(one_verdict("tests/checker/models/atwood_lambda.toml", "$$\\ddot y_1 = 0$$\n") == Verdict::Disagrees);
}

TEST_CASE("roles: a small-angle equation with the other acceleration eliminated is the solved acceleration, expanded",
          "[checker][roles]") {
    const std::string text = eomgen::test::fixture("cart_pendulum_notes.md");
    const std::map<int, std::string> planted = eomgen::test::planted_mistakes(text);
    REQUIRE(planted.size() == 1);
    const CheckReport r = eomgen::test::check_text("tests/checker/models/cart_pendulum_free.toml", text);
    CHECK(eomgen::test::planted_found(r, planted) == 1);
    CHECK(r.count(Verdict::Agrees) == 8);
}

TEST_CASE("roles: a derivative that makes a denominator 0 is refused with a reason, not thrown from inside GiNaC",
          "[checker][roles]") {
    // Found by the sanitized fuzzer: 1/(d/dt l cos θ) with l a constant made GiNaC build 0^-1 inside map() and leak.
    const CheckReport r = eomgen::test::check_text(
        "models/pendulum_5_20.toml", "so the bob turns at $\\dot\\phi = \\sqrt{g/(\\frac{d}{dt}l\\cos\\theta)}$\n");
    REQUIRE(r.equations.size() == 1);
    INFO(eomgen::test::describe(r.equations[0]));
    CHECK(r.equations[0].verdict == Verdict::NotComparable);
}

TEST_CASE("roles: derivatives as notebooks and pasted text write them, and an equation times a velocity",
          "[checker][roles]") {
    const char* const pendulum = "tests/checker/models/plane_pendulum.toml";
    // \partial with its variable in braces, as Jupyter notebooks write it.
    CHECK(one_verdict(pendulum, "$$\\frac{d}{dt}\\frac{\\partial{L}}{\\partial{\\dot{\\theta}}} - "
                                "\\frac{\\partial{L}}{\\partial{\\theta}} = m l^2\\ddot\\theta + m g l\\sin\\theta$$\n") ==
          Verdict::Agrees);
    // dx/dt as plain text, also run into a product (`gl\sin\theta d\theta/dt`), and d^2x/dt^2.
    CHECK(one_verdict(pendulum, "$$ l d^2\\theta/dt^2 + g\\sin\\theta = 0$$\n") == Verdict::Agrees);
    CHECK(one_verdict(pendulum, "$$ m l^2 d^2\\theta/dt^2 d\\theta/dt + mgl\\sin\\theta d\\theta/dt = 0$$\n") ==
          Verdict::Agrees);
    CHECK(one_verdict(pendulum, "$$ m l^2 d^2\\theta/dt^2 d\\theta/dt + \\sin\\theta\\, mgld\\theta/dt = 0$$\n") ==
          Verdict::Agrees);
    // The time derivative of the energy: the equation of motion times θ̇ holds; with a slip it disagrees.
    CHECK(one_verdict(pendulum, "$$m l^2\\dot\\theta\\ddot\\theta + m g l \\sin\\theta\\,\\dot\\theta = 0$$\n") ==
          Verdict::Agrees);
    CHECK(one_verdict(pendulum, "$$m l^2\\dot\\theta\\ddot\\theta - m g l \\sin\\theta\\,\\dot\\theta = 0$$\n") ==
          Verdict::Disagrees);
    // A product with θ̇ that is no such multiple is not excused: θ̇ θ̈ = 0 is not the pendulum's equation.
    CHECK(one_verdict(pendulum, "$$\\dot\\theta\\ddot\\theta = 0$$\n") == Verdict::Disagrees);
}

TEST_CASE("roles: a name added alone to a potential is its constant, an Euler-Lagrange expression is one coordinate's",
          "[checker][roles]") {
    const char* const pendulum = "tests/checker/models/plane_pendulum.toml";
    CHECK(one_verdict(pendulum, "$$V(\\theta) = -m g l\\cos\\theta + f$$\n") == Verdict::Agrees);
    CHECK(one_verdict(pendulum, "$$V(\\theta) = -m g l\\sin\\theta + f$$\n") == Verdict::Disagrees);
    // Not added alone: f multiplies, and stays an unknown name.
    CHECK(one_verdict(pendulum, "$$V(\\theta) = -f g l\\cos\\theta$$\n") == Verdict::NotComparable);
    // The r equation written on the θ expression holds on the motion only with the θ equation: it disagrees.
    const char* const central = "tests/checker/models/central_force.toml";
    CHECK(one_verdict(central, "$$\\frac{\\partial L}{\\partial \\theta} - \\frac{d}{dt}\\frac{\\partial L}{\\partial "
                               "\\dot\\theta} = m r\\dot\\theta^2 - \\frac{k}{r^2} - m\\ddot r$$\n") == Verdict::Disagrees);
    CHECK(one_verdict(central, "$$\\frac{\\partial L}{\\partial r} - \\frac{d}{dt}\\frac{\\partial L}{\\partial \\dot r} = "
                               "m r\\dot\\theta^2 - \\frac{k}{r^2} - m\\ddot r$$\n") == Verdict::Agrees);
    CHECK(one_verdict(central, "$$\\frac{d}{dt}\\frac{\\partial L}{\\partial \\dot\\theta} = "
                               "2 m r\\dot r\\dot\\theta + m r^2\\ddot\\theta$$\n") == Verdict::Agrees);
}

TEST_CASE("roles: notes on the elastic pendulum, checked as written (the energies, an equilibrium set up by a chain)",
          "[checker][roles]") {
    // Written here in the style of course notes, before the checker read it: its first run gave four false alarms
    // ("the energies are T = …, U = …" held to the total energy; ṙ = θ̇ and r̈ = θ̈ in `\dot r = \dot\theta = 0`
    // judged as equations) and left the equilibrium value r_eq not comparable.
    const std::string text = eomgen::test::fixture("elastic_pendulum_notes.md");
    const std::map<int, std::string> planted = eomgen::test::planted_mistakes(text);
    REQUIRE(planted.size() == 1);
    const char* const model = "tests/checker/models/elastic_pendulum.toml";
    const CheckReport r = eomgen::test::check_text(model, text);
    CHECK(eomgen::test::planted_found(r, planted) == 1);
    int conditions = 0;
    for (const EquationCheck& e : r.equations) {
        INFO(eomgen::test::describe(e));
        if (e.where.line == 10) CHECK(e.verdict == Verdict::Agrees);  // T and U
        if (e.where.line == 23) {
            CHECK(e.verdict == Verdict::NotJudged);
            CHECK(e.role == Role::Condition);
            CHECK(e.reason.rfind("a condition", 0) == 0);
            ++conditions;
        }
        if (e.where.line == 24) {
            CHECK(e.verdict == Verdict::Agrees);
            CHECK(e.reason.find("the equations of motion hold there") != std::string::npos);
        }
    }
    CHECK(conditions == 5);
    // `r = r_{eq} + \rho` moves r: the small-oscillation equations in ρ and θ are expanded about r = r_eq (the value
    // of line 24), where they agree; a wrong sign in the ρ equation disagrees.
    int expanded = 0;
    for (const EquationCheck& e : r.equations) {
        if (e.where.line == 28) {
            CHECK(e.verdict == Verdict::NotJudged);
            CHECK(e.role == Role::Definition);
            CHECK(e.reason.find("as the text gives it on line 24") != std::string::npos);
        }
        if (e.where.line == 29) {
            INFO(eomgen::test::describe(e));
            CHECK(e.verdict == Verdict::Agrees);
            CHECK(e.compared_with.find("expanded about $r = r_{eq}, \\theta = 0$") != std::string::npos);
            ++expanded;
        }
    }
    CHECK(expanded == 2);
    {
        std::string sign = text;
        const std::size_t rho = sign.find("m\\ddot\\rho \\approx -k\\rho");
        REQUIRE(rho != std::string::npos);
        sign.replace(rho, 25, "m\\ddot\\rho \\approx k\\rho");
        int slips = 0;
        for (const EquationCheck& e : eomgen::test::check_text(model, sign).equations)
            if (e.where.line == 29 && e.verdict == Verdict::Disagrees) ++slips;
        CHECK(slips == 1);
    }
    // A wrong equilibrium value disagrees, with the value the equation of motion needs.
    std::string wrong = text;
    const std::size_t at = wrong.find("r_{eq} = l_0 + \\frac{mg}{k}");
    REQUIRE(at != std::string::npos);
    wrong.replace(at, 27, "r_{eq} = l_0 - \\frac{mg}{k}");
    const CheckReport w = eomgen::test::check_text(model, wrong);
    bool found = false;
    for (const EquationCheck& e : w.equations)
        if (e.where.line == 24) {
            INFO(eomgen::test::describe(e));
            CHECK(e.verdict == Verdict::Disagrees);
            CHECK(e.corrected == "r_{eq} = l_0 + \\frac{m g}{k}");
            found = true;
        }
    CHECK(found);
    // Only a chain that ends in a value sets its velocities: ṙ = θ̇ alone is not read as that condition.
    const CheckReport alone = eomgen::test::check_text(model, "$$\\dot r = \\dot\\theta$$\n");
    REQUIRE(alone.equations.size() == 1);
    CHECK(alone.equations[0].reason.find("its chain ends with") == std::string::npos);
}

TEST_CASE("roles: notes on the bead on a spinning hoop, checked as written (equilibria set by 'setting', cos a ~ 1)",
          "[checker][roles]") {
    // Written here; its first run judged θ̈ = 0 after "Setting" as an equation of motion (a false alarm), and left
    // `\cos\alpha \approx 1` and the off-bottom equilibrium `\cos\alpha_0 = g/(\omega^2 R)` not comparable.
    const std::string text = eomgen::test::fixture("bead_hoop_notes.md");
    const char* const model = "examples/bead_on_hoop.toml";
    const CheckReport r = eomgen::test::check_text(model, text);
    CHECK(r.count(Verdict::Disagrees) == 0);
    for (const EquationCheck& e : r.equations) {
        INFO(eomgen::test::describe(e));
        if (e.equation == "\\ddot\\alpha = 0") CHECK(e.reason.rfind("a condition", 0) == 0);
        if (e.equation == "\\cos\\alpha \\approx 1") CHECK(e.verdict == Verdict::Agrees);
        if (e.equation == "\\cos\\alpha_0 = \\frac{g}{\\omega^2 R}") CHECK(e.verdict == Verdict::Agrees);
    }
    // The equilibrium with a slip (g R/ω² for g/(ω² R)) disagrees.
    std::string wrong = text;
    const std::size_t at = wrong.find("\\cos\\alpha_0 = \\frac{g}{\\omega^2 R}");
    REQUIRE(at != std::string::npos);
    wrong.replace(at, std::strlen("\\cos\\alpha_0 = \\frac{g}{\\omega^2 R}"), "\\cos\\alpha_0 = \\frac{g R}{\\omega^2}");
    const CheckReport w = eomgen::test::check_text(model, wrong);
    CHECK(w.count(Verdict::Disagrees) == 1);
    CHECK(one_verdict(model, "for small $\\alpha$, $\\cos\\alpha \\approx 0$\n") != Verdict::Agrees);
    // "Setting" right before an acceleration sets it; "putting (1) into (2):" before one derives it.
    CHECK(one_verdict(model, "Setting $\\ddot\\alpha = 0$ gives the rest points.\n") == Verdict::NotJudged);
    CHECK(one_verdict(model, "Putting (1) into (2): $\\ddot\\alpha = 0$.\n") == Verdict::Disagrees);
}

TEST_CASE("roles: a link with a plus-minus sign is two equations, each judged", "[checker][roles]") {
    const char* const hoop = "examples/bead_on_hoop.toml";
    // Both signs are equilibria of the spinning hoop, which the sentence names.
    const CheckReport both = eomgen::test::check_text(
        hoop, "The off-bottom equilibrium positions are $\\alpha_0 = \\pm\\arccos\\frac{g}{\\omega^2 R}$.\n");
    REQUIRE(both.equations.size() == 1);
    INFO(eomgen::test::describe(both.equations[0]));
    CHECK(both.equations[0].verdict == Verdict::Agrees);
    CHECK(both.equations[0].reason.rfind("with either sign of ±", 0) == 0);
    // arcsin for arccos: neither sign is an equilibrium.
    const CheckReport wrong = eomgen::test::check_text(
        hoop, "The off-bottom equilibrium positions are $\\alpha_0 = \\pm\\arcsin\\frac{g}{\\omega^2 R}$.\n");
    REQUIRE(wrong.equations.size() == 1);
    CHECK(wrong.equations[0].verdict == Verdict::Disagrees);
    // The same with the Unicode sign; and a ± the reading cannot resolve stays not comparable, without looping.
    CHECK(one_verdict(hoop, "The equilibria are $\\alpha_0 = ±\\arccos\\frac{g}{\\omega^2 R}$.\n") == Verdict::Agrees);
    CHECK(one_verdict(hoop, "$q = \\pm w$\n") == Verdict::NotComparable);
}

TEST_CASE("roles: the Euler-Lagrange equation for a generic coordinate is read for each of the model's",
          "[checker][roles]") {
    const char* const spherical = "tests/checker/models/spherical_pendulum.toml";
    for (const char* q : {"q", "q_i", "p"}) {
        const std::string Q = q;
        const std::string qd = Q.size() > 1 ? "\\dot{q}_i" : "\\dot{" + Q + "}";
        const CheckReport r = eomgen::test::check_text(
            spherical, "$$\\frac{d}{dt}\\frac{\\partial L}{\\partial " + qd + "} - \\frac{\\partial L}{\\partial " + Q +
                           "} = 0$$\n");
        REQUIRE(r.equations.size() == 1);
        INFO(eomgen::test::describe(r.equations[0]));
        CHECK(r.equations[0].verdict == Verdict::Agrees);
        CHECK(r.equations[0].compared_with == "the Euler–Lagrange equation for each coordinate");
    }
    // A sign slip is one for every coordinate: it disagrees, naming the coordinate it was read as.
    const CheckReport wrong = eomgen::test::check_text(
        spherical, "$$\\frac{d}{dt}\\frac{\\partial L}{\\partial \\dot{q}} + \\frac{\\partial L}{\\partial q} = 0$$\n");
    REQUIRE(wrong.equations.size() == 1);
    CHECK(wrong.equations[0].verdict == Verdict::Disagrees);
    CHECK(eomgen::test::has_note(wrong.equations[0], "the text's $q$ is a generic coordinate: read as $\\theta$"));
    // A derivative by a name that is no velocity's coordinate is not a generic coordinate.
    CHECK(one_verdict(spherical, "$$\\frac{\\partial L}{\\partial a} = 0$$\n") == Verdict::NotComparable);
}

TEST_CASE("roles: the text's sign of the multiplier, once taken, holds for the rest of its section", "[checker][roles]") {
    const char* const atwood = "tests/checker/models/atwood_lambda.toml";
    // m₁ÿ₁ = m₁g + λ takes eomgen's sign (M q̈ = f + Aᵀλ): λ = +2m₁m₂g/(m₁+m₂) then holds only with the other one.
    const std::string eomgens = "$$m_1 \\ddot y_1 = m_1 g + \\lambda$$\n\n";
    const CheckReport wrong = eomgen::test::check_text(
        atwood, eomgens + "$$\\lambda = \\frac{2 m_1 m_2}{m_1 + m_2} g$$\n");
    for (const EquationCheck& e : wrong.equations) INFO(eomgen::test::describe(e));
    REQUIRE(wrong.equations.size() == 2);
    CHECK(wrong.equations[0].verdict == Verdict::Agrees);
    CHECK(wrong.equations[1].verdict == Verdict::Disagrees);
    CHECK(wrong.equations[1].reason.find("the one the text takes on line 1") != std::string::npos);
    CHECK(wrong.equations[1].corrected == "\\lambda = -2 \\frac{m_{1} m_{2} g}{m_{1} + m_{2}}");
    // The same value after the opposite convention (m₁ÿ₁ = m₁g − λ) agrees; alone, with no convention yet, too.
    const CheckReport other = eomgen::test::check_text(
        atwood, "$$m_1 \\ddot y_1 = m_1 g - \\lambda$$\n\n$$\\lambda = \\frac{2 m_1 m_2}{m_1 + m_2} g$$\n");
    REQUIRE(other.equations.size() == 2);
    CHECK(other.equations[1].verdict == Verdict::Agrees);
    CHECK(one_verdict(atwood, "$$\\lambda = \\frac{2 m_1 m_2}{m_1 + m_2} g$$\n") == Verdict::Agrees);
    // Another section may take the other sign.
    const CheckReport sections = eomgen::test::check_text(
        atwood, "# One\n\n" + eomgens + "# Two\n\n$$\\lambda = \\frac{2 m_1 m_2}{m_1 + m_2} g$$\n");
    REQUIRE(sections.equations.size() == 2);
    CHECK(sections.equations[1].verdict == Verdict::Agrees);
}

TEST_CASE("roles: the script L is the Lagrangian", "[checker][roles]") {
    CHECK(one_verdict(kPendulum, "$$\\mathscr{L} = \\frac12 m l^2 \\dot\\theta^2 + m g l \\cos\\theta$$\n") ==
          Verdict::Agrees);
    CHECK(one_verdict(kPendulum, "$$\\mathscr{L} = \\frac12 m l^2 \\dot\\theta^2 - m g l \\cos\\theta$$\n") ==
          Verdict::Disagrees);
}

TEST_CASE("roles: primes for time derivatives, in a text that writes no dots, and after a bracket", "[checker][roles]") {
    // A text with no \dot anywhere means θ'' as θ̈ ...
    CHECK(one_verdict(kPendulum, "$$m l^2 \\theta'' = -m g l \\sin\\theta$$\n") == Verdict::Agrees);
    CHECK(one_verdict(kPendulum, "$$m l^2 \\theta'' = m g l \\sin\\theta$$\n") == Verdict::Disagrees);
    CHECK(one_verdict(kPendulum, "$$\\left(m l^2 \\theta'\\right)' = -m g l\\sin\\theta$$\n") == Verdict::Agrees);
    // ... one that writes dots uses primes for other quantities (another frame's angle, an integration variable):
    // θ' stays a name of its own there; a prime after a bracket is its time derivative in either.
    const CheckReport dots = eomgen::test::check_text(
        kPendulum, "$$(m l^2 \\dot\\theta)' = -m g l\\sin\\theta$$\n\n$$m l^2 \\theta'' = -m g l \\sin\\theta$$\n");
    REQUIRE(dots.equations.size() == 2);
    CHECK(dots.equations[0].verdict == Verdict::Agrees);
    CHECK(dots.equations[1].verdict == Verdict::NotComparable);
}

TEST_CASE("roles: an equation written with the multiplier is corrected with its constraint force", "[checker][roles]") {
    const CheckReport r = eomgen::test::check_text("tests/checker/models/atwood_lambda.toml", "$$m_1 \\ddot y_1 = \\lambda$$\n");
    REQUIRE(r.equations.size() == 1);
    INFO(eomgen::test::describe(r.equations[0]));
    CHECK(r.equations[0].verdict == Verdict::Disagrees);
    CHECK(r.equations[0].compared_with == "the Euler–Lagrange equation for $y_{1}$ with the constraint forces");
    REQUIRE(r.equations[0].wrong_terms.size() == 1);  // only m₁g is missing, not λ extra
    CHECK(r.equations[0].corrected == "-\\lambda - m_{1} g + m_{1} \\ddot{y_{1}} = 0");
}

TEST_CASE("roles: an instant and a coordinate's initial value are given, not claimed", "[checker][roles]") {
    // The rotating-frame blog of the corpus: "from t = 0 to t = 20", "at t = t_c", "x_0 = 1".
    const char* const model = "tests/checker/models/plane_pendulum.toml";
    const auto role_of = [&](const std::string& math) {
        const CheckReport r = eomgen::test::check_text(model, "Plotted with $" + math + "$.\n");
        REQUIRE(r.equations.size() == 1);
        INFO(eomgen::test::describe(r.equations[0]));
        return std::make_pair(r.equations[0].verdict, r.equations[0].role);
    };
    for (const char* instant : {"t = 0", "t = 20", "t = t_c", "t = \\frac{\\pi}{2}"})
        CHECK(role_of(instant) == std::make_pair(Verdict::NotJudged, Role::Condition));
    for (const char* start : {"\\theta_0 = 1", "\\theta_{0} = \\frac{\\pi}{3}"})
        CHECK(role_of(start) == std::make_pair(Verdict::NotJudged, Role::ChosenValue));
    // A time the text works out from the parameters is a claim, compared as before (not given).
    CHECK(role_of("t = 2\\pi\\sqrt{l/g}").first != Verdict::NotJudged);
    CHECK(role_of("\\theta_0 = g").second != Role::ChosenValue);  // a definition of the text's, as before
}

TEST_CASE("roles: T split into named parts, one never given a value, names them", "[checker][roles]") {
    // The cart pushed by a force (corpus): "T = T_C + T_P", then only T_C = ½ M ẋ² in math.
    const char* const model = "tests/checker/models/cart_pendulum_free.toml";
    const CheckReport r = eomgen::test::check_text(model, "$$T = T_C + T_P$$\n\nThe cart's part is $T_C = \\frac{1}{2} M \\dot{x}^2$.\n");
    REQUIRE(!r.equations.empty());
    INFO(eomgen::test::describe(r.equations[0]));
    CHECK(r.equations[0].verdict == Verdict::NotJudged);
    CHECK(r.equations[0].role == Role::Definition);
    // With both parts given, the sum is compared with T as before.
    const CheckReport both = eomgen::test::check_text(
        model, "$$T = T_C + T_P$$\n\n$T_C = \\frac{1}{2} M \\dot{x}^2$ and $T_P = \\frac{1}{2} m \\dot{x}^2 + m l \\dot{x}\\dot{\\theta}"
               "\\cos\\theta + \\frac{1}{2} m l^2 \\dot{\\theta}^2$.\n");
    REQUIRE(!both.equations.empty());
    INFO(eomgen::test::describe(both.equations[0]));
    CHECK(both.equations[0].verdict == Verdict::Agrees);
}

TEST_CASE("roles: one name against a number in an inequality is a condition, not a claim", "[checker][roles]") {
    // The sign of a rate, the range of an angle, a convention for g: not judged. An inequality between expressions
    // is still not compared (not comparable), as before.
    const std::string text = "with $g > 0$, for $0 \\le \\theta < \\pi$ and $\\gamma < 0$ clockwise;\n"
                             "\n"
                             "stable while $\\frac{g}{l} > \\dot\\theta^2$.\n";
    const CheckReport r = eomgen::test::check_text(kPendulum, text);
    std::string all;
    for (const EquationCheck& e : r.equations) all += eomgen::test::describe(e) + "\n";
    INFO(all);
    const auto first = on_line(r, 1);
    REQUIRE(first.size() == 4);
    for (const EquationCheck* e : first) {
        CHECK(e->verdict == Verdict::NotJudged);
        CHECK(e->role == Role::Condition);
        CHECK(e->reason.find("a condition: the range or sign of") == 0);
    }
    const auto last = on_line(r, 3);
    REQUIRE(last.size() == 1);
    CHECK(last[0]->verdict == Verdict::NotComparable);
}

TEST_CASE("roles: the conditions of a steady motion hold for the display the paragraph runs on into, past a blank "
          "line, and an initial state does not",
          "[checker][roles]") {
    // A top written as a student writes it (tests/checker/fixtures/heavy_top_steady_notes.md): ω₃ named inside a
    // chain, "For steady precession, θ̇ = θ̈ = 0, and dividing by sin θ," then the display alone.
    const std::string text = eomgen::test::fixture("heavy_top_steady_notes.md");
    const CheckReport r = eomgen::test::check_text("models/heavy_symmetric_top.toml", text);
    CHECK(eomgen::test::planted_found(r, eomgen::test::planted_mistakes(text)) == 2);
    const std::vector<const EquationCheck*> steady = on_line(r, 24);
    REQUIRE(steady.size() == 1);
    INFO(eomgen::test::describe(*steady[0]));
    CHECK(steady[0]->verdict == Verdict::Agrees);
    CHECK(steady[0]->compared_with.find("on the motion the text considers") != std::string::npos);
    CHECK(eomgen::test::has_note(*steady[0], "the condition the text states on line 22"));
    // "Initially θ̇ = 0, and since the energy is conserved," then E in general: compared as written, not at θ̇ = 0
    // (and its slip found).
    for (const EquationCheck* e : on_line(r, 28)) {
        INFO(eomgen::test::describe(*e));
        CHECK_FALSE(eomgen::test::has_note(*e, "line 26"));
    }
    // A fast top's rate is an approximation in a limit the checker does not read: not a wrong energy.
    const std::vector<const EquationCheck*> fast = on_line(r, 30);
    REQUIRE(fast.size() == 1);
    INFO(eomgen::test::describe(*fast[0]));
    CHECK(fast[0]->verdict == Verdict::NotComparable);
    CHECK(fast[0]->reason.find("an approximation that is not an expansion") != std::string::npos);
    CHECK(r.count(Verdict::Disagrees) == 2);
    CHECK(r.count(Verdict::NotComparable) == 1);
}

TEST_CASE("roles: equilibria under a heading, a rate introduced with let, and the oscillations about an angle "
          "given by its cosine",
          "[checker][roles]") {
    // tests/checker/fixtures/bead_hoop_equilibria_notes.md against the example's bead on a spinning hoop.
    const std::string text = eomgen::test::fixture("bead_hoop_equilibria_notes.md");
    const CheckReport r = eomgen::test::check_text("examples/bead_on_hoop.toml", text);
    CHECK(eomgen::test::planted_found(r, eomgen::test::planted_mistakes(text)) == 1);
    const auto only = [&](int line, std::size_t k = 0) {
        const std::vector<const EquationCheck*> v = on_line(r, line);
        REQUIRE(v.size() > k);
        INFO(eomgen::test::describe(*v[k]));
        return *v[k];
    };
    // "Equilibria: $\ddot\alpha = 0$ gives …": a condition, not free fall; the two angles hold there.
    CHECK(only(20, 0).role == Role::Condition);
    CHECK(only(20, 1).verdict == Verdict::Agrees);
    CHECK(only(20, 2).verdict == Verdict::Agrees);
    // "Let $\omega_c^2 = g/R$": the text's name for the critical rate, not a normal frequency of the model.
    CHECK(only(22, 0).role == Role::Definition);
    // α₀ is the angle whose cosine the text gave (line 20): the oscillations in η = α − α₀ agree to first order, and
    // so does Ω = ω sin α₀ = ω √(1 − ω_c⁴/ω⁴).
    const EquationCheck eta = only(24);
    INFO(eomgen::test::describe(eta));
    CHECK(eta.verdict == Verdict::Agrees);
    CHECK(eta.reason == "agrees to first order in $\\eta$");
    CHECK(only(26, 1).verdict == Verdict::Agrees);
    CHECK(r.count(Verdict::Disagrees) == 1);
}

TEST_CASE("roles: an assumption of the problem's setting holds to the end of its section, in every comparison",
          "[checker][roles]") {
    // "Take $m_1 = m_2 = m$ and $l_1 = l_2 = l$" (tests/checker/fixtures/double_pendulum_equal_notes.md): m and l
    // stand for the model's m₂ and l₂ to the end of the section, and m₁ = m₂, l₁ = l₂ hold there in the energies, the
    // expansions (with `+ \text{const}`), the matrices and the secular equation alike.
    const std::string text = eomgen::test::fixture("double_pendulum_equal_notes.md");
    const CheckReport r = eomgen::test::check_text("examples/double_pendulum.toml", text);
    CHECK(eomgen::test::planted_found(r, eomgen::test::planted_mistakes(text)) == 1);
    for (int line : {7, 11, 15, 19, 23, 27, 31})  // the positions too: `x_2 = x_1 + l\sin\theta_2` matches the file's point
        for (const EquationCheck* e : on_line(r, line)) {
            INFO(eomgen::test::describe(*e));
            CHECK(e->verdict == Verdict::Agrees);
        }
    CHECK(on_line(r, 7).size() == 4);   // x₁, y₁, x₂, y₂
    CHECK(on_line(r, 23).size() == 2);  // M and K
    CHECK(on_line(r, 31).front()->reason.find("with either sign of ±: a normal frequency") == 0);
    CHECK(r.count(Verdict::Disagrees) == 1);
    // "with $m_1 = m_2 = m$" is a case the text looks at: its paragraph only (the corpus's double Atwood machine).
}
