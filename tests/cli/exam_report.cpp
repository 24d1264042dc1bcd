// `eomgen report` and `eomgen show --latex --standalone` as a user runs them, on model files and derivations
// this test writes itself: the report's equations are show --latex's, its simulation, plot, CSV and drift
// table are there and true, a derivation's verdicts are in it, hostile text stays text, failures write nothing.
#include "test_paths.hpp"
#include "cli/eomgen_process.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace eomgen_test;

namespace {

const fs::path kWork = fs::path(eomgen_test::binary_dir()) / "tests" / "cli" / "work" / "report";

Result eomgen(const std::vector<std::string>& args, std::map<std::string, std::string> env = {}) {
    return run_eomgen(kWork, args, std::move(env));
}

fs::path write(const std::string& name, const std::string& text) { return write_whole(kWork, name, text); }

// A bead on a hoop spun at a fixed rate: T has a velocity-free part, h is conserved, the energy is not.
const std::string kBead = R"toml(name = "bead"
title = "Bead on a spinning hoop (written by exam_report)"
[[coordinates]]
name = "a"
latex = '\alpha'
initial = 0.8
rate = 0.1
[[parameters]]
name = "m"
value = 0.2
unit = "kg"
description = "mass of the bead"
[[parameters]]
name = "R"
value = 0.5
unit = "m"
[[parameters]]
name = "w"
latex = '\omega'
value = 6
unit = "1/s"
[[parameters]]
name = "g"
value = 9.81
[lagrangian]
T = "m/2*R^2*(a'^2 + w^2*sin(a)^2)"
V = "-m*g*R*cos(a)"
)toml";

/// The rows of `show --latex` (`lhs &= rhs`, without the line break and the comment after them).
std::vector<std::string> latex_rows(const std::string& show) {
    std::vector<std::string> rows;
    std::istringstream in(show);
    for (std::string line; std::getline(in, line);) {
        if (line.find("&=") == std::string::npos) continue;
        const auto comment = line.find("  % ");
        if (comment != std::string::npos) line = line.substr(0, comment);
        if (line.size() >= 3 && line.compare(line.size() - 3, 3, " \\\\") == 0) line.resize(line.size() - 3);
        rows.push_back(line);
    }
    return rows;
}

}  // namespace

TEST_CASE("eomgen report: show --latex's equations, a simulation with its plot, CSV and drift", "[report]") {
    const fs::path model = write("bead.toml", kBead);
    const fs::path dir = kWork / "bead report";
    fs::remove_all(dir);
    const Result r = eomgen({"report", model.string(), "-o", dir.string(), "--t-end", "5", "--quiet"});
    INFO(r.output);
    REQUIRE(r.code == 0);
    const std::string md = read(dir / "bead.md");
    REQUIRE(!md.empty());

    const Result show = eomgen({"show", "--latex", model.string()});
    REQUIRE(show.code == 0);
    const std::vector<std::string> rows = latex_rows(show.output);
    REQUIRE(rows.size() >= 8);  // T, V, L, one equation, M, f, h, p
    for (const std::string& row : rows) {
        if (row.find("\\text{const}") != std::string::npos) continue;  // conserved: listed with reasons instead
        INFO(row);
        CHECK(md.find(row) != std::string::npos);
    }
    CHECK(md.find("| `w` | $\\omega$ | 6 | 1/s |") != std::string::npos);
    CHECK(md.find("mass of the bead") != std::string::npos);

    // The simulation: its CSV (201 rows and a header), its plot, and h's drift as the CSV gives it.
    const auto csv = read_csv(dir / "bead.csv");
    REQUIRE(csv.size() == 202);
    const std::string png = read(dir / "bead.png");
    REQUIRE(png.size() > 1000);
    CHECK(png.substr(0, 8) == "\x89PNG\r\n\x1a\n");
    CHECK(md.find("![coordinates, invariants and residuals against t](bead.png)") != std::string::npos);
    const int e = column(csv[0], "energy");
    const double h0 = std::stod(csv[1][std::size_t(e)]);
    double worst = 0;
    for (std::size_t k = 1; k < csv.size(); ++k)
        worst = std::max(worst, std::abs(std::stod(csv[k][std::size_t(e)]) - h0) / std::abs(h0));
    const std::regex drift(R"(\| \$h\$ \| (\S+) \| (\S+) \(relative\) \|)");
    std::smatch m;
    REQUIRE(std::regex_search(md, m, drift));
    CHECK(std::stod(m[1]) == Approx(h0).epsilon(1e-2));
    CHECK(std::stod(m[2]) == Approx(worst).epsilon(1e-2).margin(1e-300));
    CHECK(worst < 1e-8);
}

TEST_CASE("eomgen report: the drift of the invariants of a model with units, whose CSV headers carry them", "[report]") {
    // "energy [J]": the table was left out when the headers had units (the shipped bead, the main job's report).
    const fs::path dir = kWork / "units report";
    fs::remove_all(dir);
    const Result r = eomgen({"report", eomgen_test::source_dir() + "/examples/bead_on_hoop.toml", "-o",
                             dir.string(), "--t-end", "2", "--quiet"});
    INFO(r.output);
    REQUIRE(r.code == 0);
    const std::string md = read(dir / "bead_on_hoop.md");
    CHECK(read(dir / "bead_on_hoop.csv").find("energy [J]") != std::string::npos);
    CHECK(std::regex_search(md, std::regex(R"(\| \$h\$ \| -0\.534 \| \S+ \(relative\) \|)")));
}

TEST_CASE("eomgen report: the motion as a page beside the plot where the model says what to draw", "[report]") {
    // Without [[draw]] (the bead above has none): no page, no link.
    const fs::path plain = write("plain_bead.toml", kBead);
    const fs::path plain_dir = kWork / "plain report";
    fs::remove_all(plain_dir);
    REQUIRE(eomgen({"report", plain.string(), "-o", plain_dir.string(), "--t-end", "1", "--quiet"}).code == 0);
    CHECK_FALSE(fs::exists(plain_dir / "bead.html"));
    CHECK(read(plain_dir / "bead.md").find(".html") == std::string::npos);
    // With one: the page, from the report's samples, linked under the plot.
    const fs::path drawn = write("drawn_bead.toml", std::string(kBead) + "\n[[draw]]\npoint = [\"R*sin(a)\", \"-R*cos(a)\"]\n");
    const fs::path dir = kWork / "drawn report";
    fs::remove_all(dir);
    const Result r = eomgen({"report", drawn.string(), "-o", dir.string(), "--t-end", "1", "--quiet"});
    INFO(r.output);
    REQUIRE(r.code == 0);
    const std::string page = read(dir / "bead.html");
    CHECK(page.find("<canvas id=\"view\">") != std::string::npos);
    CHECK(page.find("\"kind\":\"point\"") != std::string::npos);
    CHECK(read(dir / "bead.md").find("[bead.html](bead.html)") != std::string::npos);
}

TEST_CASE("eomgen report checks a derivation and keeps its verdicts, --format latex is a whole document", "[report]") {
    const fs::path model = write("bead.toml", kBead);
    // Right T; V with the wrong sign (the slip the report must show).
    const fs::path text = write("bead_derivation.md", R"md(# The bead

$$T = \frac{1}{2} m R^2 \left(\dot\alpha^2 + \omega^2 \sin^2\alpha\right)$$

$$V = m g R \cos\alpha$$
)md");
    const fs::path dir = kWork / "checked";
    fs::remove_all(dir);
    Result r = eomgen({"report", model.string(), "-o", dir.string(), "--derivation", text.string(), "--no-simulation"});
    INFO(r.output);
    REQUIRE(r.code == 0);
    const std::string md = read(dir / "bead.md");
    CHECK(md.find("## Derivation bead\\_derivation.md") != std::string::npos);
    CHECK(md.find("Not run") != std::string::npos);
    CHECK(md.find("disagrees") != std::string::npos);
    CHECK(md.find("\n### ") != std::string::npos);  // the checker's headings, one level under the report's

    r = eomgen({"report", model.string(), "-o", dir.string(), "--derivation", text.string(), "--format", "latex",
                "--t-end", "1", "--quiet"});
    INFO(r.output);
    REQUIRE(r.code == 0);
    const std::string tex = read(dir / "bead.tex");
    CHECK(tex.find("\\documentclass") == tex.find('\\'));  // a comment line, then the class
    CHECK(tex.find("\\usepackage{amsmath}") != std::string::npos);
    CHECK(tex.find("\\begin{document}") != std::string::npos);
    CHECK(tex.rfind("\\end{document}\n") == tex.size() - 15);
    CHECK(tex.find("\\includegraphics[width=\\textwidth]{bead.png}") != std::string::npos);
    // The derivation's text is shown as escaped text, never compiled as the author's LaTeX.
    CHECK(tex.find("V = m g R \\textbackslash{}cos") != std::string::npos);
    CHECK(tex.find("\\textbf{disagrees}") != std::string::npos);
#ifdef EOMGEN_PDFLATEX
    {
        // Where pdflatex was found when the tests were configured, the document compiles.
        const std::string command = "cd '" + dir.string() + "' && '" + EOMGEN_PDFLATEX +
                                    "' -interaction=nonstopmode -halt-on-error -no-shell-escape bead.tex > pdflatex.log 2>&1";
        CHECK(std::system(command.c_str()) == 0);
        CHECK(fs::exists(dir / "bead.pdf"));
    }
#endif
}

TEST_CASE("eomgen report: hostile model text stays text, a broken compiler writes nothing", "[report]") {
    std::string hostile = kBead;
    hostile.replace(hostile.find("title = \"Bead"), 0,
                    "title = 'Bead $x$ \\input{/etc/passwd} <script>alert(1)</script> # | ` '\n#");
    const fs::path model = write("hostile.toml", hostile);
    const fs::path dir = kWork / "hostile";
    fs::remove_all(dir);
    Result r = eomgen({"report", model.string(), "-o", dir.string(), "--no-simulation", "--format", "latex"});
    INFO(r.output);
    REQUIRE(r.code == 0);
    const std::string tex = read(dir / "bead.tex");
    CHECK(tex.find("\\input{") == std::string::npos);
    CHECK(tex.find("\\textbackslash{}input\\{/etc/passwd\\}") != std::string::npos);
    r = eomgen({"report", model.string(), "-o", dir.string(), "--no-simulation"});
    REQUIRE(r.code == 0);
    const std::string md = read(dir / "bead.md");
    CHECK(md.find("<script>") == std::string::npos);
    CHECK(md.find("&lt;script&gt;") != std::string::npos);

    // A compiler that fails: exit 4, the log named, no report and no partial file in the directory.
    const fs::path broken = kWork / "broken";
    fs::remove_all(broken);
    r = eomgen({"report", model.string(), "-o", broken.string()}, {{"CXX", "/bin/false"}});
    CHECK(r.code == 4);
    CHECK(r.output.find("log: ") != std::string::npos);
    CHECK_FALSE(fs::exists(broken / "bead.md"));

    // show --standalone is a document, and needs --latex.
    const Result doc = eomgen({"show", "--latex", "--standalone", model.string()});
    REQUIRE(doc.code == 0);
    CHECK(doc.output.find("\\begin{document}") != std::string::npos);
    CHECK(doc.output.find("\\input{") == std::string::npos);
    CHECK(eomgen({"show", "--standalone", model.string()}).code == 2);
}
