/** @file exam_hamiltonian.cpp  Hamilton's equations as people publish them: the plane pendulum, the spherical
 * pendulum and the heavy symmetric top agree line by line; a slip planted in each disagrees, on its line, with
 * a correction that checks itself; without a symbolic M⁻¹ the canonical identities are used. */
#include "test_paths.hpp"
#include "checked_text.hpp"
#include "model/families.hpp"

#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace {

using eomgen::checker::CheckOptions;
using eomgen::checker::CheckReport;
using eomgen::checker::EquationCheck;
using eomgen::checker::Verdict;

const std::string kSource = eomgen_test::source_dir();

std::string read(const std::string& fixture) {
    std::ifstream in(kSource + "/tests/checker/fixtures/" + fixture, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string describe(const EquationCheck& e) {
    std::string s = std::to_string(e.where.line) + ": " + eomgen::checker::verdict_name(e.verdict) + ": " +
                    e.equation + " [" + e.compared_with + "] " + e.reason;
    for (const std::string& w : e.wrong_terms) s += "\n  - " + w;
    for (const std::string& n : e.notes) s += "\n  note: " + n;
    return s;
}

struct Fixture {
    const char* model;
    const char* correct;
    const char* planted;
    std::size_t equations;
    CheckOptions options;
};

std::vector<Fixture> fixtures() {
    CheckOptions top;
    top.map.push_back({"I", "I_{1} + M l^{2}", "the moment of inertia about the pivot"});
    return {{"tests/checker/models/plane_pendulum.toml", "hamilton_pendulum.md", "hamilton_pendulum_planted.md", 13, {}},
            {"tests/checker/models/spherical_pendulum.toml", "hamilton_spherical_pendulum.md",
             "hamilton_spherical_pendulum_planted.md", 16, {}},
            {"models/heavy_symmetric_top.toml", "hamilton_heavy_top.md", "hamilton_heavy_top_planted.md", 17, top}};
}

}  // namespace

TEST_CASE("hamilton: correct derivations agree line by line", "[checker][hamiltonian]") {
    for (const Fixture& f : fixtures()) {
        INFO(f.correct);
        const CheckReport r = eomgen::test::check_text(f.model, read(f.correct), f.options);
        for (const EquationCheck& e : r.equations) {
            INFO(describe(e));
            CHECK(e.verdict == Verdict::Agrees);
        }
        CHECK(r.equations.size() == f.equations);
    }
}

TEST_CASE("hamilton: what each kind of line is compared with", "[checker][hamiltonian]") {
    const CheckReport r = eomgen::test::check_text(fixtures()[0].model, read("hamilton_pendulum.md"));
    std::map<int, std::vector<const EquationCheck*>> by_line;
    for (const EquationCheck& e : r.equations) by_line[e.where.line].push_back(&e);
    // The two lines: ṗ_θ = −∂H/∂θ (an Euler–Lagrange equation, then an identity) and θ̇ = ∂H/∂p_θ.
    REQUIRE(by_line[19].size() == 2);
    CHECK(by_line[19][0]->compared_with == "the Euler–Lagrange equation for $\\theta$");
    REQUIRE(by_line[17].size() == 2);
    CHECK(by_line[17][1]->verdict == Verdict::Agrees);
    // H in momenta (line 13) and in velocities (line 15) are both eomgen's H.
    for (int line : {13, 15}) {
        REQUIRE(by_line[line].size() == 1);
        CHECK(by_line[line][0]->verdict == Verdict::Agrees);
    }
}

TEST_CASE("hamilton: a slip in each is found on its line, with a correction that checks itself", "[checker][hamiltonian]") {
    for (const Fixture& f : fixtures()) {
        INFO(f.planted);
        const std::string text = read(f.planted);
        int planted_line = 0;
        std::string phrase;
        {
            std::istringstream in(text);
            std::string line;
            for (int n = 1; std::getline(in, line); ++n)
                if (const std::size_t at = line.find("% planted["); at != std::string::npos) {
                    planted_line = n;
                    phrase = line.substr(at + 10, line.rfind(']') - at - 10);
                }
        }
        REQUIRE(planted_line > 0);
        const CheckReport r = eomgen::test::check_text(f.model, text, f.options);
        int found = 0;
        for (const EquationCheck& e : r.equations) {
            INFO(describe(e));
            if (e.verdict != Verdict::Disagrees) continue;
            CHECK(e.where.line == planted_line);  // no false alarm
            ++found;
            std::string all;
            for (const std::string& w : e.wrong_terms) all += w + "\n";
            CHECK(all.find(phrase) != std::string::npos);
            REQUIRE_FALSE(e.corrected.empty());
            // The correction, written into the text in place of the slip's display, agrees.
            std::string fixed;
            std::istringstream in(text);
            std::string line;
            for (int n = 1; std::getline(in, line); ++n) fixed += (n == planted_line ? "$$" + e.corrected + "$$" : line) + "\n";
            const CheckReport again = eomgen::test::check_text(f.model, fixed, f.options);
            for (const EquationCheck& a : again.equations) {
                INFO("after the correction: " << describe(a));
                CHECK(a.verdict != Verdict::Disagrees);
            }
        }
        CHECK(found >= 1);
    }
}

TEST_CASE("hamilton: without a symbolic inverse mass matrix, the canonical identities", "[checker][hamiltonian]") {
    const eomgen::Model m = eomgen::parse_model(
        eomgen::family_model_text(eomgen::parse_family_spec("pendulum:n=4")), "--family pendulum:n=4");
    const eomgen::Equations eq = eomgen::derive_equations(m);
    const std::string latex = m.coordinates[0].latex;  // \theta_{1}
    const std::string text = "$$\\dot{" + latex + "} = \\frac{\\partial H}{\\partial p_{" + latex + "}}$$\n" +
                             "$$\\dot{p}_{" + latex + "} = -\\frac{\\partial H}{\\partial " + latex + "}$$\n" +
                             "$$\\frac{\\partial (H + H^2)}{\\partial " + latex + "} = 0$$\n";
    const CheckReport r = eomgen::checker::check_derivation(m, eq, eomgen::checker::parse_derivation(text, "x.md"), {});
    REQUIRE(r.equations.size() == 3);
    for (std::size_t k = 0; k < 2; ++k) {
        INFO(describe(r.equations[k]));
        CHECK(r.equations[k].verdict == Verdict::Agrees);
    }
    INFO(describe(r.equations[2]));
    CHECK(r.equations[2].verdict == Verdict::NotComparable);
    CHECK(r.equations[2].reason.find("couples 4 coordinates") != std::string::npos);
}

TEST_CASE("hamilton: dH/dt = -dL/dt, and a term linear in the velocities", "[checker][hamiltonian]") {
    // A charge in a magnetic field and a driving force: L = m/2 (ẋ² + ẏ²) + (b/2)(x ẏ − y ẋ) + k cos(w t) x.
    const auto& [m, eq] = eomgen::test::derived_model("tests/checker/models/charge_in_field.toml");
    const std::string text =
        "$$p_x = m \\dot x - \\frac{b}{2} y, \\quad p_y = m \\dot y + \\frac{b}{2} x$$\n"
        "$$H = \\frac{(p_x + \\frac{b}{2} y)^2 + (p_y - \\frac{b}{2} x)^2}{2m} - k x \\cos(\\omega t)$$\n"
        "$$\\frac{\\partial H}{\\partial t} = -\\frac{\\partial L}{\\partial t} = k \\omega x \\sin(\\omega t)$$\n"
        "$$\\dot x = \\frac{\\partial H}{\\partial p_x} = \\frac{1}{m}\\left(p_x + \\frac{b}{2} y\\right)$$\n"
        "$$\\dot p_x = -\\frac{\\partial H}{\\partial x} = \\frac{b}{2m}\\left(p_y - \\frac{b}{2} x\\right) + k \\cos(\\omega t)$$\n"
        "$$\\frac{\\partial H}{\\partial t} = -k \\omega x \\sin(\\omega t)$$\n";
    const CheckReport r = eomgen::checker::check_derivation(m, eq, eomgen::checker::parse_derivation(text, "x.md"), {});
    REQUIRE(r.equations.size() == 10);
    for (std::size_t k = 0; k + 1 < r.equations.size(); ++k) {
        INFO(describe(r.equations[k]));
        CHECK(r.equations[k].verdict == Verdict::Agrees);
    }
    INFO(describe(r.equations.back()));
    CHECK(r.equations.back().verdict == Verdict::Disagrees);  // the sign of ∂H/∂t
    CHECK(r.equations.back().corrected == "\\frac{\\partial H}{\\partial t} = k \\omega x \\sin\\left(\\omega t\\right)");
}

TEST_CASE("hamilton: H written in velocities and differentiated so is read as the text set it up", "[checker][hamiltonian]") {
    // ∂H/∂θ of the spherical pendulum: at fixed θ̇, φ̇ it has +m l² sinθ cosθ φ̇²; at fixed p (Hamilton) −.
    const std::string h = "$$H = \\frac{1}{2} m l^2 \\left(\\dot\\theta^2 + \\sin^2\\theta\\,\\dot\\phi^2\\right) - m g l \\cos\\theta$$\n\n";
    const std::string at_fixed_velocities =
        "$$-\\frac{\\partial H}{\\partial \\theta} = -m l^2 \\sin\\theta\\cos\\theta\\,\\dot\\phi^2 - m g l \\sin\\theta$$\n";
    const std::string at_fixed_momenta =
        "$$-\\frac{\\partial H}{\\partial \\theta} = m l^2 \\sin\\theta\\cos\\theta\\,\\dot\\phi^2 - m g l \\sin\\theta$$\n";
    const char* model = "tests/checker/models/spherical_pendulum.toml";
    const CheckReport set_up = eomgen::test::check_text(model, h + at_fixed_velocities + at_fixed_momenta);
    REQUIRE(set_up.equations.size() == 3);
    for (const EquationCheck& e : set_up.equations) {
        INFO(describe(e));
        CHECK(e.verdict == Verdict::Agrees);
    }
    bool noted = false;
    for (const std::string& n : set_up.equations[1].notes) noted = noted || n.find("read as the text set it up") != std::string::npos;
    CHECK(noted);
    // Without H in velocities before it, the line at fixed velocities is not Hamilton's: it disagrees.
    const CheckReport bare = eomgen::test::check_text(model, at_fixed_velocities);
    REQUIRE(bare.equations.size() == 1);
    CHECK(bare.equations[0].verdict == Verdict::Disagrees);
}

TEST_CASE("hamilton: Poisson brackets of coordinates, momenta and H", "[checker][hamiltonian]") {
    const CheckReport r = eomgen::test::check_text(
        "tests/checker/models/spherical_pendulum.toml",
        "$$\\{\\theta, p_\\theta\\} = 1, \\quad \\{\\theta, p_\\phi\\} = 0, \\quad \\{p_\\theta, \\theta\\} = -1$$\n\n"
        "$$\\{\\theta, H\\} = \\frac{p_\\theta}{m l^2} = \\dot\\theta$$\n\n"
        "$$\\{p_\\phi, H\\} = 0$$\n\n"  // φ is cyclic: p_φ is conserved
        "$$\\{p_\\theta, H\\} = \\frac{p_\\phi^2 \\cos\\theta}{m l^2 \\sin^3\\theta} - m g l \\sin\\theta$$\n\n"
        "$$\\{\\theta, p_\\theta\\} = -1$$\n");
    REQUIRE(r.equations.size() == 8);
    for (std::size_t k = 0; k < 7; ++k) {
        INFO(describe(r.equations[k]));
        CHECK(r.equations[k].verdict == Verdict::Agrees);
    }
    INFO(describe(r.equations[7]));
    CHECK(r.equations[7].verdict == Verdict::Disagrees);
    CHECK(r.equations[7].corrected == "\\{\\theta, p_\\theta\\} = 1");
    // A brace that is not a bracket is refused with its reason.
    const CheckReport bad = eomgen::test::check_text("tests/checker/models/spherical_pendulum.toml", "$$\\{\\theta\\} = 1$$\n");
    REQUIRE(bad.equations.size() == 1);
    CHECK(bad.equations[0].verdict == Verdict::NotComparable);
    CHECK(bad.equations[0].reason.find("Poisson bracket") != std::string::npos);
}
