/** @file exam_derivation.cpp  Sections, display and inline math, aligned rows, places in the file. */
#include "checker/derivation.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace {

const char* const kText =
    "# Title\n"                                 // 1
    "\n"                                        // 2
    "Text with $a = b$ and a price of \\$5.\n"  // 3
    "\n"                                        // 4
    "## First part\n"                           // 5
    "$$\n"                                      // 6
    "\\begin{aligned}\n"                        // 7
    "T & =\\frac{1}{2} m v^{2} \\\\\n"          // 8
    "& =E\n"                                    // 9
    "\\end{aligned}\n"                          // 10
    "$$\n"                                      // 11
    "```\n"                                     // 12
    "$$ not math $$\n"                          // 13
    "```\n"                                     // 14
    "### Sub\n"                                 // 15
    "\\[ x = 1 \\]\n"                           // 16
    " ## Second part\n"                         // 17
    "$$ V = m g h $$\n";                        // 18

}  // namespace

TEST_CASE("derivation: headings, math rows and their places", "[checker]") {
    const eomgen::checker::Derivation d = eomgen::checker::parse_derivation(kText, "x.md");
    REQUIRE(d.sections.size() == 4);
    CHECK(d.sections[0].title == "Title");
    CHECK(d.sections[1].title == "First part");
    CHECK(d.sections[1].level == 2);
    CHECK(d.sections[3].title == "Second part");  // a heading indented by a space still counts
    CHECK(d.sections[3].line == 17);

    REQUIRE(d.rows.size() == 5);
    CHECK_FALSE(d.rows[0].display);
    CHECK(d.rows[0].text == "a = b");
    CHECK(d.position(d.rows[0].offset).line == 3);
    CHECK(d.position(d.rows[0].offset).column == 12);
    // Aligned rows: split at \\, & and the environment blanked, offsets still the file's.
    CHECK(d.rows[1].display);
    CHECK(d.rows[1].block == d.rows[2].block);
    CHECK(d.rows[2].row_in_block == 1);
    CHECK(d.rows[1].text.find('&') == std::string::npos);
    CHECK(d.rows[1].text.find("\\begin") == std::string::npos);
    const std::size_t eq = d.rows[2].text.find('=');
    CHECK(d.text[d.rows[2].offset + eq] == '=');
    CHECK(d.position(d.rows[2].offset + eq).line == 9);
    CHECK(d.rows[3].text == " x = 1 ");
    CHECK(d.rows[3].section == 2);
    CHECK(d.rows[4].section == 3);
}

TEST_CASE("derivation: --section selects headings and their subsections", "[checker]") {
    const eomgen::checker::Derivation d = eomgen::checker::parse_derivation(kText, "x.md");
    const std::vector<int> first = eomgen::checker::select_sections(d, {"first"});
    REQUIRE(first.size() == 1);
    int selected = 0;
    for (const auto& r : d.rows) selected += eomgen::checker::row_selected(d, r, first, false) ? 1 : 0;
    CHECK(selected == 3);  // the two aligned rows and \[ x = 1 \] under "### Sub"
    CHECK(eomgen::checker::select_sections(d, {"nothing like it"}).empty());
    CHECK(eomgen::checker::select_sections(d, {}).size() == 4);
}

TEST_CASE("derivation: never throws on odd text", "[checker]") {
    for (const char* t : {"", "$", "$$", "$$ unterminated", "\\begin{aligned} a & = b", "# ", "```", "$a$$b$",
                          "\\[", "\\(x\\)", "$$\\begin{aligned}\\end{aligned}$$", "\n\n\n$x=1$"}) {
        CHECK_NOTHROW(eomgen::checker::parse_derivation(t, "odd.md"));
    }
}

// Regression (shared/repro/check_hang_*.md): prose between two '$$' was read as one formula. Delimiters that
// do not pair up are reported at their place, and the math around them is still found.
TEST_CASE("derivation: delimiters that do not pair up are reported at their place", "[checker]") {
    using eomgen::checker::parse_derivation;
    auto messages = [](const eomgen::checker::Derivation& d) {
        std::string all;
        for (const auto& p : d.problems) {
            const auto at = d.position(p.offset);
            all += std::to_string(at.line) + ":" + std::to_string(at.column) + " " + p.message + "\n";
        }
        return all;
    };
    SECTION("a display holding a '$' is not a display; the inline math in it is read") {
        const auto d = parse_derivation("$$\nSo $x = 1$ and\nthen $y = 2$.\n$$\n", "t.md");
        INFO(messages(d));
        REQUIRE(d.problems.size() == 2);
        CHECK(d.position(d.problems[0].offset).line == 1);
        CHECK(d.problems[0].message.find("a '$' at 2:4") != std::string::npos);
        CHECK(d.position(d.problems[1].offset).line == 4);
        CHECK(d.problems[1].message.find("not closed") != std::string::npos);
        REQUIRE(d.rows.size() == 2);
        CHECK(d.rows[0].text == "x = 1");
        CHECK(d.rows[1].text == "y = 2");
    }
    SECTION("a blank line inside '$$' ... '$$'") {
        const auto d = parse_derivation("Text\n$$ a = b\n\nmore text $$\n", "t.md");
        REQUIRE(d.problems.size() == 2);
        CHECK(d.problems[0].message.find("a blank line at 3:1") != std::string::npos);
    }
    SECTION("unclosed \\[, \\begin, $ and \\(") {
        const auto d = parse_derivation("\\[ x = 1\n\n\\begin{align} a &= b\n\nSo $x = 1 and\n\nthen \\(y\n", "t.md");
        INFO(messages(d));
        REQUIRE(d.problems.size() == 4);
        CHECK(d.position(d.problems[0].offset).line == 1);
        CHECK(d.problems[1].message.find("\\end{align}") != std::string::npos);
        CHECK(d.position(d.problems[2].offset).column == 4);
        CHECK(d.problems[3].message.find("\\(") != std::string::npos);
    }
    SECTION("what is not a problem") {
        // (A blank line between the formula and its closing or opening `$$` is space, as renderers take it.)
        for (const char* t : {"$$ a = b \\text{ for $x > 0$} $$", "a price of $5 and $", "\\$ x", "$$\na\n$$\n\n$b$",
                              "costs 5 $ or so", "$$\na = b % planted[$b$ where $c$ belongs]\n$$",
                              "$$ \\omega^2 = g/l\n\n$$\n", "$$\n\n a = b $$\n"}) {
            const auto d = parse_derivation(t, "t.md");
            INFO(t << "\n" << messages(d));
            CHECK(d.problems.empty());
        }
    }
}

TEST_CASE("derivation: an environment inside single dollars and rows broken with \\\\ in $$ are rows", "[checker]") {
    const char* const text =
        "$\\begin{align} T &= a \\\\ V &= b \\end{align}$\n"  // 1: as Jupyter notebooks write a display
        "\n"
        "$$ x = 1 \\\\ y = 2 $$\n"                             // 3: MathJax breaks the line at \\ without an environment
        "\n"
        "$$ M = \\begin{pmatrix} a \\\\ b \\end{pmatrix} $$\n";  // 5: a \\ inside an environment is no row break
    const eomgen::checker::Derivation d = eomgen::checker::parse_derivation(text, "x.md");
    REQUIRE(d.rows.size() == 5);
    CHECK(d.rows[0].display);
    CHECK(d.rows[0].text.find("T") != std::string::npos);
    CHECK(d.rows[0].text.find("V") == std::string::npos);
    CHECK(d.rows[1].text.find("V") != std::string::npos);
    CHECK(d.rows[2].text.find("x = 1") != std::string::npos);
    CHECK(d.rows[3].text.find("y = 2") != std::string::npos);
    CHECK(d.rows[3].row_in_block == 1);
    CHECK(d.rows[4].text.find("pmatrix") != std::string::npos);
}

TEST_CASE("derivation: forums' delimiters, math in headings, wrapped environments", "[checker]") {
    const char* const text =
        "## The Lagrangian $L = T - V$\n"                                                   // 1: a heading's math
        "Given ##\\dot\\varphi=\\omega## and [itex]x = 1[/itex].\n"                        // 2: forum inline
        "[tex]y = 2[/tex]\n"                                                                 // 3: forum display
        "$$\\begin{equation}\\begin{aligned} a &= 1 \\\\ b &= 2 \\end{aligned}\\end{equation}$$\n"  // 4: nested
        "$$ \\left\\{ \\begin{array}{l} x = l\\sin\\phi \\\\ y = -l\\cos\\phi \\end{array} \\right. $$\n"  // 5
        "### not math: ## alone\n";                                                          // 6
    const eomgen::checker::Derivation d = eomgen::checker::parse_derivation(text, "x.md");
    std::vector<std::string> rows;
    for (const auto& r : d.rows) {
        std::string t = r.text;
        t.erase(0, t.find_first_not_of(' '));
        t.erase(t.find_last_not_of(' ') + 1);
        rows.push_back(std::to_string(d.position(r.offset).line) + ": " + t);
    }
    INFO(Catch::Detail::stringify(rows));
    REQUIRE(rows.size() == 8);
    CHECK(rows[0] == "1: L = T - V");
    CHECK(rows[1] == "2: \\dot\\varphi=\\omega");
    CHECK(rows[2] == "2: x = 1");
    CHECK(rows[3] == "3: y = 2");
    CHECK(rows[4].find("a") != std::string::npos);
    CHECK(rows[5].find("b") != std::string::npos);
    CHECK(rows[6].find("x = l\\sin\\phi") != std::string::npos);
    CHECK(rows[7].find("y = -l\\cos\\phi") != std::string::npos);
    CHECK(rows[7].find("\\right") == std::string::npos);  // the wrap's `\right.` closes the system, not the row
    CHECK(d.sections.size() == 2);
    CHECK(d.sections[0].title == "The Lagrangian $L = T - V$");
}

TEST_CASE("derivation: an array whose cells are equations gives one row per cell", "[checker]") {
    // The free cart's README: `\begin{array}{cc} x_1 = x & y_1 = 0 \\ … \end{array}`; its `&` were alignment marks,
    // so `x_1 = x y_1 = 0` was read as one chain.
    const auto d = eomgen::checker::parse_derivation(
        "$$\\begin{array}{cc} x_1 = x & y_1 = 0 \\\\ x_2 = x + l & y_2 = -l \\end{array}$$\n"
        "$$\\begin{aligned} a &= b \\\\ c &= d \\end{aligned}$$\n"
        "$$\\begin{array}{rcl} e & = & f \\end{array}$$\n",
        "t.md");
    std::vector<std::string> rows;
    for (const auto& r : d.rows) {
        std::string t = r.text;
        t.erase(0, t.find_first_not_of(' '));
        t.erase(t.find_last_not_of(' ') + 1);
        rows.push_back(t);
    }
    INFO(Catch::Detail::stringify(rows));
    REQUIRE(rows.size() == 7);
    CHECK(rows[0] == "x_1 = x");
    CHECK(rows[1] == "y_1 = 0");
    CHECK(d.position(d.rows[1].offset).column == 30);  // the cell starts just after its `&`, in the file
    CHECK(rows[3] == "y_2 = -l");
    CHECK(rows[4].find("a") != std::string::npos);  // aligned: `a &= b` stays one row
    CHECK(rows[4].find("b") != std::string::npos);
    CHECK(rows[6].find("e") != std::string::npos);  // `e & = & f`: cells without a relation, one row
    CHECK(rows[6].find("f") != std::string::npos);
}
