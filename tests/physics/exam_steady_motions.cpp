/** @file exam_steady_motions.cpp  Steady motions of holonomic and nonholonomic models other than the bicycle
 *  (eomgen modes --steady): the rolling disc's upright rolling against its closed-form wobble frequency and
 *  stability bound, the heavy top's steady precession against Goldstein's condition, and the sleeping top (in
 *  tilt angles, where Euler angles are singular) against its stability bound I3² ω² > 4 I M g l. */
#include "test_paths.hpp"
#include "mechanics/lagrangian.hpp"
#include "mechanics/small_oscillations.hpp"
#include "mechanics/steady_motion.hpp"
#include "mechanics/steady_sweep.hpp"
#include "model/model_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace {

std::size_t index_of(const eomgen::Model& m, const std::string& name) {
    for (std::size_t i = 0; i < m.dof(); ++i)
        if (m.coordinates[i].name == name) return i;
    throw std::logic_error(name);
}

}  // namespace

TEST_CASE("steady motion: a coin rolling upright wobbles at the closed-form rate and falls below sqrt(g/3R)",
          "[physics][steady]") {
    const eomgen::Model model = eomgen::load_model(eomgen_test::source_dir() + "/models/rolling_disc.toml");
    const eomgen::Equations eq = eomgen::derive_equations(model);
    eomgen::SteadyMotionSolver solver(model, eq);
    const double m = 1.0, R = 0.1, g = 9.81, Id = m * R * R / 4, Ia = m * R * R / 2;
    for (double spin : {20.0, 5.0}) {
        eomgen::SteadyMotionOptions o;
        o.rates.push_back({index_of(model, "psi"), GiNaC::numeric(int(spin)), "psi_dot"});
        const eomgen::SteadyMotion s = solver.solve(o);
        REQUIRE(s.decoupled);
        CHECK(s.residual < 1e-12);
        // Lean: (I_d + mR²) θ'' + (I_a + mR²) Ω φ' − m g R θ = 0 and I_d φ'' = I_a Ω θ': θ'' = −ω² θ with
        // ω² = ((I_a + mR²) I_a Ω² / I_d − m g R) / (I_d + mR²); upright rolling is stable for Ω² > g/(3R).
        const double w2 = ((Ia + m * R * R) * Ia * spin * spin / Id - m * g * R) / (Id + m * R * R);
        double largest = 0;
        for (Eigen::Index k = 0; k < s.eigenvalues.size(); ++k) largest = std::max(largest, std::abs(s.eigenvalues(k)));
        CHECK(largest == Approx(std::sqrt(std::abs(w2))).epsilon(1e-12));
        CHECK(s.stability == (spin * spin > g / (3 * R) ? "marginally stable" : "unstable"));
    }
}

TEST_CASE("steady motion: the heavy top's precession angle satisfies Goldstein's steady-precession condition",
          "[physics][steady]") {
    const eomgen::Model model = eomgen::load_model(eomgen_test::source_dir() + "/models/heavy_symmetric_top.toml");
    const eomgen::Equations eq = eomgen::derive_equations(model);
    eomgen::SteadyMotionOptions o;
    o.rates.push_back({index_of(model, "phi"), GiNaC::numeric(4), "phi_dot=4"});
    o.rates.push_back({index_of(model, "psi"), GiNaC::numeric(100), "psi_dot=100"});
    o.at["theta"] = 1.8;
    const eomgen::SteadyMotion s = eomgen::steady_motion(model, eq, o);
    auto p = [&](const char* name) {
        for (const eomgen::Parameter& x : model.parameters)
            if (x.name == name) return x.value;
        throw std::logic_error(name);
    };
    const double theta = s.q[index_of(model, "theta")], I = p("I1") + p("M") * p("l") * p("l"), I3 = p("I3");
    const double w3 = 100 + 4 * std::cos(theta);
    // Goldstein (5.72) with I = I1 + M l² about the pivot: I cos θ φ'² − I3 ω3 φ' + M g l = 0.
    CHECK(I * std::cos(theta) * 16 - I3 * w3 * 4 + p("M") * p("g") * p("l") == Approx(0).margin(1e-12));
    CHECK(s.cyclic.size() == 2);
    CHECK_FALSE(s.decoupled);  // the precession and spin rates feed back into the nutation
    REQUIRE(s.eigenvalues.size() == 2);
    CHECK(std::abs(s.eigenvalues(0).real()) < 1e-9);  // nutation: a pure oscillation
    // Without a good guess Newton's method reaches the sleeping top at θ = 0, where the Euler angles are singular.
    eomgen::SteadyMotionOptions sleeping;
    sleeping.rates.push_back({index_of(model, "psi"), GiNaC::numeric(100), "psi_dot=100"});
    CHECK_THROWS_WITH(eomgen::steady_motion(model, eq, sleeping), Catch::Contains("singular"));
}

TEST_CASE("steady motion: the sleeping top, in tilt angles, is stable above omega = 2 sqrt(I M g l)/I3", "[physics][steady]") {
    // The top's axis tilted by a about x and b about y (no singularity upright), spinning by psi about it: a
    // massless frame at the pivot carries the tilts, the top sits on it at distance l.
    const char* text = R"~(
name = "sleeping_top"
[[coordinates]]
name = "a"
[[coordinates]]
name = "b"
[[coordinates]]
name = "psi"
[[parameters]]
name = "M"
value = 0.5
[[parameters]]
name = "l"
value = 0.05
[[parameters]]
name = "I1"
value = 0.0004
[[parameters]]
name = "I3"
value = 0.0006
[[parameters]]
name = "g"
value = 9.81
[[parameters]]
name = "w"
value = 100
[gravity]
vector = ["0", "0", "-g"]
[[bodies]]
name = "pivot"
mass = 0
inertia = [0, 0, 0]
position = ["0", "0", "0"]
orientation = [["x", "a"], ["y", "b"]]
[[bodies]]
name = "top"
mass = "M"
inertia = ["I1", "I1", "I3"]
position = { body = "pivot", point = ["0", "0", "l"] }
orientation = { body = "pivot", rotations = [["z", "psi"]] }
)~";
    const eomgen::Model model = eomgen::parse_model(text, "sleeping_top.toml");
    const eomgen::Equations eq = eomgen::derive_equations(model);
    eomgen::SteadyMotionSolver solver(model, eq);
    eomgen::SteadyMotionOptions o;
    o.rates.push_back({index_of(model, "psi"), model.parameters[5].symbol, "psi_dot=w"});
    const eomgen::SteadyMotion s = solver.solve(o);
    REQUIRE(s.decoupled);
    CHECK(s.stability == "marginally stable");
    const eomgen::SteadySweep sweep = eomgen::sweep_steady_motion(model, solver, o, s, "w", 10, 100, 10);
    REQUIRE(sweep.changes.size() == 1);
    const double I = 0.0004 + 0.5 * 0.05 * 0.05, critical = 2 * std::sqrt(I * 0.5 * 9.81 * 0.05) / 0.0006;
    CHECK(sweep.changes[0].value == Approx(critical).epsilon(1e-13));
    CHECK(sweep.changes[0].from == "unstable");
}
