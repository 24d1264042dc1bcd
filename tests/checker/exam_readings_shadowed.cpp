/** @file exam_readings_shadowed.cpp  Readings the corpus' newer texts needed (docs/checker.md): a parameter written
 * with the Lagrangian's letter (a rod of length L), the derivative of a position the text defines, a root of a rate
 * on a constrained motion, the multiplier's rate, and \text{det}. */
#include "checked_text.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace {

using eomgen::checker::CheckReport;
using eomgen::checker::Verdict;

const char* const kCartL = "tests/checker/models/cart_pendulum_length_L.toml";  // x, θ; M, m, L (a length), g

}  // namespace

TEST_CASE("shadowed label: L is the Lagrangian where only the Lagrangian makes sense, the rod's length elsewhere",
          "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text(kCartL, R"(# Cart

$$L = T - V$$

$$L = \frac12 (M+m)\dot x^2 + m L \dot x\dot\theta\cos\theta + \frac12 m L^2\dot\theta^2 + m g L\cos\theta$$

$$\frac{\partial L}{\partial \dot x} = (M+m)\dot x + m L\dot\theta\cos\theta$$

$$\frac{\partial L}{\partial \theta} = -m L \dot x\dot\theta\sin\theta + m g L\sin\theta$$

$$\frac{d}{dt}\frac{\partial L}{\partial \dot\theta} = m L \ddot x\cos\theta - m L\dot x\dot\theta\sin\theta + m L^2\ddot\theta$$

The rod is $L = 2 l_0$ long, with $l_0$ its half length.
)");
    INFO(eomgen::test::describe_all(r));
    REQUIRE(r.equations.size() == 6);
    for (std::size_t k = 0; k < 3; ++k) {
        CHECK(r.equations[k].verdict == Verdict::Agrees);
        CHECK(eomgen::test::has_note(r.equations[k], "reads $L$ here as eomgen's $L$, not the model's parameter $L$ "
                                                     "written with the same letter"));
    }
    CHECK(r.equations[3].verdict == Verdict::Disagrees);  // the sign of the gravity term
    CHECK(r.equations[4].verdict == Verdict::Agrees);
    CHECK(r.equations[5].verdict != Verdict::Agrees);  // a length: not the Lagrangian
    CHECK(r.equations[5].verdict != Verdict::Disagrees);
}

TEST_CASE("a rate of a position the text defines is compared with that definition's derivative",
          "[checker][definitions]") {
    const CheckReport r = eomgen::test::check_text(kCartL, R"(# Cart

The bob is at $x_p = x + L \sin{\theta}$, so that

$$\dot{x_p} = \dot{x} + L \cos{\theta}$$

$$\dot{x_p} = \dot{x} + L \dot\theta\cos{\theta}$$
)");
    INFO(eomgen::test::describe_all(r));
    REQUIRE(r.equations.size() == 3);
    CHECK(r.equations[1].verdict == Verdict::Disagrees);
    CHECK(r.equations[1].compared_with == "the time derivative of $x_{p}$ as the text defines it at line 3");
    CHECK(r.equations[1].corrected.find("\\dot{\\theta}") != std::string::npos);
    CHECK(r.equations[2].verdict == Verdict::Agrees);
}

TEST_CASE("a root of the rate on a constrained motion is compared squared, and the multiplier's rate is not 0",
          "[checker][multipliers]") {
    // The dome of the corpus (r, θ; r = R by a multiplier λ, the normal force).
    const CheckReport r = eomgen::test::check_text("tests/checker/corpus/dome_multiplier_pse/model.toml", R"(# Dome

$$Mr\dot{\theta}^2-Mg\cos\theta+\lambda=0$$

$$\dot{\theta}=\sqrt{\frac{g}{r}\cos\theta-\frac{\lambda}{Mr}}$$

$$\dot{\theta}=\sqrt{\frac{g}{r}\cos\theta+\frac{\lambda}{Mr}}$$

$$\ddot \theta = -\frac{\frac{g}{r}\sin\theta\dot \theta+\frac{1}{Mr}\dot\lambda}{2\dot\theta}$$
)");
    INFO(eomgen::test::describe_all(r));
    REQUIRE(r.equations.size() == 4);
    CHECK(r.equations[0].verdict == Verdict::Agrees);
    CHECK(r.equations[1].verdict == Verdict::Agrees);
    CHECK(r.equations[1].reason.find("after squaring both sides") != std::string::npos);
    CHECK(r.equations[2].verdict == Verdict::Disagrees);
    CHECK(r.equations[3].verdict == Verdict::NotComparable);
    CHECK(r.equations[3].reason.find("multiplier") != std::string::npos);
}

TEST_CASE("\\text{det} is a determinant", "[checker][readings]") {
    const CheckReport r = eomgen::test::check_text("tests/checker/models/two_carts.toml", R"(# Two carts

$$\text{det}\left(\begin{bmatrix} 2k - m\omega^2 & -k \\ -k & 2k - m\omega^2 \end{bmatrix}\right) = 0$$
)");
    INFO(eomgen::test::describe_all(r));
    REQUIRE(r.equations.size() == 1);
    CHECK(r.equations[0].verdict != Verdict::NotComparable);
}
