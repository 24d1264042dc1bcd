/** @file test_particle_tree.cpp  The tree of point masses found in T (mechanics/particle_tree.hpp) and its O(n)
 * recursion (eomgen/particle_tree.hpp) against the dense solve of M q̈ = f, at random states and parameters. */
#include "eomgen/particle_tree.hpp"
#include "mechanics/lagrangian.hpp"
#include "mechanics/particle_tree.hpp"
#include "model/families.hpp"
#include "model/model_file.hpp"

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include <random>
#include <string>

namespace {

struct Derived {
    eomgen::Model model;
    eomgen::Equations eq;
};

Derived derive(const std::string& text) {
    Derived d{eomgen::parse_model(text, "tree_test.toml"), {}};
    d.eq = eomgen::derive_equations(d.model);
    return d;
}

Derived family(const std::string& spec) {
    return derive(eomgen::family_model_text(eomgen::parse_family_spec(spec)));
}

double number(const GiNaC::ex& e, const GiNaC::exmap& at) {
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(at))).to_double();
}

/// Model text: coordinates, parameters (name = value) and T, V.
std::string model_text(const std::vector<std::string>& coordinates, const std::vector<std::string>& parameters,
                       const std::string& T, const std::string& V) {
    std::string s = "name = \"tree_test\"\n";
    for (const std::string& c : coordinates) s += "[[coordinates]]\nname = \"" + c + "\"\ninitial = 0.3\n";
    for (const std::string& p : parameters) s += "[[parameters]]\nname = \"" + p + "\"\nvalue = 1.0\n";
    s += "[lagrangian]\nT = \"\"\"" + T + "\"\"\"\nV = \"\"\"" + V + "\"\"\"\n";
    return s;
}

/// The recursion's q̈ against M⁻¹f at `states` random states (q, q̇, parameters in (0.3, 1.7)); returns the
/// largest relative difference.
template <int N, int D>
double worst_difference(const Derived& d, const eomgen::ParticleTree& tree, int states) {
    REQUIRE(d.model.dof() == std::size_t(N));
    REQUIRE(tree.components == std::size_t(D));
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.3, 1.7), angle(-1.5, 1.5);
    std::array<int, N> parent{}, order{};
    for (int k = 0; k < N; ++k) {
        parent[std::size_t(k)] = tree.parent[std::size_t(k)];
        order[std::size_t(k)] = tree.order[std::size_t(k)];
    }
    double worst = 0;
    for (int s = 0; s < states; ++s) {
        GiNaC::exmap at;
        for (const auto& c : d.model.coordinates) {
            at[c.q] = angle(rng);
            at[c.qd] = 2 * angle(rng);
        }
        for (const auto& p : d.model.parameters) at[p.symbol] = u(rng);
        Eigen::Matrix<double, N, N> M;
        Eigen::Matrix<double, N, 1> f, x;
        eomgen::ParticleTreeTerms<double, N, D> in;
        for (int i = 0; i < N; ++i) {
            f(i) = number(d.eq.f[std::size_t(i)], at);
            for (int j = 0; j < N; ++j) M(i, j) = number(d.eq.M(unsigned(i), unsigned(j)), at);
            for (int c = 0; c < D; ++c) {
                in.lever(c, i) = number(tree.lever[std::size_t(i)][std::size_t(c)], at);
                in.bias(c, i) = number(tree.bias[std::size_t(i)][std::size_t(c)], at);
                in.weight(c, i) = number(tree.weight[std::size_t(i)][std::size_t(c)], at);
            }
            in.joint_inertia(i) = number(tree.joint_inertia[std::size_t(i)], at);
            in.force(i) = number(tree.force[std::size_t(i)], at);
        }
        const Eigen::Matrix<double, N, 1> dense = M.ldlt().solve(f);
        Eigen::Matrix<double, N, 1> qdd;
        eomgen::particle_tree_accelerations(parent, order, in, qdd, 0.0, x.setZero());
        worst = std::max(worst, (qdd - dense).norm() / dense.norm());
    }
    return worst;
}

}  // namespace

TEST_CASE("particle tree: the n-link pendulum in absolute angles is a chain, and its recursion is M^-1 f",
          "[particle_tree]") {
    const Derived d = family("pendulum:n=7");
    const auto tree = eomgen::find_particle_tree(d.model, d.eq);
    REQUIRE(tree);
    CHECK(tree->parent == std::vector<int>{-1, 0, 1, 2, 3, 4, 5});
    CHECK(tree->components == 2);
    CHECK(worst_difference<7, 2>(d, *tree, 20) < 1e-12);
}

TEST_CASE("particle tree: a branching pendulum, declared out of order, with a joint inertia and damping",
          "[particle_tree]") {
    // b and c hang from a's bob; d hangs from c's. Coordinates listed leaves first. Each pin has a flywheel J
    // on c, and c is damped (a generalized force, which the recursion takes with the potential's).
    const std::string T =
        "1/2*m1*((l1*cos(a)*a')^2 + (l1*sin(a)*a')^2)"
        " + 1/2*m2*((l1*cos(a)*a' + l2*cos(b)*b')^2 + (l1*sin(a)*a' + l2*sin(b)*b')^2)"
        " + 1/2*m3*((l1*cos(a)*a' + l3*cos(c)*c')^2 + (l1*sin(a)*a' + l3*sin(c)*c')^2)"
        " + 1/2*m4*((l1*cos(a)*a' + l3*cos(c)*c' + l4*cos(d)*d')^2 + (l1*sin(a)*a' + l3*sin(c)*c' + l4*sin(d)*d')^2)"
        " + 1/2*J*c'^2";
    const std::string V = "-g*(m1*l1*cos(a) + m2*(l1*cos(a) + l2*cos(b)) + m3*(l1*cos(a) + l3*cos(c))"
                          " + m4*(l1*cos(a) + l3*cos(c) + l4*cos(d)))";
    std::string text = model_text({"d", "b", "c", "a"}, {"m1", "m2", "m3", "m4", "l1", "l2", "l3", "l4", "g", "J", "k"},
                                  T, V);
    text += "[forces]\nc = \"-k*c'\"\n";
    const Derived d = derive(text);
    const auto tree = eomgen::find_particle_tree(d.model, d.eq);
    REQUIRE(tree);
    // Coordinates: d, b, c, a. a is the root, b and c hang from it, d from c.
    CHECK(tree->parent == std::vector<int>{2, 3, 3, -1});
    CHECK(tree->order.front() == 3);
    CHECK(worst_difference<4, 2>(d, *tree, 20) < 1e-12);
}

TEST_CASE("particle tree: a chain in space whose pins have different axes needs three components",
          "[particle_tree]") {
    // Link k turns about an axis in the y-z plane, tilted by e_k: its end moves by
    // l_k (cos q_k, sin q_k cos e_k, sin q_k sin e_k), so its lever is l_k (-sin q, cos q cos e, cos q sin e).
    auto link = [](int k, const std::string& comp) {
        const std::string q = "q" + std::to_string(k), l = "l" + std::to_string(k), e = "e" + std::to_string(k);
        if (comp == "x") return l + "*cos(" + q + ")";
        if (comp == "y") return l + "*sin(" + q + ")*cos(" + e + ")";
        return l + "*sin(" + q + ")*sin(" + e + ")";
    };
    auto speed = [](int upto, const std::string& comp) {
        std::string s;
        for (int k = 1; k <= upto; ++k) {
            const std::string q = "q" + std::to_string(k), l = "l" + std::to_string(k), e = "e" + std::to_string(k);
            const std::string lever = comp == "x"   ? "-" + l + "*sin(" + q + ")"
                                      : comp == "y" ? l + "*cos(" + q + ")*cos(" + e + ")"
                                                    : l + "*cos(" + q + ")*sin(" + e + ")";
            s += (k > 1 ? " + " : "") + lever + "*" + q + "'";
        }
        return s;
    };
    std::string T, V;
    for (int k = 1; k <= 3; ++k) {
        const std::string m = "m" + std::to_string(k);
        T += (k > 1 ? " + " : "") + ("1/2*" + m + "*((" + speed(k, "x") + ")^2 + (" + speed(k, "y") + ")^2 + (" +
                                     speed(k, "z") + ")^2)");
        std::string z;
        for (int j = 1; j <= k; ++j) z += (j > 1 ? " + " : "") + link(j, "z");
        V += (k > 1 ? " + " : "") + m + "*g*(" + z + ")";
    }
    const Derived d = derive(model_text({"q1", "q2", "q3"}, {"m1", "m2", "m3", "l1", "l2", "l3", "e1", "e2", "e3", "g"},
                                        T, V));
    const auto tree = eomgen::find_particle_tree(d.model, d.eq);
    REQUIRE(tree);
    CHECK(tree->parent == std::vector<int>{-1, 0, 1});
    CHECK(tree->components == 3);
    CHECK(worst_difference<3, 3>(d, *tree, 20) < 1e-12);
}

TEST_CASE("particle tree: what is not a tree of point masses is left to the dense solve", "[particle_tree]") {
    // Rods: a rod's centre moves with two coordinates' levers that another rod's end does not share.
    CHECK_FALSE(eomgen::find_particle_tree(family("rods:n=4").model, family("rods:n=4").eq));
    // The double pendulum with T multiplied out: no squares to read.
    CHECK_FALSE(eomgen::find_particle_tree(
        derive(model_text({"a", "b"}, {"m", "l", "g"},
                          "m*l^2*a'^2 + 1/2*m*l^2*b'^2 + m*l^2*a'*b'*cos(a - b)", "-m*g*l*(2*cos(a) + cos(b))"))
            .model,
        derive(model_text({"a", "b"}, {"m", "l", "g"},
                          "m*l^2*a'^2 + 1/2*m*l^2*b'^2 + m*l^2*a'*b'*cos(a - b)", "-m*g*l*(2*cos(a) + cos(b))"))
            .eq));
    // Relative angles: the second link's lever depends on both coordinates.
    const Derived relative = derive(model_text(
        {"a", "b"}, {"m", "l", "g"},
        "1/2*m*((l*cos(a)*a')^2 + (l*sin(a)*a')^2) + 1/2*m*((l*cos(a)*a' + l*cos(a + b)*(a' + b'))^2 + "
        "(l*sin(a)*a' + l*sin(a + b)*(a' + b'))^2)",
        "-m*g*l*(2*cos(a) + cos(a + b))"));
    CHECK_FALSE(eomgen::find_particle_tree(relative.model, relative.eq));
}

TEST_CASE("particle tree: a cart under a pendulum is a tree read upside down, and exact", "[particle_tree]") {
    // The bob's y moves with th alone and its x with x and th: th is read as the root, x as its child (the tree
    // is of T's squares, not of the mechanism), and the recursion is exact all the same.
    const Derived cart = derive(model_text({"x", "th"}, {"M", "m", "l", "g"},
                                           "1/2*M*x'^2 + 1/2*m*((x' + l*cos(th)*th')^2 + (l*sin(th)*th')^2)",
                                           "-m*g*l*cos(th)"));
    const auto tree = eomgen::find_particle_tree(cart.model, cart.eq);
    REQUIRE(tree);
    CHECK(tree->parent == std::vector<int>{1, -1});
    CHECK(worst_difference<2, 2>(cart, *tree, 20) < 1e-12);
}
