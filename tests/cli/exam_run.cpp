// `eomgen run` as a user runs it, on model files this test writes itself (none is in models/): exit codes,
// CSV rows and columns, invariants along the trajectory, events, the cache (no compiler on a second run,
// invalidated by an edit, safe under two concurrent runs, refused when unsafe), a broken compiler, plots.
#include "test_paths.hpp"
#include "cli/eomgen_process.hpp"

#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace eomgen_test;

namespace {

const fs::path kWork = fs::path(eomgen_test::binary_dir()) / "tests" / "cli" / "work" / "run";

Result eomgen(const std::vector<std::string>& args, std::map<std::string, std::string> env = {}) {
    return run_eomgen(kWork, args, std::move(env));
}

fs::path write_model(const std::string& name, const std::string& text) { return write_whole(kWork, name, text); }

double max_relative_drift(const std::vector<std::vector<std::string>>& rows, const std::string& name) {
    const int c = column(rows[0], name);
    const double first = std::stod(rows[1][std::size_t(c)]);
    double drift = 0;
    for (std::size_t r = 1; r < rows.size(); ++r)
        drift = std::max(drift, std::abs(std::stod(rows[r][std::size_t(c)]) - first) / std::abs(first));
    return drift;
}

// An elastic pendulum: a bob on a spring, in polar coordinates. Written here, compiled by eomgen run.
const std::string kSpringPendulum = R"toml(name = "spring_pendulum"
title = "Elastic pendulum (written by exam_run)"
[[coordinates]]
name = "r"
initial = 1.2
[[coordinates]]
name = "phi"
initial = 0.4
rate = 0.3
[[parameters]]
name = "m"
value = 0.7
unit = "kg"
[[parameters]]
name = "k"
value = 30
[[parameters]]
name = "l0"
value = 1
[[parameters]]
name = "g"
value = 9.81
[lagrangian]
T = "m/2*(r'^2 + r^2*phi'^2)"
V = "k/2*(r - l0)^2 - m*g*r*cos(phi)"
)toml";

std::size_t cache_entries(const fs::path& cache) {
    std::size_t n = 0;
    if (!fs::exists(cache)) return 0;
    for (const auto& e : fs::directory_iterator(cache)) n += e.path().extension() == ".so";
    return n;
}

/// A compiler wrapper that records each call, then runs c++.
fs::path counting_compiler() {
    const fs::path script = kWork / "counting-c++";
    std::ofstream(script) << "#!/bin/sh\necho called >> \"" << (kWork / "compiler-calls").string()
                          << "\"\nexec c++ \"$@\"\n";
    fs::permissions(script, fs::perms::owner_all);
    return script;
}

std::size_t compiler_calls() {
    std::ifstream in(kWork / "compiler-calls");
    std::size_t n = 0;
    for (std::string line; std::getline(in, line);) ++n;
    return n;
}

}  // namespace

TEST_CASE("eomgen run integrates a model file of the user's: CSV rows, energy kept, events", "[run]") {
    const fs::path model = write_model("spring_pendulum.toml", kSpringPendulum);
    const fs::path csv = kWork / "spring.csv";
    const Result r = eomgen({"run", model.string(), "--t-end", "10", "--rtol", "1e-12", "--atol", "1e-14",
                             "--samples", "50", "--csv", csv.string(), "--quiet"});
    INFO(r.output);
    REQUIRE(r.code == 0);
    CHECK(r.output.find("model:   spring_pendulum") != std::string::npos);
    const auto rows = read_csv(csv);
    REQUIRE(rows.size() == 52);  // header + 51 samples
    CHECK(rows[0] == std::vector<std::string>{"t", "r", "phi", "r_dot", "phi_dot", "energy"});
    CHECK(max_relative_drift(rows, "energy") <= 1e-9);

    // --until: the event stops the run where phi crosses 0.
    const Result e = eomgen({"run", model.string(), "--until", "phi=0", "--t-end", "10", "--quiet"});
    INFO(e.output);
    CHECK(e.code == 0);
    CHECK(e.output.find("stopped: at event phi=0") != std::string::npos);

    // The simulator's option errors, as eomgen-sim gives them.
    const Result bad = eomgen({"run", model.string(), "--set", "mass=2", "--quiet"});
    CHECK(bad.code == 2);
    CHECK(bad.output.find("no parameter 'mass'") != std::string::npos);
}

TEST_CASE("eomgen run on a constrained model writes residuals and multipliers", "[run]") {
    const fs::path model = write_model("cartesian_pendulum.toml", R"toml(name = "cartesian_pendulum"
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
)toml");
    const fs::path csv = kWork / "cartesian.csv";
    const Result r = eomgen({"run", model.string(), "--t-end", "5", "--rtol", "1e-12", "--atol", "1e-14",
                             "--samples", "20", "--csv", csv.string(), "--quiet"});
    INFO(r.output);
    REQUIRE(r.code == 0);
    const auto rows = read_csv(csv);
    REQUIRE(rows.size() == 22);
    const int residual = column(rows[0], "residual_rod"), lambda = column(rows[0], "lambda_rod");
    for (std::size_t i = 1; i < rows.size(); ++i) {
        CHECK(std::abs(std::stod(rows[i][std::size_t(residual)])) < 1e-9);
        CHECK(std::stod(rows[i][std::size_t(lambda)]) != 0.0);  // the rod pulls
    }
    CHECK(max_relative_drift(rows, "energy") <= 1e-9);
}

TEST_CASE("eomgen run caches: no compiler on a re-run, a new entry after an edit, concurrent runs", "[run][cache]") {
    const fs::path cache = kWork / "cache-counted";
    fs::remove_all(cache);
    fs::remove(kWork / "compiler-calls");
    const std::map<std::string, std::string> env = {{"XDG_CACHE_HOME", cache.string()},
                                                     {"CXX", counting_compiler().string()}};
    const fs::path model = write_model("cached.toml", kSpringPendulum);
    REQUIRE(eomgen({"run", model.string(), "--t-end", "1", "--quiet"}, env).code == 0);
    CHECK(compiler_calls() == 1);
    CHECK(cache_entries(cache / "eomgen") == 1);
    CHECK((fs::status(cache / "eomgen").permissions() & fs::perms::all) == fs::perms::owner_all);
    const Result again = eomgen({"run", model.string(), "--t-end", "1", "--progress"}, env);
    CHECK(again.code == 0);
    CHECK(again.output.find("loaded from the cache") != std::string::npos);
    CHECK(compiler_calls() == 1);  // no compiler the second time

    std::string edited = kSpringPendulum;
    edited.replace(edited.find("value = 30"), 10, "value = 31");
    write_model("cached.toml", edited);
    REQUIRE(eomgen({"run", model.string(), "--t-end", "1", "--quiet"}, env).code == 0);
    CHECK(compiler_calls() == 2);
    CHECK(cache_entries(cache / "eomgen") == 2);

    // Two runs of a new model at once: both succeed and leave one valid entry, no temporary directory.
    edited.replace(edited.find("value = 31"), 10, "value = 32");
    const fs::path fresh = write_model("concurrent.toml", edited);
    std::map<std::string, std::string> env2 = env;
    const pid_t a = start({"run", fresh.string(), "--t-end", "1", "--quiet"}, env2, kWork / "a.log");
    const pid_t b = start({"run", fresh.string(), "--t-end", "1", "--quiet"}, env2, kWork / "b.log");
    const Result ra = finish(a, kWork / "a.log"), rb = finish(b, kWork / "b.log");
    INFO(ra.output << rb.output);
    CHECK(ra.code == 0);
    CHECK(rb.code == 0);
    CHECK(cache_entries(cache / "eomgen") == 3);
    for (const auto& e : fs::directory_iterator(cache / "eomgen"))
        CHECK(e.path().filename().string().rfind("tmp.", 0) != 0);
    const std::size_t before = compiler_calls();
    REQUIRE(eomgen({"run", fresh.string(), "--t-end", "1", "--quiet"}, env).code == 0);
    CHECK(compiler_calls() == before);  // the entry the two left is valid

    const Result cleared = eomgen({"cache", "clear"}, env);
    CHECK(cleared.code == 0);
    CHECK(cache_entries(cache / "eomgen") == 0);
}

TEST_CASE("eomgen run: a broken or missing compiler gives exit 4 with the log, and no cache entry", "[run][cache]") {
    const fs::path cache = kWork / "cache-broken";
    fs::remove_all(cache);
    const fs::path broken = kWork / "broken-c++";
    std::ofstream(broken) << "#!/bin/sh\necho 'fatal: this compiler is broken' >&2\nexit 1\n";
    fs::permissions(broken, fs::perms::owner_all);
    const fs::path model = write_model("broken.toml", kSpringPendulum);
    const Result r = eomgen({"run", model.string(), "--quiet"}, {{"XDG_CACHE_HOME", cache.string()}, {"CXX", broken.string()}});
    INFO(r.output);
    CHECK(r.code == 4);
    const auto log_at = r.output.find("log: ");
    REQUIRE(log_at != std::string::npos);
    const std::string log = r.output.substr(log_at + 5, r.output.find('\n', log_at) - log_at - 5);
    CHECK(read(log).find("this compiler is broken") != std::string::npos);
    CHECK(r.output.find("command: " + broken.string()) != std::string::npos);
    CHECK(cache_entries(cache / "eomgen") == 0);

    const Result missing =
        eomgen({"run", model.string(), "--quiet"}, {{"XDG_CACHE_HOME", cache.string()}, {"CXX", "no-such-compiler-x"}});
    CHECK(missing.code == 4);
    CHECK(missing.output.find("cannot start the C++ compiler 'no-such-compiler-x'") != std::string::npos);
    CHECK(cache_entries(cache / "eomgen") == 0);
}

TEST_CASE("eomgen run refuses a cache others can write and an entry that is a symbolic link", "[run][cache]") {
    const fs::path cache = kWork / "cache-unsafe";
    fs::remove_all(cache);
    fs::create_directories(cache / "eomgen");
    fs::permissions(cache / "eomgen", fs::perms::all);
    const fs::path model = write_model("unsafe.toml", kSpringPendulum);
    const Result r = eomgen({"run", model.string(), "--quiet"}, {{"XDG_CACHE_HOME", cache.string()}});
    CHECK(r.code == 3);
    CHECK(r.output.find("writable by other users") != std::string::npos);

    // A symbolic link planted where an entry goes: compile once with --progress to learn the entry's name.
    fs::permissions(cache / "eomgen", fs::perms::owner_all);
    REQUIRE(eomgen({"run", model.string(), "--t-end", "1", "--quiet"}, {{"XDG_CACHE_HOME", cache.string()}}).code == 0);
    fs::path entry;
    for (const auto& e : fs::directory_iterator(cache / "eomgen"))
        if (e.path().extension() == ".so") entry = e.path();
    REQUIRE(!entry.empty());
    fs::rename(entry, kWork / "moved.so");
    fs::create_symlink(kWork / "moved.so", entry);
    const Result link = eomgen({"run", model.string(), "--quiet"}, {{"XDG_CACHE_HOME", cache.string()}});
    INFO(link.output);
    CHECK(link.code == 3);
    CHECK(link.output.find("symbolic link") != std::string::npos);
}

TEST_CASE("eomgen run --plot writes a PNG and an SVG, a path with spaces and shell syntax is just a path", "[run][plot]") {
    const fs::path dir = kWork / "odd dir; $(echo PWNED) `x`";
    fs::create_directories(dir);
    const fs::path model = dir / "-spring pendulum.toml";
    std::ofstream(model) << kSpringPendulum;
    const fs::path png = dir / "motion.png", svg = dir / "motion.svg";
    fs::remove(png);
    const Result r = eomgen({"run", "--quiet", "--t-end", "5", "--plot", png.string(), "--plot-phase", "phi", "--",
                             model.string()});
    INFO(r.output);
    REQUIRE(r.code == 0);
    CHECK(("\n" + r.output).find("\nPWNED") == std::string::npos);  // the path is printed; no command ran
    CHECK_FALSE(fs::exists("PWNED"));
    const std::string bytes = read(png);
    REQUIRE(bytes.size() > 1000);
    CHECK(bytes.substr(0, 8) == "\x89PNG\r\n\x1a\n");
    const fs::path csv = dir / "motion.csv";
    REQUIRE(eomgen({"run", "--quiet", "--t-end", "5", "--samples", "40", "--csv", csv.string(), "--plot",
                    svg.string(), "--", model.string()})
                .code == 0);
    const std::string text = read(svg);
    CHECK(text.find("<svg") != std::string::npos);
    CHECK(text.find("phi") != std::string::npos);
    CHECK(eomgen({"run", "--quiet", "--plot", (dir / "x.pdf").string(), "--", model.string()}).code == 2);
}

TEST_CASE("eomgen run records a model's [outputs] in the CSV and plots them", "[run][outputs]") {
    const fs::path model = write_model("bob.toml", R"toml(name = "bob"
title = "Pendulum with its bob's position recorded (written by exam_run)'); system('touch PWNED_TITLE'); print('"
[[coordinates]]
name = "theta"
initial = 1.1
rate = -0.4
[[parameters]]
name = "m"
value = 0.3
[[parameters]]
name = "l"
value = 0.8
unit = "m"
[[parameters]]
name = "g"
value = 9.81
[lagrangian]
T = "m/2*l^2*theta'^2"
V = "-m*g*l*cos(theta)"
[outputs]
x_bob = { expr = "l*sin(theta)", unit = "m" }
y_bob = { expr = "-l*cos(theta)", unit = "m" }
v_bob = { expr = "l*theta'", unit = "m/s" }
w_bob = { expr = "theta'", unit = "rad/s", description = "units are read by UDUNITS-2: the title carries the attack" }
)toml");
    const fs::path csv = kWork / "bob.csv", png = kWork / "bob.png";
    fs::remove(png);
    const Result r =
        eomgen({"run", model.string(), "--t-end", "3", "--samples", "30", "--set", "l=1.5", "--csv",
                csv.string(), "--plot", png.string(), "--plot-xy", "x_bob,y_bob", "--quiet"});
    INFO(r.output);
    REQUIRE(r.code == 0);
    const auto rows = read_csv(csv);
    REQUIRE(rows.size() == 32);
    // The outputs come after the columns a model without them has, in the model file's order.
    CHECK(rows[0] ==
          std::vector<std::string>{"t", "theta", "theta_dot", "energy", "x_bob [m]", "y_bob [m]", "v_bob [m/s]",
                                               "w_bob [rad/s]"});
    const double l = 1.5;  // --set reaches the outputs too
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const double theta = std::stod(rows[i][1]), theta_dot = std::stod(rows[i][2]);
        CHECK(std::stod(rows[i][4]) == Approx(l * std::sin(theta)).epsilon(1e-14).margin(1e-15));
        CHECK(std::stod(rows[i][5]) == Approx(-l * std::cos(theta)).epsilon(1e-14).margin(1e-15));
        CHECK(std::stod(rows[i][6]) == Approx(l * theta_dot).epsilon(1e-14).margin(1e-15));
    }
    CHECK(read(png).substr(0, 8) == "\x89PNG\r\n\x1a\n");
    CHECK_FALSE(fs::exists("PWNED_TITLE"));  // the title is text in the gnuplot script, not a command

    // The SVG's text: the outputs panel names each output with its unit, the x-y panel its axes.
    const fs::path svg = kWork / "bob.svg";
    REQUIRE(eomgen({"run", model.string(), "--t-end", "3", "--plot", svg.string(), "--plot-xy", "x_bob,y_bob",
                    "--plot-xy", "theta,v_bob", "--quiet"})
                .code == 0);
    const std::string text = read(svg);
    auto has = [&text](const std::string& label) {
        return text.find("<text>" + label + "</text>") != std::string::npos;
    };
    for (const char* label :
         {"outputs", "v_bob [m/s]", "x_bob [m]", "y_bob [m]", "y_bob against x_bob", "v_bob against theta"})
        CHECK(has(label));
    // The drift panel draws the invariants (energy), not the outputs: no curve there is titled by a bare
    // output name.
    CHECK(has("energy"));
    for (const char* output : {"x_bob", "y_bob", "v_bob"}) CHECK_FALSE(has(output));

    const Result unknown =
        eomgen({"run", model.string(), "--plot", svg.string(), "--plot-xy", "x_bob,z_bob", "--quiet"});
    CHECK(unknown.code == 2);
    CHECK(unknown.output.find("--plot-xy x_bob,z_bob: no output, coordinate or velocity 'z_bob'") !=
          std::string::npos);
    // --plot-xy without --plot: a mistake on the command line.
    CHECK(eomgen({"run", model.string(), "--plot-xy", "x_bob,y_bob", "--quiet"}).code == 2);
}

namespace {

/// The points of the first polyline in an SVG with at least `min_points` vertices, after its first `M`
/// (gnuplot draws a key sample "M x,y L x,y" first, then "M" and the curve).
std::vector<std::pair<double, double>> first_curve(const std::string& svg, std::size_t min_points) {
    for (std::size_t at = svg.find(" d='"); at != std::string::npos; at = svg.find(" d='", at + 1)) {
        const std::size_t end = svg.find('\'', at + 4);
        std::string d = svg.substr(at + 4, end - at - 4);
        std::vector<std::vector<std::pair<double, double>>> pieces;
        std::istringstream in(d);
        for (std::string token; in >> token;) {
            if (token[0] == 'M') pieces.emplace_back();
            if (pieces.empty()) break;
            double x = 0, y = 0;
            char comma = 0;
            std::istringstream xy(token.substr(1));
            if (xy >> x >> comma >> y) pieces.back().emplace_back(x, y);
        }
        for (const auto& piece : pieces)
            if (piece.size() >= min_points) return piece;
    }
    return {};
}

}  // namespace

TEST_CASE("eomgen run --plot: the curve drawn is the CSV's data, point for point", "[run][plot]") {
    const fs::path model = write_model("plot_data.toml", kSpringPendulum);
    const fs::path csv = kWork / "plot_data.csv", svg = kWork / "plot_data.svg";
    REQUIRE(eomgen({"run", "--quiet", "--t-end", "3", "--samples", "30", "--csv", csv.string(), "--plot", svg.string(),
                    model.string()})
                .code == 0);
    const auto rows = read_csv(csv);
    REQUIRE(rows.size() == 32);  // header and 31 samples
    const auto curve = first_curve(read(svg), rows.size() - 1);
    REQUIRE(curve.size() == rows.size() - 1);  // the first panel's first curve: r against t
    // The drawing is an affine image of (t, r): fit it on the first and last points, then every other point
    // must land where its CSV row puts it (SVG coordinates are printed to 0.01 px).
    const int r_col = column(rows[0], "r");
    auto data = [&](std::size_t k) {
        return std::make_pair(std::stod(rows[k + 1][0]), std::stod(rows[k + 1][std::size_t(r_col)]));
    };
    std::size_t lo = 0, hi = 0;  // the smallest and largest r, for a well-conditioned fit in y
    for (std::size_t k = 0; k < curve.size(); ++k) {
        if (data(k).second < data(lo).second) lo = k;
        if (data(k).second > data(hi).second) hi = k;
    }
    const std::size_t last = curve.size() - 1;
    const double sx = (curve[last].first - curve[0].first) / (data(last).first - data(0).first);
    const double sy = (curve[hi].second - curve[lo].second) / (data(hi).second - data(lo).second);
    for (std::size_t k = 0; k < curve.size(); ++k) {
        CHECK(std::abs(curve[0].first + sx * (data(k).first - data(0).first) - curve[k].first) < 0.02);
        CHECK(std::abs(curve[lo].second + sy * (data(k).second - data(lo).second) - curve[k].second) < 0.02);
    }
}

TEST_CASE("eomgen run --method radau5: the stiff example's event where dopri5 finds it, in far fewer right-hand sides",
          "[run][radau5]") {
    const std::string model = eomgen_test::source_dir() + "/examples/stiff_spring_pendulum.toml";
    const auto event_and_rhs = [&](const std::string& method) {
        const Result r = eomgen({"run", model, "--method", method, "--until", "theta=0", "--rtol", "1e-8", "--atol",
                                 "1e-10", "--t-end", "10", "--quiet"});
        INFO(r.output);
        REQUIRE(r.code == 0);
        REQUIRE(r.output.find("stopped: at event theta=0") != std::string::npos);
        const auto at = r.output.find("event:   theta=0 at t = ");
        REQUIRE(at != std::string::npos);
        const auto steps = r.output.find(" right-hand sides");
        const auto comma = r.output.rfind(", ", steps);
        REQUIRE(steps != std::string::npos);
        if (method == "radau5") CHECK(r.output.find("Jacobians") != std::string::npos);
        return std::pair<double, double>(std::stod(r.output.substr(at + 24)),
                                         std::stod(r.output.substr(comma + 2, steps - comma - 2)));
    };
    const auto [t_radau, rhs_radau] = event_and_rhs("radau5");
    const auto [t_dopri, rhs_dopri] = event_and_rhs("dopri5");
    CHECK(std::abs(t_radau - t_dopri) < 1e-6);
    CHECK(rhs_dopri > 20 * rhs_radau);
}

TEST_CASE("eomgen run --plot: axes and curves carry the coordinates' units (issue 29)", "[run][plot]") {
    const fs::path model = write_model("cart_units.toml", R"toml(name = "cart_units"
[[coordinates]]
name = "x"
unit = "cm"
initial = 10
[[coordinates]]
name = "theta"
unit = "deg"
initial = 30
[[parameters]]
name = "M"
value = 1
unit = "kg"
[[parameters]]
name = "m"
value = 0.2
unit = "kg"
[[parameters]]
name = "l"
value = 0.5
unit = "m"
[[parameters]]
name = "g"
value = 9.81
unit = "m/s^2"
[lagrangian]
T = "(M + m)/2*x'^2 + m*l*x'*theta'*cos(theta) + m/2*l^2*theta'^2"
V = "-m*g*l*cos(theta)"
)toml");
    const fs::path svg = kWork / "cart_units.svg";
    fs::remove(svg);
    const Result r = eomgen({"run", "--quiet", "--t-end", "1", "--plot", svg.string(), "--plot-phase", "theta", "--",
                             model.string()});
    INFO(r.output);
    REQUIRE(r.code == 0);
    const std::string text = read(svg);
    // Two units: each curve has its own (the CSV is in SI); the phase portrait's axes have q's and q̇'s.
    CHECK(text.find("x [m]") != std::string::npos);
    CHECK(text.find("theta [rad]") != std::string::npos);
    CHECK(text.find("theta_dot [rad/s]") != std::string::npos);
}
