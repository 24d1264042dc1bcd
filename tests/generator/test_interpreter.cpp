/** @file test_interpreter.cpp  The interpreter (generator/interpreter): a tape against GiNaC's own evaluation, and
 * every model file's interpreted table against its derived equations evaluated independently at random states. */
#include "interpreter/interpreted_table.hpp"
#include "interpreter/tape.hpp"
#include "mechanics/double_evaluator.hpp"
#include "model/model_file.hpp"
#include "test_paths.hpp"

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace eomgen;
using namespace eomgen::interpreter;

double ginac_value(const GiNaC::ex& e, const GiNaC::exmap& at) {
    const GiNaC::ex v = GiNaC::evalf(e.subs(at));
    REQUIRE(GiNaC::is_a<GiNaC::numeric>(v));
    return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

bool close(double a, double b, double tol) { return std::abs(a - b) <= tol * (1 + std::abs(b)); }

}  // namespace

TEST_CASE("a tape computes what GiNaC computes: each operation, rationals, powers, shared terms", "[interpreter]") {
    GiNaC::symbol a("a"), b("b"), x("x"), t("t");
    codegen::SymbolTable table;
    table.info = {{codegen::SymbolKind::Parameter, 0, "a", "a", "a", "p_.a"},
                  {codegen::SymbolKind::Parameter, 1, "b", "b", "b", "p_.b"},
                  {codegen::SymbolKind::Coordinate, 0, "x", "x", "x", "q_(0)"},
                  {codegen::SymbolKind::Time, 0, "t", "t", "t", "t"},
                  {codegen::SymbolKind::Constant, 0, "pi_", "pi", "\\pi", "pi"}};
    table.exprs = {a, b, x, t, GiNaC::Pi};
    const std::vector<GiNaC::ex> values = {
        a * GiNaC::sin(x) + b * GiNaC::cos(x) - GiNaC::numeric(3, 7) * GiNaC::pow(x, 5),
        GiNaC::tan(x / 3) + GiNaC::exp(-t) * GiNaC::log(a) - GiNaC::sqrt(b + x * x),
        GiNaC::asin(x / 2) + GiNaC::acos(x / 3) + GiNaC::atan(a * x) + GiNaC::atan2(x, -a),
        GiNaC::sinh(x) - GiNaC::cosh(t) * GiNaC::tanh(a), GiNaC::abs(x - b) + GiNaC::pow(a, GiNaC::numeric(3, 2)),
        GiNaC::pow(x + a, -2) - 1 / (a * b * x) + GiNaC::pow(a, x), GiNaC::Pi * a + 5, GiNaC::numeric(-2, 3),
        GiNaC::pow(GiNaC::sin(x) + a, 3) * GiNaC::pow(GiNaC::sin(x) + a, 4) + GiNaC::pow(b, GiNaC::numeric(-5, 2))};
    const Tape tape = record_tape(table, values);
    REQUIRE(tape.outputs.size() == values.size());
    std::vector<double> registers(static_cast<std::size_t>(tape.registers())), out(values.size());
    for (const std::vector<double>& point : {std::vector<double>{1.3, 0.7, 0.4, 0.25}, {2.1, 1.9, -1.2, 3.5}}) {
        std::copy(point.begin(), point.end(), registers.begin());
        registers[4] = M_PI;
        tape.run(registers.data(), out.data());
        const GiNaC::exmap at = {{a, point[0]}, {b, point[1]}, {x, point[2]}, {t, point[3]}};
        for (std::size_t k = 0; k < values.size(); ++k) {
            INFO("value " << k << ": " << values[k]);
            CHECK(close(out[k], ginac_value(values[k], at), 1e-13));
        }
    }
    // sin(x), in two of the values, is computed once, as the emitted code's sin_x is.
    CHECK(std::count_if(tape.code.begin(), tape.code.end(), [](const Instruction& i) { return i.op == TapeOp::Sin; }) == 1);
}

TEST_CASE("a tape's non-smooth functions take the runtime's values at their switching points", "[interpreter]") {
    GiNaC::symbol a("a"), x("x");
    codegen::SymbolTable table;
    table.info = {{codegen::SymbolKind::Parameter, 0, "a", "a", "a", "p_.a"},
                  {codegen::SymbolKind::Coordinate, 0, "x", "x", "x", "q_(0)"}};
    table.exprs = {a, x};
    GiNaC::exvector sign_args{x}, heaviside_args{x}, max_args{x, a}, min_args{x, a};
    const Tape tape = record_tape(table, {GiNaC::function(GiNaC::function::find_function("sign", 1), sign_args),
                                          GiNaC::function(GiNaC::function::find_function("heaviside", 1), heaviside_args),
                                          GiNaC::function(GiNaC::function::find_function("max", 2), max_args),
                                          GiNaC::function(GiNaC::function::find_function("min", 2), min_args)});
    std::vector<double> r(static_cast<std::size_t>(tape.registers())), out(4);
    auto at = [&](double av, double xv) {
        r[0] = av;
        r[1] = xv;
        tape.run(r.data(), out.data());
        return out;
    };
    CHECK(at(1, 0) == std::vector<double>{0, 0.5, 1, 0});
    CHECK(at(1, -2) == std::vector<double>{-1, 0, 1, -2});
    CHECK(at(1, 3) == std::vector<double>{1, 1, 3, 1});
}

TEST_CASE("every model file's interpreted functions agree with its equations at random states", "[interpreter][models]") {
    namespace fs = std::filesystem;
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(fs::path(eomgen_test::source_dir()) / "models"))
        if (e.path().extension() == ".toml") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    REQUIRE(files.size() >= 15);
    std::mt19937 rng(20261128);
    std::uniform_real_distribution<double> uniform(-1, 1);
    for (const fs::path& file : files) {
        INFO(file.filename().string());
        const Model model = parse_model(read_model_file(file.string()), file.string());
        const Equations eq = derive_equations(model);
        const InterpretedTable interpreted(interpret(model, eq));
        const ModelTable& table = interpreted.table();
        const int n = table.nq, np = table.n_params, nc = table.n_constraints;
        REQUIRE(n == static_cast<int>(model.dof()));
        std::vector<std::max_align_t> block(table.params_size / sizeof(std::max_align_t) + 1);
        table.init_params(block.data());
        std::vector<double> params(static_cast<std::size_t>(np));
        table.param_values(block.data(), params.data());
        for (int i = 0; i < np; ++i) CHECK(params[static_cast<std::size_t>(i)] == model.parameters[static_cast<std::size_t>(i)].value);
        if (np > 0) {  // --set reaches the tapes
            CHECK(table.set_param(block.data(), model.parameters[0].name.c_str(), 1.25 * params[0] + 0.5));
            CHECK_FALSE(table.set_param(block.data(), "no_such_parameter", 1));
            table.param_values(block.data(), params.data());
        }
        std::vector<double> x0(static_cast<std::size_t>(2 * n));
        table.default_state(x0.data());
        for (int i = 0; i < n; ++i) CHECK(x0[static_cast<std::size_t>(i)] == model.coordinates[static_cast<std::size_t>(i)].initial);

        int compared = 0;
        for (int attempt = 0; attempt < 20 && compared < 3; ++attempt) {
            std::vector<double> x(static_cast<std::size_t>(2 * n));
            for (double& v : x) v = uniform(rng);
            const double t = 0.3 + 0.1 * attempt;
            GiNaC::exmap at;
            for (int i = 0; i < np; ++i) at[model.parameters[static_cast<std::size_t>(i)].symbol] = params[static_cast<std::size_t>(i)];
            for (int i = 0; i < n; ++i) {
                at[model.coordinates[static_cast<std::size_t>(i)].q] = x[static_cast<std::size_t>(i)];
                at[model.coordinates[static_cast<std::size_t>(i)].qd] = x[static_cast<std::size_t>(n + i)];
            }
            at[model.t] = t;
            DoubleEvaluator value = DoubleEvaluator::at(at);
            Eigen::MatrixXd M(n, n);
            Eigen::VectorXd f(n);
            bool finite = true;
            for (int i = 0; i < n && finite; ++i) {
                const auto fi = value(eq.f[static_cast<std::size_t>(i)]);
                finite = fi.has_value();
                if (fi) f(i) = *fi;
                for (int j = 0; j < n && finite; ++j) {
                    const auto mij = value(eq.M(static_cast<unsigned>(i), static_cast<unsigned>(j)));
                    finite = mij.has_value();
                    if (mij) M(i, j) = *mij;
                }
            }
            if (!finite) continue;  // a state outside the model's domain (a square root of a negative number)
            std::vector<double> xdot(static_cast<std::size_t>(2 * n));
            if (table.rhs(t, x.data(), block.data(), xdot.data()) != kTableOk) continue;  // singular there
            ++compared;
            const double* q = x.data();
            const double* qd = x.data() + n;
            Eigen::MatrixXd Mt(n, n);
            REQUIRE(table.mass_matrix(t, q, block.data(), Mt.data()) == kTableOk);
            CHECK((Mt - M).norm() <= 1e-12 * (1 + M.norm()));
            const Eigen::Map<const Eigen::VectorXd> qdd(xdot.data() + n, n);
            for (int i = 0; i < n; ++i) CHECK(xdot[static_cast<std::size_t>(i)] == qd[i]);
            Eigen::VectorXd residual = M * qdd - f;
            if (nc > 0) {
                Eigen::MatrixXd A(nc, n);
                Eigen::VectorXd gamma(nc), g(nc), c(nc), lambda(nc);
                REQUIRE(table.constraints(t, q, qd, block.data(), A.data(), gamma.data()) == kTableOk);
                REQUIRE(table.constraint_residuals(t, q, qd, block.data(), g.data(), c.data()) == kTableOk);
                REQUIRE(table.multipliers(t, x.data(), block.data(), lambda.data()) == kTableOk);
                for (int k = 0; k < nc; ++k) {
                    const ConstraintEquations& ce = eq.constraints[static_cast<std::size_t>(k)];
                    CHECK(close(gamma(k), *value(ce.gamma), 1e-12));
                    CHECK(close(g(k), *value(ce.position), 1e-12));
                    CHECK(close(c(k), *value(ce.velocity), 1e-12));
                    for (int i = 0; i < n; ++i) CHECK(close(A(k, i), *value(ce.jacobian[static_cast<std::size_t>(i)]), 1e-12));
                }
                residual -= A.transpose() * lambda;
                const double a = model.baumgarte_alpha, b = model.baumgarte_beta;
                CHECK((A * qdd - (gamma - 2 * a * c - b * b * g)).norm() <= 1e-8 * (1 + gamma.norm() + A.norm() * qdd.norm()));
            }
            CHECK(residual.norm() <= 1e-8 * (1 + f.norm() + M.norm() * qdd.norm()));
            double h = 0;
            REQUIRE(table.energy(t, q, qd, block.data(), &h) == kTableOk);
            CHECK(close(h, *value(eq.energy), 1e-12));
            std::vector<double> out(static_cast<std::size_t>(std::max({n, table.n_conserved, table.n_outputs, 1})));
            REQUIRE(table.momenta(t, q, qd, block.data(), out.data()) == kTableOk);
            for (int i = 0; i < n; ++i) CHECK(close(out[static_cast<std::size_t>(i)], *value(eq.momenta[static_cast<std::size_t>(i)]), 1e-12));
            REQUIRE(table.lagrangian_gradient(t, q, qd, block.data(), out.data()) == kTableOk);
            for (int i = 0; i < n; ++i) CHECK(close(out[static_cast<std::size_t>(i)], *value(eq.dLdq[static_cast<std::size_t>(i)]), 1e-12));
            REQUIRE(table.conserved(t, q, qd, block.data(), out.data()) == kTableOk);
            for (int k = 0; k < table.n_conserved; ++k)
                CHECK(close(out[static_cast<std::size_t>(k)], *value(eq.conserved[static_cast<std::size_t>(k)].value), 1e-12));
            REQUIRE(table.outputs(t, q, qd, block.data(), out.data()) == kTableOk);
            for (int k = 0; k < table.n_outputs; ++k)
                CHECK(close(out[static_cast<std::size_t>(k)], *value(model.outputs[static_cast<std::size_t>(k)].expr.expr), 1e-12));
        }
        CHECK(compared == 3);
    }
}

namespace {

/// Central differences of f (R^m-valued, of the state x and the parameter block) by x_j and by parameter j.
template <class F>
Eigen::MatrixXd central(const ModelTable& table, std::vector<std::max_align_t> block, std::vector<double> x, int m, F f,
                        bool by_parameters) {
    const int n = by_parameters ? table.n_params : 2 * table.nq;
    Eigen::MatrixXd D(m, n);
    std::vector<double> values(static_cast<std::size_t>(table.n_params));
    table.param_values(block.data(), values.data());
    for (int j = 0; j < n; ++j) {
        double& z = by_parameters ? values[static_cast<std::size_t>(j)] : x[static_cast<std::size_t>(j)];
        const double z0 = z, h = 1e-6 * (1 + std::abs(z0));
        Eigen::VectorXd plus(m), minus(m);
        for (const auto& [sign, out] : {std::pair<double, Eigen::VectorXd*>{1, &plus}, {-1, &minus}}) {
            z = z0 + sign * h;
            if (by_parameters) table.set_param(block.data(), table.param_names[j], z);
            REQUIRE(f(x.data(), block.data(), out->data()) == kTableOk);
        }
        z = z0;
        if (by_parameters) table.set_param(block.data(), table.param_names[j], z0);
        D.col(j) = (plus - minus) / (2 * h);
    }
    return D;
}

bool near(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).norm() <= 1e-6 * (1 + b.norm()); }

}  // namespace

TEST_CASE("the interpreted Jacobians agree with central differences on every model file", "[interpreter][jacobian]") {
    namespace fs = std::filesystem;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> uniform(-1, 1);
    for (const auto& e : fs::directory_iterator(fs::path(eomgen_test::source_dir()) / "models")) {
        if (e.path().extension() != ".toml" || e.path().stem() == "whipple_bicycle") continue;  // the bicycle: its own case
        INFO(e.path().filename().string());
        const Model model = parse_model(read_model_file(e.path().string()), e.path().string());
        const InterpretedTable interpreted(interpret(model, derive_equations(model)));
        const ModelTable& table = interpreted.table();
        const int n = table.nq, nx = 2 * n, np = table.n_params, nc = table.n_constraints, no = table.n_outputs,
                  ns = table.n_switches;
        REQUIRE(table.jacobian);
        std::vector<std::max_align_t> block(table.params_size / sizeof(std::max_align_t) + 1);
        table.init_params(block.data());
        std::vector<double> x(static_cast<std::size_t>(nx));
        table.default_state(x.data());
        for (double& v : x) v += 0.3 * uniform(rng);  // near the model's own start: inside its domain
        const double t = 0.7;
        std::vector<double> xdot(static_cast<std::size_t>(nx));
        if (table.rhs(t, x.data(), block.data(), xdot.data()) != kTableOk) continue;
        auto rhs = [&](const double* xs, const void* p, double* out) { return table.rhs(t, xs, p, out); };
        Eigen::MatrixXd J(nx, nx), Jp(nx, np);
        REQUIRE(table.jacobian(t, x.data(), block.data(), J.data()) == kTableOk);
        REQUIRE(table.parameter_jacobian(t, x.data(), block.data(), Jp.data()) == kTableOk);
        CHECK(near(J, central(table, block, x, nx, rhs, false)));
        CHECK(near(Jp, central(table, block, x, nx, rhs, true)));
        if (no > 0) {
            Eigen::MatrixXd Yx(no, nx), Yp(no, np);
            REQUIRE(table.output_jacobian(t, x.data(), block.data(), Yx.data(), Yp.data()) == kTableOk);
            auto outputs = [&](const double* xs, const void* p, double* out) { return table.outputs(t, xs, xs + n, p, out); };
            CHECK(near(Yx, central(table, block, x, no, outputs, false)));
            CHECK(near(Yp, central(table, block, x, no, outputs, true)));
        }
        if (nc > 0) {
            Eigen::MatrixXd Lx(nc, nx), Lp(nc, np), Rx(2 * nc, nx), Rp(2 * nc, np);
            REQUIRE(table.multiplier_jacobian(t, x.data(), block.data(), Lx.data(), Lp.data()) == kTableOk);
            auto lambda = [&](const double* xs, const void* p, double* out) { return table.multipliers(t, xs, p, out); };
            CHECK(near(Lx, central(table, block, x, nc, lambda, false)));
            CHECK(near(Lp, central(table, block, x, nc, lambda, true)));
            REQUIRE(table.constraint_residual_jacobian(t, x.data(), block.data(), Rx.data(), Rp.data()) == kTableOk);
            auto residuals = [&](const double* xs, const void* p, double* out) {
                return table.constraint_residuals(t, xs, xs + n, p, out, out + nc);
            };
            CHECK(near(Rx, central(table, block, x, 2 * nc, residuals, false)));
            CHECK(near(Rp, central(table, block, x, 2 * nc, residuals, true)));
        }
        if (ns > 0) {
            Eigen::MatrixXd Sx(ns, nx), Sp(ns, np), St(ns, 1);
            REQUIRE(table.switching_jacobian(t, x.data(), block.data(), Sx.data(), Sp.data(), St.data()) == kTableOk);
            auto switching = [&](const double* xs, const void* p, double* out) { return table.switching(t, xs, xs + n, p, out); };
            CHECK(near(Sx, central(table, block, x, ns, switching, false)));
            CHECK(near(Sp, central(table, block, x, ns, switching, true)));
        }
    }
}

TEST_CASE("an interpreted model reports a singular mass matrix with the state, never a NaN", "[interpreter][errors]") {
    const Model model = parse_model(R"toml(name = "degenerate"
[[coordinates]]
name = "x"
initial = 0
[[parameters]]
name = "m"
value = 1
[lagrangian]
T = "m/2*x^2*x'^2"
V = "m*x"
)toml",
                                    "degenerate.toml");
    const InterpretedTable interpreted(interpret(model, derive_equations(model)));
    const ModelTable& table = interpreted.table();
    std::vector<std::max_align_t> block(table.params_size / sizeof(std::max_align_t) + 1);
    table.init_params(block.data());
    double x[2] = {0, 0}, xdot[2] = {0, 0};
    CHECK(table.rhs(0.5, x, block.data(), xdot) == kTableSingularMassMatrix);
    double t = 0;
    CHECK(std::string(table.error_message(&t)).find("mass matrix is singular") != std::string::npos);
    CHECK(t == 0.5);
    x[0] = 2;
    CHECK(table.rhs(0.5, x, block.data(), xdot) == kTableOk);
    CHECK(xdot[1] == Approx(-0.25));  // m x² x'' + m x x'² + m = 0 at x' = 0
}

TEST_CASE("interpreted tables of several models live at once, each with its own functions", "[interpreter]") {
    auto pendulum = [](double l) {
        return parse_model("name = \"p\"\n[[coordinates]]\nname = \"phi\"\ninitial = 0.5\n[[parameters]]\nname = \"l\"\nvalue = " +
                               std::to_string(l) + "\n[lagrangian]\nT = \"l^2*phi'^2/2\"\nV = \"-9.81*l*cos(phi)\"\n",
                           "p.toml");
    };
    std::vector<std::unique_ptr<InterpretedTable>> tables;
    for (int k = 1; k <= 3; ++k) {
        const Model m = pendulum(k);
        tables.push_back(std::make_unique<InterpretedTable>(interpret(m, derive_equations(m))));
    }
    for (int k = 1; k <= 3; ++k) {
        const ModelTable& table = tables[static_cast<std::size_t>(k - 1)]->table();
        std::vector<std::max_align_t> block(table.params_size / sizeof(std::max_align_t) + 1);
        table.init_params(block.data());
        double x[2], xdot[2];
        table.default_state(x);
        REQUIRE(table.rhs(0, x, block.data(), xdot) == kTableOk);
        CHECK(xdot[1] == Approx(-9.81 / k * std::sin(0.5)));
    }
}

TEST_CASE("the interpreted switching surfaces' derivatives, in t as well, against central differences", "[interpreter][jacobian]") {
    const Model model = parse_model(R"toml(name = "belt_block"
[[coordinates]]
name = "x"
initial = 0.2
rate = 0.1
[[parameters]]
name = "m"
value = 1.5
[[parameters]]
name = "k"
value = 4
[[parameters]]
name = "mu"
value = 0.3
[[parameters]]
name = "v"
value = 0.5
[[parameters]]
name = "w"
value = 2
[lagrangian]
T = "m/2*x'^2"
V = "k/2*x^2 + max(x - 1, 0)^2"
[forces]
x = "-mu*m*9.81*sign(x' - v*cos(w*t))"
)toml",
                                    "belt_block.toml");
    const InterpretedTable interpreted(interpret(model, derive_equations(model)));
    const ModelTable& table = interpreted.table();
    REQUIRE(table.n_switches >= 2);
    const int ns = table.n_switches, np = table.n_params;
    std::vector<std::max_align_t> block(table.params_size / sizeof(std::max_align_t) + 1);
    table.init_params(block.data());
    std::vector<double> x = {0.4, -0.2};
    const double t = 0.3;
    Eigen::MatrixXd Sx(ns, 2), Sp(ns, np), St(ns, 1);
    REQUIRE(table.switching_jacobian(t, x.data(), block.data(), Sx.data(), Sp.data(), St.data()) == kTableOk);
    auto at = [&](double time) {
        return [&table, time](const double* xs, const void* p, double* out) { return table.switching(time, xs, xs + 1, p, out); };
    };
    CHECK(near(Sx, central(table, block, x, ns, at(t), false)));
    CHECK(near(Sp, central(table, block, x, ns, at(t), true)));
    Eigen::VectorXd plus(ns), minus(ns);
    REQUIRE(at(t + 1e-6)(x.data(), block.data(), plus.data()) == kTableOk);
    REQUIRE(at(t - 1e-6)(x.data(), block.data(), minus.data()) == kTableOk);
    CHECK(near(St, (plus - minus) / 2e-6));
    CHECK(St.norm() > 0);  // the belt's speed changes with t
    // Away from the surfaces, rhs's Jacobian by the state is the smooth side's.
    Eigen::MatrixXd J(2, 2);
    REQUIRE(table.jacobian(t, x.data(), block.data(), J.data()) == kTableOk);
    auto rhs = [&](const double* xs, const void* p, double* out) { return table.rhs(t, xs, p, out); };
    CHECK(near(J, central(table, block, x, 2, rhs, false)));
}
