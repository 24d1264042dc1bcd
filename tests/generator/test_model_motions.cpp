/** @file test_model_motions.cpp  [[motions]] in model files: what loads, and each bad entry at file:line:col. */
#include "model/model_file.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace {

// A two-coordinate model; the tests append a [[motions]] table.
const std::string kModel =
    "[[coordinates]]\nname = \"theta\"\n[[coordinates]]\nname = \"phi\"\n"
    "[[parameters]]\nname = \"g\"\nvalue = 9.81\n"
    "[lagrangian]\nT = \"1/2*(theta'^2 + sin(theta)^2*phi'^2)\"\nV = \"-g*cos(theta)\"\n";  // 10 lines

std::string error_of(const std::string& motions) {
    try {
        eomgen::parse_model(kModel + motions, "test.toml");
    } catch (const eomgen::ModelError& e) {
        return e.what();
    }
    FAIL_CHECK("the model loaded instead of failing:\n" << motions);
    return {};
}

}  // namespace

TEST_CASE("motions: a [[motions]] table loads with its constants and conditions", "[model][motions]") {
    const eomgen::Model m = eomgen::parse_model(
        kModel + "[[motions]]\nname = \"conical\"\nsection = \"Conical\"\nconstants = [\"Omega\"]\n"
                 "conditions = [\"theta' = 0\", \"phi' = Omega\"]\n",
        "test.toml");
    REQUIRE(m.motions.size() == 1);
    const eomgen::Motion& mo = m.motions[0];
    CHECK(mo.name == "conical");
    CHECK(mo.section == "Conical");
    REQUIRE(mo.constants.size() == 1);
    CHECK(mo.constants[0].latex == "\\Omega");
    REQUIRE(mo.conditions.size() == 2);
    CHECK(mo.conditions[0].coordinate == 0);
    CHECK(mo.conditions[0].velocity);
    CHECK(mo.conditions[0].value.expr.is_zero());
    CHECK(mo.conditions[1].coordinate == 1);
    CHECK((mo.conditions[1].value.expr - mo.constants[0].symbol).is_zero());
    // A coordinate given as a function of t.
    const eomgen::Model m2 = eomgen::parse_model(
        kModel + "[[motions]]\nname = \"turning\"\nconditions = [\"phi = 2*t\"]\n", "test.toml");
    REQUIRE(m2.motions.size() == 1);
    CHECK_FALSE(m2.motions[0].conditions[0].velocity);
}

TEST_CASE("motions: each bad entry is reported at its place", "[model][motions]") {
    CHECK(error_of("[[motions]]\nname = \"a\"\n") ==
          "test.toml:11:1: missing key 'conditions' in [[motions]] (such as \"theta' = 0\")");
    CHECK(error_of("[[motions]]\nname = \"a\"\nconditions = []\n") ==
          "test.toml:13:14: 'conditions' must be a non-empty array of strings such as \"theta' = 0\"");
    // The left side: a coordinate or its velocity.
    CHECK(error_of("[[motions]]\nname = \"a\"\nconditions = [\"x' = 0\"]\n") ==
          "test.toml:13:16: the left side of a condition is a coordinate or its velocity (such as theta or "
          "theta'), not 'x''");
    // No '=' (or two).
    CHECK(error_of("[[motions]]\nname = \"a\"\nconditions = [\"theta' 0\"]\n") ==
          "test.toml:13:16: a condition is one equation 'coordinate = value' or 'coordinate' = value', such as "
          "\"theta' = 0\"");
    // The value: an unknown name at its column, velocities refused.
    CHECK(error_of("[[motions]]\nname = \"a\"\nconditions = [\"theta' = 0\", \"phi' = w\"]\n")
              == "test.toml:13:37: unknown symbol 'w'");
    CHECK(error_of("[[motions]]\nname = \"a\"\nconditions = [\"phi' = theta'\"]\n")
              .find("no velocities") != std::string::npos);
    // A coordinate given twice.
    CHECK(error_of("[[motions]]\nname = \"a\"\nconditions = [\"theta' = 0\", \"theta = 1\"]\n") ==
          "test.toml:13:30: 'theta' is already given by the condition \"theta' = 0\" of motion 'a'");
    // A constant that is a name of the model, a duplicate motion, an unknown key.
    CHECK(error_of("[[motions]]\nname = \"a\"\nconstants = [\"g\"]\nconditions = [\"theta' = 0\"]\n") ==
          "test.toml:13:15: the constant 'g' of motion 'a' is already a name of the model");
    CHECK(error_of("[[motions]]\nname = \"a\"\nconditions = [\"theta' = 0\"]\n"
                   "[[motions]]\nname = \"a\"\nconditions = [\"phi' = 0\"]\n") ==
          "test.toml:15:9: duplicate motion 'a': already on line 12");
    CHECK(error_of("[[motions]]\nname = \"a\"\nconditons = [\"theta' = 0\"]\n").find("unknown key 'conditons'") !=
          std::string::npos);
}
