/** @file exam_readings.cpp  Readings the corpus of real derivations taught the checker (docs/checker.md): an
 * evaluation bar, a subscript written in both cases, `\neq` as a claim, and a row's own letter before the label
 * of the sentence leading into its display. Each against the plane pendulum (models/pendulum.toml: φ; m, l, g). */
#include "checked_text.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace {

using eomgen::checker::CheckReport;
using eomgen::checker::EquationCheck;
using eomgen::checker::Verdict;

const char* const kModel = "models/pendulum.toml";

/// The verdicts on `line` of the text, described for INFO().
std::vector<const EquationCheck*> on_line(const CheckReport& r, int line) {
    std::vector<const EquationCheck*> out;
    for (const EquationCheck& e : r.equations)
        if (e.where.line == line) out.push_back(&e);
    return out;
}

std::string described(const CheckReport& r) {
    std::string s;
    for (const EquationCheck& e : r.equations) s += eomgen::test::describe(e) + "\n";
    return s;
}

}  // namespace

TEST_CASE("readings: an evaluation bar puts its point in, or leaves a frame's rate as it is", "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text(kModel, R"(# Pendulum

$$ V = -m g l \cos\phi $$

At the bottom the force vanishes:

$$ \left.\frac{\partial V}{\partial \phi}\right|_{\phi=0} = 0 $$

and away from it, where a slip is made:

$$ \left.\frac{\partial V}{\partial \phi}\right|_{\phi=\pi/2} = 0 $$

$$ \left.\frac{d}{dt}\left(m l^2 \dot{\phi}\right)\right|_{\text{inertial}} = -m g l \sin\phi $$

$$ \left.\frac{\partial V}{\partial \phi}\right|_{\text{eq}} = 0 $$
)");
    INFO(described(r));
    const auto at_zero = on_line(r, 7), at_right_angle = on_line(r, 11), inertial = on_line(r, 13),
               unread = on_line(r, 15);
    REQUIRE(at_zero.size() == 1);
    CHECK(at_zero[0]->verdict == Verdict::Agrees);
    REQUIRE(at_right_angle.size() == 1);
    CHECK(at_right_angle[0]->verdict == Verdict::Disagrees);  // m g l at φ = π/2, not 0
    REQUIRE(inertial.size() == 1);
    CHECK(inertial[0]->verdict == Verdict::Agrees);  // the φ equation, the frame a label
    REQUIRE(unread.size() == 1);
    CHECK(unread[0]->verdict == Verdict::NotComparable);
    CHECK(unread[0]->reason.find("evaluation bar") != std::string::npos);
}

TEST_CASE("readings: a name written with its subscript in both cases is one name, with a note", "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text(kModel, R"(# Pendulum

The moment of inertia about the pivot is $I_{P} = m l^2$, and

$$ L = \frac{1}{2} I_{p} \dot{\phi}^2 + m g l \cos\phi $$

$$ I_{p} \ddot{\phi} = -m g l \sin\phi $$

$$ I_{p} \ddot{\phi} = -m g \sin\phi $$
)");
    INFO(described(r));
    const auto lagrangian = on_line(r, 5), motion = on_line(r, 7), slip = on_line(r, 9);
    REQUIRE(lagrangian.size() == 1);
    CHECK(lagrangian[0]->verdict == Verdict::Agrees);
    REQUIRE(motion.size() == 1);
    CHECK(motion[0]->verdict == Verdict::Agrees);
    REQUIRE(slip.size() == 1);
    CHECK(slip[0]->verdict == Verdict::Disagrees);
    // The note is on the row where the second spelling first appears.
    CHECK(eomgen::test::has_note(*lagrangian[0], "the same name but for the case of its subscript"));
}

TEST_CASE("readings: a \\neq b claims that the sides differ, and a name against a number is a condition",
          "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text(kModel, R"(# Pendulum

$$ \frac{\partial L}{\partial \phi} \neq 0 $$

$$ \frac{\partial L}{\partial \dot{\phi}} \neq m l^2 \dot{\phi} $$

For $\phi \neq 0$ the bob is off the vertical.
)");
    INFO(described(r));
    const auto differs = on_line(r, 3), same = on_line(r, 5), condition = on_line(r, 7);
    REQUIRE(differs.size() == 1);
    CHECK(differs[0]->verdict == Verdict::Agrees);
    REQUIRE(same.size() == 1);
    CHECK(same[0]->verdict == Verdict::Disagrees);
    REQUIRE(condition.size() == 1);
    CHECK(condition[0]->verdict == Verdict::NotJudged);
}

TEST_CASE("readings: a row that begins with its own letter is labelled by it, not by the sentence before",
          "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text(kModel, R"(# Pendulum

About the pivot the kinetic energy is purely rotational:

$$
  L(\phi, \dot{\phi}) = \frac{1}{2} m l^2 \dot{\phi}^2 + m g l \cos\phi, \\
  p_\phi = \frac{\partial L}{\partial \dot{\phi}} = m l^2 \dot{\phi}
$$
)");
    INFO(described(r));
    for (const int line : {6, 7}) {
        const auto rows = on_line(r, line);
        REQUIRE(!rows.empty());
        for (const EquationCheck* e : rows) CHECK(e->verdict == Verdict::Agrees);
    }
    // A Lagrangian alone under the energy it is built from; another quantity's letter under a label still answers
    // to it.
    const CheckReport one = eomgen::test::check_text(kModel, R"(# Pendulum

The kinetic energy is purely rotational:

$$ L = \frac{1}{2} m l^2 \dot{\phi}^2 + m g l \cos\phi $$

The kinetic energy is

$$ V = -m g l \cos\phi $$
)");
    INFO(described(one));
    const auto lagrangian = on_line(one, 5), potential = on_line(one, 9);
    REQUIRE(lagrangian.size() == 1);
    CHECK(lagrangian[0]->verdict == Verdict::Agrees);
    REQUIRE(potential.size() == 1);
    CHECK(potential[0]->verdict == Verdict::Disagrees);
    CHECK(potential[0]->compared_with.find("its label") != std::string::npos);
}

TEST_CASE("readings: a bracket left open inside a brace group closes with the group, and the chain goes on after it",
          "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text(kModel, R"(# Pendulum

$$ \ddot{\phi} = \frac{-m g l \sin\phi}{(m l^2} = -\frac{g}{l}\sin\phi $$

$$ \ddot{\phi} = \frac{-m g l \sin\phi}{(m l} $$
)");
    INFO(described(r));
    const auto chain = on_line(r, 3), slip = on_line(r, 5);
    REQUIRE(chain.size() == 2);  // split at both '=' (before, the open '(' hid the second)
    for (const EquationCheck* e : chain) CHECK(e->verdict == Verdict::Agrees);
    CHECK(eomgen::test::has_note(*chain[0], "that is not closed as closed at the end of its group"));
    REQUIRE(slip.size() == 1);
    CHECK(slip[0]->verdict == Verdict::Disagrees);
}

TEST_CASE("readings: \\text{const.} with its full stop is the text's constant", "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text(kModel, R"(# Pendulum

$$ \frac{1}{2} m l^2 \dot{\phi}^2 - m g l \cos\phi = \text{const.} $$
)");
    INFO(described(r));
    const auto energy = on_line(r, 3);
    REQUIRE(energy.size() == 1);
    CHECK(energy[0]->verdict == Verdict::Agrees);
}

TEST_CASE("readings: a bracket's ')' typed after the \\right that follows it closes the bracket", "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text(kModel, R"(# Pendulum

$$ m l^2 \ddot{\phi} = l\left( -m g (\sin\phi \right)) $$

$$ m l^2 \ddot{\phi} = l\left( -m (\sin\phi \right)) $$

$$ m l^2 \ddot{\phi} = l\left( -m g (\sin\phi \right) $$
)");
    INFO(described(r));
    const auto right = on_line(r, 3), slip = on_line(r, 5), unclosed = on_line(r, 7);
    REQUIRE(right.size() == 1);
    CHECK(right[0]->verdict == Verdict::Agrees);
    CHECK(eomgen::test::has_note(*right[0], "typed after \\right"));
    REQUIRE(slip.size() == 1);
    CHECK(slip[0]->verdict == Verdict::Disagrees);
    REQUIRE(unclosed.size() == 1);  // no ')' after the \right: still not read
    CHECK(unclosed[0]->verdict == Verdict::NotComparable);
}

TEST_CASE("readings: d/dt of a state vector, entry by entry, the entries with accelerations on the motion",
          "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text(kModel, R"(# Pendulum

$$ \frac{d}{dt}\begin{pmatrix}\phi\\ \dot{\phi}\end{pmatrix} = \begin{pmatrix}\dot{\phi}\\ -\frac{g}{l}\sin\phi\end{pmatrix} $$

$$ \frac{d}{dt}\begin{pmatrix}\phi\\ \dot{\phi}\end{pmatrix} = \begin{pmatrix}\dot{\phi}\\ -\frac{g}{l}\cos\phi\end{pmatrix} $$

$$ \frac{d}{dt}\begin{pmatrix}\phi\\ \dot{\phi}\end{pmatrix} = \begin{pmatrix}\phi\\ -\frac{g}{l}\sin\phi\end{pmatrix} $$
)");
    INFO(described(r));
    const auto right = on_line(r, 3), slip = on_line(r, 5), first_row = on_line(r, 7);
    REQUIRE(right.size() == 1);
    CHECK(right[0]->verdict == Verdict::Agrees);
    CHECK(right[0]->compared_with.find("equations of motion") != std::string::npos);
    REQUIRE(slip.size() == 1);
    CHECK(slip[0]->verdict == Verdict::Disagrees);
    REQUIRE(!slip[0]->wrong_terms.empty());
    CHECK(slip[0]->wrong_terms.front().find("row 2") != std::string::npos);
    REQUIRE(first_row.size() == 1);  // the derivative of φ is φ̇, not φ
    CHECK(first_row[0]->verdict == Verdict::Disagrees);
    REQUIRE(!first_row[0]->wrong_terms.empty());
    CHECK(first_row[0]->wrong_terms.front().find("row 1") != std::string::npos);
}

TEST_CASE("readings: a limit the prose takes (as c -> 0) is the model's equation at that value, for the display after it",
          "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text("models/damped_pendulum.toml", R"(# Damped pendulum

$$ m l^2 \ddot\phi + c \dot\phi + m g l \sin\phi = 0 $$

As $c \to 0$ it becomes the undamped pendulum,

$$ m l^2 \ddot\phi + m g l \sin\phi = 0 $$

and in the limit $c \rightarrow 0$ a slip:

$$ m l^2 \ddot\phi + m g \sin\phi = 0 $$

Without a limit the damping is missing:

$$ m l^2 \ddot\phi + m g l \sin\phi = 0 $$

As $m \to 0$ the mass matrix vanishes, which is no value to put in:

$$ c \dot\phi = 0 $$
)");
    INFO(described(r));
    const auto damped = on_line(r, 3), limit = on_line(r, 7), slip = on_line(r, 11), after = on_line(r, 15),
               degenerate = on_line(r, 19);
    REQUIRE(damped.size() == 1);
    CHECK(damped[0]->verdict == Verdict::Agrees);
    REQUIRE(limit.size() == 1);
    CHECK(limit[0]->verdict == Verdict::Agrees);
    CHECK(eomgen::test::has_note(*limit[0], "in the limit $c \\to 0$ the text takes on line 5"));
    REQUIRE(slip.size() == 1);
    CHECK(slip[0]->verdict == Verdict::Disagrees);
    CHECK(slip[0]->corrected.find("c") == std::string::npos);  // corrected in the limit: no damping term
    REQUIRE(after.size() == 1);  // the limit holds for the display its sentence leads into, not beyond
    CHECK(after[0]->verdict == Verdict::Disagrees);
    REQUIRE(degenerate.size() == 1);
    CHECK(degenerate[0]->verdict != Verdict::Agrees);
    CHECK(!eomgen::test::has_note(*degenerate[0], "in the limit"));
}

TEST_CASE("readings: \\lim_{x \\to a} f is f at a, or its series' constant term there", "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text(kModel, R"(# Pendulum

$$ \lim_{\phi \to 0} \frac{m g l \sin\phi}{\phi} = m g l $$

$$ \lim_{\phi \to 0} \frac{\partial V}{\partial \phi} = 0 $$

$$ m l^2 \ddot\phi = - \lim_{\phi \to \pi/2} \frac{\partial V}{\partial \phi} $$

$$ \lim_{\phi \to 0} \frac{1}{\phi} = 0 $$

$$ \lim_{\phi \to \infty} \phi = 0 $$
)");
    INFO(described(r));
    const auto quotient = on_line(r, 3), derivative = on_line(r, 5), at_point = on_line(r, 7), pole = on_line(r, 9),
               infinity = on_line(r, 11);
    REQUIRE(quotient.size() == 1);
    CHECK(quotient[0]->verdict == Verdict::Agrees);  // 0/0: the series' constant term
    REQUIRE(derivative.size() == 1);
    CHECK(derivative[0]->verdict == Verdict::Agrees);  // the derivative taken first, then φ = 0
    REQUIRE(at_point.size() == 1);  // -m g l: not the equation of motion, which has sin φ
    CHECK(at_point[0]->verdict != Verdict::Agrees);
    REQUIRE(pole.size() == 1);
    CHECK(pole[0]->verdict == Verdict::NotComparable);
    CHECK(pole[0]->reason.find("not finite") != std::string::npos);
    REQUIRE(infinity.size() == 1);
    CHECK(infinity[0]->verdict == Verdict::NotComparable);
}

TEST_CASE("readings: (i) \\quad and (2)\\qquad before a row are its label, not a factor", "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text(kModel, R"(# Pendulum

$$ (i) \quad m l^2 \ddot\phi + m g l \sin\phi = 0 $$

$$ (2)\qquad m l^2 \ddot\phi = - m g l \sin\phi $$

$$ (iii) \quad m l^2 \ddot\phi + m g \sin\phi = 0 $$
)");
    INFO(described(r));
    const auto first = on_line(r, 3), second = on_line(r, 5), slip = on_line(r, 7);
    REQUIRE(first.size() == 1);
    CHECK(first[0]->verdict == Verdict::Agrees);
    REQUIRE(second.size() == 1);
    CHECK(second[0]->verdict == Verdict::Agrees);
    REQUIRE(slip.size() == 1);
    CHECK(slip[0]->verdict == Verdict::Disagrees);
    CHECK(slip[0]->equation.find("iii") == std::string::npos);
}

TEST_CASE("readings: a limit after its formula, the sentence ended, is not put into the next one", "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text("models/damped_pendulum.toml", R"(# Damped pendulum

$$ m l^2 \ddot\phi + c \dot\phi + m g l \sin\phi = 0 $$

which is the undamped pendulum as $c \to 0$. The damping stays in what follows:

$$ m l^2 \ddot\phi + m g l \sin\phi = 0 $$
)");
    INFO(described(r));
    const auto next = on_line(r, 7);
    REQUIRE(next.size() == 1);
    CHECK(next[0]->verdict == Verdict::Disagrees);
    CHECK(!eomgen::test::has_note(*next[0], "in the limit"));
}

TEST_CASE("readings: the text's undefined x, y in a model of polar coordinates, only where the line then holds",
          "[checker][readings]") {
    // A particle on the paraboloid x^2 + y^2 = a z in cylindrical rho, phi, z (a corpus text's model).
    const CheckReport r = eomgen::test::check_text("tests/checker/corpus/central_paraboloid_multiplier_mathse/model.toml",
                                                   R"(# Paraboloid

$$ x^2 + y^2 = a z $$

$$ x^2 - y^2 = a z $$
)");
    INFO(described(r));
    const auto constraint = on_line(r, 3), other = on_line(r, 5);
    REQUIRE(constraint.size() == 1);
    CHECK(constraint[0]->verdict == Verdict::Agrees);
    CHECK(eomgen::test::has_note(*constraint[0], "the text's Cartesian $x = \\rho \\cos \\phi$"));
    REQUIRE(other.size() == 1);  // the angle's convention is a guess: no disagreement on it
    CHECK(other[0]->verdict == Verdict::NotComparable);
}

TEST_CASE("readings: the coordinates of a point agree with a point the model file gives, and never disagree",
          "[checker][readings]") {
    // models/pendulum.toml draws the bob at (l sin φ, −l cos φ).
    const CheckReport r = eomgen::test::check_text(kModel, R"(# Pendulum

The bob is at

$$ x = l \sin\phi $$

$$ y = -l \cos\phi $$

## Measured downward

$$ x_b = l \sin\phi $$

$$ y_b = l \cos\phi $$

## As vectors

$$ \vec{r} = l\sin\phi\,\hat{x} - l\cos\phi\,\hat{y} $$

$$ \mathbf{r}_{2} = l\sin\phi\,\mathbf{i} + l\cos\phi\,\mathbf{j} $$
)");
    INFO(described(r));
    for (const int line : {5, 7, 17}) {
        const auto v = on_line(r, line);
        REQUIRE(v.size() == 1);
        CHECK(v[0]->verdict == Verdict::Agrees);
        CHECK(v[0]->compared_with.find("the position of the model's point") == 0);
    }
    // y down: the text's axes are not the file's, which is no slip; the first row says which points the file has.
    for (const int line : {11, 13, 19}) {
        const auto v = on_line(r, line);
        REQUIRE(v.size() == 1);
        CHECK(v[0]->verdict != Verdict::Disagrees);
        CHECK(v[0]->verdict != Verdict::Agrees);
    }
    CHECK(eomgen::test::has_note(*on_line(r, 11)[0], "no point the model file gives"));
}

TEST_CASE("readings: a point's coordinates as a list, and its coordinates at a point the text considers",
          "[checker][readings]") {
    // models/pendulum.toml draws the bob at (l sin φ, −l cos φ).
    const CheckReport r = eomgen::test::check_text(kModel, R"(# Pendulum

The bob is at $x, y = l \sin\phi, -l \cos\phi$, or $\mathbf{r} = (l \sin\phi, -l\cos\phi)$.

Hanging straight down, $\phi = 0$, it is at $x, y = 0, -l$.

Level with the pivot, $\phi = \frac{\pi}{2}$, it is at $x, y = l, l$.
)");
    INFO(described(r));
    const auto general = on_line(r, 3);
    REQUIRE(general.size() == 3);
    for (const auto* v : general) {
        CHECK(v->verdict == Verdict::Agrees);
        CHECK(v->compared_with.find("the position of the model's point") == 0);
    }
    int agree = 0;
    for (const auto* v : on_line(r, 5)) agree += v->verdict == Verdict::Agrees;
    CHECK(agree == 2);  // x = 0, y = -l where φ = 0 (the condition itself is not judged)
    const auto level = on_line(r, 7);
    const EquationCheck* slip = nullptr;
    for (const auto* v : level)
        if (v->verdict == Verdict::Disagrees) slip = v;
        else CHECK(v->verdict != Verdict::NotComparable);
    REQUIRE(slip != nullptr);
    CHECK(slip->equation == "y = l");
    CHECK(slip->corrected == "y = 0");
    CHECK(slip->compared_with.find("where $\\phi = \\frac{1}{2} \\pi$ (the condition on line 7") != std::string::npos);
    // Without formulas of its own for the point, a coordinate at a point that no point of the model has is no slip:
    // the text's axes may be another's.
    const CheckReport alone = eomgen::test::check_text(kModel, R"(# Pendulum

Level with the pivot, $\phi = \frac{\pi}{2}$, it is at $x, y = l, l$.
)");
    INFO(described(alone));
    for (const EquationCheck& e : alone.equations) CHECK(e.verdict != Verdict::Disagrees);
}

TEST_CASE("readings: r_M and r_m are two points where M and m are two masses of the model", "[checker][readings]") {
    // A cart (M, coordinate x) with a pendulum (m, l, θ) below it, drawn at (x, 0) and (x + l sin θ, −l cos θ).
    const CheckReport r = eomgen::test::check_text("tests/checker/corpus/cart_spring_report/model.toml", R"(# Cart

$$ \vec{r_M} = x \hat{x} $$

$$ \vec{r_m} = (x + l\sin\theta) \hat{x} - l\cos\theta\,\hat{y} $$
)");
    INFO(described(r));
    for (const int line : {3, 5}) {
        const auto v = on_line(r, line);
        REQUIRE(v.size() == 1);
        CHECK(v[0]->verdict == Verdict::Agrees);
    }
}

TEST_CASE("readings: a matrix expression between bars is its determinant, and a vector's magnitude is not cut at its +",
          "[checker][readings]") {
    // Three masses on a ring (Goldstein 6.10, a corpus text's model): V and T in bold are its stiffness and mass matrices.
    const CheckReport r = eomgen::test::check_text("tests/checker/corpus/spring_ring/model.toml", R"(# Ring

$$ \left|\mathbf{V}-\omega^{2}\mathbf{T}\right| = 0 $$

$$ T = \frac{1}{2} m R^2 \left|\dot{\vec{\theta}} + \vec{\omega}\times\vec{\theta}\right|^2 $$
)");
    INFO(described(r));
    const auto secular = on_line(r, 3), magnitude = on_line(r, 5);
    REQUIRE(secular.size() == 1);
    CHECK(secular[0]->verdict == Verdict::Agrees);
    REQUIRE(magnitude.size() == 1);
    CHECK(magnitude[0]->verdict == Verdict::NotComparable);
    CHECK(magnitude[0]->reason.find("missing \\right") == std::string::npos);
}

TEST_CASE("readings: the text's own macros are read as their bodies, with their arguments", "[checker][readings][macros]") {
    const CheckReport r = eomgen::test::check_text(kModel, R"(\newcommand{\pl}{\partial}
\newcommand*{\dd}[1][t]{\frac{d}{d #1}}
\def\half#1{\frac{#1}{2}}
\let\ph=\phi
\DeclareMathOperator{\Sin}{sin}
\newcommand{\loop}{\loop x}

# Pendulum

$$ L = \half{m l^2 \dot\ph^2} + m g l \cos\ph $$

$$ \dd\left(\frac{\pl L}{\pl \dot\ph}\right) - \frac{\pl L}{\pl \ph} = 0 \Rightarrow m l^2 \ddot\ph + m g l \Sin\ph = 0 $$

A slip, written with the same macros:

$$ \dd[t]\left(\frac{\pl L}{\pl \dot\ph}\right) = -m g \Sin\ph $$

$$ \loop = 0 $$
)");
    INFO(described(r));
    const auto lagrangian = on_line(r, 10), equation = on_line(r, 12), slip = on_line(r, 16), endless = on_line(r, 18);
    REQUIRE(!lagrangian.empty());
    CHECK(lagrangian[0]->verdict == Verdict::Agrees);
    REQUIRE(!equation.empty());
    for (const EquationCheck* e : equation) CHECK(e->verdict == Verdict::Agrees);
    REQUIRE(!slip.empty());
    CHECK(slip[0]->verdict == Verdict::Disagrees);  // -m g l sin φ: the l is missing
    // A macro whose body uses itself stops expanding (bounded): the row is reported, not lost, and nothing hangs.
    CHECK(!endless.empty());
}
