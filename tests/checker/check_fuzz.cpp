/** @file check_fuzz.cpp  Random and mangled LaTeX: the parser and the checker answer, they never throw or
 * crash. */
#include "test_paths.hpp"
#include "checker/checker.hpp"
#include "checker/latex_parser.hpp"
#include "model/model_file.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <string>
#include <vector>

namespace {

const std::vector<std::string> kPieces = {"\\frac",
                                          "{",
                                          "}",
                                          "\\left(",
                                          "\\right)",
                                          "(",
                                          ")",
                                          "^",
                                          "_",
                                          "\\int",
                                          "d",
                                          "x",
                                          "\\theta",
                                          "\\dot",
                                          "\\ddot",
                                          "=",
                                          "+",
                                          "-",
                                          "/",
                                          "\\cdot",
                                          "\\times",
                                          "2",
                                          "0.5",
                                          "\\sin",
                                          "\\cos",
                                          "\\sqrt",
                                          "[",
                                          "]",
                                          "|",
                                          ",",
                                          "\\psi",
                                          "m",
                                          "w",
                                          "g",
                                          "\\prime",
                                          "'",
                                          "\\\\",
                                          "&",
                                          "\\mathbf",
                                          "\\text",
                                          "\\partial",
                                          "t",
                                          "\\begin{array}",
                                          "\\end{array}",
                                          "\\pi",
                                          "\\circ",
                                          "\\left|",
                                          "\\right|",
                                          "\\approx",
                                          "<",
                                          "\\operatorname{dot}",
                                          "%",
                                          "\\quad",
                                          "\\rightarrow",
                                          " ",
                                          "\\,",
                                          "1",
                                          "\\infty",
                                          "\\sum",
                                          "0",
                                          // The LaTeX people publish (latex_normalize, Poisson brackets).
                                          "&theta;", "&#952;", "&#x3b8", "&amp;", "&", "\xCE\xB8", "\xCC\x87",
                                          "\xC2\xB2", "\xC2\xBD", "\xE2\x88\x92", "\\{", "\\}", "\\tag{1}",
                                          "\\quad (1)", "\\text{const}", "p_\\psi", "H", "\\simeq"};

std::string random_formula(std::mt19937& rng, int length) {
    std::uniform_int_distribution<std::size_t> pick(0, kPieces.size() - 1);
    std::string s;
    for (int i = 0; i < length; ++i) s += kPieces[pick(rng)] + (rng() % 3 == 0 ? " " : "");
    return s;
}

}  // namespace

TEST_CASE("fuzz: random formulas never make the parser throw", "[checker][parser]") {
    std::mt19937 rng(20240601u);
    eomgen::checker::LatexContext ctx;
    const GiNaC::symbol psi("psi", "\\psi"), t("t");
    ctx.names["\\psi"] = psi;
    ctx.names["t"] = t;
    ctx.time = t;
    for (int i = 0; i < 3000; ++i) {
        const std::string f = random_formula(rng, 1 + int(rng() % 25));
        INFO(f);
        std::vector<eomgen::checker::Chain> chains;
        REQUIRE_NOTHROW(chains = eomgen::checker::parse_math(f, ctx));
        for (const auto& c : chains)
            for (const auto& s : c.sides)
                if (!s.ok) CHECK(s.error_offset <= f.size());
    }
    // Bytes, including broken UTF-8 and NUL.
    for (int i = 0; i < 1000; ++i) {
        std::string f;
        for (int k = int(rng() % 40); k > 0; --k) f += char(rng() % 256);
        REQUIRE_NOTHROW(eomgen::checker::parse_math(f, ctx));
        REQUIRE_NOTHROW(eomgen::checker::canonical_name(f));
    }
}

TEST_CASE("fuzz: mangled derivations never make the checker throw", "[checker]") {
    const eomgen::Model model = eomgen::load_model(eomgen_test::source_dir() + "/models/door.toml");
    const eomgen::Equations eq = eomgen::derive_equations(model);
    std::mt19937 rng(7u);
    const std::string base =
        "# Door\n$$\n\\begin{aligned}\nT & =\\frac{1}{6} m w^{2} \\dot{\\psi}^{2} \\\\\n& =\\frac{1}{2} I "
        "\\dot{\\psi}^{2}\n"
        "\\end{aligned}\n$$\n$V=\\frac{m g}{2}(w \\sin \\theta \\sin \\psi+h \\cos \\theta)$ and "
        "$$\\frac{d}{d t}\\left(\\frac{1}{3} m w^{2} \\dot{\\psi}\\right)+\\frac{1}{2} m g w \\sin \\theta "
        "\\cos \\psi=0$$\n";
    for (int i = 0; i < 60; ++i) {
        std::string doc = base;
        // Delete, duplicate or insert a few pieces.
        for (int k = 0; k < 4; ++k) {
            const std::size_t at = rng() % doc.size();
            switch (rng() % 3) {
                case 0:
                    doc.erase(at, 1 + rng() % 6);
                    break;
                case 1:
                    doc.insert(at, doc.substr(rng() % doc.size(), rng() % 8));
                    break;
                default:
                    doc.insert(at, " " + random_formula(rng, 1 + int(rng() % 4)) + " ");
            }
            if (doc.empty()) doc = "$";
        }
        INFO(doc);
        const eomgen::checker::Derivation d = eomgen::checker::parse_derivation(doc, "fuzz.md");
        REQUIRE_NOTHROW(eomgen::checker::check_derivation(model, eq, d, {}));
    }
}
