/** @file exam_motions.cpp  Lines that hold on one particular motion ([[motions]]) and the text's own
 * abbreviations ("Write k = g/l"): the conical pendulum, correct and with planted mistakes. */
#include "checked_text.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <string>

namespace {

using eomgen::checker::CheckReport;
using eomgen::checker::EquationCheck;
using eomgen::checker::Role;
using eomgen::checker::Verdict;

const char* const kConical = "tests/checker/models/conical_pendulum.toml";

const EquationCheck& at_line(const CheckReport& r, int line) {
    for (const EquationCheck& e : r.equations)
        if (e.where.line == line) return e;
    FAIL("no equation on line " << line);
    return r.equations.front();
}

using eomgen::test::has_note;

}  // namespace

TEST_CASE("motions: a correct derivation on the conical motion agrees, with no false alarm", "[checker][motions]") {
    const CheckReport r = eomgen::test::check_text(kConical, eomgen::test::fixture("conical_correct.md"));
    for (const EquationCheck& e : r.equations) {
        INFO(eomgen::test::describe(e));
        CHECK(e.verdict != Verdict::Disagrees);
    }
    // And the two definitions: v = l sin θ φ̇, a quantity of the motion, agrees through its use on line 22; k
    // is the text's name for a constant, an abbreviation for the rest of the section, named where it is used.
    CHECK(r.count(Verdict::Agrees) == 10);
    CHECK(at_line(r, 20).compared_with == "its use on line 22");
    CHECK(at_line(r, 3).verdict == Verdict::NotJudged);
    CHECK(at_line(r, 3).reason == "a definition: the text's abbreviation $k = g/l$ for the rest of its section");
    CHECK(has_note(at_line(r, 5), "using $k = g/l$ (line 3)"));  // the θ equation, outside any derivative
    const EquationCheck& k = at_line(r, 9);
    CHECK(k.verdict == Verdict::Agrees);
    CHECK(k.reason == "agrees on the motion 'conical' ($\\dot{\\theta} = 0$, $\\dot{\\phi} = \\sqrt{\\frac{g}{l \\cos "
                      "\\theta}}$)");
    CHECK(has_note(k, "using $k = g/l$ (line 3)"));
    // ω₀, which the text never defines, is a constant of the motion: φ̇ sin²θ is constant on it.
    CHECK(at_line(r, 18).verdict == Verdict::Agrees);
    CHECK(at_line(r, 18).reason.find("$\\omega_{0}$ is that constant of the motion") != std::string::npos);
    CHECK(has_note(at_line(r, 22), "using $v = l\\sin\\theta\\,\\dot\\phi$ (line 20)"));
    // φ = φ̇ t: a function of t, right for the initial value it chooses.
    CHECK(at_line(r, 24).reason.find("for the initial value it chooses") != std::string::npos);
}

TEST_CASE("motions: every planted mistake is found at its line, with its correction", "[checker][motions]") {
    const std::string text = eomgen::test::fixture("conical_planted.md");
    const std::map<int, std::string> planted = eomgen::test::planted_mistakes(text);
    REQUIRE(planted.size() == 4);
    const CheckReport r = eomgen::test::check_text(kConical, text);
    std::map<int, int> found;
    for (const EquationCheck& e : r.equations) {
        INFO(eomgen::test::describe(e));
        if (e.verdict != Verdict::Disagrees) continue;
        const auto p = planted.find(e.where.line);
        REQUIRE(p != planted.end());  // no false alarm
        std::string all = e.difference + e.corrected;
        for (const std::string& w : e.wrong_terms) all += w;
        for (const std::string& n : e.notes) all += n;
        CHECK(all.find(p->second) != std::string::npos);
        ++found[e.where.line];
    }
    CHECK(found.size() == planted.size());
    // The wrong definition (k = g l) is named where it is used, and the correction is the motion's value.
    CHECK(at_line(r, 5).corrected == "\\dot\\phi^2 \\cos\\theta = \\frac{g}{l}");
    CHECK(at_line(r, 18).corrected == "v^2 = \\frac{l g \\sin^{2} \\theta}{\\cos \\theta}");
    CHECK(at_line(r, 14).wrong_terms.at(0) ==
          "$\\omega_{0}$ is set equal to $\\phi \\sin^{2} \\theta$, which is not constant on the motion (its rate of "
          "change is the difference)");
}

TEST_CASE("motions: a motion that does not solve the equations of motion decides nothing, and says so",
          "[checker][motions]") {
    const CheckReport r = eomgen::test::check_text(kConical, eomgen::test::fixture("conical_planted.md"));
    const EquationCheck& e = at_line(r, 22);
    INFO(eomgen::test::describe(e));
    CHECK(e.verdict == Verdict::NotComparable);
    CHECK(e.reason.find("the motion 'wrong conical'") != std::string::npos);
    CHECK(e.reason.find("does not solve the model's Euler–Lagrange equation for $\\theta$") != std::string::npos);
}

TEST_CASE("motions: a motion that cannot be evaluated decides nothing", "[checker][motions]") {
    const CheckReport r =
        eomgen::test::check_text(kConical, "# Imaginary rate\n\n$$ \\dot\\phi^2 \\cos\\theta = -\\frac{g}{l} $$\n");
    REQUIRE(r.equations.size() == 1);
    INFO(eomgen::test::describe(r.equations[0]));
    CHECK(r.equations[0].verdict == Verdict::NotComparable);
    CHECK(r.equations[0].reason.find("cannot be evaluated on the motion 'imaginary'") != std::string::npos);
}

TEST_CASE("motions: without [[motions]] a line of the motion is taken for the energy integral", "[checker][motions]") {
    // The same line against the model without the motion is compared with what it looks closest to, the
    // conservation of h, and disagrees; with the motion it agrees on it.
    const std::string line = "$$ l\\cos\\theta = \\frac{g}{\\dot\\phi^2} $$\n";
    const CheckReport without = eomgen::test::check_text("tests/checker/models/spherical_pendulum.toml", line);
    REQUIRE(without.equations.size() == 1);
    CHECK(without.equations[0].verdict == Verdict::Disagrees);
    CHECK(without.equations[0].compared_with.find("the conservation of $h$") != std::string::npos);
    const CheckReport with = eomgen::test::check_text(kConical, line);
    REQUIRE(with.equations.size() == 1);
    CHECK(with.equations[0].verdict == Verdict::Agrees);
    CHECK(with.equations[0].compared_with == "the motion 'conical'");
}

TEST_CASE("definitions: a definition of a name the model knows that contradicts it disagrees at its line",
          "[checker][definitions]") {
    // p_φ is eomgen's momentum: "write p_φ = m l² φ̇" is a claim about it (sin²θ is missing), not a new name.
    const CheckReport r = eomgen::test::check_text(
        kConical, "# Momentum\n\nWrite $p_{\\phi} = m l^2 \\dot\\phi$; then\n\n$$ \\dot\\phi^2\\cos\\theta = \\frac{g}{l} $$\n");
    const EquationCheck& def = at_line(r, 3);
    INFO(eomgen::test::describe(def));
    CHECK(def.verdict == Verdict::Disagrees);
    CHECK(def.compared_with == "$p_{\\phi}$");  // eomgen's p_φ
    CHECK(def.corrected == "p_{\\phi} = m l^{2} \\dot{\\phi} \\sin^{2} \\theta");
    CHECK(at_line(r, 5).verdict == Verdict::Agrees);  // the line after it, on the conical motion
}

TEST_CASE("definitions: an abbreviation holds for the rest of its section, and after it only where a line then agrees",
          "[checker][definitions]") {
    const CheckReport r = eomgen::test::check_text(
        "tests/checker/models/spherical_pendulum.toml",
        "# One\n\nWrite $k = g/l$.\n\n$$ \\ddot\\theta = \\sin\\theta\\cos\\theta\\,\\dot\\phi^2 - k\\sin\\theta $$\n\n"
        "# Two\n\n$$ \\ddot\\theta = \\sin\\theta\\cos\\theta\\,\\dot\\phi^2 - k\\sin\\theta $$\n\n"
        "$$ \\ddot\\theta = \\sin\\theta\\cos\\theta\\,\\dot\\phi^2 + k\\sin\\theta $$\n");
    const EquationCheck& in = at_line(r, 5);
    INFO(eomgen::test::describe(in));
    CHECK(in.verdict == Verdict::Agrees);
    CHECK_FALSE(has_note(in, "with a value an earlier section gives the name"));
    // In section Two, k is not defined: an earlier section's value is taken only as a second reading that agrees
    // (a text whose forces are defined in a section before its equations), and said; a line it would make wrong is
    // not judged with it (k may mean something else there).
    const EquationCheck& out = at_line(r, 9);
    INFO(eomgen::test::describe(out));
    CHECK(out.verdict == Verdict::Agrees);
    CHECK(has_note(out, "with a value an earlier section gives the name"));
    const EquationCheck& other = at_line(r, 11);
    INFO(eomgen::test::describe(other));
    CHECK(other.verdict == Verdict::NotComparable);
    CHECK_FALSE(has_note(other, "using"));
}
