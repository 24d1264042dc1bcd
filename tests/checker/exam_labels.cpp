/** @file exam_labels.cpp  Equations named in the prose before them ("Lagrange's equation for ψ", "the θ
 * equation", "the energy", "the angular momentum"): the phrasings read and those left alone, correct labels on
 * the spherical pendulum and the heavy top without a false alarm, wrong labels found at their lines. */
#include "checked_text.hpp"
#include "checker/labels.hpp"
#include "checker/latex_parser.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace {

using eomgen::checker::CheckOptions;
using eomgen::checker::CheckReport;
using eomgen::checker::EquationCheck;
using eomgen::checker::LabelKind;
using eomgen::checker::ProseLabel;
using eomgen::checker::Verdict;

const char* const kPendulum = "tests/checker/models/spherical_pendulum.toml";  // θ, φ

/// The label of the display that follows `prose` (the text: a heading, `prose`, a blank line, `$$ x = 0 $$`).
std::optional<ProseLabel> label_of(const std::string& prose, const std::string& display = "$$ x = 0 $$") {
    const auto& model = eomgen::test::derived_model(kPendulum).first;
    const auto d = eomgen::checker::parse_derivation("# S\n\n" + prose + "\n\n" + display + "\n", "t.md");
    REQUIRE(!d.rows.empty());
    const auto coordinate = [&](const std::string& latex) {
        for (std::size_t k = 0; k < model.coordinates.size(); ++k)
            if (eomgen::checker::canonical_name(latex) == eomgen::checker::canonical_name(model.coordinates[k].latex))
                return int(k);
        return -1;
    };
    return eomgen::checker::label_before(d, d.rows.back().offset + 1, coordinate, model);
}

struct Fixture {
    const char* model;
    const char* correct;
    const char* planted;
    CheckOptions options;
};

std::vector<Fixture> fixtures() {
    CheckOptions top;
    top.map.push_back({"I", "I_{1} + M l^{2}", "the moment of inertia about the pivot"});
    return {{kPendulum, "labels_spherical_pendulum.md", "labels_spherical_pendulum_planted.md", {}},
            {"models/heavy_symmetric_top.toml", "labels_heavy_top.md", "labels_heavy_top_planted.md", top}};
}

bool has_note(const EquationCheck& e, const std::string& part) {
    for (const std::string& n : e.notes)
        if (n.find(part) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST_CASE("labels: the phrasings that name an equation", "[checker][labels]") {
    using V = std::vector<std::size_t>;
    struct Case {
        const char* prose;
        LabelKind kind;
        V coordinates;
    };
    const Case cases[] = {
        {"Lagrange's equation for $\\theta$ is:", LabelKind::EulerLagrange, {0}},
        {"The Euler–Lagrange equation for θ:", LabelKind::EulerLagrange, {0}},
        {"The Euler-Lagrange equation for $\\theta$ then reads", LabelKind::EulerLagrange, {0}},
        {"Now the $\\phi$ equation reads", LabelKind::EulerLagrange, {1}},
        {"The φ-equation gives", LabelKind::EulerLagrange, {1}},
        {"The equation of motion for phi is", LabelKind::EulerLagrange, {1}},
        {"Lagrange’s equations for θ and φ are", LabelKind::EulerLagrange, {0, 1}},
        {"The energy integral is", LabelKind::Energy, {}},
        {"Since there is no friction, the total energy is conserved:", LabelKind::Energy, {}},
        {"The energy (here the kinetic energy plus the potential energy) is", LabelKind::Energy, {}},
        {"The Hamiltonian is", LabelKind::Hamiltonian, {}},
        {"The Jacobi integral is", LabelKind::Hamiltonian, {}},
        {"The energy function is", LabelKind::Hamiltonian, {}},
        {"Conservation of energy gives", LabelKind::Energy, {}},
        {"$p_\\phi$ is conserved:", LabelKind::Momentum, {1}},
        {"The momentum conjugate to $\\phi$ is", LabelKind::Momentum, {1}},
        {"The angular momentum about the vertical is a constant:", LabelKind::Momentum, {}},
        {"The kinetic energy is", LabelKind::Kinetic, {}},
        {"The potential energy of the bob is", LabelKind::Potential, {}},
        {"The Lagrangian is then", LabelKind::Lagrangian, {}},
    };
    for (const Case& c : cases) {
        INFO(c.prose);
        const auto l = label_of(c.prose);
        REQUIRE(l);
        CHECK(l->kind == c.kind);
        CHECK(l->coordinates == c.coordinates);
        CHECK(l->unknown.empty());
        CHECK(l->line == 3);
    }
    // A display in an environment, after its own `$$`: the sentence before the `\begin`.
    const auto aligned = label_of("Lagrange's equation for $\\phi$ is", "$$\n\\begin{aligned}\nx &= 0\n\\end{aligned}\n$$");
    REQUIRE(aligned);
    CHECK(aligned->coordinates == V{1});
    CHECK(aligned->phrase == "Lagrange's equation for $\\phi$");
    // Unicode subscripts: θ₁ is \theta_{1} (the spherical pendulum has no θ₁).
    const auto subscript = label_of("The θ₁ equation is");
    REQUIRE(subscript);
    CHECK(subscript->unknown == std::vector<std::string>{"\\theta_{1}"});
    // A coordinate the model does not have is kept as written.
    const auto unknown = label_of("The ψ-equation is");
    REQUIRE(unknown);
    CHECK(unknown->coordinates.empty());
    CHECK(unknown->unknown == std::vector<std::string>{"\\psi"});
}

TEST_CASE("labels: 'the last equation (...)' after a display labels its last row", "[checker][labels]") {
    const auto& model = eomgen::test::derived_model(kPendulum).first;
    const auto coordinate = [&](const std::string& latex) {
        return eomgen::checker::canonical_name(latex) == "\\phi" ? 1 : -1;
    };
    for (const char* words : {"The last equation (Lagrange's equation for $\\phi$) says that",
                              "The first equation, the φ equation, says that"}) {
        INFO(words);
        const auto d = eomgen::checker::parse_derivation(
            "# S\n\nThe equations are\n\n$$\n\\begin{aligned}\nx &= 0 \\\\\ny &= 0\n\\end{aligned}\n$$\n\nWe see.\n\n" +
                std::string(words) + " much.\n\n$$ z = 0 $$\n",
            "t.md");
        std::vector<std::size_t> displays;  // x = 0, y = 0, z = 0
        for (const auto& row : d.rows)
            if (row.display) displays.push_back(row.offset + 1);
        REQUIRE(displays.size() == 3);
        const bool last = std::string(words).find("last") != std::string::npos;
        const auto labelled = eomgen::checker::label_before(d, displays[last ? 1 : 0], coordinate, model);
        REQUIRE(labelled);
        CHECK(labelled->kind == LabelKind::EulerLagrange);
        CHECK(labelled->coordinates == std::vector<std::size_t>{1});
        CHECK(labelled->line == 14);
        CHECK_FALSE(eomgen::checker::label_before(d, displays[last ? 0 : 1], coordinate, model));
        CHECK_FALSE(eomgen::checker::label_before(d, displays[2], coordinate, model));  // no reference to it
    }
}

TEST_CASE("labels: prose that names no equation, or names an ingredient", "[checker][labels]") {
    for (const char* prose : {
             "Lagrange's equations are",                                  // no coordinate
             "Lagrange's equation for the pendulum is",                   // a word, not a coordinate
             "Using the energy, we get",                                  // an ingredient
             "Substituting this into the θ equation gives",               // an ingredient
             "From the angular momentum and the energy we find",          // ingredients
             "Lagrange's equation for θ is trivial. The other one is",    // the label is in an earlier sentence
             "The rotational energy is",                                  // a part of T
             "To find the energy we need",                                // no naming verb, an ingredient
             "The Lagrangian without the rod's kinetic energy:",          // a quantity left out
             "The derivative of the energy is",                           // what is done with it
             "The θ equation is long, and its solution, which we discuss at length later in this chapter, takes the form",
         }) {
        INFO(prose);
        CHECK_FALSE(label_of(prose));
    }
    // Inline math is never labelled.
    const auto& model = eomgen::test::derived_model(kPendulum).first;
    const auto d = eomgen::checker::parse_derivation("Lagrange's equation for θ is $\\ddot\\theta = 0$.\n", "t.md");
    REQUIRE(d.rows.size() == 1);
    CHECK_FALSE(eomgen::checker::label_before(d, d.rows[0].offset + 1, [](const std::string&) { return 0; }, model));
}

TEST_CASE("labels: correct labels agree, with a note naming the label", "[checker][labels]") {
    for (const Fixture& f : fixtures()) {
        INFO(f.correct);
        const CheckReport r = eomgen::test::check_text(f.model, eomgen::test::fixture(f.correct), f.options);
        int named = 0;
        for (const EquationCheck& e : r.equations) {
            INFO(eomgen::test::describe(e));
            CHECK(e.verdict != Verdict::Disagrees);
            if (has_note(e, "its label names")) ++named;
        }
        CHECK(named >= 9);
    }
    // The spherical pendulum's label for a coordinate it does not have: a note, the verdict as before.
    const CheckReport r =
        eomgen::test::check_text(kPendulum, eomgen::test::fixture("labels_spherical_pendulum.md"));
    bool chi = false;
    for (const EquationCheck& e : r.equations)
        if (e.where.line == 44) {
            chi = true;
            CHECK(e.verdict == Verdict::Agrees);
            CHECK(has_note(e, "its label (“The equation of motion for $\\chi$”, line 42) names $\\chi$, which is no "
                              "coordinate of the model: the label is not checked"));
        }
    CHECK(chi);
}

TEST_CASE("labels: wrong labels are found at their lines, saying what the equation is", "[checker][labels]") {
    for (const Fixture& f : fixtures()) {
        INFO(f.planted);
        const std::string text = eomgen::test::fixture(f.planted);
        const std::map<int, std::string> planted = eomgen::test::planted_mistakes(text);
        REQUIRE(planted.size() >= 3);
        const CheckReport r = eomgen::test::check_text(f.model, text, f.options);
        std::map<int, int> found;
        for (const EquationCheck& e : r.equations) {
            INFO(eomgen::test::describe(e));
            if (e.verdict != Verdict::Disagrees) continue;
            const auto p = planted.find(e.where.line);
            REQUIRE(p != planted.end());  // no false alarm
            REQUIRE(e.wrong_terms.size() == 1);
            CHECK(e.wrong_terms[0].find(p->second) != std::string::npos);
            CHECK(e.corrected.empty());  // the label or the equation: no correction is claimed
            ++found[e.where.line];
        }
        CHECK(found.size() == planted.size());
    }
    // The verdict's text, pinned.
    const CheckReport r =
        eomgen::test::check_text(kPendulum, eomgen::test::fixture("labels_spherical_pendulum_planted.md"));
    const EquationCheck* theta = nullptr;
    for (const EquationCheck& e : r.equations)
        if (e.where.line == 9) theta = &e;
    REQUIRE(theta);
    CHECK(theta->compared_with == "its label (“Lagrange's equation for $\\phi$”, line 7)");
    CHECK(theta->reason == "the equation holds, but it is not the one its label names");
    CHECK(theta->wrong_terms[0] ==
          "labelled the $\\phi$ equation (“Lagrange's equation for $\\phi$”, line 7), but it is the $\\theta$ equation "
          "(the Euler–Lagrange equation for $\\theta$, the same equation): the label or the equation is wrong");
}

TEST_CASE("labels: the Hamiltonian is h, not T + V, on a spinning hoop", "[checker][labels]") {
    // T = ½mR²(α̇² + ω² sin²α), V = −mgR cos α: h = ½mR²(α̇² − ω² sin²α) − mgR cos α is conserved, T + V is not.
    const std::string text = R"(# Bead on a spinning hoop

The Jacobi integral is conserved:

$$ \frac12 m R^2 \dot\alpha^2 - \frac12 m R^2 \omega^2 \sin^2\alpha - m g R \cos\alpha = \text{const} $$

and, in words, the energy is conserved:

$$ \frac12 m R^2 \dot\alpha^2 - \frac12 m R^2 \omega^2 \sin^2\alpha - m g R \cos\alpha = \text{const} $$

The Hamiltonian is

$$ E = \frac12 m R^2 \left(\dot\alpha^2 + \omega^2 \sin^2\alpha\right) - m g R \cos\alpha $$
)";
    const CheckReport r = eomgen::test::check_text("examples/bead_on_hoop.toml", text);
    REQUIRE(r.equations.size() == 3);
    for (const EquationCheck& e : r.equations) {
        INFO(eomgen::test::describe(e));
        if (e.where.line < 13) {
            CHECK(e.verdict == Verdict::Agrees);
            CHECK(has_note(e, "the quantity its label names"));
        } else {
            REQUIRE(e.verdict == Verdict::Disagrees);
            CHECK(e.wrong_terms.at(0) ==
                  "labelled the Hamiltonian $h$ (“The Hamiltonian”, line 11), but it is the energy $E = T + V$: the label "
                  "or the equation is wrong");
        }
    }
}

TEST_CASE("labels: a double pendulum's θ₂ equation called the θ₁ equation", "[checker][labels]") {
    std::string text = eomgen::test::fixture("double_pendulum_textbook.md");
    const std::string label = "Lagrange's equation for $\\theta_2$:";
    const std::size_t at = text.find(label);
    REQUIRE(at != std::string::npos);
    for (const char* wrong : {"The θ₁ equation:", "Lagrange's equation for $\\theta_{1}$:"}) {
        INFO(wrong);
        const CheckReport right = eomgen::test::check_text("examples/double_pendulum.toml", text);
        const CheckReport r = eomgen::test::check_text("examples/double_pendulum.toml",
                                                       std::string(text).replace(at, label.size(), wrong));
        REQUIRE(r.equations.size() == right.equations.size());
        for (std::size_t k = 0; k < r.equations.size(); ++k) {
            const EquationCheck& e = r.equations[k];
            INFO(eomgen::test::describe(e));
            if (e.where.line != 21) {
                CHECK(e.verdict == right.equations[k].verdict);
                continue;
            }
            CHECK(right.equations[k].verdict == Verdict::Agrees);
            REQUIRE(e.verdict == Verdict::Disagrees);
            CHECK(e.wrong_terms.at(0).find("labelled the $\\theta_1$ equation") == 0);
            CHECK(e.wrong_terms.at(0).find("but it is the $\\theta_2$ equation") != std::string::npos);
        }
    }
}

TEST_CASE("labels: an equation that disagrees is compared with the equation it is closest to", "[checker][labels]") {
    // θ's equation with a flipped sign of the gravity term, called φ's (and then θ's).
    const std::string slip =
        "\n\n$$ m l^2 \\ddot\\theta - m l^2 \\sin\\theta\\cos\\theta\\,\\dot\\phi^2 - m g l \\sin\\theta = 0 $$\n";
    const CheckReport wrong = eomgen::test::check_text(kPendulum, "# S\n\nLagrange's equation for $\\phi$ is:" + slip);
    const CheckReport right = eomgen::test::check_text(kPendulum, "# S\n\nLagrange's equation for $\\theta$ is:" + slip);
    REQUIRE(wrong.equations.size() == 1);
    REQUIRE(right.equations.size() == 1);
    for (const CheckReport* r : {&wrong, &right}) {
        INFO(eomgen::test::describe(r->equations[0]));
        CHECK(r->equations[0].verdict == Verdict::Disagrees);
        CHECK(r->equations[0].compared_with == "the Euler–Lagrange equation for $\\theta$");
        CHECK_FALSE(r->equations[0].corrected.empty());
    }
    CHECK(has_note(wrong.equations[0], "its label (“Lagrange's equation for $\\phi$”, line 3) names the $\\phi$ "
                                       "equation, but the equation is closest to the $\\theta$ equation"));
    CHECK_FALSE(has_note(right.equations[0], "its label"));
}

TEST_CASE("labels: a label names the equations written inline after it, not a display that a 'so' brings",
          "[checker][labels]") {
    // Notes on the spherical pendulum's Hamiltonian written here: on its first run H = … was held to "The
    // conjugate momenta are $p_\theta = …$ and $p_\phi = …$, so" (a false alarm).
    const CheckReport r = eomgen::test::check_text("tests/checker/models/spherical_pendulum.toml",
                                                   eomgen::test::fixture("spherical_hamiltonian_notes.md"));
    for (const EquationCheck& e : r.equations) {
        INFO(eomgen::test::describe(e));
        CHECK(e.verdict != Verdict::Disagrees);
    }
    CHECK(r.count(Verdict::Agrees) >= 11);
}
