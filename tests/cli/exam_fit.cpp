// `eomgen fit` as a user runs it: the worked example of docs/sensitivities.md (the damped pendulum's l and c from
// 1,000 noisy samples, examples/fit/), the estimates within their standard errors of the values the data were made
// with, a combination the data cannot separate, and the data and options a user gets wrong.
#include "test_paths.hpp"
#include "cli/eomgen_process.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace eomgen_test;

namespace {

const fs::path kWork = fs::path(eomgen_test::binary_dir()) / "tests" / "cli" / "work" / "fit";
const std::string kModel = eomgen_test::source_dir() + "/models/damped_pendulum.toml";
const std::string kData = eomgen_test::source_dir() + "/examples/fit/damped_pendulum_data.csv";

Result eomgen(const std::vector<std::string>& args) { return run_eomgen(kWork, args); }

/// The number after `"name": "NAME", "value": ` (or standard_error) in eomgen fit's JSON.
double json_field(const std::string& json, const std::string& name, const std::string& field) {
    const std::regex re("\"name\": \"" + name + "\", \"value\": ([-0-9.e+]+), \"standard_error\": ([-0-9.e+]+|null)");
    std::smatch m;
    REQUIRE(std::regex_search(json, m, re));
    const std::string text = field == "value" ? m[1].str() : m[2].str();
    return text == "null" ? std::nan("") : std::stod(text);
}

/// Whether the estimate NAME (a regex) in eomgen fit's JSON lies within `errors` of its standard errors of `truth`.
bool within_errors(const std::string& json, const std::string& name, double truth, double errors) {
    const double v = json_field(json, name, "value"), se = json_field(json, name, "standard_error");
    INFO(name << " = " << v << " +- " << se << ", truth " << truth);
    return std::abs(v - truth) < errors * se;
}

/// phi of the damped pendulum run with `options` (t-end 6, 301 samples), plus seeded Gaussian noise of 0.01 rad
/// and, with probability `outliers` per sample, a throw of 0.2-0.5 rad either way; written as `name` in kWork. The
/// count of samples thrown in `thrown`.
std::string noisy_phi(const std::vector<std::string>& options, const std::string& name, unsigned seed,
                      double outliers = 0, int* thrown = nullptr) {
    const fs::path truth = kWork / ("truth_" + name);
    std::vector<std::string> args{"run", kModel, "--t-end", "6", "--samples", "300", "--rtol", "1e-12", "--atol",
                                  "1e-14", "--csv", truth.string(), "--quiet"};
    args.insert(args.end(), options.begin(), options.end());
    const Result made = eomgen(args);
    INFO(made.output);
    REQUIRE(made.code == 0);
    const auto rows = read_csv(truth);
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, 0.01);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::string text = "t [s],phi [rad]\n";
    for (std::size_t i = 1; i < rows.size(); ++i) {
        double y = std::stod(rows[i][std::size_t(column(rows[0], "phi"))]) + noise(rng);
        if (outliers > 0 && u(rng) < outliers) {
            y += (u(rng) < 0.5 ? -1 : 1) * (0.2 + 0.3 * u(rng));
            if (thrown) ++*thrown;
        }
        text += rows[i][0] + "," + std::to_string(y) + "\n";
    }
    return write_whole(kWork, name, text).string();
}

}  // namespace

TEST_CASE("eomgen fit recovers the damped pendulum's l and c within their standard errors", "[fit]") {
    // examples/fit/make_data.py made the data with l = 1 m, c = 0.2 N m s and noise of 0.01 rad.
    const fs::path csv = kWork / "fitted.csv";
    const Result f = eomgen({"fit", kModel, kData, "--free", "l=1.3:0.1:10", "--free", "c=0.1:0:2", "--format",
                             "json", "--csv", csv.string(), "--quiet"});
    INFO(f.output);
    REQUIRE(f.code == 0);
    CHECK(f.output.find("\"converged\": true") != std::string::npos);
    const double l = json_field(f.output, "l", "value"), sl = json_field(f.output, "l", "standard_error");
    const double c = json_field(f.output, "c", "value"), sc = json_field(f.output, "c", "standard_error");
    // Noise of 0.01 rad over 1,000 samples: standard errors of order 1e-4; the truth within 3 of them.
    CHECK(sl > 2e-5);
    CHECK(sl < 1e-3);
    CHECK(sc > 5e-5);
    CHECK(sc < 3e-3);
    CHECK(std::abs(l - 1.0) < 3 * sl);
    CHECK(std::abs(c - 0.2) < 3 * sc);
    // The residuals' RMS is the noise's 0.01.
    const std::regex rms("\"rms\": ([0-9.e-]+)");
    std::smatch m;
    REQUIRE(std::regex_search(f.output, m, rms));
    CHECK(std::stod(m[1].str()) == Approx(0.01).epsilon(0.05));

    // The CSV: t, the data, the fitted model and the residual, the last = model − data.
    const auto rows = read_csv(csv);
    REQUIRE(rows.size() == 1001);
    CHECK(rows[0] == std::vector<std::string>{"t [s]", "phi [rad]", "phi_model [rad]", "phi_residual [rad]"});
    const auto& row = rows[500];
    CHECK(std::stod(row[3]) == Approx(std::stod(row[2]) - std::stod(row[1])).margin(1e-15));

    // The same fit in text, with the initial angle free as well.
    const Result t = eomgen({"fit", kModel, kData, "--free", "l=1.3:0.1:10", "--free", "c=0.1:0:2", "--free",
                             "x0:phi=0.9", "--quiet"});
    INFO(t.output);
    REQUIRE(t.code == 0);
    CHECK(t.output.find("fixed:   m = 1 kg, g = 9.81 m/s^2") != std::string::npos);
    CHECK(std::regex_search(t.output, std::regex("x0:phi = 1\\.00[0-9]* rad \\+- 0\\.00[0-9]* rad")));
    CHECK(t.output.find("correlation:") != std::string::npos);
}

TEST_CASE("eomgen fit: two experiments share l and c, each with its own initial angle", "[fit]") {
    // The second experiment starts at phi = 0.5 (the first at the file's 1.0); its data are made here, with noise
    // of 0.01 rad from a seeded generator.
    const std::string second = noisy_phi({"--init", "phi=0.5"}, "half.csv", 7);
    const fs::path csv = kWork / "two.csv";
    const Result f = eomgen({"fit", kModel, kData, second, "--free", "l=1.3:0.1:10", "--free", "c=0.1:0:2",
                             "--free", "x0:phi=0.8", "--format", "json", "--csv", csv.string(), "--quiet"});
    INFO(f.output);
    REQUIRE(f.code == 0);
    CHECK(within_errors(f.output, "l", 1.0, 4));
    CHECK(within_errors(f.output, "x0:phi\\[1\\]", 1.0, 4));
    CHECK(within_errors(f.output, "x0:phi\\[2\\]", 0.5, 4));
    CHECK(json_field(f.output, "x0:phi\\[1\\]", "standard_error") < 0.01);
    CHECK(json_field(f.output, "x0:phi\\[2\\]", "standard_error") < 0.01);
    // The plot of both experiments against the fit, and their residuals.
    const fs::path svg = kWork / "two.svg";
    const Result p = eomgen({"fit", kModel, kData, second, "--free", "l=1.3:0.1:10", "--free", "c=0.1:0:2",
                             "--free", "x0:phi=0.8", "--plot", svg.string(), "--quiet"});
    INFO(p.output);
    REQUIRE(p.code == 0);
    const std::string drawn = read(svg);
    CHECK(drawn.find("data [2]") != std::string::npos);
    CHECK(drawn.find("residual (model - data)") != std::string::npos);
    const Result bad = eomgen({"fit", kModel, kData, "--free", "l", "--plot", (kWork / "fit.pdf").string(), "--quiet"});
    CHECK(bad.code == 2);
    CHECK(bad.output.find(".png or .svg") != std::string::npos);

    const auto out = read_csv(csv);
    REQUIRE(out.size() == 1 + 1000 + 301);
    CHECK(out[0][0] == "experiment");
    CHECK(out[1][0] == "1");
    CHECK(out.back()[0] == "2");
}

TEST_CASE("eomgen fit to a declared output: the door's tilt from the speed of its edge", "[fit]") {
    // v_edge = w psi' ([outputs] of models/door.toml), measured with noise of 0.01 m/s until just before it shuts.
    const std::string door = eomgen_test::source_dir() + "/models/door.toml";
    const fs::path truth = kWork / "door_truth.csv";
    const Result made = eomgen({"run", door, "--t-end", "2.9", "--samples", "290", "--rtol", "1e-12", "--atol",
                                "1e-14", "--csv", truth.string(), "--quiet"});
    INFO(made.output);
    REQUIRE(made.code == 0);
    const auto rows = read_csv(truth);
    std::mt19937 rng(3);
    std::normal_distribution<double> noise(0.0, 0.01);
    std::string text = "t [s],v_edge [m/s]\n";
    for (std::size_t i = 1; i < rows.size(); ++i)
        text += rows[i][0] + "," + std::to_string(std::stod(rows[i][std::size_t(column(rows[0], "v_edge"))]) + noise(rng)) +
                "\n";
    const fs::path data = write_whole(kWork, "door_edge.csv", text);
    const Result f = eomgen({"fit", door, data.string(), "--free", "theta=0.03:0.001:0.5", "--format", "json", "--quiet"});
    INFO(f.output);
    REQUIRE(f.code == 0);
    const double theta = json_field(f.output, "theta", "value"), s = json_field(f.output, "theta", "standard_error");
    CHECK(s > 0);
    CHECK(s < 1e-3);
    CHECK(std::abs(theta - 0.0234) < 4 * s);
}

TEST_CASE("eomgen fit says which combination the data do not determine", "[fit]") {
    // phi'' + c/(m l^2) phi' + (g/l) sin phi = 0: with l, g and c free only g/l and c/l^2 are seen.
    const Result f = eomgen({"fit", kModel, kData, "--free", "l", "--free", "g", "--free", "c", "--quiet"});
    INFO(f.output);
    REQUIRE(f.code == 0);
    CHECK(f.output.find("l = ") != std::string::npos);
    CHECK(f.output.find("+- (not determined by the data)") != std::string::npos);
    CHECK(std::regex_search(f.output, std::regex("not determined: changing the values along dl/l = [+-]0\\.408, "
                                                 "dg/g = [+-]0\\.408, dc/c = [+-]0\\.816")));
    const Result j = eomgen({"fit", kModel, kData, "--free", "l", "--free", "g", "--free", "c", "--format", "json",
                             "--quiet"});
    CHECK(j.output.find("\"standard_error\": null") != std::string::npos);
}

TEST_CASE("eomgen fit: data and options that do not fit the model file", "[fit]") {
    const auto data = [](const std::string& name, const std::string& text) {
        return write_whole(kWork, name, text).string();
    };
    struct Case {
        std::string data;
        std::vector<std::string> options;
        std::string message;
    };
    const std::vector<Case> cases{
        {data("theta.csv", "t,theta\n0,1\n0.1,0.9\n"), {"--free", "l"}, "theta.csv:1:3: 'theta' is neither a state nor a declared output of the model (states: phi, phi_dot)"},
        {data("order.csv", "t,phi\n0,1\n0.2,0.9\n0.1,0.8\n"), {"--free", "l"}, "order.csv:4:1: t = 0.1 does not come after"},
        {data("nan.csv", "t,phi\n0,1\n0.1,nan\n0.2,0.8\n"), {"--free", "l"}, "nan.csv:3:5: 'nan' is not a finite number"},
        {data("empty_cell.csv", "t,phi\n0,1\n0.1,\n"), {"--free", "l"}, "empty_cell.csv:3:5: '' is not a finite number"},
        {data("unit.csv", "t,phi [deg]\n0,57\n0.1,50\n"), {"--free", "l"}, "unit.csv:1:3: phi is in rad (the unit eomgen run writes), not deg"},
        {data("first.csv", "time,phi\n0,1\n"), {"--free", "l"}, "first.csv:1:1: the first column must be t"},
        {data("negative.csv", "t,phi\n-1,1\n0,1\n"), {"--free", "l"}, "negative.csv:2:1: t < 0"},
        {data("short.csv", "t,phi\n0,1\n"), {"--free", "l", "--free", "c"}, "1 measurements for 2 unknowns"},
        {kData, {"--free", "ll"}, "has no parameter 'll'; did you mean 'l'?"},
        {kData, {"--free", "l=2:3:1"}, "the lower bound must be below the upper"},
        {kData, {"--free", "l=5:0.1:2"}, "is outside"},
        {kData, {"--free", "l", "--weight", "theta=2"}, "no measured column 'theta'"},
        {kData, {"--free", "l", "--method", "rk4"}, "needs a method with error control"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args{"fit", kModel, c.data, "--quiet"};
        args.insert(args.end(), c.options.begin(), c.options.end());
        const Result r = eomgen(args);
        INFO(r.output);
        CHECK(r.code == 2);
        CHECK(r.output.find(c.message) != std::string::npos);
    }
}

namespace {

/// The first two columns (t and the first state) of an `eomgen run` CSV, as a data file in kWork named `name`.
std::string first_two_columns(const std::string& csv, const std::string& name) {
    const std::string path = (kWork / name).string();
    std::ifstream in(csv);
    std::ofstream out(path);
    for (std::string line; std::getline(in, line);) out << line.substr(0, line.find(',', line.find(',') + 1)) << "\n";
    return path;
}

/// The value printed as "  NAME = VALUE" in eomgen fit's report.
double estimate(const std::string& report, const std::string& name) {
    const auto at = report.find("  " + name + " = ");
    REQUIRE(at != std::string::npos);
    return std::stod(report.substr(at + name.size() + 5));
}

}  // namespace

TEST_CASE("eomgen fit of a constrained model: the rod's length and where the bob starts", "[fit]") {
    // l is in the constraint x^2 + y^2 = l^2 and x(0) leaves it: each evaluation projects the start onto the rod, as
    // the sensitivities' consistent start assumes (consistent_sensitivities.hpp).
    const std::string model = eomgen_test::source_dir() + "/models/pendulum_cartesian.toml";
    const std::string csv = (kWork / "cartesian_truth.csv").string();
    const Result truth = eomgen({"run", model, "--t-end", "2", "--samples", "40", "--rtol", "1e-12", "--atol", "1e-14",
                                 "--csv", csv, "--quiet"});
    INFO(truth.output);
    REQUIRE(truth.code == 0);
    const Result fitted = eomgen({"fit", model, first_two_columns(csv, "cartesian_data.csv"), "--free", "l=1.2:0.5:2",
                                  "--free", "x0:x=0.45:0:1", "--rtol", "1e-12", "--atol", "1e-14", "--quiet"});
    INFO(fitted.output);
    REQUIRE(fitted.code == 0);
    CHECK(std::abs(estimate(fitted.output, "l") - 1.0) < 1e-7);
    CHECK(std::abs(estimate(fitted.output, "x0:x") - 0.479425538604203) < 1e-7);
}

TEST_CASE("eomgen fit of a model with switching surfaces: the friction door's tilt and friction", "[fit]") {
    // The door's hinge friction is sign(psi'): the sensitivities jump where a motion reverses (saltation.hpp). Data
    // without noise from the model's own motion (released at rest, closing in 4.46 s) give back its values.
    const std::string model = eomgen_test::source_dir() + "/examples/friction_door.toml";
    const std::string csv = (kWork / "friction_door_truth.csv").string();
    const Result truth = eomgen({"run", model, "--t-end", "4", "--samples", "80", "--rtol", "1e-12", "--atol",
                                 "1e-14", "--csv", csv, "--quiet"});
    INFO(truth.output);
    REQUIRE(truth.code == 0);
    const std::string data_path = first_two_columns(csv, "friction_door_data.csv");  // t and psi
    const Result fitted = eomgen({"fit", model, data_path, "--free", "tau_f=1:0:5", "--free", "theta=0.03:0.001:0.5",
                                  "--rtol", "1e-12", "--atol", "1e-14", "--quiet"});
    INFO(fitted.output);
    REQUIRE(fitted.code == 0);
    CHECK(std::abs(estimate(fitted.output, "tau_f") - 1.5) < 1e-6);
    CHECK(std::abs(estimate(fitted.output, "theta") - 0.0234) < 1e-8);
}

TEST_CASE("eomgen fit: each experiment with its own settings (--set K:NAME=V, --init K:NAME=V)", "[fit]") {
    // The second experiment swings a bob of 2 kg from phi = 0.5 (the first: the example's 1 kg from 1 rad). l and c
    // are shared; the initial angles are fitted per experiment, each from its own --init.
    const std::string second = noisy_phi({"--set", "m=2", "--init", "phi=0.5"}, "heavy.csv", 11);
    const std::vector<std::string> common{"fit", kModel, kData, second, "--free", "l=1.3:0.1:10", "--free",
                                          "c=0.1:0:2", "--free", "x0:phi", "--format", "json", "--quiet"};
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> args = common;
        args.insert(args.end(), extra.begin(), extra.end());
        return eomgen(args);
    };
    const Result f = with({"--set", "2:m=2000 g", "--init", "2:phi=0.5"});
    INFO(f.output);
    REQUIRE(f.code == 0);
    CHECK(within_errors(f.output, "l", 1.0, 4));
    CHECK(within_errors(f.output, "c", 0.2, 4));
    CHECK(within_errors(f.output, "x0:phi\\[2\\]", 0.5, 4));
    // Each experiment's start: the first's from the model file, the second's from its own --init.
    CHECK(f.output.find("\"name\": \"x0:phi[1]\", \"value\"") != std::string::npos);
    CHECK(std::regex_search(f.output, std::regex("\"x0:phi\\[2\\]\", [^}]*\"start\": 0.5\\}")));
    CHECK(f.output.find("\"set\": {\"m\": 2}, \"init\": {\"phi\": 0.5}") != std::string::npos);
    const std::regex rms_re("\"rms\": ([0-9.e-]+)");
    std::smatch m;
    REQUIRE(std::regex_search(f.output, m, rms_re));
    const double rms = std::stod(m[1].str());
    CHECK(rms == Approx(0.01).epsilon(0.1));
    // Without the second experiment's own mass the model cannot follow its data as closely.
    const Result wrong = with({"--init", "2:phi=0.5"});
    INFO(wrong.output);
    REQUIRE(wrong.code == 0);
    REQUIRE(std::regex_search(wrong.output, m, rms_re));
    CHECK(std::stod(m[1].str()) > 1.3 * rms);
    // The text report says what each experiment sets for itself.
    const Result t = eomgen({"fit", kModel, kData, second, "--free", "l=1.3:0.1:10", "--free", "c=0.1:0:2", "--set",
                             "2:m=2", "--init", "2:phi=0.5", "--quiet"});
    INFO(t.output);
    CHECK(t.output.find("heavy.csv: 301 times x 1 column (phi); its own m = 2 kg, phi = 0.5 rad") != std::string::npos);

    struct Case {
        std::vector<std::string> options;
        std::string message;
    };
    const std::vector<Case> cases{
        {{"--set", "3:m=2"}, "--set 3:m=2: there is no experiment 3 (K: is the place of a data file, from 1; there are 2 data files)"},
        {{"--set", "2:l=2"}, "--set 2:l=2: l is free, one value fitted for every experiment"},
        {{"--set", "2:mass=2"}, "--set 2:mass=2: damped_pendulum has no parameter 'mass'"},
        {{"--init", "2:ph=1"}, "--init 2:ph=1: no state 'ph'; did you mean 'phi'?"},
        {{"--init", "2:phi=2 m"}, "experiment 2: --init phi=2 m: "},
        {{"--free", "x0:phi_dot:-1:1", "--init", "2:phi_dot=3"}, "--free x0:phi_dot[2]: experiment 2 starts at 3"},
    };
    for (const Case& k : cases) {
        std::vector<std::string> args{"fit", kModel, kData, second, "--free", "l", "--quiet"};
        args.insert(args.end(), k.options.begin(), k.options.end());
        const Result r = eomgen(args);
        INFO(r.output);
        CHECK(r.code == 2);
        CHECK(r.output.find(k.message) != std::string::npos);
    }
}

TEST_CASE("eomgen fit: a parameter each experiment has its own (--free K:NAME)", "[fit]") {
    // The second series is the same pendulum with more damping (c = 0.35, from phi = 0.5): l is shared, c is each
    // experiment's own unknown.
    const std::string second = noisy_phi({"--set", "c=0.35", "--init", "phi=0.5"}, "damped_more.csv", 17);
    const std::vector<std::string> common{"fit", kModel, kData, second, "--free", "l=1.3:0.1:10", "--init", "2:phi=0.5",
                                          "--format", "json", "--quiet"};
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> args = common;
        args.insert(args.end(), extra.begin(), extra.end());
        return eomgen(args);
    };
    const Result own = with({"--free", "1:c=0.1:0:2", "--free", "2:c:0:2", "--set", "2:c=0.25"});
    INFO(own.output);
    REQUIRE(own.code == 0);
    CHECK(within_errors(own.output, "l", 1.0, 4));
    CHECK(within_errors(own.output, "c\\[1\\]", 0.2, 4));
    CHECK(within_errors(own.output, "c\\[2\\]", 0.35, 4));
    // Experiment 2's c starts where its own --set puts it; the shared l comes first, then each experiment's own.
    CHECK(std::regex_search(own.output, std::regex("\"c\\[2\\]\", [^}]*\"start\": 0.25\\}")));
    CHECK(own.output.find("\"name\": \"l\"") < own.output.find("\"name\": \"c[1]\""));
    CHECK(own.output.find("\"name\": \"c[1]\"") < own.output.find("\"name\": \"c[2]\""));
    const std::regex rms_re("\"rms\": ([0-9.e-]+)");
    std::smatch m;
    REQUIRE(std::regex_search(own.output, m, rms_re));
    const double rms = std::stod(m[1].str());
    CHECK(rms == Approx(0.01).epsilon(0.1));
    // One c for both cannot follow both series.
    const Result shared = with({"--free", "c=0.1:0:2"});
    INFO(shared.output);
    REQUIRE(shared.code == 0);
    REQUIRE(std::regex_search(shared.output, m, rms_re));
    CHECK(std::stod(m[1].str()) > 1.3 * rms);
    // K:x0:STATE: one experiment's initial value only.
    const Result start = with({"--free", "1:c=0.1:0:2", "--free", "2:c:0:2", "--free", "2:x0:phi=0.45"});
    INFO(start.output);
    REQUIRE(start.code == 0);
    CHECK(within_errors(start.output, "x0:phi\\[2\\]", 0.5, 4));
    CHECK(start.output.find("x0:phi[1]") == std::string::npos);

    struct Case {
        std::vector<std::string> options;
        std::string message;
    };
    const std::vector<Case> cases{
        {{"--free", "3:c"}, "--free 3:c: there is no experiment 3 (K: is the place of a data file, from 1; there are 2 data files)"},
        {{"--free", "c", "--free", "2:c"}, "--free 2:c: c is already free for every experiment (--free c)"},
        {{"--free", "1:c", "--free", "c"}, "--free c: c is already free for experiment 1 (--free 1:c)"},
        {{"--free", "2:c", "--free", "2:c=0.3"}, "--free 2:c: given twice"},
        {{"--free", "2:cc"}, "--free 2:cc: damped_pendulum has no parameter 'cc'; did you mean 'c'?"},
        {{"--free", "0:c"}, "--free 0:c: there is no experiment 0"},
    };
    for (const Case& k : cases) {
        std::vector<std::string> args{"fit", kModel, kData, second, "--free", "l", "--quiet"};
        args.insert(args.end(), k.options.begin(), k.options.end());
        const Result r = eomgen(args);
        INFO(r.output);
        CHECK(r.code == 2);
        CHECK(r.output.find(k.message) != std::string::npos);
    }
}

TEST_CASE("eomgen fit --loss: robust losses against outliers, with standard errors that stay honest", "[fit]") {
    // 5 % of the samples thrown off by 0.2-0.5 rad. Least squares keeps the truth inside its errors only by
    // making them large (its s is the outliers' spread); the robust losses give errors near the clean data's.
    int thrown = 0;
    const std::string data = noisy_phi({}, "outliers.csv", 23, 0.05, &thrown);
    REQUIRE(thrown > 5);
    const auto run = [&](const std::string& loss) {
        const Result r = eomgen({"fit", kModel, data, "--free", "l=1.3:0.1:10", "--free", "c=0.1:0:2", "--loss", loss,
                                 "--format", "json", "--quiet"});
        INFO(loss << "\n" << r.output);
        REQUIRE(r.code == 0);
        return r.output;
    };
    const std::string squared = run("squared");
    const double sc_squared = json_field(squared, "c", "standard_error");
    for (const std::string loss : {"huber:0.03", "soft_l1:0.03", "cauchy:0.03", "arctan:0.03", "tukey:0.05"}) {
        const std::string out = run(loss);
        INFO(loss << "\n" << out);
        CHECK(within_errors(out, "l", 1.0, 3));
        CHECK(within_errors(out, "c", 0.2, 3));
        CHECK(json_field(out, "c", "standard_error") < sc_squared / 3);
        // The residuals beyond the scale are the ones thrown (give or take a sample near it).
        const std::regex beyond("\"beyond_scale\": ([0-9]+)");
        std::smatch m;
        REQUIRE(std::regex_search(out, m, beyond));
        CHECK(std::abs(std::stoi(m[1].str()) - thrown) <= 3);
    }
    const Result text = eomgen({"fit", kModel, data, "--free", "l=1.3:0.1:10", "--free", "c=0.1:0:2", "--loss",
                                "huber:0.03", "--quiet"});
    INFO(text.output);
    CHECK(std::regex_search(text.output, std::regex("loss:    huber with scale 0.03: [0-9]+ of 301 residuals beyond it "
                                                    "count less than in least squares")));
    CHECK(text.output.find("(s: the scale of the robust estimate)") != std::string::npos);

    const std::vector<std::pair<std::string, std::string>> bad{
        {"huber", "--loss huber: give the scale, huber:S"},
        {"l1:2", "--loss l1:2: expected squared, or huber, soft_l1, cauchy, arctan or tukey"},
        {"huber:-1", "--loss huber:-1: the scale must be a positive number"},
        {"huber:x", "--loss huber:x: "},
        {"squared:1", "--loss squared:1: squared (least squares) has no scale"},
    };
    for (const auto& [loss, message] : bad) {
        const Result r = eomgen({"fit", kModel, kData, "--free", "l", "--loss", loss, "--quiet"});
        INFO(r.output);
        CHECK(r.code == 2);
        CHECK(r.output.find(message) != std::string::npos);
    }
}
