// `eomgen run --interpret` as a user runs it: the same CSV as the compiled run (a damped and driven model with an
// output and an event, a constrained one, an ensemble), no compiler needed, and what it refuses.
#include "test_paths.hpp"
#include "cli/eomgen_process.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace eomgen_test;

namespace {

const fs::path kWork = fs::path(eomgen_test::binary_dir()) / "tests" / "cli" / "work" / "run_interpreted";

Result eomgen(const std::vector<std::string>& args, std::map<std::string, std::string> env = {}) {
    return run_eomgen(kWork, args, std::move(env));
}

// Damped (R), driven (a force in t) and with an output: power() and outputs() run on tapes too.
const char* kDriven = R"toml(name = "driven_pendulum"
[[coordinates]]
name = "phi"
initial = 0.4
unit = "deg"
[[parameters]]
name = "m"
value = 1.5
unit = "kg"
[[parameters]]
name = "l"
value = 0.8
unit = "m"
[[parameters]]
name = "c"
value = 0.3
[[parameters]]
name = "g"
value = 9.81
unit = "m/s^2"
[[parameters]]
name = "tau"
value = 0.5
unit = "N*m"
[[parameters]]
name = "w"
value = 2
unit = "1/s"
[lagrangian]
T = "m/2*l^2*phi'^2"
V = "-m*g*l*cos(phi)"
R = "c/2*phi'^2"
[forces]
phi = "tau*sin(w*t)"
[outputs]
height = { expr = "-l*cos(phi)", unit = "m" }
)toml";

/// The largest difference of two CSVs of the same columns, relative to 1 + |value|.
double largest_difference(const fs::path& a, const fs::path& b) {
    const auto ra = read_csv(a), rb = read_csv(b);
    REQUIRE(ra.size() == rb.size());
    REQUIRE(ra[0] == rb[0]);
    double worst = 0;
    for (std::size_t i = 1; i < ra.size(); ++i)
        for (std::size_t j = 0; j < ra[i].size(); ++j) {
            const std::string& x = ra[i][j];
            const std::string& y = rb[i][j];
            char* end = nullptr;
            const double u = std::strtod(x.c_str(), &end);
            if (x.empty() || *end != '\0') {  // a word (an ensemble's status): the same in both
                CHECK(x == y);
                continue;
            }
            worst = std::max(worst, std::abs(u - std::stod(y)) / (1 + std::abs(u)));
        }
    return worst;
}

}  // namespace

TEST_CASE("eomgen run --interpret writes the compiled run's CSV, without a compiler", "[run][interpret]") {
    const fs::path model = write_whole(kWork, "driven.toml", kDriven);
    const fs::path compiled = kWork / "driven_compiled.csv", interpreted = kWork / "driven_interpreted.csv";
    const std::vector<std::string> common = {"run", model.string(), "--t-end", "6", "--rtol", "1e-11", "--samples", "60",
                                             "--set", "c=0.5", "--init", "phi=30", "--quiet"};
    std::vector<std::string> a = common, b = common;
    a.insert(a.end(), {"--csv", compiled.string()});
    b.insert(b.end(), {"--csv", interpreted.string(), "--interpret"});
    const Result rc = eomgen(a);
    INFO(rc.output);
    REQUIRE(rc.code == 0);
    // No compiler at all: the interpreter does not start one, and writes nothing into the cache.
    const fs::path cache = kWork / "cache-none";
    fs::remove_all(cache);
    const Result ri = eomgen(b, {{"CXX", "no-such-compiler-x"}, {"XDG_CACHE_HOME", cache.string()}});
    INFO(ri.output);
    REQUIRE(ri.code == 0);
    CHECK((!fs::exists(cache / "eomgen") || fs::is_empty(cache / "eomgen")));
    const auto rows = read_csv(interpreted);
    CHECK(column(rows[0], "height") >= 0);
    CHECK(column(rows[0], "work") >= 0);
    CHECK(largest_difference(compiled, interpreted) <= 1e-12);

    // An event stops both at the same time.
    const Result ec = eomgen({"run", model.string(), "--until", "phi=0", "--quiet"});
    const Result ei = eomgen({"run", model.string(), "--until", "phi=0", "--quiet", "--interpret"});
    REQUIRE(ec.code == 0);
    REQUIRE(ei.code == 0);
    const auto stop = [](const std::string& out) { return out.substr(out.find("stopped:")); };
    CHECK(stop(ec.output).substr(0, 40) == stop(ei.output).substr(0, 40));

    // Without --interpret, a missing compiler's message names it.
    const Result missing = eomgen({"run", model.string(), "--quiet", "--no-cache"}, {{"CXX", "no-such-compiler-x"}});
    CHECK(missing.code == 4);
    CHECK(missing.output.find("--interpret runs the model without a compiler") != std::string::npos);
}

TEST_CASE("eomgen run --interpret on a constrained model: residuals, multipliers, an ensemble", "[run][interpret]") {
    const fs::path model = fs::path(eomgen_test::source_dir()) / "models" / "pendulum_cartesian.toml";
    const fs::path compiled = kWork / "cartesian_compiled.csv", interpreted = kWork / "cartesian_interpreted.csv";
    const Result rc = eomgen({"run", model.string(), "--t-end", "4", "--rtol", "1e-12", "--csv", compiled.string(), "--quiet"});
    const Result ri = eomgen({"run", model.string(), "--t-end", "4", "--rtol", "1e-12", "--csv", interpreted.string(),
                              "--quiet", "--interpret"});
    INFO(rc.output << ri.output);
    REQUIRE(rc.code == 0);
    REQUIRE(ri.code == 0);
    const auto rows = read_csv(interpreted);
    CHECK(column(rows[0], "lambda_rod") >= 0);
    CHECK(largest_difference(compiled, interpreted) <= 1e-10);

    const fs::path sweep_c = kWork / "sweep_compiled.csv", sweep_i = kWork / "sweep_interpreted.csv";
    const Result sc = eomgen({"run", model.string(), "--sweep", "g=5:15:3", "--t-end", "2", "--out", sweep_c.string(), "--quiet"});
    const Result si = eomgen({"run", model.string(), "--sweep", "g=5:15:3", "--t-end", "2", "--out", sweep_i.string(), "--quiet", "--interpret"});
    INFO(sc.output << si.output);
    REQUIRE(sc.code == 0);
    REQUIRE(si.code == 0);
    CHECK(largest_difference(sweep_c, sweep_i) <= 1e-9);
    for (const auto& row : read_csv(sweep_i)) CHECK(row[2] != "failed");
}

TEST_CASE("eomgen run --interpret: radau5 and sensitivities on the tapes' Jacobians, and a singular M reported",
          "[run][interpret]") {
    const fs::path model = write_whole(kWork, "driven.toml", kDriven);
    for (const std::vector<std::string>& extra : {std::vector<std::string>{"--method", "radau5"},
                                                  {"--sensitivities", "c,l,x0:phi"}}) {
        const fs::path compiled = kWork / "jac_compiled.csv", interpreted = kWork / "jac_interpreted.csv";
        std::vector<std::string> a = {"run", model.string(), "--t-end", "3", "--rtol", "1e-10", "--samples", "30",
                                      "--quiet"};
        a.insert(a.end(), extra.begin(), extra.end());
        std::vector<std::string> b = a;
        a.insert(a.end(), {"--csv", compiled.string()});
        b.insert(b.end(), {"--csv", interpreted.string(), "--interpret"});
        const Result rc = eomgen(a);
        const Result ri = eomgen(b);
        INFO(rc.output << ri.output);
        REQUIRE(rc.code == 0);
        REQUIRE(ri.code == 0);
        CHECK(largest_difference(compiled, interpreted) <= 1e-8);
        if (extra[0] == "--sensitivities") CHECK(column(read_csv(interpreted)[0], "dphi/dc") >= 0);
    }

    const fs::path singular = write_whole(kWork, "singular.toml", R"toml(name = "singular_interpreted"
[[coordinates]]
name = "x"
initial = 0
[lagrangian]
T = "x^2*x'^2/2"
V = "x"
)toml");
    const Result s = eomgen({"run", singular.string(), "--interpret", "--quiet"});
    INFO(s.output);
    CHECK(s.code == 2);
    CHECK(s.output.find("mass matrix is singular") != std::string::npos);
    CHECK(s.output.find("nan") == std::string::npos);
}

TEST_CASE("eomgen fit --interpret: the compiled fit's estimates, errors and correlations", "[fit][interpret]") {
    const fs::path root = eomgen_test::source_dir();
    const std::vector<std::string> fit = {"fit", (root / "models" / "damped_pendulum.toml").string(),
                                          (root / "examples" / "fit" / "damped_pendulum_data.csv").string(),
                                          "--free", "l=1.3:0.1:10", "--free", "c=0.1:0:2", "--quiet"};
    std::vector<std::string> interpreted = fit;
    interpreted.push_back("--interpret");
    const Result c = eomgen(fit);
    const Result i = eomgen(interpreted, {{"CXX", "no-such-compiler-x"}});
    INFO(c.output << i.output);
    REQUIRE(c.code == 0);
    REQUIRE(i.code == 0);
    // Everything but the solver's line (its time) is the same text.
    auto without_timing = [](const std::string& out) {
        const std::size_t at = out.find("solver:");
        REQUIRE(at != std::string::npos);
        return out.substr(0, at) + out.substr(out.find('\n', at));
    };
    CHECK(without_timing(c.output) == without_timing(i.output));
    CHECK(i.output.find("l = 0.99994") != std::string::npos);
}

TEST_CASE("eomgen report --interpret writes the report without a compiler", "[report][interpret]") {
    const fs::path model = fs::path(eomgen_test::source_dir()) / "models" / "pendulum_cartesian.toml";
    const fs::path out = kWork / "report";
    fs::remove_all(out);
    const Result r = eomgen({"report", model.string(), "--interpret", "-o", out.string(), "--quiet"},
                            {{"CXX", "no-such-compiler-x"}});
    INFO(r.output);
    REQUIRE(r.code == 0);
    const std::string md = read(out / "pendulum_cartesian.md");
    CHECK(md.find("multiplier rod = ") != std::string::npos);  // the simulation ran, constrained
    CHECK(fs::exists(out / "pendulum_cartesian.csv"));
}
