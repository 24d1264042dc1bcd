/** @file exam_output.cpp  CSV output: header, full-precision round trip, no half-written file on error. */
#include "../approx.hpp"

#include "eomgen/integrate.hpp"
#include "eomgen/output.hpp"

#include <Eigen/Core>
#include <catch2/catch.hpp>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using State = Eigen::Vector2d;

void oscillator(const double&, const State& x, State& xdot) {
    xdot(0) = x(1);
    xdot(1) = -x(0);
}

std::vector<std::string> read_lines(const fs::path& path) {
    std::ifstream in(path);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream ss(line);
    for (std::string field; std::getline(ss, field, ',');) fields.push_back(field);
    return fields;
}

/// A fresh directory under the system temporary directory, removed at the end of the test. The tag and
/// the clock keep test cases that ctest runs in parallel processes apart.
struct ScratchDir {
    fs::path path;
    explicit ScratchDir(const std::string& tag) {
        const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
        path = fs::temp_directory_path() / ("eomgen_output_test_" + tag + "_" + std::to_string(stamp));
        fs::create_directories(path);
    }
    ~ScratchDir() {
        std::error_code ignored;
        fs::remove_all(path, ignored);
    }
};

}  // namespace

TEST_CASE("samples to CSV: header, extra columns, values that read back exactly", "[runtime][output]") {
    ScratchDir dir("samples");
    const std::string file = (dir.path / "run.csv").string();
    const auto r = eomgen::integrate(oscillator, 0.0, State(1.0, 0.0), 1.0, {}, {}, {0.0, 1.0 / 3, 1.0});
    eomgen::write_csv(file, {"q", "q_dot"}, {"energy"}, r.samples, [](const double&, const State& x) {
        return std::array<double, 1>{0.5 * x.squaredNorm()};
    });
    const auto lines = read_lines(file);
    REQUIRE(lines.size() == 4);
    CHECK(lines[0] == "t,q,q_dot,energy");
    for (std::size_t i = 0; i < 3; ++i) {
        const auto fields = split(lines[i + 1]);
        REQUIRE(fields.size() == 4);
        CHECK(std::strtod(fields[0].c_str(), nullptr) == r.samples[i].t);  // max_digits10: exact round trip
        CHECK(std::strtod(fields[1].c_str(), nullptr) == r.samples[i].x(0));
        CHECK(std::strtod(fields[2].c_str(), nullptr) == r.samples[i].x(1));
        CHECK(std::strtod(fields[3].c_str(), nullptr) == 0.5 * r.samples[i].x.squaredNorm());
    }
    CHECK(!fs::exists(file + ".tmp"));
}

TEST_CASE("CsvWriter: quoted names, long double digits, nothing visible before commit", "[runtime][output]") {
    ScratchDir dir("stream");
    const std::string file = (dir.path / "ld.csv").string();
    using StateL = Eigen::Matrix<long double, 2, 1>;
    eomgen::CsvWriter<long double> writer(file, {"a", "b,c"});
    const StateL x(1.0L / 3, 2.0L / 3);
    writer.write_row(0.1L, x);
    CHECK(!fs::exists(file));  // nothing visible until commit
    writer.commit();
    const auto lines = read_lines(file);
    REQUIRE(lines.size() == 2);
    CHECK(lines[0] == "t,a,\"b,c\"");
    const auto fields = split(lines[1]);
    REQUIRE(fields.size() == 3);
    CHECK(std::strtold(fields[1].c_str(), nullptr) == x(0));
    CHECK(std::strtold(fields[2].c_str(), nullptr) == x(1));
}

TEST_CASE("a failed run leaves no half-written file and keeps the previous one", "[runtime][output]") {
    ScratchDir dir("failed");
    const std::string file = (dir.path / "run.csv").string();
    { std::ofstream(file) << "previous\n"; }
    const auto bad = [](const double& t, const State& x, State& xdot) {
        oscillator(t, x, xdot);
        if (t > 0.5) xdot(0) = std::nan("");
    };
    try {
        eomgen::CsvWriter<double> writer(file, {"q", "q_dot"});
        eomgen::integrate(bad, 0.0, State(1.0, 0.0), 1.0, {}, {}, {},
                          [&](const double& t, const State& x) { writer.write_row(t, x); });
        writer.commit();
        FAIL("no exception");
    } catch (const eomgen::NonFiniteState&) {
    }
    CHECK(read_lines(file) == std::vector<std::string>{"previous"});
    CHECK(!fs::exists(file + ".tmp"));

    eomgen::CsvWriter<double> writer(file, {"q", "q_dot"}, {"e"});
    CHECK_THROWS_AS(writer.write_row(0.0, State(1, 2)), std::invalid_argument);  // missing extra column
    CHECK_THROWS_AS(eomgen::CsvWriter<double>((dir.path / "no" / "such" / "dir.csv").string(), {"q"}),
                    std::runtime_error);
}
