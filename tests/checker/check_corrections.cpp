/** @file check_corrections.cpp  A property over every fixture and the seed's reports: each correction the
 * checker prints holds. It is checked here from the outside, as a line the text could have written: appended
 * to the text as a display of its own, with the same map, it must agree. No `0 (...)` or `- (0)` forms, and no
 * disagreement without its correction. */
#include "test_paths.hpp"
#include "checked_text.hpp"
#include "checker/symbol_map.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using eomgen::checker::CheckOptions;
using eomgen::checker::CheckReport;
using eomgen::checker::EquationCheck;
using eomgen::checker::MapEntry;
using eomgen::checker::Verdict;

const std::string kSource = eomgen_test::source_dir();

struct Case {
    std::string model;    ///< relative to the source tree
    std::string text;     ///< relative to the source tree (or absolute)
    std::string section;  ///< --section, or ""
    std::string map;      ///< map file relative to the source tree, or ""
    std::vector<MapEntry> entries = {};
};

std::string read(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// The options for a correction appended at the end of the text, as if written on `line`: entries scoped to
/// that line apply everywhere, the other entries of the same names are left out.
CheckOptions options_for_line(const CheckOptions& o, int line) {
    CheckOptions out;
    out.sections = o.sections;
    std::vector<std::string> scoped;
    for (const MapEntry& e : o.map)
        if (e.first_line != 0 && line >= e.first_line && line <= e.last_line) scoped.push_back(e.name);
    for (MapEntry e : o.map) {
        const bool here = e.first_line != 0 && line >= e.first_line && line <= e.last_line;
        if (e.first_line != 0 && !here) continue;
        if (!here && std::find(scoped.begin(), scoped.end(), e.name) != scoped.end()) continue;
        e.first_line = e.last_line = 0;
        out.map.push_back(e);
    }
    return out;
}

/// Checks every correction of the case's report; returns how many were checked.
int check_case(const Case& c) {
    CheckOptions o;
    if (!c.section.empty()) o.sections.push_back(c.section);
    if (!c.map.empty()) o.map = eomgen::checker::load_map_file(kSource + "/" + c.map);
    o.map.insert(o.map.end(), c.entries.begin(), c.entries.end());
    const std::string path = c.text[0] == '/' ? c.text : kSource + "/" + c.text;
    const std::string text = read(path);
    const CheckReport r = eomgen::test::check_text(c.model, text, o);
    std::size_t end = text.size();
    if (!c.section.empty()) {
        const auto d = eomgen::checker::parse_derivation(text, path);
        const auto selected = eomgen::checker::select_sections(d, o.sections);
        REQUIRE_FALSE(selected.empty());
        end = d.sections[std::size_t(selected.front())].end;
    }
    int checked = 0;
    for (const EquationCheck& e : r.equations) {
        INFO(c.text << ":" << e.where.line << ": " << e.equation << "\n  corrected: " << e.corrected);
        for (const std::string& n : e.notes) INFO("note: " << n);
        // A wrong label (labels.hpp) has no correction: the label or the equation is the slip. Nor has a line
        // whose two sides change at different rates on a particular motion (motions.hpp: `\psi = \pi/2 - \Omega`,
        // which lacks a t the checker cannot guess).
        const bool drifts = !e.wrong_terms.empty() && e.wrong_terms[0].find("changes on the motion at the rate") !=
                                                          std::string::npos;
        if (e.verdict == Verdict::Disagrees && e.compared_with.rfind("its label (", 0) != 0 && !drifts)
            CHECK_FALSE(e.corrected.empty());
        if (e.corrected.empty()) continue;
        std::string flat;
        for (char ch : e.corrected)
            if (ch != ' ') flat += ch;
        CHECK(flat.find("=0\\left(") == std::string::npos);
        CHECK(flat.find("-\\left(0\\right)") == std::string::npos);
        // The correction as a display of its own at the end of the section checked (the end of the text).
        const std::string appended = text.substr(0, end) + "\n\n$$" + e.corrected + "$$\n\n" + text.substr(end);
        const CheckReport again = eomgen::test::check_text(c.model, appended, options_for_line(o, e.where.line));
        const int last_line = int(std::count(text.begin(), text.begin() + long(end), '\n')) + 3;
        bool any = false;
        for (const EquationCheck& a : again.equations) {
            if (a.where.line != last_line) continue;
            any = true;
            INFO("checked again: " << eomgen::checker::verdict_name(a.verdict) << ": " << a.reason);
            CHECK(a.verdict == Verdict::Agrees);
        }
        CHECK(any);
        ++checked;
    }
    return checked;
}

}  // namespace

TEST_CASE("corrections check themselves: every fixture", "[checker][corrections]") {
    const std::vector<Case> cases = {
        {"models/door.toml", "tests/checker/fixtures/door_correct.md", "", ""},
        {"models/door.toml", "tests/checker/fixtures/door_planted.md", "", ""},
        {"models/pendulum_5_20.toml", "tests/checker/fixtures/pendulum_correct.md", "", "", {{"I_{0}", "\\frac{1}{2} M a^{2}", "test"}}},
        {"models/pendulum_5_20.toml", "tests/checker/fixtures/pendulum_planted.md", "", ""},
        {"models/rolling_cone.toml", "tests/checker/fixtures/cone_planted.md", "", ""},
        {"models/pendulum.toml", "tests/checker/fixtures/pendulum_web_page.md", "", ""},
        {"examples/double_pendulum.toml", "tests/checker/fixtures/double_pendulum_textbook.md", "", ""},
        {"tests/checker/models/double_pendulum_cartesian.toml", "tests/checker/fixtures/double_pendulum_author_form.md", "", ""},
        {"tests/checker/models/plane_pendulum.toml", "tests/checker/fixtures/hamilton_pendulum_planted.md", "", ""},
        {"tests/checker/models/spherical_pendulum.toml", "tests/checker/fixtures/hamilton_spherical_pendulum_planted.md", "", ""},
        {"models/heavy_symmetric_top.toml", "tests/checker/fixtures/hamilton_heavy_top_planted.md", "", "",
         {{"I", "I_{1} + M l^{2}", "test"}}},
        {"tests/checker/models/plane_pendulum.toml", "tests/checker/fixtures/small_oscillations.md", "", ""},
        {"tests/checker/models/spherical_pendulum.toml", "tests/checker/fixtures/labels_spherical_pendulum_planted.md", "", ""},
        {"models/door.toml", "tests/checker/fixtures/repro/budget_power_of_sum_door.md", "", ""},
        {"models/door.toml", "tests/checker/fixtures/repro/budget_common_denominator_door.md", "", ""},
        {"models/door.toml", "tests/checker/fixtures/repro/hang_prose_between_dollars_door.md", "", ""},
        {"models/pendulum_5_20.toml", "tests/checker/fixtures/repro/hang_prose_between_dollars_pendulum.md", "", ""},
        {"models/pendulum_5_20.toml", "tests/checker/fixtures/repro/fuzz_check_stray_bracket_pendulum.md", "", ""},
        {"models/triangle_plate_5_15.toml", "tests/checker/fixtures/matrices_plate.md", "", ""},
    };
    int checked = 0;
    for (const Case& c : cases) checked += check_case(c);
    // The planted fixtures hold 5 + 5 + 2 + 3 + 2 mistakes at least, each with a correction.
    CHECK(checked >= 17);
}

TEST_CASE("corrections check themselves: the seed's reports", "[checker][corrections][seed]") {
    const char* env = std::getenv("EOMGEN_SEED");
    const std::string seed = env ? env : kSource + "/../shared/seed/000_e6b9f63eaa50a64e.txt";
    if (!std::filesystem::exists(seed)) {
        WARN("seed text " << seed << " not found [skipped]");
        return;
    }
    // The entries of tests/checker/CMakeLists.txt (cli:check_report_*).
    const std::vector<Case> cases = {
        {"models/door.toml", seed, "Exercise 30", "docs/checks/door.map.toml"},
        {"models/pendulum_5_20.toml", seed, "5-20", "docs/checks/pendulum_5_20.map.toml"},
        {"models/torque_free_top.toml", seed, "Derivation 5-6", "docs/checks/torque_free_top.map.toml"},
        {"models/triangle_plate_5_15.toml", seed, "Exercise 5-15", ""},
        {"models/rolling_cone.toml", seed, "5-17", "docs/checks/rolling_cone.map.toml"},
        {"models/dumbbell_5_18.toml", seed, "Exercise 5-18", "docs/checks/dumbbell_5_18.map.toml"},
        {"models/rolling_sphere.toml", seed, "Exercise 25", "docs/checks/rolling_sphere.map.toml"},
    };
    int checked = 0;
    for (const Case& c : cases) checked += check_case(c);
    CHECK(checked >= 15);  // the seed reports' 15 disagreements, each with its correction
}
