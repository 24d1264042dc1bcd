/** @file exam_numbers.cpp  Numbers a derivation works out: units to SI, the model's parameter values (or
 * --set, or a value the text chooses), agreement to the printed digits; planted wrong numbers are found on
 * their line and nothing else raises an alarm. */
#include "test_paths.hpp"
#include "checked_text.hpp"
#include "checker/checker.hpp"
#include "checker/symbol_map.hpp"
#include "checker/printed_numbers.hpp"
#include "checker/units.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <string>

namespace {

using eomgen::checker::CheckOptions;
using eomgen::checker::CheckReport;
using eomgen::checker::EquationCheck;
using eomgen::checker::Role;
using eomgen::checker::Verdict;

const std::string kSource = eomgen_test::source_dir();
const std::string kCorrect = kSource + "/tests/checker/fixtures/numbers_door_correct.md";
const std::string kPlanted = kSource + "/tests/checker/fixtures/numbers_door_planted.md";

CheckReport check(const std::string& path, const CheckOptions& options = {}) {
    const auto& door = eomgen::test::derived_model("models/door.toml");
    return eomgen::checker::check_derivation(door.first, door.second, eomgen::checker::read_derivation(path),
                                             options);
}

std::string describe(const EquationCheck& e) {
    return std::to_string(e.where.line) + ": " + eomgen::checker::verdict_name(e.verdict) + ": " + e.equation +
           " [" + e.compared_with + "] " + e.reason;
}

/// The check of the link whose text is `equation` (exactly one).
const EquationCheck& find(const CheckReport& r, const std::string& equation) {
    const EquationCheck* found = nullptr;
    for (const EquationCheck& e : r.equations)
        if (e.equation == equation) {
            REQUIRE(found == nullptr);
            found = &e;
        }
    INFO(equation);
    REQUIRE(found != nullptr);
    return *found;
}

}  // namespace

TEST_CASE("numbers: units and their factors to SI", "[checker][numbers]") {
    using eomgen::checker::unit_factor;
    CHECK(unit_factor("cm").value() == Approx(0.01));
    CHECK(unit_factor("~s").value() == Approx(1.0));
    CHECK(unit_factor("sec").value() == Approx(1.0));
    CHECK(unit_factor("min").value() == Approx(60.0));
    CHECK(unit_factor("degrees").value() == Approx(M_PI / 180));
    CHECK(unit_factor("km/hr").value() == Approx(1000.0 / 3600.0));
    CHECK(unit_factor("m/s^{2}").value() == Approx(1.0));
    CHECK(unit_factor("g cm^2").value() == Approx(1e-7));
    CHECK(unit_factor("~N~m").value() == Approx(1.0));  // N·m, not "Nm"
    CHECK(unit_factor("s^{-1}").value() == Approx(1.0));
    CHECK_FALSE(unit_factor(""));
    CHECK_FALSE(unit_factor("m//s"));
    CHECK_FALSE(unit_factor("/s"));
    CHECK_FALSE(unit_factor("s^"));
    CHECK_FALSE(unit_factor("theta"));
    // Factors and dimensions from UDUNITS-2; letters that are names are not units although UDUNITS-2 knows them.
    using eomgen::checker::text_unit;
    CHECK(text_unit("rpm")->factor == Approx(M_PI / 30));
    CHECK(text_unit("rev")->factor == Approx(2 * M_PI));
    CHECK(text_unit("ft")->factor == Approx(0.3048));
    CHECK(text_unit("~N~m")->dimension.str() == "kg m^2/s^2");
    CHECK(text_unit("rad/s")->dimension == text_unit("s^{-1}")->dimension);
    CHECK(text_unit("km/hr")->dimension == text_unit("m/s")->dimension);
    CHECK(text_unit("deg")->dimension.dimensionless());
    for (const char* name : {"d", "h", "a", "e", "L", "t", "T"}) {
        INFO(name);
        CHECK_FALSE(text_unit(name));
    }
    using eomgen::checker::is_unit_command;
    CHECK(is_unit_command("\\mathrm", "~s"));
    CHECK(is_unit_command("\\text", " cm"));
    CHECK(is_unit_command("\\text", "rad/s"));
    CHECK_FALSE(is_unit_command("\\text", "s"));  // T_{\text{s}}: a subscript
    CHECK_FALSE(is_unit_command("\\mathbf", "m"));
}

TEST_CASE("numbers: the number a side prints, and its digits", "[checker][numbers]") {
    using eomgen::checker::printed_number;
    const auto a = printed_number("0.45 \\mathrm{sec}");
    REQUIRE(a);
    CHECK(a->value == 0.45);
    CHECK(a->decimals == 2);
    CHECK(a->significant == 2);
    const auto b = printed_number("7.63 \\times 10^{-3} \\mathrm{~min}");  // the exponent is not the number
    REQUIRE(b);
    CHECK(b->value == 7.63);
    const auto c = printed_number("1.3^{\\circ}");
    REQUIRE(c);
    CHECK(c->value == 1.3);
    CHECK(c->decimals == 1);
    const auto d = printed_number("0.0468 \\mathrm{~rad}");
    REQUIRE(d);
    CHECK(d->significant == 3);
    CHECK(d->decimals == 4);
    CHECK_FALSE(printed_number("\\frac{0.9}{9.8}"));  // two decimals: which one is the result?
    CHECK_FALSE(printed_number("\\frac{1}{2}"));
    const auto e = printed_number("458 \\times 10^{-3} \\mathrm{~s}");  // 10 is the base of a power
    REQUIRE(e);
    CHECK(e->value == 458);
    CHECK(e->significant == 3);
    CHECK_FALSE(printed_number("m g h"));
    CHECK(printed_number("590 \\mathrm{~J}")->significant == 2);  // an integer's trailing zeros do not count
    CHECK(printed_number("3.10 \\mathrm{~J}")->significant == 3);
    CHECK(printed_number(".5")->value == 0.5);
    CHECK_FALSE(printed_number(std::string(400, '9') + ".5"));  // beyond a double: no number, no exception
}

TEST_CASE("numbers: right numbers agree to their printed digits, with no false alarm", "[checker][numbers]") {
    const CheckReport r = check(kCorrect);
    for (const EquationCheck& e : r.equations) {
        INFO(describe(e));
        CHECK(e.verdict != Verdict::Disagrees);
    }
    CHECK(r.count(Verdict::Agrees) == 9);
    const EquationCheck& t = find(r, "1.51 \\sqrt{w / g} = 0.46 \\mathrm{~s}");
    CHECK(t.verdict == Verdict::Agrees);
    // The parameters' values and eomgen's with their units (the text's where it prints one).
    CHECK(t.compared_with ==
          "the value eomgen computes with $w = 0.9\\,\\mathrm{m}$, $g = 9.8\\,\\mathrm{m/s^{2}}$ (from the model)");
    CHECK(t.reason == "agrees to the printed digits: eomgen computes $0.4576 \\mathrm{~s}$, which rounds to the printed $0.46$");
    CHECK(find(r, "2 \\theta = 2.68^{\\circ}").verdict == Verdict::Agrees);
    CHECK(find(r, "\\frac{w}{2} = 45 \\mathrm{~cm}").verdict == Verdict::Agrees);
    CHECK(find(r, "1.51 \\sqrt{w / g} = 7.63 \\times 10^{-3} \\mathrm{~min}").verdict == Verdict::Agrees);
    // The text sets θ = 90° for its paragraph; the next paragraph is back to the model's tilt.
    const EquationCheck& choice = find(r, "\\theta = 90^{\\circ}");
    CHECK(choice.verdict == Verdict::NotJudged);
    CHECK(choice.role == Role::ChosenValue);
    CHECK(choice.reason == "a value the text chooses (the model's is 0.0234): the numbers that follow in its "
                           "paragraph use it");
    const EquationCheck& chosen = find(r, "\\frac{m g w}{2} \\sin \\theta = 132 \\mathrm{~N~m}");
    CHECK(chosen.verdict == Verdict::Agrees);
    CHECK(chosen.compared_with == "the value eomgen computes with $m = 30\\,\\mathrm{kg}$, $w = 0.9\\,\\mathrm{m}$, "
                                  "$g = 9.8\\,\\mathrm{m/s^{2}}$, $\\theta = 1.5708\\,\\mathrm{rad}$ "
                                  "(from the model; chosen by the text on line 26)");
    CHECK(find(r, "\\frac{m g w}{2} \\sin \\theta = 3.10 \\mathrm{~N~m}").verdict == Verdict::Agrees);
    // A number for a quantity of the state: nothing to compare it with.
    const EquationCheck& state = find(r, "\\frac{1}{6} m w^{2} \\dot{\\psi}^{2} = 2.1 \\mathrm{~J}");
    CHECK(state.verdict == Verdict::NotComparable);
    CHECK(state.reason == "a number for a quantity that depends on $\\dot{\\psi}$, which has no value (only the "
                          "model's parameters have values): not compared");
}

TEST_CASE("numbers: planted wrong numbers are found on their line", "[checker][numbers]") {
    const CheckReport r = check(kPlanted);
    const std::map<int, std::string> expected = eomgen::test::planted_lines(kPlanted);
    REQUIRE(expected.size() == 7);
    std::map<int, int> found;
    for (const EquationCheck& e : r.equations) {
        INFO(describe(e));
        if (e.verdict != Verdict::Disagrees) continue;
        REQUIRE(expected.count(e.where.line) == 1);  // no false alarm
        ++found[e.where.line];
        REQUIRE(e.wrong_terms.size() == 1);
        CHECK(e.wrong_terms[0].find(expected.at(e.where.line)) != std::string::npos);
        CHECK_FALSE(e.corrected.empty());
    }
    for (const auto& [line, phrase] : expected) {
        INFO("planted on line " << line << ": " << phrase);
        CHECK(found[line] == 1);
    }
    // The verdict as a reader sees it: the difference, eomgen's value, the correction in the text's digits.
    const EquationCheck& t = find(r, "1.51 \\sqrt{w / g} = 0.45 \\mathrm{sec}");
    CHECK(t.difference == "-0.0076");
    REQUIRE(t.wrong_terms.size() == 1);
    CHECK(t.wrong_terms[0] == "differs by 1.7 %: eomgen computes $0.4576 \\mathrm{sec}$, which is $0.46 \\mathrm{sec}$ "
                              "to the printed 2 significant digits, not the printed $0.45$");
    CHECK(t.corrected == "1.51 \\sqrt{w / g} = 0.46 \\mathrm{sec}");
    CHECK(find(r, "\\frac{w}{2} = 0.45 \\mathrm{~cm}").corrected == "\\frac{w}{2} = 45 \\mathrm{~cm}");
    CHECK(find(r, "2 \\theta = 0.0468^{\\circ}").corrected == "2 \\theta = 2.68^{\\circ}");
    CHECK(find(r, "1.51 \\sqrt{w / g} = 7.63 \\times 10^{-3} \\mathrm{~s}").corrected ==
          "1.51 \\sqrt{w / g} = 458 \\times 10^{-3} \\mathrm{~s}");
    // A unit of another dimension: eomgen's value in SI is the correction, digits and unit together.
    CHECK(find(r, "\\frac{w}{2} = 0.45 \\mathrm{~s}").corrected == "\\frac{w}{2} = 0.45\\,\\mathrm{m}");
    CHECK(find(r, "m g h = 588 \\mathrm{~N}").corrected == "m g h = 588\\,\\mathrm{J}");
}

TEST_CASE("numbers: --set replaces the model's value", "[checker][numbers]") {
    CheckOptions o;
    o.set = {eomgen::checker::parse_set_option("w=1.0")};
    const CheckReport r = check(kCorrect, o);
    // 1.51 sqrt(1.0/9.8) = 0.4824: no longer 0.46.
    const EquationCheck& t = find(r, "1.51 \\sqrt{w / g} = 0.46 \\mathrm{~s}");
    CHECK(t.verdict == Verdict::Disagrees);
    CHECK(t.compared_with ==
          "the value eomgen computes with $w = 1\\,\\mathrm{m}$, $g = 9.8\\,\\mathrm{m/s^{2}}$ (from --set; from the model)");
    REQUIRE(t.wrong_terms.size() == 1);
    CHECK(t.wrong_terms[0] == "differs by 4.6 %: eomgen computes $0.4824 \\mathrm{~s}$, which is $0.48 \\mathrm{~s}$ "
                              "to the printed 2 significant digits, not the printed $0.46$");
    // m g h does not use w: unchanged.
    CHECK(find(r, "m g h = 588 \\mathrm{~J}").verdict == Verdict::Agrees);
}

TEST_CASE("numbers: a --set that is not NAME=number or not a parameter is refused", "[checker][numbers]") {
    using eomgen::checker::CheckError;
    using eomgen::checker::parse_set_option;
    CHECK(parse_set_option("g=9.81").second == 9.81);
    CHECK_THROWS_AS(parse_set_option("g"), CheckError);
    CHECK_THROWS_AS(parse_set_option("=3"), CheckError);
    CHECK_THROWS_AS(parse_set_option("g=fast"), CheckError);
    CHECK_THROWS_AS(parse_set_option("g=9.8m"), CheckError);
    CHECK_THROWS_AS(parse_set_option("g=inf"), CheckError);
    CheckOptions o;
    o.set = {{"width", 1.0}};
    CHECK_THROWS_WITH(check(kCorrect, o), Catch::Contains("'width' is not a parameter of the model") &&
                                              Catch::Contains("m, w, h, g, theta"));
}

TEST_CASE("numbers: signs and an integer's trailing zeros", "[checker][numbers]") {
    const CheckReport r = eomgen::test::check_text("models/door.toml",
                                                   "$-1.51 \\sqrt{w/g} = -0.46 \\text{ s}$\n\n"
                                                   "$1.51 \\sqrt{w/g} = -0.46 \\text{ s}$\n\n"
                                                   "$m g h = 590 \\mathrm{~J}$\n");
    REQUIRE(r.equations.size() == 3);
    CHECK(r.equations[0].verdict == Verdict::Agrees);
    const EquationCheck& sign = r.equations[1];
    CHECK(sign.verdict == Verdict::Disagrees);
    REQUIRE(sign.wrong_terms.size() == 1);
    CHECK(sign.wrong_terms[0] == "differs by 201 %: eomgen computes $0.4576 \\text{ s}$, which is $0.46 \\text{ s}$ to "
                                 "the printed 2 significant digits, not the printed $-0.46$");
    CHECK(sign.corrected == "1.51 \\sqrt{w/g} = 0.46 \\text{ s}");  // the minus goes
    INFO(describe(r.equations[2]));
    CHECK(r.equations[2].verdict == Verdict::Agrees);  // 588 J to two digits
}

TEST_CASE("numbers: roots of the parameters are real where they are compared", "[checker][numbers]") {
    // The cylinder rolling inside a cylinder of the corpus: 2π/ω = 2π√(3(R − r)/(2g)) with ω² = 2g/(3(R − r)).
    // At sample points with R < r the root of a negative number took another branch on each side: a false alarm.
    const char* const model = "tests/checker/corpus/roll_cylinder_in_cylinder_cheenta/model.toml";
    const auto r = eomgen::test::check_text(
        model, "$$\\frac{1}{\\sqrt{\\frac{2}{3}\\frac{g}{R-r}}} = \\sqrt{\\frac{3(R-r)}{2g}}$$\n");
    REQUIRE(r.equations.size() == 1);
    INFO(eomgen::test::describe(r.equations[0]));
    CHECK(r.equations[0].verdict == eomgen::checker::Verdict::Agrees);
    const auto w = eomgen::test::check_text(
        model, "$$\\frac{1}{\\sqrt{\\frac{2}{3}\\frac{g}{R-r}}} = \\sqrt{\\frac{2(R-r)}{3g}}$$\n");
    REQUIRE(w.equations.size() == 1);
    CHECK(w.equations[0].verdict != eomgen::checker::Verdict::Agrees);  // (a relation of parameters: not comparable)
}
