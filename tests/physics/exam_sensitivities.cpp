/**
 * @file exam_sensitivities.cpp  Forward sensitivities (sensitivities.hpp) against central differences of whole
 * trajectories on five models — unconstrained (analytic Jacobians and forward AD), constrained, rheonomic, damped
 * and driven, stiff under radau5 — and the door's closing-time sensitivity against its closed form; what is refused.
 */
#include "../approx.hpp"
#include "differences_support.hpp"

#include "eomgen/integrate.hpp"
#include "eomgen/models/bead_on_hoop.hpp"
#include "eomgen/models/door.hpp"
#include "eomgen/models/driven_chain4.hpp"
#include "eomgen/models/hoop_driven.hpp"
#include "eomgen/models/pendulum_5_20.hpp"
#include "eomgen/models/pendulum_cartesian.hpp"
#include "eomgen/models/stiff_spring_pendulum.hpp"
#include "eomgen/radau5.hpp"
#include "eomgen/sensitivities.hpp"

#include <Eigen/Core>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

using eomgen::SensitivityColumn;

/// Whether to integrate by radau5 (the stiff model) or dop853.
enum class By { Dop853, Radau5 };

constexpr double kRtol = 1e-12, kAtol = 1e-14;

/// x(t_end) of M from x0 with parameters p, tightly.
template <class M>
Eigen::VectorXd end_state(const typename M::Params& p, const typename M::State& x0, double t_end, By by) {
    auto f = [&p](const double& t, const typename M::State& x, typename M::State& xd) { M::rhs(t, x, p, xd); };
    if (by == By::Radau5) {
        eomgen::Radau5Options<double> o;
        o.rtol = kRtol;
        o.atol = kAtol;
        o.max_steps = 2000000;
        auto jac = [&p](const double& t, const typename M::State& x, auto& J) { eomgen::model_jacobian<M>(t, x, p, J); };
        return eomgen::integrate_radau5(f, jac, 0.0, x0, t_end, o).x;
    }
    eomgen::Dop853Options<double> o;
    o.rtol = kRtol;
    o.atol = kAtol;
    o.max_steps = 2000000;
    return eomgen::integrate_dop853(f, 0.0, x0, t_end, o).x;
}

/// ∂x(t_end)/∂(column) by fourth-order central differences of whole trajectories (steps of 2e-4 relative: with
/// 1e-3 the truncation error was 5e-6 on the double pendulum's a; the integrations' error over the step is about 1e-9).
template <class M>
Eigen::VectorXd difference(const typename M::Params& p, const typename M::State& x0, double t_end,
                           const SensitivityColumn& c, By by, double step) {
    const double h = step * std::max(1.0, std::abs(differences_support::column_value<M>(p, x0, c)));
    return differences_support::column_difference<M>(
        p, x0, c, h, [&](const typename M::Params& q, const typename M::State& y) { return end_state<M>(q, y, t_end, by); });
}

/// Integrates S of every column and compares each with central differences: the largest difference relative to
/// the column's largest entry. Returns the worst over the columns.
template <class M>
double worst_relative_error(const typename M::Params& p, const typename M::State& x0, double t_end,
                            const std::vector<SensitivityColumn>& columns, By by, double step = 2e-4) {
    eomgen::SensitivityResult r;
    if (by == By::Radau5) {
        eomgen::Radau5Options<double> o;
        o.rtol = kRtol;
        o.atol = kAtol;
        o.max_steps = 2000000;
        r = eomgen::integrate_sensitivities_radau5<M>(p, 0.0, x0, t_end, columns, o);
    } else {
        eomgen::Dop853Options<double> o;
        o.rtol = kRtol;
        o.atol = kAtol;
        o.max_steps = 2000000;
        r = eomgen::integrate_sensitivities<M, eomgen::Dop853>(p, 0.0, x0, t_end, columns, o);
    }
    REQUIRE(r.t == Approx(t_end));
    REQUIRE((r.x - end_state<M>(p, x0, t_end, by)).cwiseAbs().maxCoeff() < 1e-9 * std::max(1.0, r.x.norm()));
    double worst = 0;
    for (std::size_t k = 0; k < columns.size(); ++k) {
        const Eigen::VectorXd fd = difference<M>(p, x0, t_end, columns[k], by, step);
        const double scale = fd.cwiseAbs().maxCoeff();
        const double difference_max = (r.S.col(Eigen::Index(k)) - fd).cwiseAbs().maxCoeff();
        // A column that vanishes (a mass that cancels from the motion) has no relative error: both sides must be
        // 0 to the differences' round-off (1e-13 over a step of 2e-4: about 1e-9) instead.
        const double e = scale < 1e-9 ? (difference_max < 1e-9 ? 0.0 : 1.0) : difference_max / scale;
        INFO(M::name << " column " << k << ": S = " << r.S.col(Eigen::Index(k)).transpose()
                     << "\n differences = " << fd.transpose());
        CHECK(e < 1e-7);
        worst = std::max(worst, e);
    }
    return worst;
}

template <class M>
std::vector<SensitivityColumn> every_column(bool with_initial) {
    std::vector<SensitivityColumn> c;
    for (int k = 0; k < M::n_params; ++k) c.push_back({SensitivityColumn::Kind::Parameter, k});
    if (with_initial)
        for (int i = 0; i < M::nx; ++i) c.push_back({SensitivityColumn::Kind::InitialValue, i});
    return c;
}

}  // namespace

TEST_CASE("sensitivities of an unconstrained model agree with central differences: analytic Jacobians and AD",
          "[sensitivities]") {
    using P = eomgen::models::pendulum_5_20::Model<double>;  // analytic state_jacobian and parameter_jacobian
    static_assert(eomgen::has_parameter_jacobian<P>::value);
    P::State x0 = P::default_state();
    x0 << 0.4, -0.3, 0.2, 0.5;
    CHECK(worst_relative_error<P>(P::Params{}, x0, 3.0, every_column<P>(true), By::Dop853) < 1e-7);

    using B = eomgen::models::bead_on_hoop::Model<double>;  // no analytic Jacobians: forward AD through rhs()
    static_assert(!eomgen::has_parameter_jacobian<B>::value);
    B::State y0;
    y0 << 0.7, 0.3;
    CHECK(worst_relative_error<B>(B::Params{}, y0, 4.0, every_column<B>(true), By::Dop853) < 1e-7);
}

TEST_CASE("sensitivities of a constrained model go through the multipliers' solve", "[sensitivities]") {
    using C = eomgen::models::pendulum_cartesian::Model<double>;
    C::Params p;
    const double l = C::param_values(p)[1];
    C::State x0;
    x0 << l * std::sin(0.6), -l * std::cos(0.6), 0.8 * std::cos(0.6), 0.8 * std::sin(0.6);  // on the rod, moving along it
    const std::vector<SensitivityColumn> columns{eomgen::parameter_column(C::param_names, "m"),
                                                 eomgen::parameter_column(C::param_names, "g")};
    CHECK(worst_relative_error<C>(p, x0, 3.0, columns, By::Dop853) < 1e-7);

    // A rheonomic constraint (the hoop's spin phi = w t): g and m do not enter it.
    using H = eomgen::models::hoop_driven::Model<double>;
    H::Params q;
    H::State z0 = H::default_state();
    CHECK(worst_relative_error<H>(q, z0, 2.0,
                                  {eomgen::parameter_column(H::param_names, "g"),
                                   eomgen::parameter_column(H::param_names, "R")},
                                  By::Dop853) < 1e-7);
}

TEST_CASE("sensitivities of a rheonomic, damped and driven model (a chain on a shaken support)", "[sensitivities]") {
    using D = eomgen::models::driven_chain4::Model<double>;
    D::State x0 = D::default_state();
    for (int i = 0; i < D::nq; ++i) x0(i) = 0.3 - 0.1 * i;
    CHECK(worst_relative_error<D>(D::Params{}, x0, 2.0,
                                  {eomgen::parameter_column(D::param_names, "c"),
                                   eomgen::parameter_column(D::param_names, "tau"),
                                   eomgen::parameter_column(D::param_names, "A"),
                                   eomgen::parameter_column(D::param_names, "w"),
                                   eomgen::initial_column(D::state_names, "th1"),
                                   eomgen::initial_column(D::state_names, "th3_dot")},
                                  By::Dop853) < 1e-7);
}

TEST_CASE("sensitivities of the stiff spring pendulum under radau5", "[sensitivities]") {
    // The motion hardly depends on the stiff spring's k and c (S of order 1e-9): the differences take steps of
    // 5e-3 relative so that the integrations' error divided by the step stays below 1e-7 of that.
    using S = eomgen::models::stiff_spring_pendulum::Model<double>;
    S::Params p;
    S::State x0 = S::default_state();
    CHECK(worst_relative_error<S>(p, x0, 1.0,
                                  {eomgen::parameter_column(S::param_names, "k"),
                                   eomgen::parameter_column(S::param_names, "c"),
                                   eomgen::parameter_column(S::param_names, "g"),
                                   eomgen::initial_column(S::state_names, "theta")},
                                  By::Radau5, 5e-3) < 1e-7);
}

TEST_CASE("the door's closing-time sensitivity against the closed form T = K sqrt(w/(g sin theta))",
          "[sensitivities]") {
    // T ∝ (sin θ)^(-1/2) w^(1/2) g^(-1/2), whatever the constant K: dT/dθ = −T cot θ / 2, dT/dw = T/(2w),
    // dT/dg = −T/(2g), dT/dm = dT/dh = 0.
    using D = eomgen::models::door::Model<double>;
    D::Params p;
    const auto values = D::param_values(p);
    const double w = values[1], g = values[3], theta = values[4];
    eomgen::Dop853Options<double> o;
    o.rtol = kRtol;
    o.atol = kAtol;
    const auto r = eomgen::integrate_sensitivities<D, eomgen::Dop853>(
        p, 0.0, D::default_state(), 10.0, every_column<D>(false), o,
        {eomgen::state_crossing("shut", 0, -M_PI / 2)});
    REQUIRE(r.events.size() == 1);
    REQUIRE(r.stopped_by == "shut");
    const double T = r.events[0].t;
    const Eigen::RowVectorXd& dT = r.events[0].dt;
    CHECK(dT(4) == Approx(-T / (2 * std::tan(theta))).epsilon(1e-9));
    CHECK(dT(1) == Approx(T / (2 * w)).epsilon(1e-9));
    CHECK(dT(3) == Approx(-T / (2 * g)).epsilon(1e-9));
    CHECK(std::abs(dT(0)) < 1e-9 * T);
    CHECK(std::abs(dT(2)) < 1e-9 * T);
    // At the event the state's total derivative keeps psi on the event surface: d psi(T)/dp = 0.
    CHECK(r.events[0].dx.row(0).cwiseAbs().maxCoeff() < 1e-9);

    // Without the gradient (central differences of g), the same to their error.
    eomgen::SensitivityEvent plain{eomgen::state_crossing("shut", 0, -M_PI / 2).event, {}};
    const auto q = eomgen::integrate_sensitivities<D, eomgen::Dop853>(p, 0.0, D::default_state(), 10.0,
                                                                      every_column<D>(false), o, {plain});
    REQUIRE(q.events.size() == 1);
    CHECK(q.events[0].dt(4) == Approx(dT(4)).epsilon(1e-8));
}

TEST_CASE("the declared outputs' sensitivities Yx S + Yp agree with differences of the outputs", "[sensitivities]") {
    // The door's outputs z_c (the centre's height, with w and theta in it) and v_edge (the edge's speed).
    using D = eomgen::models::door::Model<double>;
    static_assert(D::n_outputs == 2);
    const D::Params p;
    D::State x0 = D::default_state();
    x0(1) = -0.2;
    const std::vector<SensitivityColumn> columns{eomgen::parameter_column(D::param_names, "theta"),
                                                 eomgen::parameter_column(D::param_names, "w"),
                                                 eomgen::initial_column(D::state_names, "psi_dot")};
    eomgen::Dop853Options<double> o;
    o.rtol = kRtol;
    o.atol = kAtol;
    const double t_end = 2.0;
    const auto r = eomgen::integrate_sensitivities<D, eomgen::Dop853>(p, 0.0, x0, t_end, columns, o, {}, {0.0, t_end});
    REQUIRE(r.samples.size() == 2);
    const auto& end = r.samples.back();
    REQUIRE(end.y.size() == 2);
    REQUIRE(end.Y.rows() == 2);
    REQUIRE(end.Y.cols() == 3);
    const auto outputs_at = [&](const D::Params& q, const D::State& y0) {
        const Eigen::VectorXd x = end_state<D>(q, y0, t_end, By::Dop853);
        D::Outputs y;
        D::outputs(t_end, x.head<1>(), x.tail<1>(), q, y);
        return Eigen::Vector2d(y);
    };
    for (std::size_t c = 0; c < columns.size(); ++c) {
        const auto values = D::param_values(p);
        const bool parameter = columns[c].kind == SensitivityColumn::Kind::Parameter;
        const double v = parameter ? values[std::size_t(columns[c].index)] : x0(columns[c].index);
        const double h = 2e-4 * std::max(1.0, std::abs(v));
        const auto at = [&](double offset) {
            D::Params q = p;
            D::State y0 = x0;
            if (parameter)
                D::set_param(q, D::param_names[std::size_t(columns[c].index)], v + offset);
            else
                y0(columns[c].index) = v + offset;
            return outputs_at(q, y0);
        };
        const Eigen::Vector2d fd = (-at(2 * h) + 8 * at(h) - 8 * at(-h) + at(-2 * h)) / (12 * h);
        INFO("column " << c << ": Y = " << end.Y.col(Eigen::Index(c)).transpose() << ", differences " << fd.transpose());
        CHECK((end.Y.col(Eigen::Index(c)) - fd).cwiseAbs().maxCoeff() <= 1e-7 * fd.cwiseAbs().maxCoeff());
    }
    // At t0 an output's sensitivity to a parameter is its explicit dependence alone (S = 0 there).
    CHECK(r.samples.front().Y.col(0).cwiseAbs().maxCoeff() > 0);
}

TEST_CASE("the multipliers' sensitivities Lx S + Lp agree with differences of the multipliers", "[sensitivities]") {
    // The Cartesian pendulum's rod tension λ at t = 3 s, against g and m.
    using C = eomgen::models::pendulum_cartesian::Model<double>;
    const C::Params p;
    const double l = C::param_values(p)[1];
    C::State x0;
    x0 << l * std::sin(0.6), -l * std::cos(0.6), 0.8 * std::cos(0.6), 0.8 * std::sin(0.6);
    const std::vector<SensitivityColumn> columns{eomgen::parameter_column(C::param_names, "g"),
                                                 eomgen::parameter_column(C::param_names, "m")};
    eomgen::Dop853Options<double> o;
    o.rtol = kRtol;
    o.atol = kAtol;
    const double t_end = 3.0;
    const auto r = eomgen::integrate_sensitivities<C, eomgen::Dop853>(p, 0.0, x0, t_end, columns, o, {}, {t_end});
    REQUIRE(r.samples.size() == 1);
    const auto& end = r.samples.back();
    REQUIRE(end.lambda.size() == 1);
    REQUIRE(end.L.rows() == 1);
    const auto values = C::param_values(p);
    for (std::size_t c = 0; c < columns.size(); ++c) {
        const double v = values[std::size_t(columns[c].index)], h = 2e-4 * std::max(1.0, std::abs(v));
        const auto at = [&](double offset) {
            C::Params q = p;
            C::set_param(q, C::param_names[std::size_t(columns[c].index)], v + offset);
            C::ConstraintVector lambda;
            C::multipliers(t_end, C::State(end_state<C>(q, x0, t_end, By::Dop853)), q, lambda);
            return lambda(0);
        };
        const double fd = (-at(2 * h) + 8 * at(h) - 8 * at(-h) + at(-2 * h)) / (12 * h);
        INFO("column " << c << ": L = " << end.L(0, Eigen::Index(c)) << ", differences " << fd);
        CHECK(std::abs(end.L(0, Eigen::Index(c)) - fd) <= 1e-7 * std::abs(fd));
    }
}

TEST_CASE("samples carry S, and S at t0 is the columns' start", "[sensitivities]") {
    using D = eomgen::models::door::Model<double>;
    const auto r = eomgen::integrate_sensitivities<D, eomgen::Dopri5>(
        D::Params{}, 0.0, D::default_state(), 1.0,
        {eomgen::parameter_column(D::param_names, "theta"), eomgen::initial_column(D::state_names, "psi_dot")}, {},
        {}, {0.0, 0.5, 1.0});
    REQUIRE(r.samples.size() == 3);
    CHECK(r.samples[0].S.col(0).isZero());
    CHECK(r.samples[0].S.col(1) == Eigen::Vector2d(0, 1));
    CHECK(r.samples[2].S == r.S);
    CHECK(r.jacobian_evaluations == r.rhs_evaluations);
}

TEST_CASE("a column that names nothing is refused", "[sensitivities]") {
    using C = eomgen::models::pendulum_cartesian::Model<double>;
    CHECK_THROWS_AS(eomgen::parameter_column(C::param_names, "mass"), std::invalid_argument);
    CHECK_THROWS_AS(eomgen::initial_column(C::state_names, "z"), std::invalid_argument);
    CHECK_THROWS_WITH((eomgen::integrate_sensitivities<C, eomgen::Dop853>(
                          C::Params{}, 0.0, C::default_state(), 1.0, {{SensitivityColumn::Kind::Parameter, 7}})),
                      Catch::Contains("out of range"));
}
