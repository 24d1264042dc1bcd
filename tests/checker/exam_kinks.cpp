/** @file exam_kinks.cpp  Derivatives through |x|, sgn, max (issue 36): the checker says on which switching surface a
 * derivative the text takes does not exist (a jump, or slopes that differ on the two sides), and not where it exists
 * (a quadratic drag at rest). */
#include "test_paths.hpp"
#include "checked_text.hpp"
#include "checker/checker.hpp"
#include "checker/kinks.hpp"
#include "model/nonsmooth.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace {

using eomgen::checker::CheckReport;
using eomgen::checker::EquationCheck;
using eomgen::checker::Verdict;

const std::string kSource = eomgen_test::source_dir();

std::string notes(const EquationCheck& e) {
    std::string all;
    for (const std::string& n : e.notes) all += n + "\n";
    return all;
}

}  // namespace

TEST_CASE("kinks: where a derivative through a jump or a kink does not exist", "[checker][nonsmooth]") {
    using eomgen::checker::surfaces_without_derivative;
    const GiNaC::symbol x("x"), v("v"), c("c");
    // sgn(v - x) jumps at x = v; |x| has a kink at 0; x|x| has the derivative 2|x|, 0 at 0; max(x, c) a kink at c.
    const auto jump = surfaces_without_derivative(c * eomgen::sign(v - x), x);
    REQUIRE(jump.size() == 1);
    CHECK(jump[0].jump);
    CHECK(jump[0].surface.is_equal(v - x));
    const auto kink = surfaces_without_derivative(eomgen::real_abs(x), x);
    REQUIRE(kink.size() == 1);
    CHECK_FALSE(kink[0].jump);
    CHECK(surfaces_without_derivative(x * eomgen::real_abs(x), x).empty());
    CHECK(surfaces_without_derivative(eomgen::real_max(x, c), x).size() == 1);
    // A surface in other variables: the derivative in x exists.
    CHECK(surfaces_without_derivative(x * eomgen::sign(v - c), x).empty());
    // Smooth: nothing.
    CHECK(surfaces_without_derivative(x * x, x).empty());
}

TEST_CASE("kinks: the checker's verdicts say where a derivative the text takes does not exist", "[checker][nonsmooth]") {
    const auto& belt = eomgen::test::derived_model("examples/block_on_belt.toml");
    const CheckReport r = eomgen::checker::check_derivation(
        belt.first, belt.second, eomgen::checker::read_derivation(kSource + "/tests/checker/fixtures/kinks_belt.md"),
        {});
    int seen = 0;
    for (const EquationCheck& e : r.equations) {
        INFO(e.equation << "\n" << notes(e));
        CHECK(e.verdict != Verdict::Disagrees);
        if (e.equation.find("\\partial Q") != std::string::npos) {
            ++seen;
            CHECK(e.verdict == Verdict::Agrees);
            CHECK(notes(e).find("the derivative in $\\dot{x}$ does not exist where $v - \\dot{x} = 0$ (the function "
                                "jumps there): the side holds away from it") != std::string::npos);
        } else if (e.equation.find("\\partial P") != std::string::npos) {
            ++seen;
            CHECK(notes(e).find("(its slopes on the two sides differ)") != std::string::npos);
        } else if (e.equation.find("\\partial D") != std::string::npos) {
            ++seen;
            CHECK(notes(e).find("does not exist") == std::string::npos);
        }
    }
    CHECK(seen == 3);
}
