/** @file linear_algebra.hpp  A text's vectors and matrices: arrays, tuples, products, determinants and
 * eigen-equations, compared entry by entry with the model's quantities. */
#pragma once

#include "checker/checker.hpp"
#include "checker/comparisons.hpp"
#include "checker/derivation.hpp"
#include "checker/latex_parser.hpp"
#include "checker/matrix_latex.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace eomgen::checker {

/// A scalar part of a side as the checker reads it: labels and declared results replaced, d/dt evaluated.
struct ScalarReading {
    bool ok = false;
    GiNaC::ex value;
    std::string problem;     ///< when !ok
    bool reference = false;  ///< the whole part is one of eomgen's quantities (a declared result, T, …)
};
/// Reads a side parsed from a piece of the text whose first byte is at file offset `base`.
using ScalarEvaluator = std::function<ScalarReading(const Side& side, std::size_t base)>;

/// The side could not be read because it holds a matrix, a tuple or a determinant: linear algebra reads it.
bool reads_as_array(const Side& side);

/**
 * The text's linear algebra. A side is a sum of terms, each a product of factors read left to right:
 * scalars (anything the LaTeX parser reads), arrays (`\begin{array}`, `pmatrix`, `bmatrix`, `matrix`, inside
 * `\left( \right)` or `\left[ \right]`), tuples `(a, b, c)` (column vectors), determinants (`vmatrix`,
 * `\left| \begin{array} … \right|`, `\det(…)`, `\operatorname{det}(…)`), vectors and matrices by name
 * (`\mathbf{X}`, `\vec{X}`, `\boldsymbol{X}`, `\bm{X}`, `\underline{X}`: one name whatever the decoration),
 * and groups of these. Juxtaposition and `\cdot` multiply matrices (`\cdot` between two vectors is their dot
 * product); `\times` between two 3-vectors is their cross product.
 *
 * What the names stand for:
 *  - `\mathbf{1}`: the 3×3 identity;
 *  - X whose components the model declares as results (`I_{xx}`, `I_{xy}`, … with I_{yx} = I_{xy} where only
 *    one is declared: a tensor; `\omega_{x}`, `\omega_{y}`, `\omega_{z}`: a vector): those results;
 *  - `\mathbf{I}` with no component declared, in a model of one body whose centre of mass stays at the
 * origin: that body's inertia tensor (about its centre of mass, body axes: mechanics/bodies.hpp);
 *  - n with an eigen-equation in the text, `A \cdot n = λ n` (A a matrix the text or the model gives, λ a
 *    scalar), where λ is an eigenvalue of A (det(A − λ1) = 0): an eigenvector, the vector the text states
 *    (`n = (1/\sqrt{2})(1, 1, 0)`) when it is one, else any vector of the eigenspace (each coordinate a free
 *    coefficient); its components `n_{x}` (`n_{1x}` for `n_{1}`) likewise;
 *  - a vector the text states with numbers and the model's symbols only (and no eigen-equation): that value.
 *
 * A link is compared entry by entry, each mismatch reported with its row and column; the side that is the
 * model's quantity (a tensor of declared results, a tuple of declared results) is the reference, and the
 * correction prints the right entry (in the array's own scale when the text writes `s [ … ]`). An
 * eigen-equation whose λ is not an eigenvalue of A disagrees (corrected to the eigenvalue of the vector the
 * text states); a stated eigenvector that is not one disagrees, the wrong components named and corrected
 * (the scale taken from the most components that agree, unit length breaking ties). In a display whose
 * first eigen-equation is about n₃, a row that uses another eigenvector's components (n₂'s) is flagged
 * with its row, and corrected to n₃'s where that holds.
 */
class LinearAlgebra {
  public:
    LinearAlgebra(const Model& model, const Derivation& d, LatexContext& ctx, ScalarEvaluator evaluate)
        : model_(model), d_(d), ctx_(ctx), evaluate_(std::move(evaluate)) {}

    /// Records the link left = right (before any is checked): eigen-equations and stated vectors.
    void note_link(const Side& left, std::size_t left_base, const Side& right, std::size_t right_base);

    /**
     * Judges left = right into r (its `where`, `section` and `equation` already set) when a side holds an
     * array, a tuple, a determinant, a vector name or a component of an eigenvector; false (r untouched)
     * otherwise.
     */
    bool check(const Side& left, std::size_t left_base, const Side& right, std::size_t right_base,
               Comparisons& cmp, EquationCheck& r);

    struct Value;  ///< a scalar or a matrix, read from a side

    /// A matrix of the model that a name answers to (`M`, `\mathbf{T}`: the mass matrix; `K`, `\mathbf{V}`: the
    /// stiffness matrix), and what it is, for the report.
    struct NamedMatrix {
        GiNaC::matrix value;
        std::string what;
    };
    /// The model's matrix for `key`, chosen for the text's matrix it is compared with (`text`; nullptr where it is
    /// used inside an expression), or std::nullopt when the name is no such matrix.
    using MatrixProvider = std::function<std::optional<NamedMatrix>(const std::string& key, const GiNaC::matrix* text)>;
    void set_model_matrices(MatrixProvider provider) { model_matrix_ = std::move(provider); }
    /// Judges one row `left = right` of a vector equation in names the model does not know (a trial solution's
    /// amplitudes: `(K - \omega^2 M) [A_1; A_2] = 0`), at file offset `at`; false when the row is no such equation.
    using RowJudge = std::function<bool(const GiNaC::ex& left, const GiNaC::ex& right, std::size_t at, EquationCheck& r)>;
    void set_row_judge(RowJudge judge) { row_judge_ = std::move(judge); }
    /// Judges a scalar equation the arrays worked out (`\det(K - \omega^2 M) = 0` with the text's ω) as the
    /// scalar checks would (a secular equation); false when they take no such equation.
    using ScalarJudge = std::function<bool(const GiNaC::ex& left, const Side& left_side, const GiNaC::ex& right,
                                           const Side& right_side, EquationCheck& r)>;
    void set_scalar_judge(ScalarJudge judge) { scalar_judge_ = std::move(judge); }
    /// Judges `name = (v_1, …, v_n)`, a vector the text names (a mode's shape), at file offset `at`; false when it
    /// is no such claim.
    using VectorJudge = std::function<bool(const std::vector<GiNaC::ex>& v, const std::string& name, std::size_t at,
                                           EquationCheck& r)>;
    void set_vector_judge(VectorJudge judge) { vector_judge_ = std::move(judge); }
    using Factor = matrix_latex::Factor;
    using Term = matrix_latex::Term;

  private:
    struct Eigen {
        GiNaC::matrix A{1, 1};
        GiNaC::ex lambda;
        int line = 0;    ///< of the eigen-equation
        int block = -1;  ///< its display block (-1: inline)
        bool judged = false;
        bool valid = false;              ///< λ is an eigenvalue of A
        bool stated_eigenvalue = false;  ///< λ is none, the stated vector is an eigenvector (of used_lambda)
        GiNaC::ex used_lambda;           ///< the eigenvalue whose eigenspace n lies in
        std::vector<GiNaC::matrix> basis;  ///< of that eigenspace (empty: unknown, see why_not)
        bool stated_fits = false;          ///< the stated vector lies in it (and is `stated`)
        GiNaC::matrix stated{1, 1};
        std::string why_not;
    };
    /// Where the eigen-equation's A and λ are written (read when first needed).
    struct EigenSources {
        std::string matrix;
        std::size_t matrix_base = 0;
        std::string lambda;
        std::size_t lambda_base = 0;
    };
    struct Stated {
        std::string source;    ///< the side that states the vector
        std::size_t base = 0;  ///< file offset of its first byte
        const Side* side = nullptr;
        int line = 0;
    };
    /// What a vector name stands for; nullopt when unknown (with `why`).
    std::optional<GiNaC::matrix> named(const std::string& key, Comparisons& cmp, std::string* why);
    /// The tensor or vector whose components the model declares as results (X_{xx}…, X_{x}…).
    std::optional<GiNaC::matrix> declared(const std::string& key) const;
    /// The model declares some component X_{…} of `key` as a result.
    bool any_declared(const std::string& key) const;
    /// A side's value; `reference` (when given): the side is the model's quantity as a whole.
    std::optional<Value> read(std::string_view source, std::size_t base, Comparisons& cmp, std::string* why,
                              bool* reference);
    std::optional<Value> evaluate(const std::vector<Term>& terms, std::string_view source, std::size_t base,
                                  Comparisons& cmp, std::string* why);
    /// Judges the eigen-equation of `key` once: λ an eigenvalue, the eigenspace, the stated vector in it.
    Eigen* eigen(const std::string& key, Comparisons& cmp);
    /// The free names left in m (symbols of neither the model nor an eigenspace).
    std::vector<std::string> unknown_names(const GiNaC::matrix& m) const;
    /// The vectors whose components `e` uses, as keys (`n_{1}`), with the component names.
    std::map<std::string, std::vector<std::string>> component_uses(const GiNaC::ex& e) const;
    /// Component symbol → its value, for the components `e` uses of vectors with a known value.
    GiNaC::exmap component_values(const GiNaC::ex& e, Comparisons& cmp);
    bool judge_link(const Side& left, std::size_t left_base, const Side& right, std::size_t right_base,
                    Comparisons& cmp, EquationCheck& r);
    bool judge_eigen_equation(const std::string& key, const Side& left, std::size_t left_base,
                              std::size_t name_at, const Side& right, std::size_t right_base,
                              std::size_t right_name_at, Comparisons& cmp, EquationCheck& r);
    bool judge_definition(const std::string& key, const Side& side, std::size_t base,
                          const std::vector<Term>& terms, Comparisons& cmp, EquationCheck& r);
    /**
     * The text's side `source` (its `terms`, first byte at file offset `base`) that reads as `text` where
     * `right` belongs, wrong at the entries `wrong`: one sentence per wrong entry into r.wrong_terms; returns
     * the side corrected (its cells replaced, in the array's own scale, when it is s · [array] or s ·
     * (tuple); else `right`).
     */
    std::string corrected_side(const std::string& source, std::size_t base, const std::vector<Term>& terms,
                               const GiNaC::matrix& text, const GiNaC::matrix& right, bool vector,
                               const std::vector<std::pair<unsigned, unsigned>>& wrong, Comparisons& cmp,
                               EquationCheck& r);
    void flag_block(const Side& left, std::size_t left_base, const Side& right, std::size_t right_base,
                    Comparisons& cmp, EquationCheck& r);
    const MathRow* row_at(std::size_t offset) const;
    /// An entry's difference with accelerations (`\frac{d}{dt}(x, \dot x) = A (x, \dot x)`: ẍ = …) that vanishes on
    /// the motion: a combination of the model's Euler–Lagrange equations (on the constraints, for a model with them).
    bool holds_on_motion(const GiNaC::ex& difference, Comparisons& cmp, double tol) const;

    const Model& model_;
    const Derivation& d_;
    LatexContext& ctx_;
    ScalarEvaluator evaluate_;
    std::map<std::string, Eigen> eigen_;
    std::map<std::string, EigenSources> eigen_sources_;
    std::map<std::string, Stated> stated_;
    std::map<std::string, std::optional<GiNaC::matrix>> stated_values_;  ///< stated vectors, read once
    std::set<std::string> used_stated_;  ///< stated vectors a link used (for its notes)
    std::set<std::string> resolving_;    ///< names being resolved (a vector stated in terms of itself)
    std::map<std::string, GiNaC::symbol> coefficients_;  ///< free coefficients of eigenspaces, by name
    bool verifying_ = false;
    MatrixProvider model_matrix_;  ///< the model's mass and stiffness matrices by name (model_matrices.cpp)
    RowJudge row_judge_;           ///< a trial solution's amplitude equations, row by row
    ScalarJudge scalar_judge_;     ///< secular equations worked out from arrays
    VectorJudge vector_judge_;     ///< the shape of a mode, named by the text
    /// A column equation whose rows the row judge takes: agrees when every row does, else disagrees naming the
    /// rows. False (r untouched) when a row is no equation it judges.
    bool judge_rows(const GiNaC::matrix& a, const GiNaC::matrix& b, std::size_t at, Comparisons& cmp, EquationCheck& r);
};

}  // namespace eomgen::checker
