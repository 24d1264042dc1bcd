/** @file exam_bicycle.cpp  The Whipple bicycle from its model file (rigid bodies, two rolling contacts) linearized
 *  about upright straight running (eomgen modes --steady), against the benchmark of Meijaard, Papadopoulos, Ruina
 *  and Schwab (2007): its published matrices, eigenvalues and weave and capsize speeds, and its appendix's closed
 *  forms written out here independently, for the benchmark's parameters and for two sets of our own. */
#include "test_paths.hpp"
#include "mechanics/lagrangian.hpp"
#include "mechanics/steady_motion.hpp"
#include "mechanics/steady_sweep.hpp"
#include "model/model_file.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <string>

namespace {

/// The benchmark's 25 parameters (Table 1), by name.
using Parameters = std::map<std::string, double>;

Parameters benchmark_parameters() {
    const double pi = std::acos(-1.0);
    return {{"w", 1.02},     {"c", 0.08},      {"lambda", pi / 10}, {"g", 9.81},     {"rR", 0.3},
            {"mR", 2.0},     {"IRxx", 0.0603}, {"IRyy", 0.12},      {"xB", 0.3},     {"zB", -0.9},
            {"mB", 85.0},    {"IBxx", 9.2},    {"IByy", 11.0},      {"IBzz", 2.8},   {"IBxz", 2.4},
            {"xH", 0.9},     {"zH", -0.7},     {"mH", 4.0},         {"IHxx", 0.05892}, {"IHyy", 0.06},
            {"IHzz", 0.00708}, {"IHxz", -0.00756}, {"rF", 0.35},    {"mF", 3.0},     {"IFxx", 0.1405},
            {"IFyy", 0.28}};
}

struct Matrices {
    Eigen::Matrix2d M, C1, K0, K2;
};

/// Appendix A of the benchmark: M, C1, K0, K2 from the parameters through the total and front-assembly masses,
/// centres of mass and inertias (the wheels' I_zz = I_xx).
Matrices closed_form(const Parameters& P) {
    auto p = [&](const char* name) { return P.at(name); };
    const double w = p("w"), c = p("c"), la = p("lambda"), rR = p("rR"), rF = p("rF");
    const double mR = p("mR"), mB = p("mB"), mH = p("mH"), mF = p("mF");
    const double xB = p("xB"), zB = p("zB"), xH = p("xH"), zH = p("zH");
    const double mT = mR + mB + mH + mF;
    const double xT = (xB * mB + xH * mH + w * mF) / mT;
    const double zT = (-rR * mR + zB * mB + zH * mH - rF * mF) / mT;
    const double ITxx = p("IRxx") + p("IBxx") + p("IHxx") + p("IFxx") + mR * rR * rR + mB * zB * zB + mH * zH * zH + mF * rF * rF;
    const double ITxz = p("IBxz") + p("IHxz") - mB * xB * zB - mH * xH * zH + mF * w * rF;
    const double ITzz = p("IRxx") + p("IBzz") + p("IHzz") + p("IFxx") + mB * xB * xB + mH * xH * xH + mF * w * w;
    const double mA = mH + mF;
    const double xA = (xH * mH + w * mF) / mA, zA = (zH * mH - rF * mF) / mA;
    const double IAxx = p("IHxx") + p("IFxx") + mH * (zH - zA) * (zH - zA) + mF * (rF + zA) * (rF + zA);
    const double IAxz = p("IHxz") - mH * (xH - xA) * (zH - zA) + mF * (w - xA) * (rF + zA);
    const double IAzz = p("IHzz") + p("IFxx") + mH * (xH - xA) * (xH - xA) + mF * (w - xA) * (w - xA);
    const double sl = std::sin(la), cl = std::cos(la);
    const double uA = (xA - w - c) * cl - zA * sl;
    const double IAll = mA * uA * uA + IAxx * sl * sl + 2 * IAxz * sl * cl + IAzz * cl * cl;
    const double IAlx = -mA * uA * zA + IAxx * sl + IAxz * cl;
    const double IAlz = mA * uA * xA + IAxz * sl + IAzz * cl;
    const double mu = c / w * cl;
    const double SR = p("IRyy") / rR, SF = p("IFyy") / rF, ST = SR + SF;
    const double SA = mA * uA + mu * mT * xT;
    Matrices m;
    m.M << ITxx, IAlx + mu * ITxz, IAlx + mu * ITxz, IAll + 2 * mu * IAlz + mu * mu * ITzz;
    m.K0 << mT * zT, -SA, -SA, -SA * sl;
    m.K2 << 0, (ST - mT * zT) / w * cl, 0, (SA + SF * sl) / w * cl;
    m.C1 << 0, mu * ST + SF * cl + ITxz / w * cl - mu * mT * zT, -(mu * ST + SF * cl), IAlz / w * cl + mu * (SA + ITzz / w * cl);
    return m;
}

/// The eigenvalues of M q'' + v C1 q' + (g K0 + v^2 K2) q = 0, sorted by real part, then imaginary part.
std::vector<std::complex<double>> eigenvalues(const Matrices& m, double v, double g) {
    Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
    A.topRightCorner<2, 2>().setIdentity();
    A.bottomLeftCorner<2, 2>() = -m.M.inverse() * (g * m.K0 + v * v * m.K2);
    A.bottomRightCorner<2, 2>() = -m.M.inverse() * (v * m.C1);
    const Eigen::Vector4cd e = Eigen::EigenSolver<Eigen::Matrix4d>(A).eigenvalues();
    std::vector<std::complex<double>> out(e.data(), e.data() + 4);
    std::sort(out.begin(), out.end(), [](auto a, auto b) { return a.real() != b.real() ? a.real() < b.real() : a.imag() < b.imag(); });
    return out;
}

double relative(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff());
}

struct Bicycle {
    eomgen::Model model = eomgen::load_model(eomgen_test::source_dir() + "/models/whipple_bicycle.toml");
    eomgen::Equations eq = eomgen::derive_equations(model);
};

Bicycle& bicycle() {
    static Bicycle b;  // derived once for all the cases (a few seconds)
    return b;
}

eomgen::SteadyMotionOptions upright(const Bicycle& b, const Parameters& p, double v) {
    eomgen::SteadyMotionOptions o;
    for (const auto& [name, value] : p) o.set[name] = value;
    o.set["v"] = v;
    std::size_t thetaR = 0;
    while (b.model.coordinates[thetaR].name != "thetaR") ++thetaR;
    const eomgen::Parameter& pv = *std::find_if(b.model.parameters.begin(), b.model.parameters.end(),
                                                [](const eomgen::Parameter& x) { return x.name == "v"; });
    const eomgen::Parameter& pr = *std::find_if(b.model.parameters.begin(), b.model.parameters.end(),
                                                [](const eomgen::Parameter& x) { return x.name == "rR"; });
    o.rates.push_back({thetaR, -pv.symbol / pr.symbol, "thetaR_dot=-v/rR"});
    return o;
}

}  // namespace

TEST_CASE("bicycle: the benchmark's M, C1, K0, K2 from the model file to 1e-12", "[physics][bicycle]") {
    Bicycle& b = bicycle();
    eomgen::SteadyMotionSolver solver(b.model, b.eq);
    const eomgen::SteadyMotionOptions o = upright(b, benchmark_parameters(), 5.0);
    const eomgen::SteadyMotion s = solver.solve(o);
    // The reduction the benchmark has: roll and steer, the rear wheel's rate a decoupled speed, yaw ignorable.
    auto name = [&](std::size_t i) { return b.model.coordinates[i].name; };
    REQUIRE(s.decoupled);
    REQUIRE(s.second_order.size() == 2);
    CHECK(name(s.second_order[0]) == "phi");
    CHECK(name(s.second_order[1]) == "delta");
    REQUIRE(s.ignorable.size() == 1);
    CHECK(name(s.ignorable[0]) == "psi");
    REQUIRE(s.dependent.size() == 1);
    CHECK(name(s.dependent[0]) == "thetaB");
    CHECK(s.residual < 1e-10);

    const auto split = eomgen::split_by_speed(b.model, solver, o, s, "v");
    REQUIRE(split);
    CHECK(split->notes.empty());
    Eigen::Matrix2d M, C1, K0, K2;  // the paper's Table 2 (rounded to 14 digits)
    M << 80.81722, 2.31941332208709, 2.31941332208709, 0.29784188199686;
    C1 << 0, 33.86641391492494, -0.85035641456978, 1.68540397397560;
    K0 << -80.95, -2.59951685249872, -2.59951685249872, -0.80329488458618;
    K2 << 0, 76.59734589573222, 0, 2.65431523794604;
    CHECK(relative(s.M, M) < 1e-12);
    CHECK(relative(split->C1, C1) < 1e-12);
    CHECK(relative(split->K0, K0) < 1e-12);
    CHECK(relative(split->K2, K2) < 1e-12);
    const Matrices cf = closed_form(benchmark_parameters());
    CHECK(relative(s.M, cf.M) < 1e-12);
    CHECK(relative(split->C1, cf.C1) < 1e-12);
    CHECK(relative(split->K0, cf.K0) < 1e-12);
    CHECK(relative(split->K2, cf.K2) < 1e-12);

    // Eigenvalues at 5 m/s (the paper's Table 3 row): castor, weave pair, capsize.
    REQUIRE(s.eigenvalues.size() == 4);
    const std::complex<double> expected[4] = {{-14.07838969279822, 0}, {-0.77534188219585, -4.46486771378823},
                                              {-0.77534188219585, 4.46486771378823}, {-0.32286642900409, 0}};
    for (int k = 0; k < 4; ++k) CHECK(std::abs(s.eigenvalues(k) - expected[k]) < 1e-11);
    CHECK(s.stability == "stable");
    // The eigenvectors over [phi, delta, phi', delta']: (M l^2 + C l + K) x = 0 and the rates l x.
    REQUIRE(s.eigenvectors.rows() == 4);
    for (Eigen::Index k = 0; k < 4; ++k) {
        const std::complex<double> l = s.eigenvalues(k);
        const Eigen::Vector2cd x = s.eigenvectors.col(k).head<2>(), xd = s.eigenvectors.col(k).tail<2>();
        const Eigen::Vector2cd r = (s.M.cast<std::complex<double>>() * l * l + s.C.cast<std::complex<double>>() * l +
                                    s.K.cast<std::complex<double>>()) * x;
        CHECK(r.norm() < 1e-9 * s.K.norm() * x.norm());
        CHECK((xd - l * x).norm() < 1e-12 * (1 + std::abs(l)) * s.eigenvectors.col(k).norm());
    }
}

TEST_CASE("bicycle: eigenvalues from 0 to 10 m/s and the weave and capsize speeds", "[physics][bicycle]") {
    Bicycle& b = bicycle();
    eomgen::SteadyMotionSolver solver(b.model, b.eq);
    const eomgen::SteadyMotionOptions o = upright(b, benchmark_parameters(), 5.0);
    const eomgen::SteadyMotion s = solver.solve(o);
    const eomgen::SteadySweep sweep = eomgen::sweep_steady_motion(b.model, solver, o, s, "v", 0, 10, 11);
    const Matrices cf = closed_form(benchmark_parameters());
    for (std::size_t k = 0; k < sweep.values.size(); ++k) {
        const auto e = eigenvalues(cf, sweep.values[k], 9.81);
        REQUIRE(sweep.eigenvalues[k].size() == 4);
        for (int j = 0; j < 4; ++j) CHECK(std::abs(sweep.eigenvalues[k](j) - e[std::size_t(j)]) < 1e-10 * (1 + std::abs(e[std::size_t(j)])));
    }
    REQUIRE(sweep.changes.size() == 2);
    CHECK(std::abs(sweep.changes[0].value / 4.2923825363 - 1) < 1e-10);  // weave: unstable -> stable
    CHECK(sweep.changes[0].to == "stable");
    CHECK(std::abs(sweep.changes[1].value / 6.0242620154 - 1) < 1e-10);  // capsize: stable -> unstable
    CHECK(sweep.changes[1].to == "unstable");
}

TEST_CASE("bicycle: two parameter sets of our own against the appendix's closed forms", "[physics][bicycle]") {
    Bicycle& b = bicycle();
    eomgen::SteadyMotionSolver solver(b.model, b.eq);
    Parameters light = benchmark_parameters();
    for (const auto& [k, v] : Parameters{{"w", 1.1}, {"c", 0.06}, {"lambda", 0.3}, {"rR", 0.33}, {"mR", 2.5},
                                         {"IRxx", 0.07}, {"IRyy", 0.13}, {"xB", 0.35}, {"zB", -0.95}, {"mB", 70.0},
                                         {"IBxx", 8.0}, {"IByy", 10.0}, {"IBzz", 2.5}, {"IBxz", 2.1}, {"xH", 0.95},
                                         {"zH", -0.75}, {"mH", 4.5}, {"IHxx", 0.06}, {"IHyy", 0.07}, {"IHzz", 0.008},
                                         {"IHxz", -0.008}, {"rF", 0.31}, {"mF", 2.8}, {"IFxx", 0.13}, {"IFyy", 0.26}})
        light[k] = v;
    Parameters heavy_front = benchmark_parameters();  // a cargo bike's loaded fork, negative trail
    heavy_front["mH"] = 25, heavy_front["xH"] = 1.1, heavy_front["zH"] = -0.5, heavy_front["IHxx"] = 1.2,
    heavy_front["IHzz"] = 0.8, heavy_front["IHxz"] = 0.3, heavy_front["c"] = -0.02, heavy_front["lambda"] = 0.2;
    for (const Parameters* set : {&light, &heavy_front}) {
        const eomgen::SteadyMotionOptions o = upright(b, *set, 3.0);
        const eomgen::SteadyMotion s = solver.solve(o);
        const auto split = eomgen::split_by_speed(b.model, solver, o, s, "v");
        REQUIRE(split);
        const Matrices cf = closed_form(*set);
        CHECK(relative(s.M, cf.M) < 1e-12);
        CHECK(relative(split->C1, cf.C1) < 1e-12);
        CHECK(relative(split->K0, cf.K0) < 1e-12);
        CHECK(relative(split->K2, cf.K2) < 1e-12);
    }
}
