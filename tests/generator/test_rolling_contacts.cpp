/** @file test_rolling_contacts.cpp  Bodies oriented by chains of rotations (after another body's) and placed at a
 *  point of another body, and wheels rolling on a plane ([[contacts]]) against hand-written constraints. */
#include "test_paths.hpp"
#include "mechanics/double_evaluator.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model_file.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include <random>
#include <string>

namespace {

const char* kHeader = R"~(
name = "disc"
[[coordinates]]
name = "x"
[[coordinates]]
name = "y"
[[coordinates]]
name = "phi"
[[coordinates]]
name = "theta"
initial = 0.3
[[coordinates]]
name = "psi"
[[parameters]]
name = "m"
value = 1.3
[[parameters]]
name = "R"
value = 0.4
[[parameters]]
name = "g"
value = 9.81
[gravity]
vector = ["0", "0", "-g"]
)~";

/// A coin on the ground as models/rolling_disc.toml has it (centre (x, y, 0) + R u, u = cos θ z + sin θ (sin φ,
/// −cos φ, 0), axis n = e_t × u), written as a body whose axis is its y and a rolling contact.
std::string contact_disc(const std::string& orientation = R"~([["z", "phi"], ["x", "theta"], ["y", "-psi"]])~") {
    return std::string(kHeader) + R"~(
[[bodies]]
name = "coin"
mass = "m"
inertia = ["m*R^2/4", "m*R^2/2", "m*R^2/4"]
position = ["x + R*sin(theta)*sin(phi)", "y - R*sin(theta)*cos(phi)", "R*cos(theta)"]
orientation = )~" + orientation + R"~(

[[contacts]]
name = "ground"
body = "coin"
radius = "R"
axis = "y"
)~";
}

/// q'' at a state from M q'' = f + Aᵀλ, A q'' = γ (values of the parameters from the model).
Eigen::VectorXd accelerations(const eomgen::Model& model, const eomgen::Equations& eq, const Eigen::VectorXd& q,
                              const Eigen::VectorXd& qd) {
    eomgen::SymbolValues v;
    for (const eomgen::Parameter& p : model.parameters) v[p.symbol] = p.value;
    for (std::size_t i = 0; i < model.dof(); ++i)
        v[model.coordinates[i].q] = q(Eigen::Index(i)), v[model.coordinates[i].qd] = qd(Eigen::Index(i));
    v[model.t] = 0;
    eomgen::DoubleEvaluator at(v);
    const auto n = Eigen::Index(model.dof()), m = Eigen::Index(eq.constraints.size());
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + m, n + m);
    Eigen::VectorXd r(n + m);
    for (Eigen::Index i = 0; i < n; ++i) {
        r(i) = *at(eq.f[std::size_t(i)]);
        for (Eigen::Index j = 0; j < n; ++j) K(i, j) = *at(eq.M(unsigned(i), unsigned(j)));
    }
    for (Eigen::Index k = 0; k < m; ++k) {
        r(n + k) = *at(eq.constraints[std::size_t(k)].gamma);
        for (Eigen::Index j = 0; j < n; ++j) K(n + k, j) = K(j, n + k) = *at(eq.constraints[std::size_t(k)].jacobian[std::size_t(j)]);
    }
    for (Eigen::Index k = 0; k < m; ++k)
        for (Eigen::Index j = 0; j < n; ++j) K(j, n + k) = -K(j, n + k);
    return K.fullPivLu().solve(r).head(n);
}

}  // namespace

TEST_CASE("rolling contact: a coin as a body and a contact moves as the hand-written rolling disc", "[rolling][bodies]") {
    const eomgen::Model hand = eomgen::load_model(eomgen_test::source_dir() + "/models/rolling_disc.toml");
    const eomgen::Model body = eomgen::parse_model(contact_disc(), "coin.toml");
    // The contact point is the coordinates' (x, y): touching holds identically and is left out.
    REQUIRE(body.constraints.size() == 2);
    CHECK(body.constraints[0].name == "ground_slip_x");
    CHECK(body.constraints[1].name == "ground_slip_y");
    CHECK(body.constraints[0].kind == eomgen::ConstraintKind::Nonholonomic);
    const eomgen::Equations eh = eomgen::derive_equations(hand), eb = eomgen::derive_equations(body);
    std::mt19937 random(5);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 5; ++trial) {
        // Same parameters in both: the hand model's m = 1, R = 0.1 taken over.
        Eigen::VectorXd q(5), qd(5);
        for (int i = 0; i < 5; ++i) q(i) = u(random), qd(i) = 3 * u(random);
        q(3) = 0.2 + 0.5 * u(random);  // lean away from flat
        const double R = 0.1;
        qd(0) = -R * qd(4) * std::cos(q(2));  // rolling: x' = −R ψ' cos φ, y' = −R ψ' sin φ
        qd(1) = -R * qd(4) * std::sin(q(2));
        eomgen::Model b = body;
        for (eomgen::Parameter& p : b.parameters) p.value = p.name == "m" ? 1.0 : p.name == "R" ? R : p.value;
        const Eigen::VectorXd a = accelerations(hand, eh, q, qd), c = accelerations(b, eb, q, qd);
        CHECK((a - c).norm() < 1e-10 * (1 + a.norm()));
    }
}

TEST_CASE("rolling contact: the touching constraint where the coordinates do not keep the wheel down", "[rolling][bodies]") {
    // The centre (x, y, z) free: touching is a holonomic constraint, z = R sin of the axis' angle from the normal.
    std::string text = contact_disc();
    const std::string from = R"~(position = ["x + R*sin(theta)*sin(phi)", "y - R*sin(theta)*cos(phi)", "R*cos(theta)"])~";
    text.replace(text.find(from), from.size(), R"~(position = ["x", "y", "R*cos(theta) + 0*x"])~");
    const eomgen::Model free_centre = eomgen::parse_model(text, "coin.toml");
    // Still identically touching: z was written as R cos θ.
    CHECK(free_centre.constraints.size() == 2);
    text.replace(text.find("R*cos(theta) + 0*x"), 18, "R*cos(theta) + x/10");
    const eomgen::Model lifted = eomgen::parse_model(text, "coin.toml");
    REQUIRE(lifted.constraints.size() == 3);
    CHECK(lifted.constraints[0].name == "ground_height");
    CHECK(lifted.constraints[0].kind == eomgen::ConstraintKind::Holonomic);
    // A parameter that is 0 in the file does not hide the constraint: --set lift=0.1 would lift the coin.
    std::string with_lift = contact_disc();
    with_lift.replace(with_lift.find(from), from.size(), R"~(position = ["x", "y", "R*cos(theta) + lift"])~");
    with_lift.replace(with_lift.find("[[parameters]]\nname = \"g\""), 0, "[[parameters]]\nname = \"lift\"\nvalue = 0\n");
    CHECK(eomgen::parse_model(with_lift, "coin.toml").constraints.size() == 3);
    // height = n·C − R √(1 − (n·a)²) = x/10 at any lean (n·a = sin θ sin... of the axis).
    eomgen::SymbolValues v;
    for (const eomgen::Parameter& p : lifted.parameters) v[p.symbol] = p.value;
    for (const eomgen::Coordinate& c : lifted.coordinates) v[c.q] = 0.37;
    eomgen::DoubleEvaluator at(v);
    CHECK(*at(lifted.constraints[0].expr.expr) == Approx(0.037).margin(1e-14));
}

TEST_CASE("bodies: a chain of rotations gives the Euler angles' energies, and relative placement", "[bodies]") {
    const std::string euler = std::string(kHeader) + R"~(
[[bodies]]
name = "top"
mass = "m"
inertia = ["m", "2*m", "3*m"]
position = ["x", "y", "R*theta"]
orientation = ["phi", "theta", "psi"]
sequence = "zxz"
)~";
    std::string chain = euler;
    chain.replace(chain.find(R"~(orientation = ["phi", "theta", "psi"])~"), 38, R"~(orientation = [["z", "phi"], ["x", "theta"], ["z", "psi"]])~");
    chain.replace(chain.find("sequence = \"zxz\"\n"), 17, "");
    const eomgen::Model am = eomgen::parse_model(euler, "a.toml"), cm = eomgen::parse_model(chain, "b.toml");
    REQUIRE(cm.bodies[0].rotations.size() == 3);
    const eomgen::Equations a = eomgen::derive_equations(am), b = eomgen::derive_equations(cm);
    // The two models' symbols are their own: compare the values at the same random states.
    std::mt19937 random(11);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 4; ++trial) {
        eomgen::SymbolValues va, vb;
        for (std::size_t i = 0; i < am.parameters.size(); ++i)
            va[am.parameters[i].symbol] = vb[cm.parameters[i].symbol] = am.parameters[i].value;
        for (std::size_t i = 0; i < am.dof(); ++i) {
            va[am.coordinates[i].q] = vb[cm.coordinates[i].q] = u(random);
            va[am.coordinates[i].qd] = vb[cm.coordinates[i].qd] = u(random);
        }
        eomgen::DoubleEvaluator ea(va), eb(vb);
        CHECK(*ea(a.T) == Approx(*eb(b.T)).epsilon(1e-13));
    }

    // A second body at a point of the first, oriented after it: its centre is r + Aᵀ ρ.
    const std::string two = euler + R"~(
[[bodies]]
name = "arm"
mass = "m"
inertia = ["m", "m", "m"]
position = { body = "top", point = ["0", "0", "R"] }
orientation = { body = "top", rotations = [["y", "theta"]] }
)~";
    const eomgen::Model tm = eomgen::parse_model(two, "c.toml");
    REQUIRE(tm.bodies.size() == 2);
    // Body z of a z-x-z rotation in space axes: (sin θ sin φ, −sin θ cos φ, cos θ) (Goldstein (4.46)).
    const GiNaC::ex phi = tm.coordinates[2].q, theta = tm.coordinates[3].q, R = tm.parameters[1].symbol;
    CHECK(eomgen::is_zero(tm.bodies[1].centre[0] - (tm.coordinates[0].q + R * GiNaC::sin(theta) * GiNaC::sin(phi)), tm));
    CHECK(eomgen::is_zero(tm.bodies[1].centre[2] - (R * theta + R * GiNaC::cos(theta)), tm));
    REQUIRE(tm.bodies[1].rotations.size() == 4);
    CHECK(tm.bodies[1].rotations[3].axis == 'y');
}

TEST_CASE("rolling contact and relative bodies: mistakes are reported where they are", "[rolling][bodies]") {
    auto error = [](const std::string& text) {
        try {
            eomgen::parse_model(text, "m.toml");
        } catch (const eomgen::ModelError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    std::string t = contact_disc();
    t.replace(t.find("body = \"coin\"\nradius"), 13, "body = \"wheel\"");
    CHECK_THAT(error(t), Catch::Contains("m.toml:") && Catch::Contains("no body named 'wheel'"));
    t = contact_disc();
    t.replace(t.find("axis = \"y\""), 10, "axis = \"w\"");
    CHECK_THAT(error(t), Catch::Contains("a wheel's axis is \"x\", \"y\" or \"z\""));
    t = contact_disc();
    t.replace(t.find("axis = \"y\""), 10, "axis = \"y\"\nnormal = \"up\"");
    CHECK_THAT(error(t), Catch::Contains("a plane's normal is one of"));
    CHECK_THAT(error(contact_disc(R"~([["z", "phi"], ["q", "theta"]])~")), Catch::Contains("a rotation's axis is"));
    CHECK_THAT(error(contact_disc(R"~([["z", "phi"], ["x"]])~")), Catch::Contains("a rotation is a pair"));
    CHECK_THAT(error(contact_disc(R"~({ body = "later", rotations = [["x", "theta"]] })~")),
               Catch::Contains("no body named 'later' before this one"));
    CHECK_THAT(error(contact_disc(R"~([["z", "phi'"]])~")), Catch::Contains("without velocities"));
    // A wheel whose axis stays along the normal lies flat: no lowest point (found by the structural fuzzer, where
    // it was a division by zero from GiNaC).
    t = contact_disc(R"~([["z", "phi"]])~");
    t.replace(t.find("axis = \"y\""), 10, "axis = \"z\"");
    CHECK_THAT(error(t), Catch::Contains("m.toml:") && Catch::Contains("the wheel lies flat"));
}

TEST_CASE("rolling contact: a torus (a tyre) touches a tube's radius lower and rolls on radius R + rho upright",
          "[rolling][bodies]") {
    for (const bool torus : {false, true}) {
        std::string text = contact_disc();
        text.replace(text.find("[[parameters]]\nname = \"g\""), 0, "[[parameters]]\nname = \"rho\"\nvalue = 0.03\n");
        if (torus) {
            text.replace(text.find("\"R*cos(theta)\"]"), 15, "\"R*cos(theta) + rho\"]");
            text.replace(text.find("radius = \"R\""), 12, "radius = \"R\"\ntube = \"rho\"");
        }
        const eomgen::Model model = eomgen::parse_model(text, "tyre.toml");
        REQUIRE(model.constraints.size() == 2);  // the centre written from the contact point: touching holds
        // Upright (theta = 0), heading phi, spinning at psi' with the contact point at rest: the material point at
        // the contact moves at (R + rho) psi' along the heading, as x' + (R + rho) psi' cos(phi) = 0 says.
        eomgen::SymbolValues v;
        for (const eomgen::Parameter& p : model.parameters) v[p.symbol] = p.value;
        for (const eomgen::Coordinate& c : model.coordinates) v[c.q] = 0, v[c.qd] = 0;
        v[model.coordinates[2].q] = 0.3;
        v[model.coordinates[4].qd] = 2;
        eomgen::DoubleEvaluator at(v);
        const double rolling = 0.4 + (torus ? 0.03 : 0.0);
        CHECK(*at(model.constraints[0].expr.expr) == Approx(rolling * 2 * std::cos(0.3)).epsilon(1e-14));
        CHECK(*at(model.constraints[1].expr.expr) == Approx(rolling * 2 * std::sin(0.3)).epsilon(1e-14));
    }
}
