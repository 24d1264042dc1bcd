/** @file check_generated_vs_symbolic.cpp  Generated C++ against the symbolic equations at random states. */
#include "test_paths.hpp"
#include "approx.hpp"

#include "eomgen/models/door.hpp"
#include "eomgen/models/pendulum.hpp"
#include "eomgen/models/pendulum_5_20.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model_file.hpp"

#include <catch2/catch.hpp>
#include <Eigen/Dense>

#include <random>
#include <string>

namespace {

/// A random state and parameter set, as GiNaC substitutions and as the generated Model's inputs.
template <class Model>
struct Sample {
    typename Model::Config q, qd;
    typename Model::Params params;
    double t = 0;
    GiNaC::exmap at;
};

template <class Model>
Sample<Model> random_sample(const eomgen::Model& model, std::mt19937& rng) {
    std::uniform_real_distribution<double> angle(-3.0, 3.0), rate(-2.0, 2.0), positive(0.5, 2.0);
    Sample<Model> s;
    s.t = positive(rng);
    s.at[model.t] = s.t;
    for (std::size_t i = 0; i < model.dof(); ++i) {
        s.q(Eigen::Index(i)) = angle(rng);
        s.qd(Eigen::Index(i)) = rate(rng);
        s.at[model.coordinates[i].q] = s.q(Eigen::Index(i));
        s.at[model.coordinates[i].qd] = s.qd(Eigen::Index(i));
    }
    for (const eomgen::Parameter& p : model.parameters) {
        const double v = positive(rng);
        REQUIRE(Model::set_param(s.params, p.name, v));
        s.at[p.symbol] = v;
    }
    return s;
}

double value(const GiNaC::ex& e, const GiNaC::exmap& at) {
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(at))).to_double();
}

template <class Model>
void check_model(const std::string& file) {
    const eomgen::Model model = eomgen::load_model(eomgen_test::source_dir() + "/models/" + file);
    const eomgen::Equations eq = eomgen::derive_equations(model);
    REQUIRE(Model::nq == int(model.dof()));
    std::mt19937 rng(20261121);
    for (int trial = 0; trial < 25; ++trial) {
        const Sample<Model> s = random_sample<Model>(model, rng);
        const int n = Model::nq;

        typename Model::MassMatrix M;
        typename Model::Config f, p, dLdq;
        Model::dynamics(s.t, s.q, s.qd, s.params, M, f);
        Model::momenta(s.t, s.q, s.qd, s.params, p);
        Model::lagrangian_gradient(s.t, s.q, s.qd, s.params, dLdq);
        Eigen::MatrixXd M_sym(n, n);
        Eigen::VectorXd f_sym(n), p_sym(n), g_sym(n);
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) M_sym(i, j) = value(eq.M(unsigned(i), unsigned(j)), s.at);
            f_sym(i) = value(eq.f[std::size_t(i)], s.at);
            p_sym(i) = value(eq.momenta[std::size_t(i)], s.at);
            g_sym(i) = value(eq.dLdq[std::size_t(i)], s.at);
        }
        const double fscale = f_sym.cwiseAbs().maxCoeff() + 1e-300;
        REQUIRE_THAT(Eigen::MatrixXd(M), eomgen::test::AllClose(M_sym, 1e-12));
        REQUIRE_THAT(Eigen::MatrixXd(f), eomgen::test::AllClose(f_sym, 1e-12, 1e-13 * fscale));
        REQUIRE_THAT(Eigen::MatrixXd(p), eomgen::test::AllClose(p_sym, 1e-12, 1e-14));
        REQUIRE_THAT(Eigen::MatrixXd(dLdq), eomgen::test::AllClose(g_sym, 1e-12, 1e-14));
        // mass_matrix() and forcing() alone agree with the shared dynamics().
        typename Model::MassMatrix M2;
        typename Model::Config f2;
        Model::mass_matrix(s.t, s.q, s.params, M2);
        Model::forcing(s.t, s.q, s.qd, s.params, f2);
        REQUIRE_THAT(Eigen::MatrixXd(M2), eomgen::test::AllClose(M_sym, 1e-12));
        REQUIRE_THAT(Eigen::MatrixXd(f2), eomgen::test::AllClose(f_sym, 1e-12, 1e-13 * fscale));

        // M is symmetric positive definite, and equals ∂²T/∂q̇² taken independently of the generator.
        REQUIRE((M - M.transpose()).norm() == 0.0);
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(M_sym);
        REQUIRE(es.eigenvalues().minCoeff() > 0);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const GiNaC::ex d2T = model.T.expr.diff(model.coordinates[std::size_t(i)].qd)
                                          .diff(model.coordinates[std::size_t(j)].qd);
                REQUIRE(M(i, j) == Approx(value(d2T, s.at)).epsilon(1e-12).margin(1e-14));
            }

        // rhs() solves M q̈ = f: its q̈ satisfies the symbolic Euler–Lagrange equations.
        typename Model::State x, xdot;
        x << s.q, s.qd;
        Model::rhs(s.t, x, s.params, xdot);
        REQUIRE_THAT(Eigen::MatrixXd(xdot.template head<Model::nq>()), eomgen::test::AllClose(s.qd, 0.0));
        GiNaC::exmap at = s.at;
        for (int i = 0; i < n; ++i) at[model.coordinates[std::size_t(i)].qdd] = xdot(n + i);
        for (int i = 0; i < n; ++i) {
            const double residual = value(eq.euler_lagrange[std::size_t(i)], at);
            REQUIRE(std::abs(residual) <= 1e-12 * (1 + fscale));
        }

        // Energies.
        const double T = value(eq.T, s.at), V = value(eq.V, s.at), h = value(eq.energy, s.at);
        REQUIRE(Model::kinetic_energy(s.t, s.q, s.qd, s.params) == Approx(T).epsilon(1e-12));
        REQUIRE(Model::potential_energy(s.t, s.q, s.qd, s.params) == Approx(V).epsilon(1e-12).margin(1e-13));
        REQUIRE(Model::lagrangian(s.t, s.q, s.qd, s.params) == Approx(T - V).epsilon(1e-12).margin(1e-13));
        REQUIRE(Model::energy(s.t, s.q, s.qd, s.params) == Approx(h).epsilon(1e-12).margin(1e-13));

        // Declared outputs: outputs() computes the model file's [outputs] expressions, in their order.
        typename Model::Outputs out;
        Model::outputs(s.t, s.q, s.qd, s.params, out);
        for (std::size_t k = 0; k < model.outputs.size(); ++k)
            REQUIRE(out(Eigen::Index(k)) ==
                    Approx(value(model.outputs[k].expr.expr, s.at)).epsilon(1e-12).margin(1e-14));
    }
    REQUIRE(Model::n_outputs == int(model.outputs.size()));
    for (std::size_t k = 0; k < model.outputs.size(); ++k)
        REQUIRE(std::string(Model::output_names[k]) == model.outputs[k].name);
}

}  // namespace

TEST_CASE("door: generated code equals the symbolic equations at random states", "[generated]") {
    REQUIRE(eomgen::models::door::Model<double>::n_outputs == 2);  // z_c, v_edge: a velocity in an output
    check_model<eomgen::models::door::Model<double>>("door.toml");
}

TEST_CASE("pendulum 5-20: generated code equals the symbolic equations at random states", "[generated]") {
    REQUIRE(eomgen::models::pendulum_5_20::Model<double>::n_outputs == 2);  // x_disk, y_disk
    check_model<eomgen::models::pendulum_5_20::Model<double>>("pendulum_5_20.toml");
}

TEST_CASE("a model without [outputs] has none, and an outputs() generic code can call", "[generated]") {
    using P = eomgen::models::pendulum::Model<double>;
    static_assert(P::n_outputs == 0 && P::output_names.size() == 0 && P::Outputs::RowsAtCompileTime == 0);
    P::Outputs out;
    P::outputs(0.0, P::Config::Constant(0.3), P::Config::Constant(0.1), P::Params{}, out);
    CHECK(out.size() == 0);
}

TEST_CASE("generated code runs in long double", "[generated]") {
    using LD = eomgen::models::pendulum_5_20::Model<long double>;
    using D = eomgen::models::pendulum_5_20::Model<double>;
    LD::State xl = LD::default_state(), dl;
    D::State xd = D::default_state(), dd;
    LD::rhs(0.0L, xl, LD::Params{}, dl);
    D::rhs(0.0, xd, D::Params{}, dd);
    for (int i = 0; i < D::nx; ++i) REQUIRE(double(dl(i)) == Approx(dd(i)).epsilon(1e-14).margin(1e-15));
}

TEST_CASE("a singular mass matrix throws instead of returning NaN", "[generated][runtime]") {
    using D = eomgen::models::door::Model<double>;
    D::Params p;
    p.w = 0;  // a door of no width has no moment of inertia
    D::State x = D::default_state(), xdot;
    REQUIRE_THROWS_AS(D::rhs(0.0, x, p, xdot), eomgen::SingularMassMatrix);
}
