/** @file matrix_latex.hpp  A side's arrays, tuples, determinants and vector names, scanned into terms of
 * factors with their places: the reading linear_algebra.hpp evaluates and judges. */
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace eomgen::checker::matrix_latex {

/// The cells of an array or tuple, by rows: byte ranges [first, second) in the side's source.
using Cells = std::vector<std::vector<std::pair<std::size_t, std::size_t>>>;

/// One factor of a term, as written.
struct Factor {
    /// Scalar: text the LaTeX parser reads; Array, Tuple: cells; Name: a vector or matrix by name; Group: a
    /// parenthesized matrix expression; Det: det of the expression inside; DetArray: `|array|`, vmatrix.
    enum Kind { Scalar, Array, Tuple, Name, Group, Det, DetArray } kind = Scalar;
    enum Op { Juxtapose, Dot, Cross } op = Juxtapose;  ///< the product with the factor before it
    std::size_t begin = 0, end = 0;                    ///< the factor in the side's source
    std::size_t inner_begin = 0, inner_end = 0;        ///< Group, Det: what it holds
    bool bars = false;                                  ///< Det: written between bars, `\left| … \right|`
    /// Det, Group: the plain capital letters M, K, T, V inside name the matrices of those names (`\det(K -
    /// \omega^2 M)`: what \det takes is a matrix, whatever its letters)
    bool letters = false;
    std::string key;  ///< Name: `n_{1}` (whatever its decoration), `I`, `1`, `\hat{k}`
    Cells cells;      ///< Array, Tuple, DetArray
    /// `^T`, `^{\top}`, `^{\mathsf{T}}`, `^\intercal` after it: transposed (a tuple, read as a column already,
    /// stays one: `[x, \theta]^T` is the column its text means)
    bool transpose = false;
};

/// A term of a sum: ± a product of factors, left to right.
struct Term {
    bool negative = false;
    std::vector<Factor> factors;
};

/**
 * Scans s[b, e) into terms. Arrays are `\begin{array|pmatrix|bmatrix|Bmatrix|matrix|smallmatrix}`, bare or in
 * `\left( \right)`/`\left[ \right]`; `vmatrix` and `\left| array \right|` are determinants, as is `\det` or
 * `\operatorname{det}` before a factor; `( … , … )` and `[ … , … ]` are tuples; `\mathbf`, `\boldsymbol`,
 * `\bm`,
 * `\vec`, `\underline`, `\overrightarrow`, `\hat` make names (with subscript and primes); `\cdot` and
 * `\times` set the next factor's product; with `matrix_letters`, a plain M, K, T or V is a name too (the inside
 * of `\det(…)`). False, with `why`, on a power or index of a matrix, an empty term, an unknown environment.
 */
bool scan(std::string_view s, std::size_t b, std::size_t e, std::vector<Term>& terms, std::string* why,
          bool matrix_letters = false);

/// s holds an environment, a determinant or a vector name: linear algebra, not a scalar, reads it.
bool mentions_array(std::string_view s);

/// Splits `n_{1x}` into its vector `n_{1}` and the component 0, 1, 2 (x, y, z); false when it is no
/// component.
bool component_of(const std::string& name, std::string* key, int* index);

/// s is only spaces, spacing commands and punctuation.
bool blank(std::string_view s);

/// [b, e) without the spaces at either end.
std::pair<std::size_t, std::size_t> trimmed(std::string_view s, std::size_t b, std::size_t e);

/// s without the spaces, spacing commands and `\cdot` it ends with (what stood before a vector's name).
std::string without_trailing_operators(std::string s);

/// The index of the one factor of a side's single term that is an array or a tuple, the others scalars; -1
/// otherwise.
int single_array(const std::vector<Term>& terms);

}  // namespace eomgen::checker::matrix_latex
