/** @file exam_linear_algebra.cpp  Vectors and matrices in a derivation (linear_algebra.hpp): the triangle
 * plate's inertia tensor, principal moments and principal axes written as arrays, tuples, products,
 * determinants and eigen-equations — a correct write-up and one with planted mistakes — and the pieces on
 * their own. */
#include "checked_text.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace {

using eomgen::checker::CheckReport;
using eomgen::checker::EquationCheck;
using eomgen::checker::Verdict;
using eomgen::test::describe;

const char* const kPlate = "models/triangle_plate_5_15.toml";

std::string wrong_terms(const EquationCheck& e) {
    std::string all;
    for (const std::string& w : e.wrong_terms) all += w + "\n";
    return all;
}

/// The verdict on the single link of `math` (one display) against the plate.
EquationCheck one(const std::string& math) {
    const CheckReport r = eomgen::test::check_text(kPlate, "# T\n\n$$" + math + "$$\n");
    REQUIRE(r.equations.size() == 1);
    return r.equations[0];
}

}  // namespace

TEST_CASE("linear algebra: a correct write-up of the plate's principal axes agrees line by line",
          "[checker][linear_algebra]") {
    const CheckReport r = eomgen::test::check_text(kPlate, eomgen::test::fixture("matrices_plate.md"));
    CHECK(r.equations.size() == 26);
    for (const EquationCheck& e : r.equations) {
        INFO(describe(e));
        CHECK(e.verdict == Verdict::Agrees);
    }
}

TEST_CASE("linear algebra: each planted mistake is found at its line, with its entry, and nothing else",
          "[checker][linear_algebra]") {
    const std::string text = eomgen::test::fixture("matrices_plate_planted.md");
    const auto planted = eomgen::test::planted_mistakes(text);
    REQUIRE(planted.size() == 5);
    const CheckReport r = eomgen::test::check_text(kPlate, text);
    int found = 0;
    for (const EquationCheck& e : r.equations) {
        INFO(describe(e));
        if (planted.count(e.where.line) && e.verdict == Verdict::Disagrees) {
            CHECK(wrong_terms(e).find(planted.at(e.where.line)) != std::string::npos);
            ++found;
            continue;
        }
        CHECK(e.verdict != Verdict::Disagrees);
        // Only what the wrong n₂ leaves unknown: its length (n₁ × n₂ = −n₃, n₂·I·n₂ = 3k).
        if (e.verdict == Verdict::NotComparable)
            CHECK(e.reason.find("depends on the length of an eigenvector") != std::string::npos);
    }
    CHECK(found == 5);
    // The corrections: the right entry in the array's own scale, the eigenvalue of the stated n₃, n₃'s
    // components.
    for (const EquationCheck& e : r.equations) {
        if (e.verdict != Verdict::Disagrees) continue;
        INFO(describe(e));
        if (e.where.line == 6)
            CHECK(
                e.corrected ==
                "\\mathbf{I} = k \\begin{pmatrix} 2 & -1 & 0 \\\\ -1 & 2 & 0 \\\\ 0 & 0 & 4 \\end{pmatrix}");
        if (e.where.line == 38)
            CHECK(e.corrected == "\\mathbf{I}\\, \\mathbf{n}_3 = \\frac{1}{3} M a^{2} \\mathbf{n}_3");
        if (e.where.line == 39) {
            CHECK(e.corrected.find("2 n_{3x} - n_{3y}") != std::string::npos);
            bool flagged = false;
            for (const std::string& n : e.notes)
                flagged =
                    flagged || n.find("row 2 of this display uses the components of $\\mathbf{n}_{2}$") == 0;
            CHECK(flagged);
        }
        if (e.where.line == 48) CHECK(e.corrected == "\\mathbf{n}_2 = \\frac{1}{\\sqrt{2}}(1, -1, 0)");
    }
}

TEST_CASE("linear algebra: the pieces", "[checker][linear_algebra]") {
    // Matrix times vector, row against column, tuples of declared results, the identity and unit vectors.
    CHECK(one("\\begin{pmatrix} 1 & 2 \\\\ 3 & 4 \\end{pmatrix} \\begin{pmatrix} 1 \\\\ 1 \\end{pmatrix} = "
              "(3, 7)")
              .verdict == Verdict::Agrees);
    const EquationCheck wrong = one(
        "\\begin{pmatrix} 1 & 2 \\\\ 3 & 4 \\end{pmatrix} \\begin{pmatrix} 1 \\\\ 1 \\end{pmatrix} = (3, 8)");
    INFO(describe(wrong));
    CHECK(wrong.verdict == Verdict::Disagrees);
    CHECK(wrong_terms(wrong).find("row 2: the left side is $7$, the right side $8$") != std::string::npos);
    CHECK(one("(1, 0, 0) \\times (0, 1, 0) = \\hat{k}").verdict == Verdict::Agrees);
    CHECK(one("(1, 2, 3) \\times (4, 5, 6) = (-3, 6, -3)").verdict == Verdict::Agrees);
    CHECK(one("(1, 2, 3) \\cdot (4, 5, 6) = 32").verdict == Verdict::Agrees);
    CHECK(one("\\det \\begin{bmatrix} a & M \\\\ 1 & 2 \\end{bmatrix} = 2 a - M").verdict == Verdict::Agrees);
    CHECK(one("\\mathbf{1} \\begin{pmatrix} a \\\\ M \\\\ 0 \\end{pmatrix} = (a, M, 0)").verdict ==
          Verdict::Agrees);
    // The model's tensor (its declared components) as the reference; a tuple of declared principal moments.
    const EquationCheck moments =
        one("\\left(I_{1}, I_{2}, I_{3}\\right) = \\left(\\frac{M a^2}{12}, \\frac{M a^2}{4}, \\frac{M "
            "a^2}{4}\\right)");
    INFO(describe(moments));
    CHECK(moments.verdict == Verdict::Disagrees);
    CHECK(wrong_terms(moments).find(
              "row 3 (z): the text's entry $\\frac{M a^2}{4}$ where $\\frac{1}{3} M a^{2}$ belongs") !=
          std::string::npos);
    const EquationCheck tensor =
        one("\\mathbf{I} = \\begin{bmatrix} M a^2/6 & -M a^2/12 & 0 \\\\ -M a^2/12 & M a^2/3 & 0 \\\\ 0 & 0 "
            "& M a^2/3 \\end{bmatrix}");
    INFO(describe(tensor));
    CHECK(tensor.verdict == Verdict::Disagrees);
    CHECK(wrong_terms(tensor) ==
          "row 2, column 2: the text's entry $M a^2/3$ where $\\frac{1}{6} M a^{2}$ belongs\n");
    // Shapes that do not fit, a vector the text never states: not comparable, with the reason.
    CHECK(one("(1, 2) = (1, 2, 3)").reason.find("different shapes: a 2-vector and a 3-vector") !=
          std::string::npos);
    CHECK(one("\\mathbf{w} = \\mathbf{I} \\mathbf{u}").reason.find("is not known") != std::string::npos);
    // A determinant above 4×4 is refused at once rather than expanded without bound.
    CHECK(one("\\begin{vmatrix} a & 1 & 0 & 0 & 0 \\\\ 1 & a & 1 & 0 & 0 \\\\ 0 & 1 & a & 1 & 0 \\\\ 0 & 0 & 1 & a & 1 "
              "\\\\ 0 & 0 & 0 & 1 & a \\end{vmatrix} = 0")
              .reason == "the determinant of a 5×5 matrix is not expanded (at most 4×4)");
    // An eigen-equation with an eigenvalue of the tensor agrees, with one that is none disagrees.
    CHECK(one("\\mathbf{I} \\cdot \\mathbf{m} = \\frac{M a^2}{4} \\mathbf{m}").verdict == Verdict::Agrees);
    CHECK(one("\\mathbf{I} \\cdot \\mathbf{m} = \\frac{M a^2}{5} \\mathbf{m}").verdict == Verdict::Disagrees);
}

TEST_CASE("linear algebra: scalar equations are left to the checker", "[checker][linear_algebra]") {
    const EquationCheck k = one("k = \\frac{M a^2}{12}");
    CHECK(k.verdict == Verdict::Agrees);
    CHECK(k.compared_with.find("the declared result k") == 0);
}

TEST_CASE("linear algebra: a Poisson bracket is not a tuple", "[checker][linear_algebra]") {
    // \{a, b\} is the parser's bracket, a scalar factor ({θ, θ} = 0), never a vector: only ( ) and [ ] make
    // tuples.
    const EquationCheck e = one("\\{\\theta, \\theta\\} (1, 0) = (0, 0)");
    INFO(describe(e));
    CHECK(e.verdict == Verdict::Agrees);
    const EquationCheck f = one("\\{\\theta, \\theta\\} (1, 0) = (1, 0)");
    CHECK(f.verdict == Verdict::Disagrees);
}

TEST_CASE("linear algebra: the torque-free top's tensor and its declared angular velocity",
          "[checker][linear_algebra]") {
    // No component of I declared, one body fixed at its centre of mass: I is that body's tensor, diag(I, I,
    // I_3); ω's components are the model's declared results (Goldstein (4.87), verified by eomgen).
    const auto check = [](const std::string& math) {
        const CheckReport r =
            eomgen::test::check_text("models/torque_free_top.toml", "# T\n\n$$" + math + "$$\n");
        REQUIRE(r.equations.size() == 1);
        INFO(describe(r.equations[0]));
        return r.equations[0];
    };
    CHECK(check("\\mathbf{I} = \\begin{pmatrix} I & 0 & 0 \\\\ 0 & I & 0 \\\\ 0 & 0 & I_3 \\end{pmatrix}")
              .verdict == Verdict::Agrees);
    const EquationCheck swapped =
        check("\\mathbf{I} = \\begin{pmatrix} I_3 & 0 & 0 \\\\ 0 & I & 0 \\\\ 0 & 0 & I \\end{pmatrix}");
    CHECK(swapped.verdict == Verdict::Disagrees);
    CHECK(wrong_terms(swapped).find("row 1, column 1: the text's entry $I_3$ where $I$ belongs") !=
          std::string::npos);
    CHECK(wrong_terms(swapped).find("row 3, column 3: the text's entry $I$ where $I_{3}$ belongs") !=
          std::string::npos);
    CHECK(check("\\mathbf{I} \\boldsymbol{\\omega} = \\left(I \\omega_x, I \\omega_y, I_3 \\omega_z\\right)")
              .verdict == Verdict::Agrees);
    const std::string omega =
        "\\boldsymbol{\\omega} = \\left(\\dot\\phi \\sin\\theta \\sin\\psi + \\dot\\theta \\cos\\psi, "
        "\\dot\\phi \\sin\\theta \\cos\\psi SIGN \\dot\\theta \\sin\\psi, \\dot\\phi \\cos\\theta + "
        "\\dot\\psi\\right)";
    CHECK(check(omega.substr(0, omega.find("SIGN")) + "-" + omega.substr(omega.find("SIGN") + 4)).verdict ==
          Verdict::Agrees);
    const EquationCheck sign =
        check(omega.substr(0, omega.find("SIGN")) + "+" + omega.substr(omega.find("SIGN") + 4));
    CHECK(sign.verdict == Verdict::Disagrees);
    CHECK(wrong_terms(sign).find("row 2 (y): the text's entry") == 0);
}

TEST_CASE("linear algebra: M and K (T and V in bold) are the model's mass and stiffness matrices",
          "[checker][linear_algebra]") {
    // Notes on two carts written here, checked as written: M and K agree with eomgen's, and nothing disagrees.
    const std::string text = eomgen::test::fixture("two_carts_matrix_notes.md");
    const CheckReport r = eomgen::test::check_text("tests/checker/models/two_carts.toml", text);
    CHECK(r.count(Verdict::Disagrees) == 0);
    int matrices = 0;
    for (const EquationCheck& e : r.equations) {
        INFO(describe(e));
        if (e.compared_with.rfind("eomgen's mass matrix", 0) == 0 ||
            e.compared_with.rfind("eomgen's stiffness matrix", 0) == 0) {
            CHECK(e.verdict == Verdict::Agrees);
            ++matrices;
        }
    }
    CHECK(matrices == 2);
    // The double pendulum: M(q) in the coordinates; M₀ and K₀ at the bottom; a wrong K₀ entry corrected.
    const char* const dp = "tests/checker/models/double_pendulum_equal.toml";
    const CheckReport d = eomgen::test::check_text(
        dp, "$$M = \\begin{pmatrix} 2 m l^2 & m l^2\\cos(\\theta_1 - \\theta_2) \\\\ m l^2\\cos(\\theta_1 - \\theta_2) & m "
            "l^2 \\end{pmatrix}$$\n\n"
            "$$M = \\begin{pmatrix} 2 m l^2 & m l^2 \\\\ m l^2 & m l^2 \\end{pmatrix}$$\n\n"
            "$$\\mathbf{V} = \\begin{pmatrix} 2 m g l & 0 \\\\ 0 & m g l \\end{pmatrix}$$\n\n"
            "$$K = \\begin{pmatrix} m g l & 0 \\\\ 0 & m g l \\end{pmatrix}$$\n");
    REQUIRE(d.equations.size() == 4);
    for (int k = 0; k < 3; ++k) {
        INFO(describe(d.equations[std::size_t(k)]));
        CHECK(d.equations[std::size_t(k)].verdict == Verdict::Agrees);
    }
    INFO(describe(d.equations[3]));
    CHECK(d.equations[3].verdict == Verdict::Disagrees);
    CHECK(d.equations[3].corrected == "K = \\begin{pmatrix} 2 m l g & 0 \\\\ 0 & m g l \\end{pmatrix}");
    // Where the model has a parameter M (a cart's mass), M is that parameter, not the mass matrix.
    const CheckReport c = eomgen::test::check_text("tests/checker/models/cart_pendulum_free.toml",
                                                   "$$M = \\begin{pmatrix} 1 & 0 \\\\ 0 & 1 \\end{pmatrix}$$\n");
    REQUIRE(c.equations.size() == 1);
    CHECK(c.equations[0].compared_with.find("mass matrix") == std::string::npos);
}

TEST_CASE("linear algebra: a transpose, ^T, ^{\\top}, of an array and of a tuple", "[checker][linear_algebra]") {
    const char* const pendulum = "tests/checker/models/plane_pendulum.toml";
    const CheckReport r = eomgen::test::check_text(
        pendulum,
        "$$\\begin{bmatrix} \\theta & \\dot\\theta \\end{bmatrix}^T = \\begin{bmatrix} \\theta \\\\ \\dot\\theta \\end{bmatrix}$$\n\n"
        "$$[\\theta, \\dot\\theta]^T = \\begin{bmatrix} \\theta \\\\ \\dot\\theta \\end{bmatrix}$$\n\n"
        "$$\\begin{bmatrix} 1 & 0 \\\\ 2 & 1 \\end{bmatrix}^{\\top} = \\begin{bmatrix} 1 & 2 \\\\ 0 & 1 \\end{bmatrix}$$\n\n"
        "$$\\begin{bmatrix} 1 & 0 \\\\ 2 & 1 \\end{bmatrix}^{T} = \\begin{bmatrix} 1 & 0 \\\\ 2 & 1 \\end{bmatrix}$$\n");
    REQUIRE(r.equations.size() == 4);
    for (const EquationCheck& e : r.equations) INFO(describe(e));
    for (std::size_t k = 0; k < 3; ++k) CHECK(r.equations[k].verdict == Verdict::Agrees);
    CHECK(r.equations[3].verdict == Verdict::Disagrees);  // a non-symmetric matrix is not its transpose
}
