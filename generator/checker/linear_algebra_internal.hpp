/** @file linear_algebra_internal.hpp  What linear_algebra.cpp (judging a link) and linear_algebra_values.cpp
 * (reading a side into a value, what names stand for) share: the value type and small helpers. Internal to the
 * checker. */
#pragma once

#include "checker/linear_algebra.hpp"

#include <optional>
#include <string>
#include <vector>

namespace eomgen::checker {

struct LinearAlgebra::Value {
    GiNaC::matrix m{1, 1};
    bool scalar = true;
};

namespace linear_algebra_detail {

using GiNaC::ex;

using namespace matrix_latex;

inline std::string dollars(const std::string& latex) {
    return "$" + latex + "$";
}

/// A vector's name as the report shows it: `n_{1}` → `$\\mathbf{n}_{1}$`.
inline std::string shown(const std::string& key) {
    if (key == "1" || key.rfind("\\hat{", 0) == 0) return dollars(key == "1" ? "\\mathbf{1}" : key);
    std::size_t end = key.find("_{");
    if (end == std::string::npos) end = key.find('\'');
    if (end == std::string::npos) end = key.size();
    const std::string bold =
        key[0] == '\\' ? "\\boldsymbol{" : "\\mathbf{";  // \mathbf does not make Greek bold
    return dollars(bold + key.substr(0, end) + "}" + key.substr(end));
}

/// a = b exactly (normal) or at random points.
inline bool same(const ex& a, const ex& b, Comparisons& cmp, double tol) {
    try {
        if (GiNaC::normal((a - b).expand()).is_zero()) return true;
    } catch (const std::exception&) {
    }
    return cmp.same(a, b, tol);
}

/// Determinants and eigenvalues are expanded symbolically for matrices up to 4×4 (a derivation's tensors and
/// mass matrices); a larger one is refused, with `why`, rather than expanded without bound.
inline bool small(const GiNaC::matrix& m, std::string* why) {
    if (m.rows() <= 4) return true;
    *why = "the determinant of a " + std::to_string(m.rows()) + "×" + std::to_string(m.cols()) +
           " matrix is not expanded (at most 4×4)";
    return false;
}

/// The names every text shares: the identity `\\mathbf{1}` and the unit vectors of the axes, `\\hat{i}`,
/// `\\hat{j}`,
/// `\\hat{k}` and `\\hat{x}`, `\\hat{y}`, `\\hat{z}`.
inline std::optional<GiNaC::matrix> builtin(const std::string& key) {
    if (key == "1") return GiNaC::matrix{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int k = 0; k < 3; ++k)
        if (key == std::string("\\hat{") + "ijk"[k] + "}" || key == std::string("\\hat{") + "xyz"[k] + "}") {
            GiNaC::matrix u(3, 1);
            u(unsigned(k), 0) = 1;
            return u;
        }
    return std::nullopt;
}

/// A basis of the null space of m (Gaussian elimination, pivots decided by normal()).
inline std::vector<GiNaC::matrix> null_space(GiNaC::matrix m) {
    const unsigned rows = m.rows(), cols = m.cols();
    std::vector<int> pivot_of_col(cols, -1);
    unsigned r = 0;
    for (unsigned c = 0; c < cols && r < rows; ++c) {
        unsigned p = r;
        while (p < rows && GiNaC::normal(m(p, c)).is_zero()) ++p;
        if (p == rows) continue;
        for (unsigned k = 0; k < cols; ++k) std::swap(m(r, k), m(p, k));
        const ex pv = m(r, c);
        for (unsigned k = 0; k < cols; ++k) m(r, k) = GiNaC::normal(m(r, k) / pv);
        for (unsigned q = 0; q < rows; ++q) {
            if (q == r) continue;
            const ex f = m(q, c);
            for (unsigned k = 0; k < cols; ++k) m(q, k) = GiNaC::normal(m(q, k) - f * m(r, k));
        }
        pivot_of_col[c] = int(r);
        ++r;
    }
    std::vector<GiNaC::matrix> basis;
    for (unsigned f = 0; f < cols; ++f) {
        if (pivot_of_col[f] >= 0) continue;
        GiNaC::matrix v(cols, 1);
        v(f, 0) = 1;
        for (unsigned c = 0; c < cols; ++c)
            if (pivot_of_col[c] >= 0) v(c, 0) = -m(unsigned(pivot_of_col[c]), f);
        basis.push_back(v);
    }
    return basis;
}

inline std::string entry_name(const GiNaC::matrix& m, unsigned i, unsigned j) {
    if (m.cols() == 1) {
        std::string s = "row " + std::to_string(i + 1);
        if (m.rows() == 3) s += std::string(" (") + char('x' + i) + ")";
        return s;
    }
    return "row " + std::to_string(i + 1) + ", column " + std::to_string(j + 1);
}

inline std::string pmatrix_latex(const GiNaC::matrix& m, Comparisons& cmp) {
    std::string s = "\\begin{pmatrix} ";
    for (unsigned i = 0; i < m.rows(); ++i) {
        for (unsigned j = 0; j < m.cols(); ++j) s += (j ? " & " : "") + cmp.latex(m(i, j));
        s += i + 1 < m.rows() ? " \\\\ " : " ";
    }
    return s + "\\end{pmatrix}";
}

/// The key of a side that is one name alone (`\mathbf{n}_{1}`, not negated) that the other side does not use, or
/// nullptr: a vector or matrix the link states, or an eigenvector it gives.
inline const std::string* lone_name(const std::vector<Term>& side, const std::vector<Term>& other) {
    if (side.size() != 1 || side[0].negative || side[0].factors.size() != 1 || side[0].factors[0].kind != Factor::Name)
        return nullptr;
    const std::string& key = side[0].factors[0].key;
    for (const Term& o : other)
        for (const Factor& f : o.factors)
            if (f.kind == Factor::Name && f.key == key) return nullptr;
    return &key;
}

}  // namespace linear_algebra_detail

}  // namespace eomgen::checker
