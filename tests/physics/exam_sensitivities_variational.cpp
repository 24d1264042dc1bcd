/**
 * @file exam_sensitivities_variational.cpp  The variational integrator's sensitivities (variational_sensitivities.hpp):
 * against central differences of whole runs of the same integrator with the same step (the derivative of its own
 * discrete motion), converging at second order to the continuous sensitivities of dop853, on three models (momenta
 * with a gyroscopic term, a mass matrix that depends on q, an explicit parameter in the potential); what is refused.
 */
#include "differences_support.hpp"

#include "eomgen/models/damped_pendulum.hpp"
#include "eomgen/models/door.hpp"
#include "eomgen/models/heavy_symmetric_top.hpp"
#include "eomgen/models/rotating_frame.hpp"
#include "eomgen/sensitivities.hpp"
#include "eomgen/symplectic.hpp"
#include "eomgen/variational_sensitivities.hpp"

#include <Eigen/Core>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace {

using eomgen::SensitivityColumn;

template <class M>
std::vector<SensitivityColumn> every_column() {
    std::vector<SensitivityColumn> c;
    for (int k = 0; k < M::n_params; ++k) c.push_back({SensitivityColumn::Kind::Parameter, k});
    for (int i = 0; i < M::nx; ++i) c.push_back({SensitivityColumn::Kind::InitialValue, i});
    return c;
}

/// (q, q̇) after round(t_end/dt) steps of the variational integrator from x0 with parameters p.
template <class M>
Eigen::VectorXd variational_end(const typename M::Params& p, const typename M::State& x0, double t_end, double dt) {
    eomgen::VariationalIntegrator<M> vi(p, dt);
    vi.set_state(0.0, typename M::Config(x0.head(M::nq)), typename M::Config(x0.tail(M::nq)));
    vi.step(std::size_t(std::llround(t_end / dt)));
    Eigen::VectorXd x(M::nx);
    x << vi.q(), vi.velocity();
    return x;
}

/// ∂x(t_end)/∂(column) of the variational runs by fourth-order central differences (steps of 1e-4 relative; 1e-4
/// for a value 0: the top's moments of inertia are 4e-4 and 6e-4 kg m², so a step relative to 1 would be no difference).
template <class M>
Eigen::VectorXd difference(const typename M::Params& p, const typename M::State& x0, double t_end, double dt,
                           const SensitivityColumn& c) {
    const double v = differences_support::column_value<M>(p, x0, c);
    return differences_support::column_difference<M>(
        p, x0, c, 1e-4 * (v != 0 ? std::abs(v) : 1.0),
        [&](const typename M::Params& q, const typename M::State& y) { return variational_end<M>(q, y, t_end, dt); });
}

/// The largest difference between S and the differences, relative to each column's largest entry (absolute where
/// the column vanishes), over every column.
template <class M>
double worst_against_differences(const typename M::Params& p, const typename M::State& x0, double t_end, double dt) {
    const auto columns = every_column<M>();
    const eomgen::SensitivityResult r = eomgen::integrate_sensitivities_symplectic<M>(p, 0.0, x0, t_end, dt, columns);
    REQUIRE(r.t == Approx(t_end));
    REQUIRE((r.x - variational_end<M>(p, x0, t_end, dt)).cwiseAbs().maxCoeff() == 0.0);  // the same run
    double worst = 0;
    for (std::size_t k = 0; k < columns.size(); ++k) {
        const Eigen::VectorXd fd = difference<M>(p, x0, t_end, dt, columns[k]);
        const double scale = fd.cwiseAbs().maxCoeff();
        const double d = (r.S.col(Eigen::Index(k)) - fd).cwiseAbs().maxCoeff();
        const double e = scale < 1e-9 ? d : d / scale;
        INFO(M::name << " column " << k << ": S = " << r.S.col(Eigen::Index(k)).transpose()
                     << "\n differences = " << fd.transpose());
        CHECK(e < 1e-7);
        worst = std::max(worst, e);
    }
    return worst;
}

/// max |S_variational(dt) − S_dop853| over every entry, relative to S_dop853's largest.
template <class M>
double distance_to_continuous(const typename M::Params& p, const typename M::State& x0, double t_end, double dt) {
    const auto columns = every_column<M>();
    eomgen::Dop853Options<double> o;
    o.rtol = 1e-13;
    o.atol = 1e-15;
    const auto exact = eomgen::integrate_sensitivities<M, eomgen::Dop853>(p, 0.0, x0, t_end, columns, o);
    const auto r = eomgen::integrate_sensitivities_symplectic<M>(p, 0.0, x0, t_end, dt, columns);
    return (r.S - exact.S).cwiseAbs().maxCoeff() / exact.S.cwiseAbs().maxCoeff();
}

}  // namespace

TEST_CASE("the variational integrator's sensitivities are the derivative of its own motion",
          "[sensitivities][symplectic]") {
    SECTION("a spring in a rotating frame: momenta with a gyroscopic term m(q̇ + w × q)") {
        using M = eomgen::models::rotating_frame::Model<double>;
        typename M::State x0 = M::default_state();
        x0(3) = 0.4;  // ẏ(0)
        const double worst = worst_against_differences<M>(M::Params{}, x0, 3.0, 0.01);
        WARN("rotating_frame, 300 steps of 0.01: worst relative difference " << worst);
    }
    SECTION("the heavy symmetric top: a mass matrix in θ, every parameter") {
        using M = eomgen::models::heavy_symmetric_top::Model<double>;
        typename M::State x0 = M::default_state();
        x0(3) = 0.3;   // φ̇(0)
        x0(5) = 5.0;  // ψ̇(0): a spinning top
        const double worst = worst_against_differences<M>(M::Params{}, x0, 0.5, 0.005);
        WARN("heavy_symmetric_top, 100 steps of 0.005: worst relative difference " << worst);
    }
    SECTION("the door: its tilt θ in the potential, its width in the mass matrix") {
        using M = eomgen::models::door::Model<double>;
        const double worst = worst_against_differences<M>(M::Params{}, M::default_state(), 2.0, 0.01);
        WARN("door, 200 steps of 0.01: worst relative difference " << worst);
    }
}

TEST_CASE("the variational integrator's sensitivities converge at second order to the continuous ones",
          "[sensitivities][symplectic]") {
    using M = eomgen::models::heavy_symmetric_top::Model<double>;
    typename M::State x0 = M::default_state();
    x0(3) = 0.3;
    x0(5) = 20.0;
    const double coarse = distance_to_continuous<M>(M::Params{}, x0, 1.0, 0.004);
    const double fine = distance_to_continuous<M>(M::Params{}, x0, 1.0, 0.002);
    INFO("dt 0.004: " << coarse << ", dt 0.002: " << fine);
    CHECK(coarse < 1e-2);
    CHECK(coarse / fine > 3.5);  // 4 for second order
    CHECK(coarse / fine < 4.5);
}

TEST_CASE("the variational integrator's sensitivities at samples and at the start", "[sensitivities][symplectic]") {
    using M = eomgen::models::rotating_frame::Model<double>;
    const auto columns = every_column<M>();
    const auto r = eomgen::integrate_sensitivities_symplectic<M>(M::Params{}, 0.0, M::default_state(), 2.0, 0.01,
                                                                 columns, {0.0, 1.0, 2.0});
    REQUIRE(r.samples.size() == 3);
    // At the start: the unit columns of the initial values, zero for the parameters.
    Eigen::MatrixXd start = Eigen::MatrixXd::Zero(M::nx, Eigen::Index(columns.size()));
    start.rightCols(M::nx).setIdentity();
    CHECK((r.samples[0].S - start).cwiseAbs().maxCoeff() < 1e-15);
    // At t = 1: the end of a run to 1.
    const auto half = eomgen::integrate_sensitivities_symplectic<M>(M::Params{}, 0.0, M::default_state(), 1.0, 0.01,
                                                                    columns);
    CHECK(r.samples[1].t == Approx(1.0));
    CHECK((r.samples[1].S - half.S).cwiseAbs().maxCoeff() == 0.0);
    CHECK((r.samples[2].S - r.S).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("the variational integrator's sensitivities refuse what the integrator refuses", "[sensitivities][symplectic]") {
    using D = eomgen::models::damped_pendulum::Model<double>;
    CHECK_THROWS_AS(eomgen::integrate_sensitivities_symplectic<D>(D::Params{}, 0.0, D::default_state(), 1.0, 0.01,
                                                                  every_column<D>()),
                    std::invalid_argument);
    using M = eomgen::models::rotating_frame::Model<double>;
    CHECK_THROWS_AS(eomgen::integrate_sensitivities_symplectic<M>(M::Params{}, 0.0, M::default_state(), 1.0, 0.0,
                                                                  every_column<M>()),
                    std::invalid_argument);
}
