/** @file exam_misspelled_names.cpp  A name written once where the text's parameter of the same letter belongs
 * (misspelled_names.cpp): flagged with the parameter written in; the text's own notation, used on other lines,
 * and a name no parameter fits stay not comparable. */
#include "checked_text.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace {

using eomgen::checker::EquationCheck;
using eomgen::checker::Verdict;

const char* const kCart = "tests/checker/models/cart_pendulum_free.toml";

/// The free cart's Lagrangian with `m_b` written for the bob's m in its last term, as one display.
const std::string kSlippedL =
    "$$L = \\frac{1}{2}(M+m)\\dot{x}^2 + m l \\dot{x}\\dot{\\theta}\\cos\\theta + \\frac{1}{2} m l^2 \\dot{\\theta}^2 "
    "+ m_b g l \\cos\\theta$$\n";

const EquationCheck* on_line(const eomgen::checker::CheckReport& r, int line, Verdict v) {
    for (const EquationCheck& e : r.equations)
        if (e.where.line == line && e.verdict == v) return &e;
    return nullptr;
}

/// No line of `text` disagrees.
void never_disagrees(const std::string& text) {
    const auto r = eomgen::test::check_text(kCart, text);
    for (const EquationCheck& e : r.equations) {
        INFO(eomgen::test::describe(e));
        CHECK(e.verdict != Verdict::Disagrees);
    }
}

}  // namespace

TEST_CASE("misspelled names: m_b written once for the text's m is a slip, corrected to m", "[checker][misspelled]") {
    const std::string text = "The cart has mass $M$, the bob $m$ on a rod of length $l$.\n\n" + kSlippedL;
    const auto r = eomgen::test::check_text(kCart, text);
    for (const EquationCheck& e : r.equations) INFO(eomgen::test::describe(e));
    const EquationCheck* slip = on_line(r, 3, Verdict::Disagrees);
    REQUIRE(slip != nullptr);
    INFO(eomgen::test::describe(*slip));
    CHECK(slip->reason.find("$m_{b}$") != std::string::npos);
    CHECK(slip->reason.find("with $m$") != std::string::npos);
    CHECK(slip->corrected.find("+ m g l \\cos\\theta") != std::string::npos);
    CHECK(slip->corrected.find("m_b") == std::string::npos);
}

TEST_CASE("misspelled names: the text's own notation, or a name no parameter fits, is not a slip",
          "[checker][misspelled]") {
    SECTION("the name on two lines is the text's notation") {
        const std::string text =
            "$$L = \\frac{1}{2}(M+m)\\dot{x}^2 + m l \\dot{x}\\dot{\\theta}\\cos\\theta + \\frac{1}{2} m l^2 "
            "\\dot{\\theta}^2 + m_b g l \\cos\\theta$$\n"
            "\n"
            "$$V = -m_b g l \\cos\\theta$$\n";
        never_disagrees(text);
    }
    SECTION("no parameter of the letter makes the line agree") {
        const std::string text =
            "$$L = \\frac{1}{2}(M+m)\\dot{x}^2 + m l \\dot{x}\\dot{\\theta}\\cos\\theta + \\frac{1}{2} m l^2 "
            "\\dot{\\theta}^2 + 2 m_b g l \\cos\\theta$$\n";
        never_disagrees(text);
    }
    SECTION("a name the text introduces only later for a parameter is still a slip where it stands before") {
        // The double Atwood machine of the corpus: `V = m g (h - y_1) + …` for m_1, and m named the common mass
        // only lines later (`m_1 = m_2 = m`).
        const std::string slip = kSlippedL + "\nFor the case of a light cart, take equal masses, $M = m = m_b$.\n";
        const auto r = eomgen::test::check_text(kCart, slip);
        const EquationCheck* found = on_line(r, 1, Verdict::Disagrees);
        REQUIRE(found != nullptr);
        INFO(eomgen::test::describe(*found));
        CHECK(found->reason.find("a slip for $m$") != std::string::npos);
        CHECK(found->reason.find("before it names a parameter so (line 3)") != std::string::npos);
        // Its link is reported once, as the slip, not also as not comparable.
        int on_first = 0;
        for (const EquationCheck& e : r.equations) on_first += e.where.line == 1 && e.where.column == found->where.column;
        CHECK(on_first == 1);
        // Used before the line (the text's notation from the start), it is not a slip.
        never_disagrees("Take equal masses, $M = m = m_b$.\n\n" + kSlippedL);
    }
    SECTION("a parameter the text never writes is not offered") {
        // m_b -> m would agree, but the text writes no m (nor M): its m_b is its own name for the bob's mass.
        const std::string text = "$$V = -m_b g l \\cos\\theta$$\n";
        never_disagrees(text);
    }
}
