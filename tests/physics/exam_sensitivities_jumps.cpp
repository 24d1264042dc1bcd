/**
 * @file exam_sensitivities_jumps.cpp  Sensitivities where the plain variational equations are not the whole story,
 * against fourth-order central differences of whole motions:
 *  - a constrained model's start (consistent_sensitivities.hpp): an initial value, or a parameter the constraints
 *    contain, moves the consistent start as --project-initial moves it (the differences project each perturbed start
 *    with project_onto_constraints, the definition);
 *  - a switching surface (saltation.hpp): the hinge friction of a swinging door, sign(ψ̇), turns at each reversal,
 *    and S jumps there (the differences integrate each perturbed motion with its steps ended at the reversals);
 *  - a motion that sticks (static friction holds the door; a block rides a belt, then slips off it: stick-slip) is
 *    followed along the surface (sliding_sensitivities.hpp; the differences follow each perturbed motion's sliding
 *    as eomgen run does, integrate_sliding).
 */
#include "differences_support.hpp"

#include "eomgen/constraints.hpp"
#include "eomgen/errors.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/models/block_on_belt.hpp"
#include "eomgen/models/friction_door.hpp"
#include "eomgen/models/friction_pendulum_cartesian.hpp"
#include "eomgen/models/grazing_oscillator.hpp"
#include "eomgen/models/hoop_driven.hpp"
#include "eomgen/models/pendulum_cartesian.hpp"
#include "eomgen/sensitivities.hpp"

#include <Eigen/Core>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

using eomgen::SensitivityColumn;

constexpr double kRtol = 1e-12, kAtol = 1e-14;

/// x(t_end) of M from x0 (projected onto the constraints first, where M has them), its steps ended at every
/// crossing of a switching surface, and along the surface where it holds the motion: the reference motion (a
/// constrained one without projections after the start, as the sensitivities' run).
template <class M>
Eigen::VectorXd end_state(const typename M::Params& p, typename M::State x0, double t_end) {
    using State = typename M::State;
    if constexpr (eomgen::is_constrained<M>::value) eomgen::project_onto_constraints<M>(0.0, x0, p);
    auto f = [&p](const double& t, const State& x, State& xd) { M::rhs(t, x, p, xd); };
    std::vector<eomgen::Event<State>> events;
    if constexpr (eomgen::has_switching<M>::value)
        for (int k = 0; k < M::n_switches; ++k)
            events.push_back({M::switch_names[std::size_t(k)],
                              [&p, k](const double& t, const State& x) {
                                  typename M::Switches s;
                                  M::switching(t, eomgen::positions<M::nq>(x), eomgen::velocities<M::nq>(x), p, s);
                                  return s(k);
                              },
                              eomgen::EventDirection::Both, eomgen::EventAction::Switch});
    eomgen::Dop853Options<double> o;
    o.rtol = kRtol;
    o.atol = kAtol;
    o.max_steps = 2000000;
    return eomgen::integrate_sliding<eomgen::Dop853>(f, 0.0, x0, t_end, o, events).x;
}

/// ∂x(t_end)/∂(column) by fourth-order central differences of whole reference motions.
template <class M>
Eigen::VectorXd difference(const typename M::Params& p, const typename M::State& x0, double t_end,
                           const SensitivityColumn& c, double step = 2e-4) {
    const double v = differences_support::column_value<M>(p, x0, c);
    const double h = step * std::max(0.1, std::abs(v));  // theta = 0.0234: a step of 1 % of it left 7e-8
    return differences_support::column_difference<M>(
        p, x0, c, h, [&](const typename M::Params& q, const typename M::State& y) { return end_state<M>(q, y, t_end); });
}

/// S at t_end by dop853 against the differences, column by column (relative to the column's largest entry).
template <class M>
eomgen::SensitivityResult check_columns(const typename M::Params& p, const typename M::State& x0, double t_end,
                                        const std::vector<SensitivityColumn>& columns, double bound = 1e-7) {
    eomgen::Dop853Options<double> o;
    o.rtol = kRtol;
    o.atol = kAtol;
    o.max_steps = 2000000;
    const auto r = eomgen::integrate_sensitivities<M, eomgen::Dop853>(p, 0.0, x0, t_end, columns, o);
    REQUIRE(r.t == Approx(t_end));
    for (std::size_t k = 0; k < columns.size(); ++k) {
        const Eigen::VectorXd fd = difference<M>(p, x0, t_end, columns[k]);
        const double scale = std::max(fd.cwiseAbs().maxCoeff(), 1e-3);
        const double off = (r.S.col(Eigen::Index(k)) - fd).cwiseAbs().maxCoeff() / scale;
        INFO(M::name << " column " << k << ": S = " << r.S.col(Eigen::Index(k)).transpose()
                     << "\n differences = " << fd.transpose() << "\n relative difference " << off);
        CHECK(off < bound);
    }
    return r;
}

}  // namespace

TEST_CASE("a constrained model's initial values and the parameters in its constraints start on the constraints",
          "[sensitivities]") {
    using C = eomgen::models::pendulum_cartesian::Model<double>;
    C::Params p;
    const double l = C::param_values(p)[1];
    C::State x0;
    x0 << l * std::sin(0.6), -l * std::cos(0.6), 0.8 * std::cos(0.6), 0.8 * std::sin(0.6);
    const auto r = check_columns<C>(p, x0, 2.0,
                                    {eomgen::parameter_column(C::param_names, "l"),
                                     eomgen::initial_column(C::state_names, "x"),
                                     eomgen::initial_column(C::state_names, "y_dot"),
                                     eomgen::parameter_column(C::param_names, "g")});
    // The linearized rod x δx + y δy = l δl holds at the end: S stayed on the constraints' tangent.
    const double x = r.x(0), y = r.x(1);
    CHECK(std::abs(x * r.S(0, 0) + y * r.S(1, 0) - l) < 1e-8);
    CHECK(std::abs(x * r.S(0, 1) + y * r.S(1, 1)) < 1e-8);

    // A rheonomic constraint, phi = w t: w moves phi_dot's start (1 per unit), phi's own start cannot move.
    using H = eomgen::models::hoop_driven::Model<double>;
    H::Params q;
    H::State z0;
    z0 << 0.5, 0.0, 2.0, H::param_values(q)[2];  // a = 0 is where the coordinates are singular: start off it
    const auto h = check_columns<H>(q, z0, 1.5,
                                    {eomgen::parameter_column(H::param_names, "w"),
                                     eomgen::initial_column(H::state_names, "a"),
                                     eomgen::initial_column(H::state_names, "phi"),
                                     eomgen::initial_column(H::state_names, "a_dot")});
    CHECK(std::abs(h.S(1, 0) - 1.5) < 1e-9);  // d phi(t)/dw = t
    CHECK(h.S.col(2).cwiseAbs().maxCoeff() < 1e-12);
}

TEST_CASE("the sensitivities jump by the saltation matrix where the hinge friction turns", "[sensitivities]") {
    using F = eomgen::models::friction_door::Model<double>;
    F::Params p;
    p.tau_f = 0.8;  // light enough for the door to swing back twice before it sticks (near t = 17 s)
    F::State x0;
    x0 << 0.3, -0.5;  // swinging down, through psi = -pi/2, and back: sign(psi') turns at each reversal
    std::vector<SensitivityColumn> columns;
    for (const char* name : {"theta", "tau_f", "w"}) columns.push_back(eomgen::parameter_column(F::param_names, name));
    columns.push_back(eomgen::initial_column(F::state_names, "psi"));
    columns.push_back(eomgen::initial_column(F::state_names, "psi_dot"));
    const auto r = check_columns<F>(p, x0, 12.0, columns);
    REQUIRE(r.switches.size() >= 2);
    INFO("reversals at t = " << r.switches[0].second << ", " << r.switches[1].second);
    CHECK(r.switches[0].first == "sign(psi')");
    // S jumps there (by O(1), not O(the 2e-6 between the samples)): the agreement above needs the saltation.
    const double ts = r.switches[0].second;
    eomgen::Dop853Options<double> o;
    o.rtol = kRtol;
    o.atol = kAtol;
    const auto around = eomgen::integrate_sensitivities<F, eomgen::Dop853>(p, 0.0, x0, ts + 1e-6, columns, o, {},
                                                                           {ts - 1e-6, ts + 1e-6});
    REQUIRE(around.samples.size() == 2);
    const Eigen::MatrixXd jump = around.samples[1].S - around.samples[0].S;
    INFO("S before the reversal:\n" << around.samples[0].S << "\nafter:\n" << around.samples[1].S);
    CHECK(jump.row(1).cwiseAbs().maxCoeff() > 1e-2 * around.samples[0].S.row(1).cwiseAbs().maxCoeff());

}

TEST_CASE("a motion that sticks on a switching surface is followed along it, and where it slips off again",
          "[sensitivities]") {
    // The door held by its hinges' static friction from about t = 8.03 s: ψ stays, ψ̇ = 0, and so do their
    // derivatives (ψ̇'s are 0: every perturbed door is held too).
    using F = eomgen::models::friction_door::Model<double>;
    F::Params p;
    p.tau_f = 2.5;  // more than gravity's torque near the turning point: static friction holds the door there
    F::State x0;
    x0 << -1.2, 0.8;
    std::vector<SensitivityColumn> door;
    for (const char* name : {"theta", "tau_f", "w"}) door.push_back(eomgen::parameter_column(F::param_names, name));
    for (const char* name : F::state_names) door.push_back(eomgen::initial_column(F::state_names, name));
    const auto held = check_columns<F>(p, x0, 12.0, door);
    REQUIRE(held.switches.size() >= 1);
    CHECK(held.switches.back().first == "sign(psi'): slides");
    CHECK(held.switches.back().second == Approx(8.026).margin(1e-3));
    CHECK(held.S.row(1).cwiseAbs().maxCoeff() < 1e-12);
    // The block on a belt: dragged up to the belt's speed, carried with it (stuck from t = 0.179 s), and slipping
    // back when the spring outpulls the friction (t = 0.676 s). Every parameter and both initial values, to t = 2 s
    // (after it, the undamped block only grazes the belt's speed once a period, where no derivative exists).
    using B = eomgen::models::block_on_belt::Model<double>;
    std::vector<SensitivityColumn> block;
    for (const char* name : B::param_names) block.push_back(eomgen::parameter_column(B::param_names, name));
    for (const char* name : B::state_names) block.push_back(eomgen::initial_column(B::state_names, name));
    const auto belt = check_columns<B>(B::Params{}, B::default_state(), 2.0, block);
    const auto when = [](const eomgen::SensitivityResult& r, const std::string& name) {
        std::vector<double> t;
        for (const auto& [n, at] : r.switches)
            if (n == name) t.push_back(at);
        return t;
    };
    const std::vector<double> slides = when(belt, "sign(v - x'): slides"),
                              leaves = when(belt, "sign(v - x'): leaves to s > 0");
    REQUIRE(slides.size() == 1);
    REQUIRE(leaves.size() == 1);
    CHECK(slides[0] == Approx(0.179357449149907).epsilon(1e-9));  // eomgen run's times for the same motion
    CHECK(leaves[0] == Approx(0.675794716081633).epsilon(1e-9));
    CHECK(when(belt, "sign(v - x'): grazes").empty());  // its arrival and exit touch the surface: no grazes
    CHECK(when(held, "sign(psi'): grazes").empty());
    // Released at the belt's speed: stuck from the start, S made tangent to the surface there. While it is carried,
    // x = x(0) + v t whatever the rest: ∂x/∂v = t, ∂x/∂x(0) = 1, ∂ẋ/∂v = 1, every other entry 0 (a changed ẋ(0)
    // is caught again at once, moving x only to second order; differences, which see that, are no reference here).
    B::State on = B::default_state();
    on(1) = B::Params{}.v;
    eomgen::Dop853Options<double> o;
    o.rtol = kRtol;
    o.atol = kAtol;
    const auto start = eomgen::integrate_sensitivities<B, eomgen::Dop853>(B::Params{}, 0.0, on, 0.3, block, o);
    const std::vector<double> from = when(start, "sign(v - x'): slides");
    REQUIRE(from.size() == 1);
    CHECK(from[0] == 0.0);
    Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(2, 7);
    expected(0, 4) = 0.3;  // v
    expected(1, 4) = 1;
    expected(0, 5) = 1;  // x(0)
    INFO("S =\n" << start.S);
    CHECK((start.S - expected).cwiseAbs().maxCoeff() < 1e-12);
}

TEST_CASE("a constrained motion that sticks is followed along its surface on the constraints", "[sensitivities]") {
    // The driven pendulum with pivot friction on a rod, in Cartesian coordinates: held from the start (gravity's
    // 1.56 N m is below the friction's 2.5), let go by the drive, held and let go again; the differences follow each
    // perturbed motion's sticking the same way. (exam_constrained_sticking.cpp checks it against its angle.)
    using C = eomgen::models::friction_pendulum_cartesian::Model<double>;
    std::vector<SensitivityColumn> columns;
    for (const char* name : {"tau_f", "A", "g"}) columns.push_back(eomgen::parameter_column(C::param_names, name));
    columns.push_back(eomgen::initial_column(C::state_names, "x"));
    const auto r = check_columns<C>(C::Params{}, C::default_state(), 5.0, columns);
    int slides = 0;
    for (const auto& [name, at] : r.switches) {
        slides += name == "sign(x*y' - y*x'): slides" ? 1 : 0;
        CHECK(name.find("grazes") == std::string::npos);
    }
    CHECK(slides >= 2);
}

TEST_CASE("a touch of a switching surface that crosses nothing is reported as a graze", "[sensitivities]") {
    // The block that slipped off the belt at t1 = 0.675794716 s left it tangentially (ẋ = v, ẍ = 0) and, undamped,
    // comes back to the belt's speed exactly so one period 2π/√(k/m) later: ẋ touches v without crossing it.
    using B = eomgen::models::block_on_belt::Model<double>;
    eomgen::Dop853Options<double> o;
    o.rtol = kRtol;
    o.atol = kAtol;
    const auto r = eomgen::integrate_sensitivities<B, eomgen::Dop853>(
        B::Params{}, 0.0, B::default_state(), 3.0, {eomgen::parameter_column(B::param_names, "mu")}, o);
    std::vector<double> grazes;
    for (const auto& [name, at] : r.switches) {
        INFO(name << " at t = " << at);
        CHECK(name.find("touches") == std::string::npos);  // the watch's own events are not reported
        if (name == "sign(v - x'): grazes") grazes.push_back(at);
    }
    REQUIRE(grazes.size() == 1);
    const double period = 2 * M_PI / std::sqrt(B::Params{}.k / B::Params{}.m);
    CHECK(grazes[0] == Approx(0.675794716081633 + period).epsilon(1e-7));
    // In time order: the crossing where it arrives, slides, leaves, grazes.
    REQUIRE(r.switches.size() == 4);
    CHECK(std::is_sorted(r.switches.begin(), r.switches.end(),
                         [](const auto& a, const auto& b) { return a.second < b.second; }));
}

TEST_CASE("a graze of a kink is no graze of a jump", "[sensitivities]") {
    // sin(t) touches x = a = 1 at t = π/2: where the force beyond it is continuous (c_kink max(x − a, 0)) nearby motions
    // still have a derivative and nothing is reported; where it jumps (c_jump > 0) the graze is.
    using G = eomgen::models::grazing_oscillator::Model<double>;
    static_assert(G::n_switches == 1, "max(x - a, 0) and heaviside(a - x) switch on one surface");
    eomgen::Dop853Options<double> o;
    o.rtol = kRtol;
    o.atol = kAtol;
    const auto grazes = [&](const G::Params& p) {
        const auto r = eomgen::integrate_sensitivities<G, eomgen::Dop853>(
            p, 0.0, G::default_state(), 2.0, {eomgen::parameter_column(G::param_names, "a")}, o);
        std::vector<double> t;
        for (const auto& [name, at] : r.switches)
            if (name == std::string(G::switch_names[0]) + ": grazes") t.push_back(at);  // one surface: x = a
        return t;
    };
    G::Params kink;
    CHECK(grazes(kink).empty());
    G::Params jump;
    jump.c_jump = 0.5;
    const std::vector<double> at = grazes(jump);
    REQUIRE(at.size() == 1);
    CHECK(at[0] == Approx(M_PI / 2).epsilon(1e-8));
}

TEST_CASE("what the sensitivities refuse at switching surfaces", "[sensitivities]") {
    using F = eomgen::models::friction_door::Model<double>;
    F::Params p;
    F::State x0;
    x0 << -1.2, 0.8;
    // radau5 does not end its steps at the surfaces.
    CHECK_THROWS_WITH(eomgen::integrate_sensitivities_radau5<F>(p, 0.0, x0, 1.0,
                                                                {eomgen::parameter_column(F::param_names, "theta")}),
                      Catch::Contains("use dopri5, dop853 or adams"));
    // A constrained model's start must be on its constraints.
    using C = eomgen::models::pendulum_cartesian::Model<double>;
    C::State off = C::default_state();
    off(0) += 0.1;
    CHECK_THROWS_AS((eomgen::integrate_sensitivities<C, eomgen::Dop853>(
                        C::Params{}, 0.0, off, 1.0, {eomgen::parameter_column(C::param_names, "g")})),
                    eomgen::InconsistentInitialConditions);
}
