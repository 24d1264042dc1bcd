/** @file test_atomic_file.cpp  Output files appear whole or not at all: after errors, exceptions and
 * signals, the old file is intact and no temporary is left. */
#include "eomgen/output.hpp"
#include "output/atomic_file.hpp"

#include <catch2/catch.hpp>

#include <csignal>
#include <fstream>
#include <iterator>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using eomgen::output::AtomicFile;

namespace {

/// A fresh empty directory for one test.
fs::path scratch(const std::string& name) {
    const fs::path d = fs::temp_directory_path() / ("eomgen_atomic_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

std::string contents(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

std::size_t entries(const fs::path& d) {
    return std::size_t(std::distance(fs::directory_iterator(d), fs::directory_iterator()));
}

}  // namespace

TEST_CASE("atomic file: written whole, replacing the old one, no temporary left", "[output]") {
    const fs::path d = scratch("whole");
    eomgen::output::write_atomically(d / "a.hpp", "old");
    eomgen::output::write_atomically(d / "a.hpp", "new text");
    CHECK(contents(d / "a.hpp") == "new text");
    CHECK(entries(d) == 1);
    fs::remove_all(d);
}

TEST_CASE("atomic file: an exception before commit leaves the old file and removes the temporary", "[output]") {
    const fs::path d = scratch("throw");
    eomgen::output::write_atomically(d / "a.hpp", "old");
    try {
        AtomicFile f(d / "a.hpp");
        f.write("half of the new");
        REQUIRE(fs::exists(f.temporary()));
        throw std::runtime_error("derivation failed");
    } catch (const std::runtime_error&) {
    }
    CHECK(contents(d / "a.hpp") == "old");
    CHECK(entries(d) == 1);
    fs::remove_all(d);
}

TEST_CASE("atomic file: a directory that does not exist is a WriteError naming the file", "[output]") {
    const fs::path d = scratch("missing");
    try {
        eomgen::output::write_atomically(d / "no" / "such" / "a.hpp", "x");
        FAIL("no error");
    } catch (const eomgen::output::WriteError& e) {
        CHECK(std::string(e.what()).find("a.hpp") != std::string::npos);
    }
    fs::remove_all(d);
}

TEST_CASE("atomic file: SIGTERM or SIGINT half way removes the temporary and ends the process", "[output]") {
    for (const int sig : {SIGTERM, SIGINT}) {
        const fs::path d = scratch("signal" + std::to_string(sig));
        eomgen::output::write_atomically(d / "a.hpp", "old");
        const pid_t child = ::fork();
        REQUIRE(child >= 0);
        if (child == 0) {
            std::signal(sig, SIG_DFL);  // as in a program of its own, not under Catch's handler
            AtomicFile f(d / "a.hpp");
            f.write("half of the new");
            std::raise(sig);
            ::_exit(0);  // not reached: the signal ends the process
        }
        int status = 0;
        REQUIRE(::waitpid(child, &status, 0) == child);
        CHECK(WIFSIGNALED(status));
        CHECK(WTERMSIG(status) == sig);
        CHECK(contents(d / "a.hpp") == "old");
        CHECK(entries(d) == 1);  // the temporary is gone
        fs::remove_all(d);
    }
}

TEST_CASE("atomic file: the runtime's CSV writer, guarded through its hooks, leaves no temporary on SIGINT",
          "[output]") {
    for (const bool guarded : {true, false}) {
        const fs::path d = scratch(std::string("csv") + (guarded ? "guarded" : "bare"));
        const pid_t child = ::fork();
        REQUIRE(child >= 0);
        if (child == 0) {
            std::signal(SIGINT, SIG_DFL);
            if (guarded) eomgen::output::guard_runtime_temporaries();
            eomgen::CsvWriter<double> csv((d / "run.csv").string(), {"x"});
            csv.write_row(0.0, Eigen::Matrix<double, 1, 1>(1.0));
            std::raise(SIGINT);
            ::_exit(0);
        }
        int status = 0;
        REQUIRE(::waitpid(child, &status, 0) == child);
        CHECK(WIFSIGNALED(status));
        // Guarded: nothing left; without the hooks (a library alone) the temporary stays: the test can fail.
        CHECK(entries(d) == (guarded ? 0u : 1u));
        fs::remove_all(d);
    }
}

TEST_CASE("atomic file: a guarded CSV that is committed is released, and stays after a later signal",
          "[output]") {
    const fs::path d = scratch("csvcommit");
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        std::signal(SIGINT, SIG_DFL);
        eomgen::output::guard_runtime_temporaries();
        {
            eomgen::CsvWriter<double> csv((d / "run.csv").string(), {"x"});
            csv.write_row(0.0, Eigen::Matrix<double, 1, 1>(1.0));
            csv.commit();
        }
        // A new temporary at the same path after the rename: the handler must not remove the committed file
        // by its old name (it is released), nor leave the new temporary.
        eomgen::CsvWriter<double> again((d / "run.csv").string(), {"x"});
        std::raise(SIGINT);
        ::_exit(0);
    }
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    CHECK(WIFSIGNALED(status));
    CHECK(fs::exists(d / "run.csv"));
    CHECK(entries(d) == 1);
    fs::remove_all(d);
}
