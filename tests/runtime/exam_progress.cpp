// The progress meter of long integrations (progress.hpp): what it writes, when, and in which form.
#include "eomgen/progress.hpp"

#include <catch2/catch.hpp>

#include <sstream>

using eomgen::ProgressMeter;
using eomgen::ProgressStyle;

TEST_CASE("progress: a line with t, t_end and the percentage, then nothing until the interval has passed",
          "[progress]") {
    std::ostringstream out;
    ProgressMeter meter(&out, ProgressStyle::Lines, 8.0, 0.0);
    REQUIRE(meter.active());
    meter.at(2.0);
    const std::string first = out.str();
    CHECK(first.rfind("integrating: t = 2 of 8 (25 %), ", 0) == 0);
    CHECK(first.back() == '\n');
    meter.at(3.0);  // within a second of the first line: throttled
    CHECK(out.str() == first);
    meter.finish();  // whole lines are not cleared
    CHECK(out.str() == first);
}

TEST_CASE("progress: on a terminal one line is rewritten in place and cleared at the end", "[progress]") {
    std::ostringstream out;
    {
        ProgressMeter meter(&out, ProgressStyle::Terminal, 10.0, 0.0);
        meter.at(12.0);  // a trial stage past t_end is shown as 100 %
    }
    CHECK(out.str().rfind("\rintegrating: t = 12 of 10 (100 %), ", 0) == 0);
    CHECK(out.str().find("\033[K") != std::string::npos);
    const std::string cleared = "\r\033[K";
    REQUIRE(out.str().size() > cleared.size());
    CHECK(out.str().substr(out.str().size() - cleared.size()) == cleared);
}

TEST_CASE("progress: silent when off, without a stream, and for runs shorter than its quiet time", "[progress]") {
    std::ostringstream out;
    ProgressMeter off(&out, ProgressStyle::None, 1.0, 0.0);
    CHECK_FALSE(off.active());
    off.at(0.5);
    ProgressMeter nowhere(nullptr, ProgressStyle::Terminal, 1.0, 0.0);
    nowhere.at(0.5);
    ProgressMeter short_run(&out, ProgressStyle::Terminal, 1.0, 60.0);
    short_run.at(0.5);
    short_run.finish();  // nothing shown, nothing to clear
    CHECK(out.str().empty());
}
