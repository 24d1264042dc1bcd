// `eomgen run --sweep/--sample` as a user runs it (the model compiled and loaded as a table): the door's closing
// time over a θ grid against the closed form, byte-identical tables for any thread count, reproducible Monte
// Carlo draws, failed members as rows, the grid's order, and bad command lines refused with exit 2.
#include "test_paths.hpp"
#include "cli/eomgen_process.hpp"

#include <catch2/catch.hpp>

#ifdef EOMGEN_HAVE_HDF5
#include <hdf5.h>
#endif

#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace eomgen_test;

namespace {

const fs::path kWork = fs::path(eomgen_test::binary_dir()) / "tests" / "cli" / "work" / "ensemble";
const std::string kDoor = eomgen_test::source_dir() + "/models/door.toml";
const std::string kPendulum = eomgen_test::source_dir() + "/models/pendulum.toml";
const double kPi = std::acos(-1.0);

/// eomgen run with `args`: its log in a directory of the running test case's own (ctest runs the cases in
/// parallel), the compiled model in one cache for all (the cache is safe for concurrent runs).
Result eomgen(std::vector<std::string> args) {
    args.insert(args.begin(), "run");
    args.push_back("--quiet");
    std::string name = Catch::getResultCapture().getCurrentTestName();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return run_eomgen(kWork / "cases" / name.substr(0, 80), args, {{"XDG_CACHE_HOME", (kWork / "cache").string()}});
}

/// A CSV table as RFC 4180 reads it (quoted fields may hold commas and doubled quotes).
std::vector<std::map<std::string, std::string>> read_table(const fs::path& p) {
    const std::string text = read(p);
    std::vector<std::vector<std::string>> rows(1);
    std::string field;
    bool quoted = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (quoted) {
            if (c == '"' && i + 1 < text.size() && text[i + 1] == '"')
                field += '"', ++i;
            else if (c == '"')
                quoted = false;
            else
                field += c;
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            rows.back().push_back(field), field.clear();
        } else if (c == '\n') {
            rows.back().push_back(field), field.clear();
            rows.emplace_back();
        } else {
            field += c;
        }
    }
    rows.pop_back();  // after the last newline
    std::vector<std::map<std::string, std::string>> table;
    for (std::size_t r = 1; r < rows.size(); ++r) {
        REQUIRE(rows[r].size() == rows[0].size());
        std::map<std::string, std::string> row;
        // Keyed by the column's name: "psi [rad]" is psi (the units are tested on their own).
        for (std::size_t c = 0; c < rows[0].size(); ++c) row[column_name(rows[0][c])] = rows[r][c];
        table.push_back(row);
    }
    return table;
}

/// The closed form of README: Δt = 1.5138456348·√(w/(g sin θ)), the constant √(π/3)/2 · Γ(1/4)/Γ(3/4).
double closing_time(double w, double g, double theta) {
    const double c = std::sqrt(kPi / 3) / 2 * std::tgamma(0.25) / std::tgamma(0.75);
    REQUIRE(c == Approx(1.5138456348).epsilon(1e-10));
    return c * std::sqrt(w / (g * std::sin(theta)));
}

const std::vector<std::string> kClosing = {kDoor, "--until", "psi=-pi/2", "--t-end", "100", "--rtol", "1e-12",
                                           "--atol", "1e-15"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

}  // namespace

TEST_CASE("run --sweep: the door's closing time over a theta grid matches the closed form to 1e-9",
          "[cli][ensemble][door]") {
    const fs::path out = kWork / "closing.csv";
    const Result r = eomgen(with(kClosing, {"--sweep", "theta=0.02:pi/2:40", "--threads", "2", "--out", out.string()}));
    INFO(r.output);
    REQUIRE(r.code == 0);
    REQUIRE(r.output.find("ensemble: 40 members (grid 40 over theta), 0 failed") != std::string::npos);
    const auto table = read_table(out);
    REQUIRE(table.size() == 40);
    for (std::size_t i = 0; i < table.size(); ++i) {
        const auto& row = table[i];
        INFO("member " << i << ": " << row.at("message"));
        REQUIRE(row.at("member") == std::to_string(i));
        REQUIRE(row.at("status") == "ok");
        REQUIRE(row.at("stopped") == "psi=-pi/2");
        const double theta = std::stod(row.at("theta"));
        REQUIRE(theta == Approx(0.02 + (kPi / 2 - 0.02) * double(i) / 39).epsilon(1e-15));
        REQUIRE(std::abs(std::stod(row.at("t")) / closing_time(0.9, 9.8, theta) - 1) <= 1e-9);
        REQUIRE(std::stod(row.at("psi")) == Approx(-kPi / 2).epsilon(1e-12));
        // The door's declared output v_edge = w ψ̇ at the end: ψ̇ = −√(3 g sin θ / w) by energy conservation.
        REQUIRE(std::stod(row.at("v_edge")) == Approx(-0.9 * std::sqrt(3 * 9.8 * std::sin(theta) / 0.9)).epsilon(1e-9));
    }
}

TEST_CASE("run --sweep: 1, 2 and 4 threads write byte-identical tables", "[cli][ensemble]") {
    std::string first;
    for (const std::string threads : {"1", "2", "4"}) {
        const fs::path out = kWork / ("threads_" + threads + ".csv");
        const Result r = eomgen(with(kClosing, {"--sweep", "theta=0.05:1.5:30", "--sweep", "w=0.5,0.9,1.3", "--threads",
                                                threads, "--out", out.string()}));
        INFO(r.output);
        REQUIRE(r.code == 0);
        const std::string text = read(out);
        REQUIRE(text.size() > 1000);
        if (first.empty())
            first = text;
        else
            REQUIRE(text == first);
    }
}

TEST_CASE("run --sweep: the grid's members, the last --sweep varying fastest", "[cli][ensemble]") {
    const fs::path out = kWork / "grid.csv";
    REQUIRE(eomgen({kDoor, "--t-end", "0.1", "--sweep", "theta=0.2,0.4", "--sweep", "psi=0:-1:3", "--out", out.string()})
                .code == 0);
    const auto table = read_table(out);
    REQUIRE(table.size() == 6);
    const double expected[6][2] = {{0.2, 0}, {0.2, -0.5}, {0.2, -1}, {0.4, 0}, {0.4, -0.5}, {0.4, -1}};
    for (std::size_t i = 0; i < 6; ++i) {
        REQUIRE(std::stod(table[i].at("theta")) == expected[i][0]);
        REQUIRE(std::stod(table[i].at("psi(0)")) == expected[i][1]);  // an initial state: psi(0), beside the final psi
        REQUIRE(table[i].at("stopped") == "t_end");
        REQUIRE(std::stod(table[i].at("t")) == 0.1);
    }
}

TEST_CASE("run --sample: a seeded Monte Carlo run is reproducible, a different seed differs", "[cli][ensemble]") {
    auto sample = [](const std::string& seed, const std::string& threads, const std::string& name) {
        const fs::path out = kWork / name;
        const Result r = eomgen({kDoor, "--t-end", "0.01", "--sample", "2000", "--dist", "theta=uniform(0.1,1.5)",
                                 "--dist", "w=normal(0.9,0.05)", "--seed", seed, "--threads", threads, "--out",
                                 out.string()});
        INFO(r.output);
        REQUIRE(r.code == 0);
        REQUIRE(r.output.find("2000 samples of theta, w (seed " + seed + ")") != std::string::npos);
        return out;
    };
    const std::string a = read(sample("7", "1", "mc_a.csv")), b = read(sample("7", "3", "mc_b.csv"));
    REQUIRE(a == b);
    REQUIRE(read(sample("8", "2", "mc_c.csv")) != a);

    // The draws have the distributions asked for: the sample mean within 4 standard errors, the spread to 10 %.
    const auto table = read_table(kWork / "mc_a.csv");
    REQUIRE(table.size() == 2000);
    double sum_theta = 0, sum_w = 0, sum_w2 = 0;
    for (const auto& row : table) {
        const double theta = std::stod(row.at("theta")), w = std::stod(row.at("w"));
        REQUIRE(theta >= 0.1);
        REQUIRE(theta < 1.5);
        sum_theta += theta, sum_w += w, sum_w2 += w * w;
    }
    const double n = 2000, mean_w = sum_w / n, sd_w = std::sqrt(sum_w2 / n - mean_w * mean_w);
    REQUIRE(std::abs(sum_theta / n - 0.8) < 4 * (1.4 / std::sqrt(12.0)) / std::sqrt(n));
    REQUIRE(std::abs(mean_w - 0.9) < 4 * 0.05 / std::sqrt(n));
    REQUIRE(sd_w == Approx(0.05).epsilon(0.1));
}

TEST_CASE("run --sweep: a member with a singular mass matrix is a row with its status and t", "[cli][ensemble]") {
    const fs::path out = kWork / "failed.csv";
    const Result r = eomgen({kPendulum, "--t-end", "1", "--sweep", "m=1,0,2", "--out", out.string()});
    INFO(r.output);
    REQUIRE(r.code == 0);
    REQUIRE(r.output.find("3 members (grid 3 over m), 1 failed") != std::string::npos);
    const auto table = read_table(out);
    REQUIRE(table.size() == 3);
    REQUIRE(table[0].at("status") == "ok");
    REQUIRE(table[2].at("status") == "ok");
    REQUIRE(table[1].at("status") == "failed");
    REQUIRE(table[1].at("t") == "0");
    REQUIRE(table[1].at("phi").empty());
    // The message holds the state "[0.5, 0]": a comma, so the field is quoted, and it reads back whole.
    REQUIRE(table[1].at("message").find("singular") != std::string::npos);
    REQUIRE(table[1].at("message").find("with state [") != std::string::npos);
}

TEST_CASE("run --sweep --plot: the closing time against theta as a PNG", "[cli][ensemble][plot]") {
    const fs::path png = kWork / "closing.png";
    fs::remove(png);
    const Result r = eomgen(with(kClosing, {"--sweep", "theta=0.05:1.5:12", "--plot", png.string(), "--plot-xy", "theta,t"}));
    INFO(r.output);
    REQUIRE(r.code == 0);
    REQUIRE(read(png).substr(1, 3) == "PNG");
    // Without --out the table goes to stdout.
    // Each column with its unit where the model file declares one.
    REQUIRE(r.output.find("member,theta [rad],status,stopped,t [s],psi [rad],psi_dot [rad/s],energy [J],z_c [m],"
                          "v_edge [m/s],message") != std::string::npos);
}

TEST_CASE("run --sweep: mistakes on the command line are exit 2 with what is wrong", "[cli][ensemble]") {
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"--sweep", "thta=0:1:3"}, "no parameter or state 'thta'; did you mean 'theta'?"},
        {{"--sweep", "theta=0:1"}, "expected START:STOP:COUNT"},
        {{"--sweep", "theta=0:1:0"}, "COUNT must be at least 1"},
        {{"--sweep", "theta=0:1:x"}, "COUNT 'x' is not a whole number"},
        {{"--sweep", "theta=0:one:3"}, "cannot read the number 'one'"},
        {{"--sweep", "theta=1,,2"}, "an empty value"},
        {{"--sweep", "theta"}, "expected NAME=START:STOP:COUNT"},
        {{"--sweep", "theta=1,2", "--sweep", "theta=3"}, "theta is varied twice"},
        {{"--sweep", "theta=1,2", "--sample", "3"}, "give one of them"},
        {{"--dist", "theta=uniform(0,1)"}, "--dist needs --sample"},
        {{"--sample", "0", "--dist", "theta=uniform(0,1)"}, "the number of members must be 1 to 2^40"},
        {{"--sample", "5"}, "--sample needs at least one --dist"},
        {{"--sample", "5", "--dist", "theta=uniform(1,0)"}, "uniform(a,b) needs a < b"},
        {{"--sample", "5", "--dist", "theta=normal(1,-1)"}, "needs sigma > 0"},
        {{"--sample", "5", "--dist", "theta=gauss(1,1)"}, "expected NAME=uniform(a,b) or NAME=normal(mu,sigma)"},
        {{"--seed", "3"}, "--seed needs an ensemble"},
        {{"--out", "x.csv"}, "--out needs an ensemble"},
        {{"--sweep", "theta=1,2", "--set", "theta=1"}, "theta is varied by the ensemble"},
        {{"--sweep", "theta=1,2", "--csv", "x.csv"}, "one row per member to --out"},
        {{"--sweep", "theta=1,2", "--plot", "p.png", "--plot-xy", "theta,tt"}, "no numeric column 'tt'; did you mean 't'?"},
        {{"--sweep", "theta=1,2", "--until", "psy=0"}, "no state 'psy'; did you mean 'psi'?"},
    };
    for (const auto& [args, message] : cases) {
        std::vector<std::string> a{kDoor};
        a.insert(a.end(), args.begin(), args.end());
        const Result r = eomgen(a);
        INFO(r.output);
        REQUIRE(r.code == 2);
        REQUIRE(r.output.find(message) != std::string::npos);
    }
    // An --out whose directory is missing is a file problem (exit 3), found before any member runs.
    const Result r = eomgen({kDoor, "--sweep", "theta=1,2", "--out", (kWork / "no_such_dir" / "x.csv").string()});
    REQUIRE(r.code == 3);
    REQUIRE(r.output.find("does not exist") != std::string::npos);
}

#ifdef EOMGEN_HAVE_HDF5
namespace {

/// /ensemble/<name> of an HDF5 table: its numbers (empty when it holds text) or its texts.
struct Column {
    std::vector<double> numbers;
    std::vector<std::string> texts;
};

std::vector<std::string> read_texts(hid_t object, bool attribute) {
    const hid_t space = attribute ? H5Aget_space(object) : H5Dget_space(object);
    const hssize_t n = H5Sget_simple_extent_npoints(space);
    std::vector<char*> p(std::size_t(std::max<hssize_t>(n, 0)));
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    H5Tset_cset(type, H5T_CSET_UTF8);  // as written: HDF5 does not convert between character sets
    REQUIRE((attribute ? H5Aread(object, type, p.data()) : H5Dread(object, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, p.data())) >= 0);
    std::vector<std::string> out(p.begin(), p.end());
    H5Dvlen_reclaim(type, space, H5P_DEFAULT, p.data());
    H5Tclose(type);
    H5Sclose(space);
    return out;
}

Column read_column(hid_t group, const std::string& name) {
    const hid_t d = H5Dopen2(group, name.c_str(), H5P_DEFAULT);
    REQUIRE(d >= 0);
    Column c;
    const hid_t type = H5Dget_type(d);
    if (H5Tget_class(type) == H5T_STRING) {
        c.texts = read_texts(d, false);
    } else {
        const hid_t space = H5Dget_space(d);
        c.numbers.resize(std::size_t(H5Sget_simple_extent_npoints(space)));
        REQUIRE(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, c.numbers.data()) >= 0);
        H5Sclose(space);
    }
    H5Tclose(type);
    H5Dclose(d);
    return c;
}

std::string read_attribute(hid_t group, const std::string& name) {
    const hid_t a = H5Aopen(group, name.c_str(), H5P_DEFAULT);
    REQUIRE(a >= 0);
    const std::vector<std::string> v = read_texts(a, true);
    H5Aclose(a);
    REQUIRE(v.size() == 1);
    return v[0];
}

}  // namespace

TEST_CASE("run --out FILE.h5: the CSV table's columns as HDF5 datasets, with the run's metadata", "[cli][ensemble][hdf5]") {
    const std::vector<std::string> args =
        with(kClosing, {"--sweep", "theta=0.1:1.5:7", "--sweep", "w=0.9,0", "--threads", "2", "--out"});
    const fs::path csv = kWork / "h5.csv", h5 = kWork / "table.h5";
    REQUIRE(eomgen(with(args, {csv.string()})).code == 0);
    fs::remove(h5);
    const Result r = eomgen(with(args, {h5.string()}));
    INFO(r.output);
    REQUIRE(r.code == 0);
    const auto table = read_table(csv);  // 14 members, 7 failed (w = 0: M singular)
    std::vector<std::string> header = read_csv(csv)[0];
    for (std::string& h : header) h = column_name(h);  // HDF5 names the datasets without units

    const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    REQUIRE(file >= 0);
    const hid_t group = H5Gopen2(file, "ensemble", H5P_DEFAULT);
    REQUIRE(group >= 0);
    const hid_t columns = H5Aopen(group, "columns", H5P_DEFAULT);
    REQUIRE(read_texts(columns, true) == header);
    H5Aclose(columns);
    for (const std::string& name : header) {
        INFO("column " << name);
        const Column c = read_column(group, name);
        const bool text = name == "status" || name == "stopped" || name == "message";
        REQUIRE((text ? c.texts.size() : c.numbers.size()) == table.size());
        for (std::size_t i = 0; i < table.size(); ++i) {
            const std::string& field = table[i].at(name);
            if (text) {
                REQUIRE(c.texts[i] == field);
            } else if (field.empty()) {
                REQUIRE(std::isnan(c.numbers[i]));
            } else {
                const double v = std::stod(field);  // the same double, bit for bit
                REQUIRE(std::memcmp(&v, &c.numbers[i], sizeof v) == 0);
            }
        }
    }
    // Each number's unit, as the CSV's header gives it, is its dataset's attribute `unit`.
    const std::vector<std::string> with_units = read_csv(csv)[0];
    for (std::size_t k = 0; k < header.size(); ++k) {
        const hid_t d = H5Dopen2(group, header[k].c_str(), H5P_DEFAULT);
        REQUIRE(d >= 0);
        const bool has_unit = H5Aexists(d, "unit") > 0;
        REQUIRE(has_unit == (with_units[k] != header[k]));
        if (has_unit) REQUIRE(header[k] + " [" + read_attribute(d, "unit") + "]" == with_units[k]);
        H5Dclose(d);
    }
    REQUIRE(with_units[1] == "theta [rad]");
    REQUIRE(read_attribute(group, "model") == "door");
    REQUIRE(read_attribute(group, "members") == "14");
    REQUIRE(read_attribute(group, "design") == "grid 7 x 2 over theta, w");
    REQUIRE(read_attribute(group, "varied") == "--sweep theta=0.1:1.5:7 --sweep w=0.9,0");
    REQUIRE(read_attribute(group, "until") == "psi=-pi/2");
    REQUIRE(read_attribute(group, "rtol") == "9.9999999999999998e-13");
    REQUIRE(read_attribute(group, "model_hash").size() == 32);
    REQUIRE_FALSE(read_attribute(group, "eomgen_version").empty());
    H5Gclose(group);
    H5Fclose(file);
    // Nothing is left beside it.
    for (const auto& e : fs::directory_iterator(kWork)) REQUIRE(e.path().string().find("table.h5.tmp") == std::string::npos);
}
#else
TEST_CASE("run --out FILE.h5 without HDF5 in this eomgen is refused with exit 2", "[cli][ensemble][hdf5]") {
    const Result r = eomgen({kDoor, "--sweep", "theta=1,2", "--out", (kWork / "x.h5").string()});
    REQUIRE(r.code == 2);
    REQUIRE(r.output.find("built without HDF5") != std::string::npos);
}
#endif
