/** @file exam_constrained_modes.cpp  Small oscillations on a constraint manifold (constrained_equilibria.hpp):
 * a system written in redundant coordinates with holonomic constraints must have the equilibria, multipliers,
 * frequencies and shapes of the same system in independent coordinates (derived by hand here), and the A that
 * `eomgen modes` gives must be the generated rhs's Jacobian on the manifold's tangent space. */
#include "eomgen/models/pendulum_cartesian.hpp"
#include "mechanics/lagrangian.hpp"
#include "mechanics/small_oscillations.hpp"
#include "model/model_file.hpp"
#include "modes_support.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include <cmath>
#include <string>

namespace {

using modes_support::at;
using modes_support::derive;
using modes_support::Derived;

Eigen::MatrixXd matrix(const std::vector<std::vector<double>>& rows) {
    Eigen::MatrixXd m(Eigen::Index(rows.size()), Eigen::Index(rows.empty() ? 0 : rows[0].size()));
    for (std::size_t i = 0; i < rows.size(); ++i)
        for (std::size_t j = 0; j < rows[i].size(); ++j) m(Eigen::Index(i), Eigen::Index(j)) = rows[i][j];
    return m;
}

}  // namespace

TEST_CASE("modes with constraints: the Cartesian pendulum, both equilibria, the rod's tension and g/l",
          "[physics][modes][constraints]") {
    const Derived d = derive(R"toml(name = "cartesian"
[[coordinates]]
name = "x"
initial = 0.3
[[coordinates]]
name = "y"
initial = -0.9
[[parameters]]
name = "m"
value = 1.7
[[parameters]]
name = "l"
value = 0.8
[[parameters]]
name = "g"
value = 9.81
[lagrangian]
T = "m/2*(x'^2 + y'^2)"
V = "m*g*y"
[[constraints]]
name = "rod"
expr = "x^2 + y^2 - l^2"
)toml");
    const double m = 1.7, l = 0.8, g = 9.81;
    const eomgen::ModesResult r = eomgen::small_oscillations(d.model, d.eq, {});
    REQUIRE(r.constraints == std::vector<std::string>{"rod"});
    REQUIRE(r.equilibria.size() == 2);
    // By hand: at rest ∇V = Aᵀλ with ∇V = (0, m g), A = (2x, 2y). Bottom (0, −l): λ = −m g/(2l), and the
    // stiffness with the rod's curvature, ∇²V − λ·2I = (m g/l) I, on the tangent (1, 0): ω² = (m g/l)/m = g/l.
    const eomgen::Equilibrium& bottom = at(r, {0, -l});
    CHECK(bottom.stability == eomgen::Stability::Stable);
    REQUIRE(bottom.multipliers.size() == 1);
    CHECK(bottom.multipliers[0] == Approx(-m * g / (2 * l)).epsilon(1e-12));
    REQUIRE(bottom.modes.size() == 1);
    CHECK(bottom.modes[0].omega2 == Approx(g / l).epsilon(1e-12));
    CHECK(std::abs(bottom.modes[0].shape[0]) == Approx(1));
    CHECK(bottom.modes[0].shape[1] == 0);
    // Top (0, l): λ = +m g/(2l), stiffness −(m g/l) I: unstable, growth √(g/l).
    const eomgen::Equilibrium& top = at(r, {0, l});
    CHECK(top.multipliers[0] == Approx(m * g / (2 * l)).epsilon(1e-12));
    CHECK(top.stability == eomgen::Stability::Unstable);
    CHECK(top.growth_rate == Approx(std::sqrt(g / l)).epsilon(1e-10));
    // The eigenvalues are those of the one degree of freedom, with no spurious zeros from the constraint.
    CHECK(bottom.eigenvalues.size() == 2);
}

TEST_CASE("modes with constraints: a double pendulum in Cartesian coordinates has the frequencies of the angles",
          "[physics][modes][constraints]") {
    // Four coordinates, two rods. In the angles (tests/physics/exam_modes.cpp, by hand):
    // ω² = (m1+m2) g [(l1+l2) ∓ √((l1+l2)² − 4 m1 l1 l2/(m1+m2))]/(2 m1 l1 l2), shape b/a = (m1+m2)(g − ω² l1)/(m2 l2 ω²).
    const Derived d = derive(R"toml(name = "double_cartesian"
[[coordinates]]
name = "x1"
initial = 0.1
[[coordinates]]
name = "y1"
initial = -0.8
[[coordinates]]
name = "x2"
initial = 0.3
[[coordinates]]
name = "y2"
initial = -2.2
[[parameters]]
name = "m1"
value = 1.3
[[parameters]]
name = "m2"
value = 0.7
[[parameters]]
name = "l1"
value = 0.9
[[parameters]]
name = "l2"
value = 1.4
[[parameters]]
name = "g"
value = 9.81
[lagrangian]
T = "m1/2*(x1'^2 + y1'^2) + m2/2*(x2'^2 + y2'^2)"
V = "m1*g*y1 + m2*g*y2"
[[constraints]]
name = "upper"
expr = "x1^2 + y1^2 - l1^2"
[[constraints]]
name = "lower"
expr = "(x2 - x1)^2 + (y2 - y1)^2 - l2^2"
)toml");
    const double m1 = 1.3, m2 = 0.7, l1 = 0.9, l2 = 1.4, g = 9.81;
    const eomgen::ModesResult r = eomgen::small_oscillations(d.model, d.eq, {});
    // Four equilibria: each rod up or down.
    CHECK(r.equilibria.size() == 4);
    const eomgen::Equilibrium& down = at(r, {0, -l1, 0, -l1 - l2});
    CHECK(down.stability == eomgen::Stability::Stable);
    REQUIRE(down.modes.size() == 2);
    const double s = l1 + l2, root = std::sqrt(s * s - 4 * m1 * l1 * l2 / (m1 + m2));
    const double w_slow = (m1 + m2) * g * (s - root) / (2 * m1 * l1 * l2);
    const double w_fast = (m1 + m2) * g * (s + root) / (2 * m1 * l1 * l2);
    CHECK(down.modes[0].omega2 == Approx(w_slow).epsilon(1e-10));
    CHECK(down.modes[1].omega2 == Approx(w_fast).epsilon(1e-10));
    // Shapes: at the bottom δx1 = l1 δa and δx2 = l1 δa + l2 δb; δy = 0.
    for (const eomgen::NormalMode& mode : down.modes) {
        const double ratio = (m1 + m2) * (g - mode.omega2 * l1) / (m2 * l2 * mode.omega2);  // δb/δa
        const double a = mode.shape[0] / l1, b = (mode.shape[2] - mode.shape[0]) / l2;
        CHECK(b / a == Approx(ratio).epsilon(1e-9));
        CHECK(mode.shape[1] == 0);
        CHECK(mode.shape[3] == 0);
    }
    // The rods' tensions at the bottom: upper carries both weights, lower the second's; λ·∂g/∂y gives the force.
    CHECK(down.multipliers[0] * (-2 * l1) + down.multipliers[1] * (2 * l2) == Approx(m1 * g));
    CHECK(down.multipliers[1] * (-2 * l2) == Approx(m2 * g));
    // Both rods up is unstable; so are the two mixed ones.
    CHECK(at(r, {0, l1, 0, l1 + l2}).stability == eomgen::Stability::Unstable);
}

TEST_CASE("modes with constraints: A is the generated rhs's Jacobian on the tangent space",
          "[physics][modes][constraints][linearize]") {
    using P = eomgen::models::pendulum_cartesian::Model<double>;
    const Derived d = modes_support::load("models/pendulum_cartesian.toml");
    const eomgen::ModesResult r = eomgen::small_oscillations(d.model, d.eq, {});
    const P::Params p;
    for (const double y : {-p.l, p.l}) {
        const eomgen::Equilibrium& e = at(r, {0, y});
        P::State x0;
        x0 << 0, y, 0, 0;
        P::StateJacobian J;
        P::ParameterJacobian B;
        P::linearization(0.0, x0, p, J, B);
        // Perturbations that keep to the manifold: δq = N δs, δq̇ = N δṡ.
        const Eigen::MatrixXd N = matrix(e.tangent);
        Eigen::MatrixXd T = Eigen::MatrixXd::Zero(4, 2 * N.cols());
        T.topLeftCorner(2, N.cols()) = N;
        T.bottomRightCorner(2, N.cols()) = N;
        const Eigen::MatrixXd A = matrix(e.A);
        CHECK(((J - A) * T).cwiseAbs().maxCoeff() <= 1e-10 * (1 + A.cwiseAbs().maxCoeff()));
    }
}

TEST_CASE("modes with constraints: what has no equilibria of this kind is refused with the reason",
          "[physics][modes][constraints]") {
    const std::string head = R"toml(name = "refused"
[[coordinates]]
name = "x"
[[coordinates]]
name = "y"
[[parameters]]
name = "w"
value = 2.0
[lagrangian]
T = "1/2*(x'^2 + y'^2)"
V = "x^2 + y^2"
)toml";
    const Derived moving = derive(head + "[[constraints]]\nname = \"slot\"\nexpr = \"x - sin(w*t)\"\n");
    CHECK_THROWS_WITH(eomgen::small_oscillations(moving.model, moving.eq, {}), Catch::Contains("depends on t"));
    const Derived rolling =
        derive(head + "[[constraints]]\nname = \"skate\"\nkind = \"nonholonomic\"\nexpr = \"x' - y*y'\"\n");
    CHECK_THROWS_WITH(eomgen::small_oscillations(rolling.model, rolling.eq, {}), Catch::Contains("nonholonomic"));
}
