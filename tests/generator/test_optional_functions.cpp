/**
 * @file test_optional_functions.cpp  [generate] and the header's optional functions: the default header holds
 * none of the analytic Jacobians or the K, C, G about rest; each flag adds exactly its own functions; the model
 * file's table is read and checked; the phase timings add up.
 */
#include "codegen/cpp_emitter.hpp"
#include "codegen/generation_timings.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/families.hpp"
#include "model/model_file.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <string>
#include <vector>

namespace {

bool holds(const std::string& header, const std::string& what) { return header.find(what) != std::string::npos; }

std::string header_of(eomgen::Model model, bool jacobians, bool stiffness) {
    model.generate.jacobians = jacobians;
    model.generate.stiffness = stiffness;
    const eomgen::Equations eq = eomgen::derive_equations(model);
    return eomgen::codegen::emit_model_header(model, eq, "test.toml");
}

const char* kSpring = R"(
name = "spring"
[[coordinates]]
name = "x"
[[parameters]]
name = "k"
value = 2.0
[lagrangian]
T = "1/2*x'^2"
V = "k*x^2/2"
)";

}  // namespace

TEST_CASE("the default header holds no optional function, and each flag adds its own", "[codegen][generate]") {
    const eomgen::Model model = eomgen::parse_model(
        eomgen::family_model_text(eomgen::parse_family_spec("pendulum:n=3")), "pendulum_3");
    const std::string plain = header_of(model, false, false);
    const std::string jac = header_of(model, true, false);
    const std::string stiff = header_of(model, false, true);
    for (const char* f : {"state_jacobian(", "parameter_jacobian(", "jacobian_terms(", "analytic_jacobian.hpp"}) {
        INFO(f);
        CHECK_FALSE(holds(plain, f));
        CHECK(holds(jac, f));
        CHECK_FALSE(holds(stiff, f));
    }
    for (const char* f : {"static void stiffness(", "static void damping(", "static void gyroscopic("}) {
        INFO(f);
        CHECK_FALSE(holds(plain, f));
        CHECK_FALSE(holds(jac, f));
        CHECK(holds(stiff, f));
    }
    // What every header has, with or without the optional functions.
    for (const std::string* h : {&plain, &jac, &stiff})
        for (const char* f : {"static void rhs(", "static void dynamics(", "static void linearization("}) CHECK(holds(*h, f));
    CHECK(plain.size() < jac.size());
    CHECK(plain.size() < stiff.size());
}

TEST_CASE("[generate] is read from the model file and checked", "[model][generate]") {
    const eomgen::Model none = eomgen::parse_model(kSpring, "spring.toml");
    CHECK_FALSE(none.generate.jacobians);
    CHECK_FALSE(none.generate.stiffness);
    const eomgen::Model both =
        eomgen::parse_model(std::string(kSpring) + "[generate]\njacobians = true\nstiffness = true\n", "spring.toml");
    CHECK(both.generate.jacobians);
    CHECK(both.generate.stiffness);
    const eomgen::Model off = eomgen::parse_model(std::string(kSpring) + "[generate]\njacobians = false\n", "spring.toml");
    CHECK_FALSE(off.generate.jacobians);
    CHECK_THROWS_WITH(eomgen::parse_model("generate = true\n" + std::string(kSpring), "spring.toml"),
                      Catch::Contains("'generate' must be a table"));
    CHECK_THROWS_WITH(eomgen::parse_model(std::string(kSpring) + "[generate]\nstiffness = 1\n", "spring.toml"),
                      Catch::Contains("spring.toml:12:13: 'stiffness' must be true or false"));
    CHECK_THROWS_WITH(eomgen::parse_model(std::string(kSpring) + "[generate]\nstifness = true\n", "spring.toml"),
                      Catch::Contains("did you mean 'stiffness'?"));
}

TEST_CASE("generate --timings: one phase per step of the header, adding up to the total", "[codegen][generate]") {
    eomgen::Model model = eomgen::parse_model(kSpring, "spring.toml");
    model.generate.jacobians = model.generate.stiffness = true;
    const eomgen::Equations eq = eomgen::derive_equations(model);
    eomgen::codegen::GenerationTimings timings;
    const auto start = std::chrono::steady_clock::now();
    const std::string with = eomgen::codegen::emit_model_header(model, eq, "spring.toml", &timings);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(with == eomgen::codegen::emit_model_header(model, eq, "spring.toml"));  // timing changes nothing
    std::vector<std::string> names;
    double sum = 0;
    for (const auto& p : timings.phases) {
        names.push_back(p.name);
        CHECK(p.seconds >= 0);
        CHECK(p.peak_mb > 0);
        sum += p.seconds;
    }
    CHECK_THAT(names, Catch::VectorContains(std::string("stiffness: linearize about rest")));
    CHECK_THAT(names, Catch::VectorContains(std::string("function dynamics()")));
    CHECK_THAT(names, Catch::VectorContains(std::string("jacobians: terms and emission")));
    const std::string table = timings.table("spring.toml");
    CHECK(holds(table, "spring.toml: generation phases"));
    CHECK(holds(table, "function stiffness()"));
    CHECK(holds(table, "total"));
    CHECK(sum <= elapsed + 1e-6);  // the phases partition the emission, none counted twice
}
