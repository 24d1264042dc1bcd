/** @file time_ode_peers.cpp  Work-precision: eomgen's integrators against Boost.Odeint, CVODE (Adams, BDF) and
 * ARKODE's highest-order explicit table whose order checks out, on three problems. */
// Usage: time_ode_peers [--quick] [--methods a,b,...]. One JSON object per line on stdout:
//   {"kind": "order", "table", "nominal", "observed", "slopes", "verified"}       ARKODE's tables, fixed steps
//   {"kind": "run", "problem", "method", "rtol", "error", "rhs_evals", "steps", "seconds"}
// and the references' cross-checks on stderr. Problems (the generated right-hand sides, double):
//   door      closing time of models/door.toml from rest at psi = 0 to psi = -pi/2 (a terminal event, each
//             method locating it its own way); error = relative error against the closed form.
//   pendulum  models/pendulum_5_20.toml from (0.5, -0.3, 0.5, 2) to t = 10; error = max |x - x_ref| / max |x_ref|,
//             x_ref by RKF 7(8) in long double at 1e-19 (checked against eomgen's Dopri5 in long double).
//   chain20   `--family pendulum:n=20` from its default state (every link at 0.5 rad, at rest) to t = 2 (0.2 with
//             --quick); x_ref as above, checked against the same integration of bench/chain_recursion.hpp's
//             independent O(n) right-hand side.
// Methods: eomgen_* (the list kEomgenMethods below: one line per integrator of the runtime), odeint_dopri5
//   (make_dense_output(rtol, rtol, runge_kutta_dopri5); the door's crossing located on calc_state by Brent),
//   cvode_adams, cvode_bdf (dense direct linear solver, difference-quotient Jacobian), arkode_<table> (ERKStep;
//   CVODE and ARKODE locate the door's crossing with their own root finding and stop exactly at t_end otherwise).
//   atol = rtol throughout; right-hand-side evaluations are counted by a wrapper around f (so CVODE BDF's
//   difference-quotient Jacobian columns count too).
#include "chain_recursion.hpp"
#include "ode_problems.hpp"

#include "eomgen/integrate.hpp"
#include "eomgen/models/door.hpp"
#include "eomgen/models/pendulum_20.hpp"
#include "eomgen/models/pendulum_5_20.hpp"

#include <boost/numeric/odeint.hpp>

#if EOMGEN_BENCH_HAVE_SUNDIALS
#include <arkode/arkode_erkstep.h>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>
#endif

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace odeint = boost::numeric::odeint;
const double kPi = std::acos(-1.0);

/// One problem on Model<double>: from x0 at t = 0 to t_end, or (door) until x(0) falls through −π/2.
template <class Model>
struct Problem {
    const char* name;
    typename Model::State x0;
    double t_end;
    bool stop_at_door_shut;
    typename Model::Params p{};
};

template <class Model>
struct Run {
    double t = 0;  ///< where the run stopped (the door's closing time)
    typename Model::State x;
    std::size_t rhs_evals = 0, steps = 0;
};

// ---- eomgen ------------------------------------------------------------------------------------------------

/// eomgen::integrate_with<Stepper> (Dopri5: Dormand–Prince 5(4); Dop853: Dormand–Prince 8(5,3); Adams:
/// variable-order Adams–Bashforth–Moulton).
template <class Model, template <class> class Stepper>
Run<Model> eomgen_run(const Problem<Model>& pr, double rtol) {
    using State = typename Model::State;
    Run<Model> r;
    auto f = [&](const double& t, const State& x, State& xdot) {
        ++r.rhs_evals;
        Model::rhs(t, x, pr.p, xdot);
    };
    typename Stepper<State>::Options opt;
    opt.rtol = rtol;
    opt.atol = rtol;
    opt.max_steps = 100000000;
    std::vector<eomgen::Event<State>> events;
    if (pr.stop_at_door_shut)
        events.push_back({"shut", [](const double&, const State& x) { return x(0) + kPi / 2; },
                          eomgen::EventDirection::Falling, eomgen::EventAction::Stop});
    const auto res = eomgen::integrate_with<Stepper>(f, 0.0, pr.x0, pr.t_end, opt, events);
    r.t = res.t;
    r.x = res.x;
    r.steps = res.accepted_steps + res.rejected_steps;
    return r;
}

template <class Model>
using Method = Run<Model> (*)(const Problem<Model>&, double);

/// eomgen's integrators in the comparison, one line each (name as it appears in the table, the run).
template <class Model>
const std::vector<std::pair<std::string, Method<Model>>> kEomgenMethods = {
    {"eomgen_dopri5", &eomgen_run<Model, eomgen::Dopri5>},
    {"eomgen_dop853", &eomgen_run<Model, eomgen::Dop853>},
    {"eomgen_adams", &eomgen_run<Model, eomgen::Adams>},
};

// ---- Boost.Odeint --------------------------------------------------------------------------------------------

template <class Model>
Run<Model> odeint_dopri5(const Problem<Model>& pr, double rtol) {
    using S = std::array<double, Model::nx>;
    using State = typename Model::State;
    Run<Model> r;
    auto sys = [&](const S& x, S& dxdt, double t) {
        ++r.rhs_evals;
        State xd;
        Model::rhs(t, State(x.data()), pr.p, xd);
        for (int i = 0; i < Model::nx; ++i) dxdt[std::size_t(i)] = xd(i);
    };
    auto st = odeint::make_dense_output(rtol, rtol, odeint::runge_kutta_dopri5<S>());
    S x0;
    for (int i = 0; i < Model::nx; ++i) x0[std::size_t(i)] = pr.x0(i);
    st.initialize(x0, 0.0, 1e-3);  // odeint needs a first step; the others choose their own
    const auto g = [](const S& x) { return x[0] + kPi / 2; };
    S x;
    for (;;) {
        const auto [ta, tb] = st.do_step(sys);
        ++r.steps;
        if (pr.stop_at_door_shut && g(st.current_state()) < 0) {
            r.t = eomgen::bench::locate_crossing(st, ta, tb, g);
            st.calc_state(r.t, x);
            break;
        }
        if (!pr.stop_at_door_shut && tb >= pr.t_end) {
            st.calc_state(pr.t_end, x);
            r.t = pr.t_end;
            break;
        }
    }
    r.x = State(x.data());
    return r;
}

// ---- SUNDIALS ------------------------------------------------------------------------------------------------

#if EOMGEN_BENCH_HAVE_SUNDIALS

template <class Model>
struct SundialsUser {
    const Problem<Model>* pr;
    std::size_t rhs_evals = 0;
};

template <class Model>
int sundials_rhs(realtype t, N_Vector y, N_Vector ydot, void* user) {
    auto* u = static_cast<SundialsUser<Model>*>(user);
    ++u->rhs_evals;
    using State = typename Model::State;
    State xd;
    Model::rhs(t, State(NV_DATA_S(y)), u->pr->p, xd);
    std::copy(xd.data(), xd.data() + Model::nx, NV_DATA_S(ydot));
    return 0;
}

int door_shut(realtype, N_Vector y, realtype* g, void*) {
    g[0] = NV_Ith_S(y, 0) + kPi / 2;
    return 0;
}

/// A SUNDIALS context, state vector and the integrator's memory, freed together.
struct SundialsRun {
    SUNContext ctx = nullptr;
    N_Vector y = nullptr;
    SUNMatrix A = nullptr;
    SUNLinearSolver ls = nullptr;
    SUNNonlinearSolver nls = nullptr;
    void* mem = nullptr;
    void (*free_mem)(void**) = nullptr;
    SundialsRun(const double* x0, int n) {
        SUNContext_Create(nullptr, &ctx);
        y = N_VNew_Serial(n, ctx);
        std::copy(x0, x0 + n, NV_DATA_S(y));
    }
    ~SundialsRun() {
        if (mem) free_mem(&mem);
        if (ls) SUNLinSolFree(ls);
        if (nls) SUNNonlinSolFree(nls);
        if (A) SUNMatDestroy(A);
        N_VDestroy(y);
        SUNContext_Free(&ctx);
    }
};

void sundials_check(int flag, const char* what) {
    if (flag < 0) {
        std::fprintf(stderr, "SUNDIALS: %s failed (%d)\n", what, flag);
        std::exit(1);
    }
}

/// The run after CVode or ERKStepEvolve returned `flag` at t (exits with a message when it failed, or when the door
/// was to shut and no root was returned).
template <class Model>
Run<Model> sundials_result(const Problem<Model>& pr, const char* what, int flag, bool at_root, double t, long steps,
                           const SundialsUser<Model>& user, N_Vector y) {
    sundials_check(flag, what);
    if (pr.stop_at_door_shut && !at_root) {
        std::fprintf(stderr, "%s: the door did not shut\n", what);
        std::exit(1);
    }
    Run<Model> r;
    r.t = t;
    r.steps = std::size_t(steps);
    r.rhs_evals = user.rhs_evals;
    r.x = typename Model::State(NV_DATA_S(y));
    return r;
}

template <class Model, int Lmm>
Run<Model> cvode_run(const Problem<Model>& pr, double rtol) {
    SundialsUser<Model> user{&pr};
    SundialsRun s(pr.x0.data(), Model::nx);
    s.mem = CVodeCreate(Lmm, s.ctx);
    s.free_mem = CVodeFree;
    sundials_check(CVodeInit(s.mem, sundials_rhs<Model>, 0.0, s.y), "CVodeInit");
    sundials_check(CVodeSetUserData(s.mem, &user), "CVodeSetUserData");
    sundials_check(CVodeSStolerances(s.mem, rtol, rtol), "CVodeSStolerances");
    sundials_check(CVodeSetMaxNumSteps(s.mem, 100000000), "CVodeSetMaxNumSteps");
    if (Lmm == CV_BDF) {
        s.A = SUNDenseMatrix(Model::nx, Model::nx, s.ctx);
        s.ls = SUNLinSol_Dense(s.y, s.A, s.ctx);
        sundials_check(CVodeSetLinearSolver(s.mem, s.ls, s.A), "CVodeSetLinearSolver");
    } else {  // Adams for non-stiff problems: functional (fixed-point) iteration, no Jacobian
        s.nls = SUNNonlinSol_FixedPoint(s.y, 0, s.ctx);
        sundials_check(CVodeSetNonlinearSolver(s.mem, s.nls), "CVodeSetNonlinearSolver");
    }
    double tout = pr.t_end;
    if (pr.stop_at_door_shut) {
        int falling = -1;
        sundials_check(CVodeRootInit(s.mem, 1, door_shut), "CVodeRootInit");
        sundials_check(CVodeSetRootDirection(s.mem, &falling), "CVodeSetRootDirection");
    } else {
        sundials_check(CVodeSetStopTime(s.mem, pr.t_end), "CVodeSetStopTime");
    }
    double t = 0;
    const int flag = CVode(s.mem, tout, s.y, &t, CV_NORMAL);
    long steps = 0;
    CVodeGetNumSteps(s.mem, &steps);
    return sundials_result(pr, "CVode", flag, flag == CV_ROOT_RETURN, t, steps, user, s.y);
}

/// ERKStep with Butcher table `table`; fixed_h > 0: fixed steps of that size (the order check), else adaptive.
template <class Model>
Run<Model> arkode_run(const Problem<Model>& pr, double rtol, ARKODE_ERKTableID table, double fixed_h = 0) {
    SundialsUser<Model> user{&pr};
    SundialsRun s(pr.x0.data(), Model::nx);
    s.mem = ERKStepCreate(sundials_rhs<Model>, 0.0, s.y, s.ctx);
    s.free_mem = ERKStepFree;
    sundials_check(ERKStepSetUserData(s.mem, &user), "ERKStepSetUserData");
    ARKodeButcherTable B = ARKodeButcherTable_LoadERK(table);
    sundials_check(ERKStepSetTable(s.mem, B), "ERKStepSetTable");
    ARKodeButcherTable_Free(B);
    sundials_check(ERKStepSStolerances(s.mem, rtol, rtol), "ERKStepSStolerances");
    sundials_check(ERKStepSetMaxNumSteps(s.mem, 100000000), "ERKStepSetMaxNumSteps");
    if (fixed_h > 0) sundials_check(ERKStepSetFixedStep(s.mem, fixed_h), "ERKStepSetFixedStep");
    if (pr.stop_at_door_shut) {
        int falling = -1;
        sundials_check(ERKStepRootInit(s.mem, 1, door_shut), "ERKStepRootInit");
        sundials_check(ERKStepSetRootDirection(s.mem, &falling), "ERKStepSetRootDirection");
    } else {
        sundials_check(ERKStepSetStopTime(s.mem, pr.t_end), "ERKStepSetStopTime");
    }
    double t = 0;
    const int flag = ERKStepEvolve(s.mem, pr.t_end, s.y, &t, ARK_NORMAL);
    long steps = 0;
    ERKStepGetNumSteps(s.mem, &steps);
    return sundials_result(pr, "ERKStepEvolve", flag, flag == ARK_ROOT_RETURN, t, steps, user, s.y);
}

struct ErkTable {
    ARKODE_ERKTableID id;
    const char* name;
};

/// ARKODE 5.4's explicit tables of order ≥ 5, highest first.
const std::vector<ErkTable> kErkTables = {
    {ARKODE_FEHLBERG_13_7_8, "FEHLBERG_13_7_8"},         {ARKODE_VERNER_8_5_6, "VERNER_8_5_6"},
    {ARKODE_DORMAND_PRINCE_7_4_5, "DORMAND_PRINCE_7_4_5"}, {ARKODE_ARK548L2SAb_ERK_8_4_5, "ARK548L2SAb_ERK_8_4_5"},
};

#endif

// ---- problems and their references ---------------------------------------------------------------------------

using Door = eomgen::models::door::Model<double>;
using Pendulum = eomgen::models::pendulum_5_20::Model<double>;
using Chain = eomgen::models::pendulum_20::Model<double>;

template <class ModelL, std::size_t N = std::size_t(ModelL::nx)>
std::array<long double, N> generated_reference(const std::array<long double, N>& x0, long double t_end,
                                               long double tol) {
    const typename ModelL::Params p;
    return eomgen::bench::reference_end_state(
        [&](long double t, const std::array<long double, N>& x, std::array<long double, N>& xd) {
            typename ModelL::State xe, xde;
            for (std::size_t i = 0; i < N; ++i) xe(int(i)) = x[i];
            ModelL::rhs(t, xe, p, xde);
            for (std::size_t i = 0; i < N; ++i) xd[i] = xde(int(i));
        },
        x0, t_end, tol);
}

template <std::size_t N>
long double max_abs_difference(const std::array<long double, N>& a, const std::array<long double, N>& b) {
    long double d = 0;
    for (std::size_t i = 0; i < N; ++i) d = std::max(d, std::abs(a[i] - b[i]));
    return d;
}

template <class Model>
std::array<long double, Model::nx> as_long_double(const typename Model::State& x) {
    std::array<long double, Model::nx> out;
    for (int i = 0; i < Model::nx; ++i) out[std::size_t(i)] = x(i);
    return out;
}

template <class Model>
typename Model::State as_state(const std::array<long double, Model::nx>& x) {
    typename Model::State out;
    for (int i = 0; i < Model::nx; ++i) out(i) = double(x[std::size_t(i)]);
    return out;
}

/// The pendulum's reference, checked against eomgen's Dopri5 in long double at 1e-18 (stderr).
Pendulum::State pendulum_reference(const Problem<Pendulum>& pr) {
    using PendulumL = eomgen::models::pendulum_5_20::Model<long double>;
    const auto x0 = as_long_double<Pendulum>(pr.x0);
    const auto ref = generated_reference<PendulumL>(x0, pr.t_end, 1e-19L);
    const PendulumL::Params p;
    eomgen::Dopri5Options<long double> opt;
    opt.rtol = opt.atol = 1e-18L;
    opt.max_steps = 10000000;
    const auto check = eomgen::integrate(
        [&](const long double& t, const PendulumL::State& x, PendulumL::State& xd) { PendulumL::rhs(t, x, p, xd); },
        0.0L, pr.x0.cast<long double>().eval(), (long double)pr.t_end, opt);
    std::array<long double, 4> c;
    for (int i = 0; i < 4; ++i) c[std::size_t(i)] = check.x(i);
    std::fprintf(stderr, "pendulum reference: RKF78 (long double, 1e-19) vs eomgen Dopri5 (long double, 1e-18): %.1Le\n",
                 max_abs_difference(ref, c));
    return as_state<Pendulum>(ref);
}

/// The chain's reference, checked against RKF78 of the O(n) recursion (an independent right-hand side; stderr).
Chain::State chain_reference(const Problem<Chain>& pr) {
    using ChainL = eomgen::models::pendulum_20::Model<long double>;
    constexpr int n = Chain::nq;
    const auto x0 = as_long_double<Chain>(pr.x0);
    const auto ref = generated_reference<ChainL>(x0, pr.t_end, 1e-19L);
    const auto v = ChainL::param_values(ChainL::Params{});
    const std::vector<long double> m(v.begin(), v.begin() + n), l(v.begin() + n, v.begin() + 2 * n);
    const long double g = v[2 * n];
    const auto check = eomgen::bench::reference_end_state(
        [&](long double, const std::array<long double, 2 * n>& x, std::array<long double, 2 * n>& xd) {
            eomgen::bench::chain_rhs_recursive<n>(x.data(), m.data(), l.data(), g, xd.data());
        },
        x0, pr.t_end, 1e-18L);
    std::fprintf(stderr,
                 "chain20 reference: RKF78 (long double, 1e-19) vs RKF78 of the O(n) recursion (long double, 1e-18): "
                 "%.1Le\n",
                 max_abs_difference(ref, check));
    return as_state<Chain>(ref);
}

void print_run(const char* problem, const std::string& method, double rtol, double error, std::size_t evals,
               std::size_t steps, double seconds) {
    std::printf("{\"kind\": \"run\", \"problem\": \"%s\", \"method\": \"%s\", \"rtol\": %.3e, \"error\": %.3e, "
                "\"rhs_evals\": %zu, \"steps\": %zu, \"seconds\": %.4e}\n",
                problem, method.c_str(), rtol, error, evals, steps, seconds);
    std::fflush(stdout);
}

/// Every selected method at every tolerance on one problem; `error(run)` measures a run.
template <class Model, class Error>
void sweep(const Problem<Model>& pr, const std::vector<double>& tolerances, const std::set<std::string>& only,
           const std::string& arkode_name, [[maybe_unused]] int arkode_table, Error&& error) {
    std::vector<std::pair<std::string, std::function<Run<Model>(double)>>> methods;
    for (const auto& [name, run] : kEomgenMethods<Model>) methods.push_back({name, [&pr, run = run](double tol) { return run(pr, tol); }});
    methods.push_back({"odeint_dopri5", [&pr](double tol) { return odeint_dopri5<Model>(pr, tol); }});
#if EOMGEN_BENCH_HAVE_SUNDIALS
    methods.push_back({"cvode_adams", [&pr](double tol) { return cvode_run<Model, CV_ADAMS>(pr, tol); }});
    methods.push_back({"cvode_bdf", [&pr](double tol) { return cvode_run<Model, CV_BDF>(pr, tol); }});
    if (!arkode_name.empty())
        methods.push_back({arkode_name, [&pr, arkode_table](double tol) {
                               return arkode_run<Model>(pr, tol, ARKODE_ERKTableID(arkode_table));
                           }});
#endif
    for (double tol : tolerances)
        for (const auto& [name, run] : methods) {
            if (!only.empty() && !only.count(name)) continue;
            double seconds = 0;
            const Run<Model> r = eomgen::bench::timed([&, run = run] { return run(tol); }, seconds, 2);
            print_run(pr.name, name, tol, error(r), r.rhs_evals, r.steps, seconds);
        }
}

#if EOMGEN_BENCH_HAVE_SUNDIALS
/**
 * The observed order of one of ARKODE's tables on one problem: fixed steps h = t_end/4, t_end/8, ... against
 * the long-double reference `ref`, the slopes log2(e(h)/e(h/2)) while both errors stay above `floor` (round-off);
 * the observed order is the mean of the last two slopes.
 */
template <class Model>
double observed_order(const ErkTable& t, const Problem<Model>& pr, const typename Model::State& ref, double floor,
                      std::string& slopes_text) {
    std::vector<double> errors, slopes;
    for (int k = 2; k <= 12; ++k) {
        Run<Model> r;
        try {
            r = arkode_run<Model>(pr, 1e-6, t.id, std::ldexp(pr.t_end, -k));
        } catch (const std::exception&) {  // a step too large for stability: the next, smaller one
            continue;
        }
        errors.push_back((r.x - ref).cwiseAbs().maxCoeff() / ref.cwiseAbs().maxCoeff());
        if (errors.back() < floor) break;
    }
    std::ostringstream sl;
    for (std::size_t i = 1; i < errors.size(); ++i)
        if (errors[i] >= floor) {
            slopes.push_back(std::log2(errors[i - 1] / errors[i]));
            sl << (slopes.size() > 1 ? ", " : "") << std::setprecision(3) << slopes.back();
        }
    slopes_text = sl.str();
    return slopes.size() >= 2 ? (slopes[slopes.size() - 1] + slopes[slopes.size() - 2]) / 2 : std::nan("");
}

/**
 * Each of ARKODE's tables of nominal order ≥ 5, checked on the door (to t = 2, before it shuts) and the pendulum
 * (to t = 8). A table's order counts as verified when both problems show it to within 0.3 (a whole number, the
 * same on both); the peer is the table of the highest verified order (its nominal order is reported beside it).
 */
int check_arkode_orders(std::string& name) {
    using DoorL = eomgen::models::door::Model<long double>;
    using PendulumL = eomgen::models::pendulum_5_20::Model<long double>;
    const Problem<Door> door{"door", Door::State::Zero(), 2.0, false};
    const Door::State door_ref = as_state<Door>(generated_reference<DoorL>(as_long_double<Door>(door.x0), 2.0L, 1e-19L));
    const Problem<Pendulum> pendulum{"pendulum", Pendulum::State(0.5, -0.3, 0.5, 2.0), 8.0, false};
    const Pendulum::State pendulum_ref =
        as_state<Pendulum>(generated_reference<PendulumL>(as_long_double<Pendulum>(pendulum.x0), 8.0L, 1e-19L));
    int best = -1;
    int best_order = 0;
    for (const ErkTable& t : kErkTables) {
        ARKodeButcherTable B = ARKodeButcherTable_LoadERK(t.id);
        const int nominal = B->q;
        ARKodeButcherTable_Free(B);
        std::string door_slopes, pendulum_slopes;
        const double od = observed_order(t, door, door_ref, 1e-13, door_slopes);
        const double op = observed_order(t, pendulum, pendulum_ref, 1e-12, pendulum_slopes);
        const double whole = std::round(od);
        const bool consistent = std::abs(od - whole) <= 0.3 && std::abs(op - whole) <= 0.3;
        const int verified = consistent ? int(whole) : 0;
        std::printf("{\"kind\": \"order\", \"table\": \"%s\", \"nominal\": %d, \"door\": %.2f, \"door_slopes\": [%s], "
                    "\"pendulum\": %.2f, \"pendulum_slopes\": [%s], \"verified\": %d}\n",
                    t.name, nominal, od, door_slopes.c_str(), op, pendulum_slopes.c_str(), verified);
        if (verified > best_order) {
            best = int(t.id);
            best_order = verified;
            name = std::string("arkode_") + t.name;
        }
    }
    return best;
}
#endif

std::set<std::string> split(const std::string& list) {
    std::set<std::string> out;
    std::stringstream ss(list);
    for (std::string item; std::getline(ss, item, ',');)
        if (!item.empty()) out.insert(item);
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    bool quick = false;
    std::set<std::string> only;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--quick") == 0) {
            quick = true;
        } else if (std::strcmp(argv[i], "--methods") == 0 && i + 1 < argc) {
            only = split(argv[++i]);
        } else {
            std::fprintf(stderr, "usage: time_ode_peers [--quick] [--methods a,b,...]\n");
            return 2;
        }
    }
    std::vector<double> tolerances;
    for (int k = 8; k <= 28; k += quick ? 4 : 1) tolerances.push_back(std::pow(10.0, -k / 2.0));

    std::string arkode_name;
    int arkode_table = -1;
#if EOMGEN_BENCH_HAVE_SUNDIALS
    arkode_table = check_arkode_orders(arkode_name);
#else
    std::fprintf(stderr, "SUNDIALS not found when time_ode_peers was built: CVODE and ARKODE are not measured\n");
#endif

    const Door::Params dp;
    const double t_exact = eomgen::bench::door_closing_time(dp.w, dp.g, dp.theta);
    const Problem<Door> door{"door", Door::State::Zero(), 1000.0, true};
    sweep(door, tolerances, only, arkode_name, arkode_table,
          [&](const Run<Door>& r) { return std::abs(r.t - t_exact) / t_exact; });

    const Problem<Pendulum> pendulum{"pendulum", Pendulum::State(0.5, -0.3, 0.5, 2.0), 10.0, false};
    const Pendulum::State pref = pendulum_reference(pendulum);
    sweep(pendulum, tolerances, only, arkode_name, arkode_table, [&](const Run<Pendulum>& r) {
        return (r.x - pref).cwiseAbs().maxCoeff() / pref.cwiseAbs().maxCoeff();
    });

    const Problem<Chain> chain{"chain20", Chain::default_state(), quick ? 0.2 : 2.0, false};
    const Chain::State cref = chain_reference(chain);
    sweep(chain, tolerances, only, arkode_name, arkode_table, [&](const Run<Chain>& r) {
        return (r.x - cref).cwiseAbs().maxCoeff() / cref.cwiseAbs().maxCoeff();
    });
    return 0;
}
