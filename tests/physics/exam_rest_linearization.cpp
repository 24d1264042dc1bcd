/** @file exam_rest_linearization.cpp  The generated stiffness(), damping() and gyroscopic() (about rest): closed forms
 * derived here by hand, and the matrices `eomgen modes` finds at each equilibrium. */
#include "eomgen/models/damped_pendulum.hpp"
#include "eomgen/models/pendulum_5_20.hpp"
#include "eomgen/models/rotating_frame.hpp"
#include "modes_support.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include <cmath>

namespace {

/// The generated K, C, G at an equilibrium equal the ones eomgen modes derived for it.
template <class Model>
void matches_modes(const std::string& model_file) {
    const modes_support::Derived d = modes_support::load(model_file);
    const eomgen::ModesResult r = eomgen::small_oscillations(d.model, d.eq, {});
    REQUIRE_FALSE(r.equilibria.empty());
    const typename Model::Params p;
    for (const eomgen::Equilibrium& e : r.equilibria) {
        typename Model::Config q;
        for (int i = 0; i < Model::nq; ++i) q(i) = e.q[std::size_t(i)];
        typename Model::MassMatrix K, C, G;
        Model::stiffness(0.0, q, p, K);
        Model::damping(0.0, q, p, C);
        Model::gyroscopic(0.0, q, p, G);
        for (int i = 0; i < Model::nq; ++i)
            for (int j = 0; j < Model::nq; ++j) {
                const auto ij = [&](const std::vector<std::vector<double>>& m) { return m[std::size_t(i)][std::size_t(j)]; };
                CHECK(K(i, j) == Approx(ij(e.K)).margin(1e-12));
                CHECK(C(i, j) == Approx(ij(e.C)).margin(1e-12));
                CHECK(G(i, j) == Approx(ij(e.G)).margin(1e-12));
            }
    }
}

}  // namespace

TEST_CASE("stiffness() and gyroscopic(): a spring-held mass in a rotating frame, by hand",
          "[physics][modes][linearize]") {
    // L = m/2((x' − w y)² + (y' + w x)²) − k/2 (x² + y²): β = m w (−y, x), so D_xy = ∂β_x/∂y − ∂β_y/∂x = −2 m w
    // (the Coriolis force −2m w × v); V_eff = (k − m w²)(x² + y²)/2, so K = (k − m w²) I anywhere.
    using R = eomgen::models::rotating_frame::Model<double>;
    const R::Params p;
    R::Config q;
    q << 0.3, -0.7;
    R::MassMatrix K, C, G;
    R::stiffness(0.0, q, p, K);
    R::damping(0.0, q, p, C);
    R::gyroscopic(0.0, q, p, G);
    CHECK(K.isApprox((p.k - p.m * p.w * p.w) * Eigen::Matrix2d::Identity(), 1e-14));
    CHECK(C.isZero());
    CHECK(G(0, 1) == Approx(-2 * p.m * p.w).epsilon(1e-14));
    CHECK(G(1, 0) == Approx(2 * p.m * p.w).epsilon(1e-14));
    CHECK(G(0, 0) == 0);
    // About rest at the origin the first-order form is [0 I; −M⁻¹K −M⁻¹G] (M = m I): linearization() agrees.
    R::StateJacobian A;
    R::ParameterJacobian B;
    R::linearization(0.0, R::State::Zero(), p, A, B);
    Eigen::Matrix4d expected = Eigen::Matrix4d::Zero();
    expected.topRightCorner<2, 2>().setIdentity();
    expected.bottomLeftCorner<2, 2>() = -K / p.m;
    expected.bottomRightCorner<2, 2>() = -G / p.m;
    CHECK((A - expected).cwiseAbs().maxCoeff() <= 1e-13);
}

TEST_CASE("stiffness(), damping(), gyroscopic() equal eomgen modes' K, C, G at every equilibrium",
          "[physics][modes][linearize]") {
    matches_modes<eomgen::models::rotating_frame::Model<double>>("tests/physics/rotating_frame.toml");
    matches_modes<eomgen::models::damped_pendulum::Model<double>>("models/damped_pendulum.toml");
    matches_modes<eomgen::models::pendulum_5_20::Model<double>>("models/pendulum_5_20.toml");
}
