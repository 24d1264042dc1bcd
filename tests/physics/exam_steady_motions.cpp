/** @file exam_steady_motions.cpp  Steady motions of holonomic and nonholonomic models other than the bicycle
 *  (eomgen modes --steady): the rolling disc's upright rolling against its closed-form wobble frequency and
 *  stability bound, and the heavy top's steady precession against Goldstein's condition. */
#include "mechanics/lagrangian.hpp"
#include "mechanics/small_oscillations.hpp"
#include "mechanics/steady_motion.hpp"
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
    const eomgen::Model model = eomgen::load_model(EOMGEN_SOURCE_DIR "/models/rolling_disc.toml");
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
    const eomgen::Model model = eomgen::load_model(EOMGEN_SOURCE_DIR "/models/heavy_symmetric_top.toml");
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
