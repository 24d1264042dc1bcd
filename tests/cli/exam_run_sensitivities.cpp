// `eomgen run --sensitivities` as a user runs it, on model files this test writes: the CSV's columns of
// S = dx/d(...) against central differences of whole `eomgen run`s, through the compiled table's Jacobians
// (analytic for an unconstrained model, forward AD through the multipliers' solve for a constrained one); the
// mistakes a user makes and what is refused.
#include "cli/eomgen_process.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace eomgen_test;

namespace {

const fs::path kWork = fs::path(EOMGEN_BINARY_DIR) / "tests" / "cli" / "work" / "run_sensitivities";

Result eomgen(const std::vector<std::string>& args) { return run_eomgen(kWork, args); }

const std::string kSpringPendulum = R"toml(name = "spring_pendulum_s"
[[coordinates]]
name = "r"
unit = "m"
initial = 1.2
[[coordinates]]
name = "phi"
unit = "rad"
initial = 0.4
rate = 0.3
[[parameters]]
name = "m"
value = 0.7
unit = "kg"
[[parameters]]
name = "k"
value = 30
unit = "N/m"
[[parameters]]
name = "l0"
value = 1
unit = "m"
[[parameters]]
name = "g"
value = 9.81
unit = "m/s^2"
[lagrangian]
T = "m/2*(r'^2 + r^2*phi'^2)"
V = "k/2*(r - l0)^2 - m*g*r*cos(phi)"
)toml";

const std::string kCartesian = R"toml(name = "cartesian_pendulum_s"
[[coordinates]]
name = "x"
initial = 0.6
[[coordinates]]
name = "y"
initial = -0.8
[[parameters]]
name = "m"
value = 2
[[parameters]]
name = "l"
value = 1
[[parameters]]
name = "g"
value = 9.81
[lagrangian]
T = "m/2*(x'^2 + y'^2)"
V = "m*g*y"
[[constraints]]
name = "rod"
expr = "x^2 + y^2 - l^2"
)toml";

/// The last CSV row's values of `names`.
std::vector<double> last_row(const fs::path& csv, const std::vector<std::string>& names) {
    const auto rows = read_csv(csv);
    REQUIRE(rows.size() > 2);
    std::vector<double> v;
    for (const auto& n : names) v.push_back(std::stod(rows.back()[std::size_t(column(rows[0], n))]));
    return v;
}

const std::vector<std::string> kTight{"--t-end", "2", "--rtol", "1e-12", "--atol", "1e-14", "--samples", "10",
                                      "--quiet"};

/// x(2) of `model` with `extra` options (a --set or --init), from the CSV's last row.
std::vector<double> end_state(const fs::path& model, const std::vector<std::string>& states,
                              const std::vector<std::string>& extra, const std::string& tag) {
    const fs::path csv = kWork / ("end_" + tag + ".csv");
    std::vector<std::string> args{"run", model.string(), "--csv", csv.string()};
    args.insert(args.end(), kTight.begin(), kTight.end());
    args.insert(args.end(), extra.begin(), extra.end());
    const Result r = eomgen(args);
    INFO(r.output);
    REQUIRE(r.code == 0);
    return last_row(csv, states);
}

/// Central differences of end_state in `option` (--set or --init) NAME about `value` with step h.
std::vector<double> central(const fs::path& model, const std::vector<std::string>& states, const std::string& option,
                            const std::string& name, double value, double h) {
    const auto at = [&](double v, const std::string& tag) {
        char text[64];
        std::snprintf(text, sizeof text, "%.17g", v);
        return end_state(model, states, {option, name + "=" + text}, tag);
    };
    const auto plus = at(value + h, "plus"), minus = at(value - h, "minus");
    std::vector<double> d;
    for (std::size_t i = 0; i < plus.size(); ++i) d.push_back((plus[i] - minus[i]) / (2 * h));
    return d;
}

void check_close(const std::vector<double>& s, const std::vector<double>& fd, double rtol) {
    double scale = 0;
    for (double v : fd) scale = std::max(scale, std::abs(v));
    for (std::size_t i = 0; i < s.size(); ++i) {
        INFO("component " << i << ": S = " << s[i] << ", differences " << fd[i]);
        CHECK(std::abs(s[i] - fd[i]) <= rtol * scale);
    }
}

}  // namespace

TEST_CASE("eomgen run --sensitivities: the CSV's columns against differences of whole runs", "[run][sensitivities]") {
    const fs::path model = write_whole(kWork, "spring_pendulum_s.toml", kSpringPendulum);
    const fs::path csv = kWork / "spring_s.csv";
    std::vector<std::string> args{"run", model.string(), "--sensitivities", "k,x0:phi", "--csv", csv.string()};
    args.insert(args.end(), kTight.begin(), kTight.end());
    const Result r = eomgen(args);
    INFO(r.output);
    REQUIRE(r.code == 0);
    CHECK(r.output.find("sensitivities at t = 2 s:") != std::string::npos);
    CHECK(r.output.find("dr/dk = ") != std::string::npos);
    const auto rows = read_csv(csv);
    REQUIRE(rows.size() == 12);
    // Each column with its unit: state's over the parameter's (m/(N/m)), 1/s for a rate over its coordinate.
    const std::vector<std::string> expected_tail{"dr/dk [m/(N/m)]", "dphi/dk [rad/(N/m)]", "dr_dot/dk [m/s/(N/m)]",
                                                 "dphi_dot/dk [rad/s/(N/m)]", "dr/dphi(0) [m/rad]", "dphi/dphi(0) [1]",
                                                 "dr_dot/dphi(0) [m/s/rad]", "dphi_dot/dphi(0) [1/s]"};
    REQUIRE(rows[0].size() >= expected_tail.size());
    CHECK(std::vector<std::string>(rows[0].end() - long(expected_tail.size()), rows[0].end()) == expected_tail);
    // At t = 0: S is 0 for k, the unit vector of phi for phi(0).
    CHECK(std::stod(rows[1][std::size_t(column(rows[0], "dr/dk"))]) == 0.0);
    CHECK(std::stod(rows[1][std::size_t(column(rows[0], "dphi/dphi(0)"))]) == 1.0);

    const std::vector<std::string> states{"r", "phi", "r_dot", "phi_dot"};
    std::vector<std::string> dk, dphi0;
    for (const auto& s : states) {
        dk.push_back("d" + s + "/dk");
        dphi0.push_back("d" + s + "/dphi(0)");
    }
    // Steps of 1e-4 relative: truncation 1e-8, the runs' error (1e-12) over the step 1e-8.
    check_close(last_row(csv, dk), central(model, states, "--set", "k", 30, 30e-4), 1e-6);
    check_close(last_row(csv, dphi0), central(model, states, "--init", "phi", 0.4, 1e-4), 1e-6);
}

TEST_CASE("eomgen run --sensitivities of a constrained model, and what it refuses", "[run][sensitivities]") {
    const fs::path model = write_whole(kWork, "cartesian_pendulum_s.toml", kCartesian);
    const fs::path csv = kWork / "cartesian_s.csv";
    std::vector<std::string> args{"run", model.string(), "--sensitivities", "g", "--csv", csv.string()};
    args.insert(args.end(), kTight.begin(), kTight.end());
    const Result r = eomgen(args);
    INFO(r.output);
    REQUIRE(r.code == 0);
    CHECK(r.output.find("no projection onto the constraints") != std::string::npos);
    const std::vector<std::string> states{"x", "y", "x_dot", "y_dot"};
    std::vector<std::string> dg;
    for (const auto& s : states) dg.push_back("d" + s + "/dg");
    check_close(last_row(csv, dg), central(model, states, "--set", "g", 9.81, 9.81e-4), 1e-6);

    // The rod's length moves the consistent initial state; an initial value leaves the constraints.
    for (const std::string& column : {"l", "x0:x"}) {
        const Result refused = eomgen({"run", model.string(), "--sensitivities", column, "--quiet"});
        INFO(refused.output);
        CHECK(refused.code == 2);
        CHECK(refused.output.find("is not done") != std::string::npos);
        CHECK(refused.output.find("model:") == std::string::npos);  // refused before the report starts
    }
}

TEST_CASE("eomgen run --sensitivities: a user's mistakes", "[run][sensitivities]") {
    const fs::path model = write_whole(kWork, "spring_pendulum_s.toml", kSpringPendulum);
    const std::map<std::vector<std::string>, std::string> cases{
        {{"--sensitivities", "kk"}, "has no parameter 'kk'; did you mean 'k'?"},
        {{"--sensitivities", "x0:rr"}, "no state 'rr'; did you mean 'r'?"},
        {{"--sensitivities", "k,k"}, "--sensitivities k: given twice"},
        {{"--sensitivities", "k", "--method", "rk4", "--dt", "0.01"}, "needs a method with error control"},
        {{"--sensitivities", "k", "--sweep", "g=9:10:3"}, "of an ensemble's members is not done"},
    };
    for (const auto& [extra, message] : cases) {
        std::vector<std::string> args{"run", model.string(), "--quiet"};
        args.insert(args.end(), extra.begin(), extra.end());
        const Result r = eomgen(args);
        INFO(r.output);
        CHECK(r.code == 2);
        CHECK(r.output.find(message) != std::string::npos);
    }
    const Result report = eomgen({"report", model.string(), "--sensitivities", "k", "-o", (kWork / "r").string()});
    INFO(report.output);
    CHECK(report.code == 2);
    CHECK(report.output.find("--sensitivities is an option of eomgen run") != std::string::npos);
    CHECK(!fs::exists(kWork / "r"));
}
