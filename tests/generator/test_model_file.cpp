/** @file test_model_file.cpp  Model files: real models load; every problem is reported at file:line:col. */
#include "test_paths.hpp"
#include "model/model_file.hpp"
#include "model/names.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

namespace {

using Catch::Matchers::Contains;
using Catch::Matchers::Matches;
using Catch::Matchers::StartsWith;

bool same(const GiNaC::ex& a, const GiNaC::ex& b) {
    return (a - b).expand().is_zero();
}

const eomgen::Parameter& parameter(const eomgen::Model& model, const std::string& name) {
    const auto it = std::find_if(model.parameters.begin(), model.parameters.end(),
                                 [&](const eomgen::Parameter& p) { return p.name == name; });
    REQUIRE(it != model.parameters.end());
    return *it;
}

/// "test.toml:line:col: message" of the ModelError `text` gives; fails the test when it loads.
std::string error_of(const std::string& text) {
    try {
        eomgen::parse_model(text, "test.toml");
    } catch (const eomgen::ModelError& e) {
        return e.what();
    }
    FAIL_CHECK("the model loaded instead of failing:\n" << text);
    return {};
}

std::string latex_of(const GiNaC::ex& e) {
    std::ostringstream out;
    out << GiNaC::latex << e;
    return out.str();
}

// A minimal valid model; tests append or substitute lines.
const std::string kCoordinate = "[[coordinates]]\nname = \"psi\"\n";
const std::string kParameter = "[[parameters]]\nname = \"m\"\nvalue = 2.0\n";
const std::string kLagrangian = "[lagrangian]\nT = \"1/2*m*psi'^2\"\nV = \"m*psi\"\n";

}  // namespace

TEST_CASE("models/door.toml loads with T and V as in Goldstein", "[model]") {
    const eomgen::Model model = eomgen::load_model(eomgen_test::source_dir() + "/models/door.toml");
    CHECK(model.name == "door");
    CHECK(model.title == "Closing tilted door");
    CHECK(model.source == "Goldstein ch. 5, Ex. 30");
    CHECK_THAT(model.description, StartsWith("A uniform door of mass m"));
    REQUIRE(model.dof() == 1);
    REQUIRE(model.parameters.size() == 5);

    const eomgen::Coordinate& psi = model.coordinates[0];
    CHECK(psi.name == "psi");
    CHECK(psi.latex == "\\psi");
    CHECK(psi.q.get_name() == "psi");
    CHECK(psi.qd.get_name() == "psi_dot");
    CHECK(psi.qdd.get_name() == "psi_ddot");
    CHECK(latex_of(psi.qd) == "\\dot{\\psi}");
    CHECK(latex_of(psi.qdd) == "\\ddot{\\psi}");
    CHECK(psi.initial == 0.0);
    CHECK(psi.rate == 0.0);
    CHECK(psi.where.str() == eomgen_test::source_dir() + "/models/door.toml:10:9");

    const GiNaC::ex m = parameter(model, "m").symbol, w = parameter(model, "w").symbol,
                    h = parameter(model, "h").symbol, g = parameter(model, "g").symbol,
                    theta = parameter(model, "theta").symbol;
    CHECK(parameter(model, "m").value == 30.0);
    CHECK(parameter(model, "w").value == 0.9);
    CHECK(parameter(model, "theta").value == 0.0234);
    CHECK(parameter(model, "g").unit == "m/s^2");
    CHECK(parameter(model, "theta").latex == "\\theta");
    CHECK(parameter(model, "m").latex == "m");
    CHECK(parameter(model, "h").description == "height of the door");

    CHECK(same(model.T.expr, GiNaC::numeric(1, 6) * m * GiNaC::pow(w, 2) * GiNaC::pow(psi.qd, 2)));
    CHECK(
        same(model.V.expr, m * g / 2 * (w * GiNaC::sin(theta) * GiNaC::sin(psi.q) + h * GiNaC::cos(theta))));
    CHECK(model.T.text == "1/6 * m * w^2 * psi'^2");
    CHECK(model.T.where.line == 49);
    CHECK(model.T.where.column == 6);
}

TEST_CASE("models/pendulum_5_20.toml loads with its multi-line T", "[model]") {
    const eomgen::Model model = eomgen::load_model(eomgen_test::source_dir() + "/models/pendulum_5_20.toml");
    CHECK(model.name == "pendulum_5_20");
    REQUIRE(model.dof() == 2);
    REQUIRE(model.parameters.size() == 5);
    const eomgen::Coordinate& theta = model.coordinates[0];
    const eomgen::Coordinate& phi = model.coordinates[1];
    CHECK(theta.name == "theta");
    CHECK(phi.name == "phi");
    CHECK(theta.initial == 0.5);
    CHECK(phi.initial == -0.3);
    CHECK(parameter(model, "g").value == 9.81);

    const GiNaC::ex m = parameter(model, "m").symbol, l = parameter(model, "l").symbol,
                    M = parameter(model, "M").symbol, a = parameter(model, "a").symbol,
                    g = parameter(model, "g").symbol;
    const GiNaC::ex td = theta.qd, pd = phi.qd;
    const GiNaC::ex T =
        m * l * l * td * td / 6 +
        M / 2 * (l * l * td * td + 2 * a * l * td * pd * GiNaC::cos(phi.q - theta.q) + a * a * pd * pd) +
        M * a * a / 4 * pd * pd;
    const GiNaC::ex V =
        -m * g * l * GiNaC::cos(theta.q) / 2 - M * g * (l * GiNaC::cos(theta.q) + a * GiNaC::cos(phi.q));
    CHECK(same(model.T.expr, T));
    CHECK(same(model.V.expr, V));
    CHECK(model.T.where.line == 58);  // the first newline of """ is not part of the text
    CHECK(model.T.where.column == 1);
}

TEST_CASE("model errors read file:line:col: message", "[model]") {
    const eomgen::SourceLocation where{"a.toml", 3, 7};
    CHECK(where.str() == "a.toml:3:7");
    CHECK(eomgen::SourceLocation{"a.toml", 0, 0}.str() == "a.toml");
    const eomgen::ModelError e(where, "unknown symbol 'x'");
    CHECK(std::string(e.what()) == "a.toml:3:7: unknown symbol 'x'");
    CHECK(e.message() == "unknown symbol 'x'");
    CHECK(e.where().line == 3);
    CHECK_THROWS_WITH(eomgen::load_model("/nonexistent/model.toml"),
                      StartsWith("/nonexistent/model.toml: cannot open"));
}

TEST_CASE("a minimal model, defaults and constant expressions", "[model]") {
    const std::string text =
        "[[coordinates]]\nname = \"theta1\"\ninitial = \"pi/4\"\nrate = -1\n"
        "[[parameters]]\nname = \"m_rod\"\nvalue = \"sqrt(2)/2\"\n"
        "[lagrangian]\nT = \"1/2*m_rod*dot(theta1)^2 + 0.5*t\"\n";
    const eomgen::Model model = eomgen::parse_model(text, "dir/simple_model.toml");
    CHECK(model.name == "simple_model");  // from the file name
    CHECK(model.path == "dir/simple_model.toml");
    REQUIRE(model.dof() == 1);
    CHECK(model.coordinates[0].latex == "\\theta_{1}");
    CHECK(latex_of(model.coordinates[0].qd) == "\\dot{\\theta_{1}}");
    CHECK(model.coordinates[0].initial == Approx(0.7853981633974483));
    CHECK(model.coordinates[0].rate == -1.0);
    CHECK(model.parameters[0].latex == "m_{rod}");
    CHECK(model.parameters[0].value == Approx(0.7071067811865476));
    CHECK(same(model.T.expr,
               model.parameters[0].symbol * GiNaC::pow(model.coordinates[0].qd, 2) / 2 + model.t / 2));
    CHECK(model.V.expr.is_zero());  // V may be left out
    CHECK(model.t.get_name() == "t");
}

TEST_CASE("TOML syntax errors keep toml++'s position", "[model]") {
    CHECK_THAT(error_of("name = \"x\"\nfoo = = 1\n"), StartsWith("test.toml:2:7: invalid TOML: "));
    CHECK_THAT(error_of("name = \"x\"\n[[coordinates]]\nname = \"psi\"\nname = \"phi\"\n"),
               StartsWith("test.toml:4:") && Contains("invalid TOML"));
}

// Found by the mutation test below: toml++ 3.3 compiled header-only without NDEBUG aborted on a table
// header broken by a newline (an assert in parse_key) instead of reporting a syntax error.
TEST_CASE("regression: toml++ aborted on a newline inside a table header", "[model]") {
    CHECK_THAT(error_of(kCoordinate + "[\nlagrangian]\nT = \"psi'^2\"\n"),
               StartsWith("test.toml:3:2: invalid TOML: "));
    CHECK_THAT(error_of("[[\ncoordinates]]\n"), StartsWith("test.toml:1:3: invalid TOML: "));
}

TEST_CASE("missing keys, wrong types and unknown keys", "[model]") {
    SECTION("missing name of a coordinate, at its table") {
        CHECK_THAT(error_of("[[coordinates]]\nlatex = 'x'\n" + kLagrangian),
                   StartsWith("test.toml:1:1: missing key 'name' in [[coordinates]]"));
    }
    SECTION("missing value of a parameter") {
        CHECK_THAT(error_of(kCoordinate + "\n[[parameters]]\nname = \"m\"\n" + kLagrangian),
                   StartsWith("test.toml:4:1: missing key 'value' in [[parameters]]"));
    }
    SECTION("missing coordinates, [lagrangian] and T") {
        // Placed at the end of the file, where the missing section would go.
        CHECK_THAT(error_of(kParameter + kLagrangian), Matches("test\\.toml:[0-9]+:1: missing \\[\\[coordinates\\]\\].*"));
        CHECK_THAT(error_of(kCoordinate + kParameter), Matches("test\\.toml:[0-9]+:1: missing \\[lagrangian\\].*"));
        CHECK_THAT(error_of(kCoordinate + kParameter + "[lagrangian]\nV = \"m\"\n"),
                   StartsWith("test.toml:6:1: missing key 'T' in [lagrangian]"));
    }
    SECTION("wrong types, at the value") {
        CHECK_THAT(
            error_of(kCoordinate + "initial = true\n" + kParameter + kLagrangian),
            StartsWith("test.toml:3:11: 'initial' must be a number or a string with a constant expression") &&
                Contains("not a boolean"));
        CHECK_THAT(error_of("[[coordinates]]\nname = 3\n" + kLagrangian),
                   StartsWith("test.toml:2:8: 'name' must be a string, not an integer"));
        CHECK_THAT(
            error_of("[coordinates]\nname = \"psi\"\n" + kLagrangian),
            StartsWith("test.toml:1:1: 'coordinates' must be an array of tables, written [[coordinates]]"));
        CHECK_THAT(error_of(kCoordinate + kParameter + "[lagrangian]\nT = 1\n"),
                   StartsWith("test.toml:7:5: 'T' must be a string with an expression, not an integer"));
        CHECK_THAT(error_of(kCoordinate + "rate = inf\n" + kLagrangian),
                   StartsWith("test.toml:3:8: 'rate' must be a finite"));
        CHECK_THAT(error_of("title = 1\n" + kCoordinate + kLagrangian),
                   StartsWith("test.toml:1:9: 'title' must be a string"));
    }
    SECTION("unknown keys, at the key, with the closest valid key") {
        CHECK(error_of(kCoordinate + "intial = 0.1\n" + kParameter + kLagrangian) ==
              "test.toml:3:1: unknown key 'intial' in [[coordinates]]; did you mean 'initial'?");
        CHECK(error_of(kCoordinate + kParameter + "  vlaue = 1\n" + kLagrangian) ==
              "test.toml:6:3: unknown key 'vlaue' in [[parameters]]; did you mean 'value'?");
        CHECK(error_of(kCoordinate + kParameter + "[lagrangian]\nt = \"psi'^2\"\n") ==
              "test.toml:7:1: unknown key 't' in [lagrangian]; did you mean 'T'?");
        CHECK(error_of("nmae = \"x\"\n" + kCoordinate + kLagrangian) ==
              "test.toml:1:1: unknown key 'nmae' at the top level; did you mean 'name'?");
        CHECK_THAT(
            error_of(kCoordinate + "colour = 1\n" + kLagrangian),
            StartsWith("test.toml:3:1: unknown key 'colour' in [[coordinates]] (expected one of: name"));
    }
}

TEST_CASE("duplicate names are reported at the second, with the line of the first", "[model]") {
    CHECK(error_of(kCoordinate + kParameter + "[[parameters]]\nname = \"m\"\nvalue = 1\n" + kLagrangian) ==
          "test.toml:7:9: duplicate name 'm': already the name of a parameter on line 4");
    // Parameters before coordinates in the file: still the later one is reported.
    CHECK(error_of("[[parameters]]\nname = \"psi\"\nvalue = 1\n" + kCoordinate + kLagrangian) ==
          "test.toml:5:9: duplicate name 'psi': already the name of a parameter on line 2");
    CHECK(error_of("name = \"psi\"\n" + kCoordinate + kLagrangian) ==
          "test.toml:3:9: duplicate name 'psi': already the model's name on line 1");
}

TEST_CASE("invalid and reserved names are refused at the name", "[model]") {
    auto with_parameter = [](const std::string& name) {
        return kCoordinate + "[[parameters]]\nname = \"" + name + "\"\nvalue = 1\n" + kLagrangian;
    };
    CHECK(error_of(with_parameter("class")) ==
          "test.toml:4:9: cannot use 'class' as a parameter name: 'class' is a C++ keyword");
    CHECK_THAT(error_of(with_parameter("t")),
               StartsWith("test.toml:4:9: cannot use 't'") && Contains("reserved for time"));
    CHECK_THAT(error_of(with_parameter("t3")), StartsWith("test.toml:4:9: ") && Contains("temporaries"));
    CHECK_THAT(error_of(with_parameter("psi_dot")),
               StartsWith("test.toml:4:9: ") && Contains("velocity of coordinate 'psi'"));
    CHECK_THAT(error_of(with_parameter("not")), Contains("C++ keyword"));
    CHECK_THAT(error_of(with_parameter("sin")), Contains("function"));
    CHECK_THAT(error_of(with_parameter("Scalar")), Contains("generated code"));
    CHECK_THAT(error_of(with_parameter("2m")),
               StartsWith("test.toml:4:9: ") && Contains("not an identifier"));
    CHECK_THAT(error_of(with_parameter("")), StartsWith("test.toml:4:9: ") && Contains("may not be empty"));
    CHECK_THAT(error_of("name = \"my-door\"\n" + kCoordinate + kLagrangian),
               StartsWith("test.toml:1:9: cannot use 'my-door' as a model name"));
    CHECK_THAT(error_of("name = \"and\"\n" + kCoordinate + kLagrangian),
               StartsWith("test.toml:1:9: ") && Contains("keyword"));
    try {
        eomgen::parse_model(kCoordinate + kLagrangian, "models/my-model.toml");
        FAIL("a model named after an invalid file name loaded");
    } catch (const eomgen::ModelError& e) {
        CHECK_THAT(e.what(), StartsWith("models/my-model.toml: no 'name' given"));
    }
}

TEST_CASE("expression errors point at the character inside the string", "[model]") {
    SECTION("basic string") {
        CHECK(error_of(kCoordinate + kParameter + "[lagrangian]\nT = \"1/2*m*psi'^2 + thta\"\n") ==
              "test.toml:7:21: unknown symbol 'thta'");
    }
    SECTION("basic string with escapes before the error") {
        // \u0031 is "1" and \t a tab: six and two characters in the file, one in the expression.
        CHECK_THAT(
            error_of(kCoordinate + kParameter + "[lagrangian]\nT = \"\\u0031/2*m*psi'^2 +\\t\\\"x\"\n"),
            StartsWith("test.toml:7:27: unexpected character '\"'"));
        CHECK_THAT(error_of(kCoordinate + kParameter + "[lagrangian]\nT = \"\\u0031/2*m*psi'^2 +\\t zz\"\n"),
                   StartsWith("test.toml:7:28: unknown symbol 'zz'"));
    }
    SECTION("literal string") {
        CHECK_THAT(error_of(kCoordinate + kParameter + "[lagrangian]\nT = 'm*psi**2'\n"),
                   StartsWith("test.toml:7:11: '**' is not an operator: use ^ for powers"));
    }
    SECTION("third line of a multi-line basic string") {
        const std::string text = kCoordinate + kParameter +
                                 "[lagrangian]\n"               // line 6
                                 "T = \"\"\"\n"                 // line 7: first newline is trimmed
                                 "  1/2*m*psi'^2\n"             // line 8
                                 "+ 1/2*m*psi^2\n"              // line 9
                                 "+ 1/2*m*(2 psi')^2\"\"\"\n";  // line 10: missing operator at psi'
        CHECK(error_of(text) ==
              "test.toml:10:12: missing operator before 'psi': write 2*psi (there is no "
              "implicit multiplication)");
    }
    SECTION("multi-line literal string and a line-ending backslash") {
        CHECK_THAT(error_of(kCoordinate + kParameter + "[lagrangian]\nT = '''\nm*psi'^2\n  + x'''\n"),
                   StartsWith("test.toml:9:5: unknown symbol 'x'"));
        CHECK_THAT(
            error_of(kCoordinate + kParameter + "[lagrangian]\nT = \"\"\"m*psi'^2 \\\n     + (m\"\"\"\n"),
            StartsWith("test.toml:8:8: unclosed '('"));
    }
    SECTION("error at the end of the expression") {
        CHECK_THAT(error_of(kCoordinate + kParameter + "[lagrangian]\nT = \"m*psi'^2 +\"\n"),
                   StartsWith("test.toml:7:15: missing operand after '+'"));
        CHECK_THAT(error_of(kCoordinate + kParameter + "[lagrangian]\nT = \"\"\n"),
                   StartsWith("test.toml:7:6: empty expression"));
    }
    SECTION("V must not contain a velocity") {
        CHECK(error_of(kCoordinate + kParameter +
                       "[lagrangian]\nT = \"m*psi'^2\"\nV = \"m*psi + dot(psi)\"\n") ==
              "test.toml:8:14: velocity dot(psi) not allowed here: the potential energy V(q, t) must not "
              "depend on velocities");
        CHECK_THAT(error_of(kCoordinate + kParameter + "[lagrangian]\nT = \"m*psi'^2\"\nV = \"m*psi'\"\n"),
                   StartsWith("test.toml:8:8: velocity psi' not allowed here"));
    }
    SECTION("initial values and parameter values are constants") {
        CHECK(error_of(kCoordinate + "initial = \"pi/4 + m\"\n" + kParameter + kLagrangian) ==
              "test.toml:3:19: 'm' is not a constant: only numbers, pi and functions may be used here");
        CHECK_THAT(error_of(kCoordinate + kParameter + "[[parameters]]\nname = \"l\"\nvalue = \"2*m\"\n" +
                            kLagrangian),
                   StartsWith("test.toml:8:12: 'm' is not a constant"));
        CHECK_THAT(error_of(kCoordinate + "rate = \"log(-1)\"\n" + kLagrangian),
                   StartsWith("test.toml:3:9: not a real number"));
    }
    SECTION("CRLF line ends and non-ASCII text before the string") {
        CHECK_THAT(error_of("[[coordinates]]\r\nname = \"psi\"\r\n[lagrangian]\r\nT = \"\"\"\r\n psi'^2\r\n "
                            "+ zz\"\"\"\r\n"),
                   StartsWith("test.toml:6:4: unknown symbol 'zz'"));
        // toml++ counts columns in code points; the column reported counts bytes (ψ is two).
        // (A description, not a LaTeX name or a unit, holds the non-ASCII text: LaTeX names are ASCII, see
        // docs/security.md, and units are read by UDUNITS-2.)
        CHECK_THAT(error_of("parameters = [{name = \"k\", description = \"ψψ\", value = \"1 + m\"}]\n"
                            "coordinates = [{name = \"psi\"}]\nlagrangian.T = \"psi'^2\"\n"),
                   StartsWith("test.toml:1:63: unknown symbol 'm'"));
    }
}

TEST_CASE("mutated model files load or fail with a ModelError, nothing else", "[model]") {
    std::ifstream in(eomgen_test::source_dir() + "/models/pendulum_5_20.toml", std::ios::binary);
    std::ostringstream buffer;
    buffer << in.rdbuf();
    const std::string original = buffer.str();
    REQUIRE(original.size() > 100);
    const std::string alphabet = "\"'\\\n\r[]=#.,_ ^*()umtx\xcf\x88";
    std::mt19937 rng(7);
    int loaded = 0;
    for (int i = 0; i < 400; ++i) {
        std::string text = original;
        // Mutate near T and V most of the time: that is where the string-to-file mapping works.
        const std::size_t from = (i % 4 != 0) ? text.find("[lagrangian]") : 0;
        for (int k = 0; k < 3; ++k) {
            const std::size_t at = std::uniform_int_distribution<std::size_t>(from, text.size() - 1)(rng);
            const char c = alphabet[std::uniform_int_distribution<std::size_t>(0, alphabet.size() - 1)(rng)];
            switch (rng() % 3) {
                case 0:
                    text[at] = c;
                    break;
                case 1:
                    text.insert(at, 1, c);
                    break;
                default:
                    text.erase(at, 1);
            }
        }
        try {
            eomgen::parse_model(text, "fuzz.toml");
            ++loaded;
        } catch (const eomgen::ModelError& e) {
            INFO(e.what());
            CHECK_THAT(e.what(), StartsWith("fuzz.toml"));
            if (e.where().line > 0) {
                CHECK(e.where().column >= 1);
                CHECK(e.where().line <= static_cast<int>(std::count(text.begin(), text.end(), '\n')) + 1);
            }
        }
    }
    CHECK(loaded < 400);
}

TEST_CASE("identifier and reserved-name rules", "[model][names]") {
    for (const char* ok : {"m", "theta", "x1", "m_rod", "M", "tx", "t_a", "sinx", "final", "Alpha", "e"}) {
        INFO(ok);
        CHECK(eomgen::name_problem(ok, {"psi"}).empty());
    }
    CHECK(eomgen::reserved_name_reason("psi_dot").empty());  // only reserved when psi is a coordinate
    for (const char* bad :
         {"class",   "and",      "not",    "xor_eq", "bitor", "co_await",   "nullptr",   "t",
          "t0",      "t3",       "t10",    "pi",     "dot",   "sin",        "atan2",     "sqrt",
          "Scalar",  "Model",    "Params", "Config", "State", "MassMatrix", "Conserved", "Eigen",
          "std",     "eomgen",   "M_PI",   "NAN",    "x_",    "a__b",       "sin_theta", "cos_psi",
          "psi_dot", "psi_ddot", "_x",     "1x",     "a-b",   "",           "ψ"}) {
        INFO(bad);
        CHECK_FALSE(eomgen::name_problem(bad, {"psi"}).empty());
    }
    CHECK(eomgen::is_cpp_keyword("or_eq"));
    CHECK_FALSE(eomgen::is_cpp_keyword("override"));
    CHECK(eomgen::is_identifier("a_1"));
    CHECK_FALSE(eomgen::is_identifier("_a"));
}

TEST_CASE("closest names and default LaTeX", "[model][names]") {
    CHECK(eomgen::edit_distance("intial", "initial") == 1);
    CHECK(eomgen::edit_distance("thetq", "theta") == 1);
    CHECK(eomgen::edit_distance("vlaue", "value") == 1);  // a swap of neighbours counts once
    CHECK(eomgen::closest_name("intial", {"name", "latex", "initial", "rate"}) == "initial");
    CHECK(eomgen::closest_name("x", {"m", "g"}).empty());
    CHECK(eomgen::closest_name("t", {"T", "V"}) == "T");
    CHECK(eomgen::closest_name("colour", {"name", "latex", "initial", "rate"}).empty());

    CHECK(eomgen::default_latex("alpha") == "\\alpha");
    CHECK(eomgen::default_latex("Omega") == "\\Omega");
    CHECK(eomgen::default_latex("Alpha") == "A");
    CHECK(eomgen::default_latex("theta1") == "\\theta_{1}");
    CHECK(eomgen::default_latex("theta12") == "\\theta_{12}");
    CHECK(eomgen::default_latex("m_rod") == "m_{rod}");
    CHECK(eomgen::default_latex("phi_alpha_2") == "\\phi_{\\alpha,2}");
    CHECK(eomgen::default_latex("x") == "x");
    CHECK(eomgen::default_latex("mass") == "mass");
}

TEST_CASE("[outputs]: strings and tables, in file order, with units and LaTeX", "[model][outputs]") {
    const std::string text = kCoordinate + kParameter + kLagrangian +
                             "[outputs]\n"
                             "y_bob = { expr = \"-m*cos(psi)\", unit = \"m\", latex = 'y_{\\mathrm{b}}', "
                             "description = \"height\" }\n"
                             "speed = \"m*psi'\"\n"
                             "[outputs.a_t]\nexpr = \"t*psi\"\n";
    const eomgen::Model model = eomgen::parse_model(text, "test.toml");
    REQUIRE(model.outputs.size() == 3);
    const auto& [y, speed, at] = std::tie(model.outputs[0], model.outputs[1], model.outputs[2]);
    CHECK(y.name == "y_bob");  // the file's order, not the table's sorted one
    CHECK(speed.name == "speed");
    CHECK(at.name == "a_t");
    const GiNaC::ex m = model.parameters[0].symbol, psi = model.coordinates[0].q,
                    psi_dot = model.coordinates[0].qd;
    CHECK(same(y.expr.expr, -m * GiNaC::cos(psi)));
    CHECK(same(speed.expr.expr, m * psi_dot));
    CHECK(same(at.expr.expr, model.t * psi));
    CHECK(y.unit == "m");
    CHECK(y.latex == "y_{\\mathrm{b}}");
    CHECK(y.description == "height");
    CHECK(speed.unit.empty());
    CHECK(speed.latex == "speed");
    CHECK(at.latex == "a_{t}");
    CHECK(y.where.str() == "test.toml:10:1");
    CHECK(speed.expr.where.str() == "test.toml:11:10");
    CHECK(eomgen::parse_model(kCoordinate + kParameter + kLagrangian, "test.toml").outputs.empty());
}

TEST_CASE("[outputs] errors, each at file:line:col", "[model][outputs]") {
    const std::string head = kCoordinate + kParameter + kLagrangian + "[outputs]\n";  // [outputs] on line 9
    CHECK(error_of(head + "x = \"m*sin(pis)\"\n") ==
          "test.toml:10:12: unknown symbol 'pis'; did you mean 'pi'?");
    CHECK_THAT(error_of(head + "x = { expr = \"psi''\" }\n"), StartsWith("test.toml:10:19: only one prime"));
    CHECK(
        error_of(head + "x = 3\n") ==
        "test.toml:10:5: output 'x' must be a string with an expression or a table { expr = \"...\", unit = "
        "\"...\" }, not an integer");
    CHECK(error_of(head + "x = { unit = \"m\" }\n") ==
          "test.toml:10:5: missing key 'expr' in output 'x' (what to record)");
    CHECK(error_of(head + "x = { expr = \"psi\", unti = \"m\" }\n") ==
          "test.toml:10:21: unknown key 'unti' in output 'x'; did you mean 'unit'?");
    CHECK_THAT(error_of(head + "x = { expr = \"psi\", latex = 'x\\input{a}' }\n"),
               StartsWith("test.toml:10:31: \\input is not among"));
    CHECK_THAT(error_of(head + "x = { expr = \"psi\", unit = \"m\\u0007\" }\n"),
               StartsWith("test.toml:10:30: 'unit' holds the control character U+0007"));
    CHECK_THAT(error_of("outputs = \"psi\"\n" + kCoordinate + kParameter + kLagrangian),
               StartsWith("test.toml:1:11: 'outputs' must be a table [outputs]"));
}

TEST_CASE("[outputs] names: identifiers, not reserved, not another name or CSV column", "[model][outputs]") {
    const std::string head = kCoordinate + kParameter + kLagrangian + "[outputs]\n";
    auto named = [&](const std::string& name) { return error_of(head + name + " = \"psi\"\n"); };
    CHECK(named("m") == "test.toml:10:1: duplicate name 'm': already the name of a parameter on line 4");
    CHECK(named("psi") == "test.toml:10:1: duplicate name 'psi': already the name of a coordinate on line 2");
    CHECK(named("psi_dot") ==
          "test.toml:10:1: cannot use 'psi_dot' as an output name: 'psi_dot' is the name of the velocity of "
          "coordinate 'psi'");
    CHECK_THAT(named("energy"),
               StartsWith("test.toml:10:1: cannot use 'energy'") && Contains("CSV column of the energy"));
    CHECK_THAT(named("work"), Contains("CSV column of the work of the forces"));
    CHECK_THAT(named("h"), Contains("energy function among the conserved quantities"));
    CHECK_THAT(named("p_psi"), Contains("momentum of coordinate 'psi'"));
    CHECK_THAT(named("t"), Contains("reserved for time"));
    CHECK_THAT(named("M_PI"), Contains("macro"));
    CHECK_THAT(named("class"), Contains("C++ keyword"));
    CHECK_THAT(named("\"x bob\""), StartsWith("test.toml:10:1: ") && Contains("not an identifier"));
    const std::string constrained = kCoordinate + "[[coordinates]]\nname = \"y\"\n" + kLagrangian +
                                    "[[constraints]]\nname = \"rod\"\nexpr = \"psi - y\"\n[outputs]\n";
    CHECK_THAT(error_of(constrained + "lambda_rod = \"psi\"\n"),
               StartsWith("test.toml:12:1: cannot use 'lambda_rod' as an output name") &&
                   Contains("multiplier of constraint 'rod'"));
    CHECK_THAT(error_of(constrained + "residual_rod = \"psi\"\n"), Contains("residual of constraint 'rod'"));
    CHECK_THAT(error_of(constrained + "rod = \"psi\"\n"), Contains("already the name of a constraint"));
}
