// `eomgen run --sensitivities` as a user runs it, on model files this test writes: the CSV's columns of
// S = dx/d(...) against central differences of whole `eomgen run`s, through the compiled table's Jacobians
// (analytic for an unconstrained model, forward AD through the multipliers' solve for a constrained one); the
// mistakes a user makes and what is refused.
#include "test_paths.hpp"
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

const fs::path kWork = fs::path(eomgen_test::binary_dir()) / "tests" / "cli" / "work" / "run_sensitivities";

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

/// Central differences of end_state in `option` (--set or --init) NAME about `value` with step h, each run with
/// `also` (--project-initial, a method).
std::vector<double> central(const fs::path& model, const std::vector<std::string>& states, const std::string& option,
                            const std::string& name, double value, double h,
                            const std::vector<std::string>& also = {}) {
    const auto at = [&](double v, const std::string& tag) {
        char text[64];
        std::snprintf(text, sizeof text, "%.17g", v);
        std::vector<std::string> extra{option, name + "=" + text};
        extra.insert(extra.end(), also.begin(), also.end());
        return end_state(model, states, extra, tag);
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

    // The rod's length and an initial value move the consistent start: as --project-initial moves each changed
    // start onto the rod (the differences' runs project theirs).
    const fs::path csv2 = kWork / "cartesian_s2.csv";
    args = {"run", model.string(), "--sensitivities", "l,x0:x", "--csv", csv2.string()};
    args.insert(args.end(), kTight.begin(), kTight.end());
    const Result moved = eomgen(args);
    INFO(moved.output);
    REQUIRE(moved.code == 0);
    std::vector<std::string> dl, dx0;
    for (const auto& s : states) {
        dl.push_back("d" + s + "/dl");
        dx0.push_back("d" + s + "/dx(0)");
    }
    check_close(last_row(csv2, dl), central(model, states, "--set", "l", 1, 1e-4, {"--project-initial"}), 1e-6);
    check_close(last_row(csv2, dx0), central(model, states, "--init", "x", 0.6, 1e-4, {"--project-initial"}), 1e-6);
}

TEST_CASE("eomgen run --sensitivities by rk4 and symplectic, and with the state alone in the error control", "[run][sensitivities]") {
    const fs::path model = write_whole(kWork, "spring_pendulum_s.toml", kSpringPendulum);
    const std::vector<std::string> states{"r", "phi", "r_dot", "phi_dot"};
    std::vector<std::string> dk;
    for (const auto& s : states) dk.push_back("d" + s + "/dk");
    // rk4: S is the derivative of RK4's own motion, so differences of rk4 runs with the same steps agree with it.
    const std::vector<std::string> rk4{"--method", "rk4", "--dt", "0.01"};
    const fs::path csv = kWork / "spring_rk4.csv";
    std::vector<std::string> args{"run", model.string(), "--sensitivities", "k", "--csv", csv.string()};
    args.insert(args.end(), kTight.begin(), kTight.end());
    args.insert(args.end(), rk4.begin(), rk4.end());
    const Result r = eomgen(args);
    INFO(r.output);
    REQUIRE(r.code == 0);
    CHECK(r.output.find("fixed steps of 0.01") != std::string::npos);
    check_close(last_row(csv, dk), central(model, states, "--set", "k", 30, 30e-4, rk4), 1e-6);

    // symplectic: the same for the variational integrator's own motion, through the table's derivatives of the
    // momenta and of dL/dq, for a parameter and an initial rate.
    const std::vector<std::string> symplectic{"--method", "symplectic", "--dt", "0.01"};
    const fs::path vcsv = kWork / "spring_symplectic.csv";
    std::vector<std::string> vargs{"run", model.string(), "--sensitivities", "k,x0:phi_dot", "--csv", vcsv.string()};
    vargs.insert(vargs.end(), kTight.begin(), kTight.end());
    vargs.insert(vargs.end(), symplectic.begin(), symplectic.end());
    const Result v = eomgen(vargs);
    INFO(v.output);
    REQUIRE(v.code == 0);
    CHECK(v.output.find("(variational midpoint), fixed steps of 0.01") != std::string::npos);
    CHECK(v.output.find("steps:   200, ") != std::string::npos);
    check_close(last_row(vcsv, dk), central(model, states, "--set", "k", 30, 30e-4, symplectic), 1e-6);
    std::vector<std::string> dphidot;
    for (const auto& s : states) dphidot.push_back("d" + s + "/dphi_dot(0)");
    check_close(last_row(vcsv, dphidot), central(model, states, "--init", "phi_dot", 0.3, 1e-4, symplectic), 1e-6);

    // --state-error-only: fewer steps, S still close to the differences (at the accuracy of those steps).
    const fs::path both = kWork / "spring_both.csv", state = kWork / "spring_state.csv";
    const auto steps = [&](const fs::path& out, bool state_only) {
        std::vector<std::string> a{"run", model.string(), "--sensitivities", "k,x0:phi", "--csv", out.string(),
                                   "--t-end", "2", "--rtol", "1e-9", "--atol", "1e-12"};
        if (state_only) a.push_back("--state-error-only");
        const Result run = eomgen(a);
        INFO(run.output);
        REQUIRE(run.code == 0);
        const auto at = run.output.find("steps:   ");
        REQUIRE(at != std::string::npos);
        CHECK(run.output.find(state_only ? "the state alone in the error control" : "under the same error control") !=
              std::string::npos);
        return std::stoi(run.output.substr(at + 9));
    };
    const int all = steps(both, false), state_alone = steps(state, true);
    CHECK(state_alone < all);
    check_close(last_row(state, dk), central(model, states, "--set", "k", 30, 30e-4), 1e-5);
}

TEST_CASE("eomgen run --sweep --sensitivities: each member's S in the table", "[run][sensitivities]") {
    const fs::path model = write_whole(kWork, "spring_pendulum_s.toml", kSpringPendulum);
    const fs::path table = kWork / "sweep_s.csv";
    std::vector<std::string> args{"run", model.string(), "--sweep", "g=9:10:3", "--sensitivities", "k,x0:phi",
                                  "--out", table.string(), "--t-end", "2", "--rtol", "1e-12", "--atol", "1e-14",
                                  "--until", "phi=0"};
    const Result r = eomgen(args);
    INFO(r.output);
    REQUIRE(r.code == 0);
    const auto rows = read_csv(table);
    REQUIRE(rows.size() == 4);
    for (const std::string& name : {"dr/dk [m/(N/m)]", "dphi_dot/dphi(0) [1/s]", "dt/dk [s/(N/m)]", "dt/dphi(0) [s/rad]"})
        CHECK(std::find(rows[0].begin(), rows[0].end(), name) != rows[0].end());
    // Member 1 (g = 9.5) against one run with its values: the same numbers.
    const Result single = eomgen({"run", model.string(), "--set", "g=9.5", "--sensitivities", "k,x0:phi", "--t-end",
                                  "2", "--rtol", "1e-12", "--atol", "1e-14", "--until", "phi=0"});
    INFO(single.output);
    REQUIRE(single.code == 0);
    const auto at = single.output.find("dt/dk = ");
    REQUIRE(at != std::string::npos);
    const double dt_dk = std::stod(single.output.substr(at + 8));
    const double member = std::stod(rows[2][std::size_t(column(rows[0], "dt/dk [s/(N/m)]"))]);
    CHECK(std::abs(member - dt_dk) <= 1e-9 * std::abs(dt_dk));
    const auto dr = single.output.find("dr/dk = ");  // S where the run ended: the report's
    REQUIRE(dr != std::string::npos);
    const double dr_dk = std::stod(single.output.substr(dr + 8));
    CHECK(std::abs(std::stod(rows[2][std::size_t(column(rows[0], "dr/dk [m/(N/m)]"))]) - dr_dk) <=
          1e-9 * std::max(1e-6, std::abs(dr_dk)));
    CHECK(rows[2][std::size_t(column(rows[0], "stopped"))] == "phi=0");
}

TEST_CASE("eomgen run --sensitivities: a user's mistakes", "[run][sensitivities]") {
    const fs::path model = write_whole(kWork, "spring_pendulum_s.toml", kSpringPendulum);
    const std::map<std::vector<std::string>, std::string> cases{
        {{"--sensitivities", "kk"}, "has no parameter 'kk'; did you mean 'k'?"},
        {{"--sensitivities", "x0:rr"}, "no state 'rr'; did you mean 'r'?"},
        {{"--sensitivities", "k,k"}, "--sensitivities k: given twice"},
        {{"--sensitivities", "k", "--method", "symplectic", "--dt", "0.01", "--until", "phi=0"},
         "--until needs --method dopri5"},
        {{"--sensitivities", "k", "--method", "symplectic", "--dt", "0.01", "--state-error-only"},
         "symplectic takes fixed steps"},
        {{"--sensitivities", "k", "--method", "rk4", "--dt", "0.01", "--state-error-only"}, "rk4 takes fixed steps"},
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
