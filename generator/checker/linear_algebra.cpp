/** @file linear_algebra.cpp  A text's vectors and matrices: arrays, tuples, products, determinants and
 * eigen-equations, compared entry by entry with the model's quantities (linear_algebra_values.cpp reads a side
 * into its value). */
#include "checker/linear_algebra_internal.hpp"

#include "mechanics/bodies.hpp"

#include <algorithm>
#include <cstring>
#include <cctype>
#include <set>
#include <stdexcept>

namespace eomgen::checker {

using GiNaC::ex;
using namespace linear_algebra_detail;
using namespace matrix_latex;

namespace {
/// A correction on one line: the source's line breaks (inside arrays) as spaces.
std::string one_line(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '\n' || c == '\r') c = ' ';
        if (c == ' ' && !out.empty() && out.back() == ' ') continue;
        out += c;
    }
    return out;
}
}  // namespace

bool LinearAlgebra::check(const Side& left, std::size_t left_base, const Side& right, std::size_t right_base,
                          Comparisons& cmp, EquationCheck& r) {
    // `\left|\mathbf{V} - \omega^2 \mathbf{T}\right|`: a bold name of one of the model's matrices.
    auto names_model_matrix = [&](const std::string& source) {
        if (!model_matrix_) return false;
        for (const char* deco : {"\\mathbf{", "\\boldsymbol{", "\\bm{", "\\mathsf{"})
            for (std::size_t k = source.find(deco); k != std::string::npos; k = source.find(deco, k + 1)) {
                const std::size_t b = k + std::strlen(deco), e = source.find('}', b);
                if (e != std::string::npos && e == b + 1 && model_matrix_(source.substr(b, 1), nullptr)) return true;
            }
        return false;
    };
    bool involved = false;
    for (const Side* s : {&left, &right}) {
        if (s->empty()) return false;
        involved = involved || reads_as_array(*s) || mentions_array(s->source) ||
                   (s->ok && !component_uses(s->value).empty()) || names_model_matrix(s->source);
    }
    if (!involved) return false;
    judge_link(left, left_base, right, right_base, cmp, r);
    if (!verifying_) flag_block(left, left_base, right, right_base, cmp, r);
    r.corrected = one_line(r.corrected);
    return true;
}

bool LinearAlgebra::judge_rows(const GiNaC::matrix& a, const GiNaC::matrix& b, std::size_t at, Comparisons& cmp,
                               EquationCheck& r) {
    if (!row_judge_ || a.rows() < 2) return false;
    std::vector<EquationCheck> rows;
    for (unsigned i = 0; i < a.rows(); ++i) {
        EquationCheck row = r;
        row.notes.clear();
        if (!row_judge_(a(i, 0), b(i, 0), at, row) || row.verdict == Verdict::NotComparable ||
            row.verdict == Verdict::NotJudged)
            return false;
        rows.push_back(std::move(row));
    }
    const auto wrong =
        std::count_if(rows.begin(), rows.end(), [](const EquationCheck& x) { return x.verdict == Verdict::Disagrees; });
    r.compared_with = rows.front().compared_with;
    if (wrong == 0) {
        r.verdict = Verdict::Agrees;
        r.reason = "row by row: " + rows.front().reason;
        return true;
    }
    r.verdict = Verdict::Disagrees;
    r.reason = "row by row, as the amplitude equations it stands for";
    for (unsigned i = 0; i < rows.size(); ++i) {
        if (rows[i].verdict != Verdict::Disagrees) continue;
        const std::string row =
            "row " + std::to_string(i + 1) + " (" + dollars(cmp.latex(a(i, 0)) + " = " + cmp.latex(b(i, 0))) + ")";
        if (!rows[i].reason.empty()) r.wrong_terms.push_back(row + ": " + rows[i].reason);
        for (const std::string& w : rows[i].wrong_terms) r.wrong_terms.push_back(row + ": " + w);
        if (!rows[i].corrected.empty())
            r.notes.push_back("row " + std::to_string(i + 1) + " corrected: $" + rows[i].corrected + "$");
    }
    return true;
}

bool LinearAlgebra::judge_link(const Side& left, std::size_t left_base, const Side& right,
                               std::size_t right_base, Comparisons& cmp, EquationCheck& r) {
    const double tol = std::max(1e-9, left.rounding + right.rounding);
    std::vector<Term> terms[2];
    std::string why;
    const Side* sides[2] = {&left, &right};
    const std::size_t bases[2] = {left_base + left.begin, right_base + right.begin};
    for (int k = 0; k < 2; ++k)
        if (!scan(sides[k]->source, 0, sides[k]->source.size(), terms[k], &why)) {
            r.reason = "cannot read " + dollars(sides[k]->source) + ": " + why;
            return false;
        }
    // A stated eigenvector: n = (…), judged against its eigen-equation.
    for (int k = 0; k < 2; ++k)
        if (const std::string* key = lone_name(terms[k], terms[1 - k]); key && eigen_.count(*key))
            return judge_definition(*key, *sides[1 - k], bases[1 - k], terms[1 - k], cmp, r);
    // The text's statement of a vector that is not the model's: a definition, compared where it is used.
    for (int k = 0; k < 2; ++k) {
        const auto& t = terms[k];
        if (t.size() != 1 || t[0].negative || t[0].factors.size() != 1 ||
            t[0].factors[0].kind != Factor::Name)
            continue;
        const auto st = stated_.find(t[0].factors[0].key);
        if (st == stated_.end() || st->second.side != sides[1 - k]) continue;
        const auto x = read(sides[1 - k]->source, bases[1 - k], cmp, &why, nullptr);
        if (!x) {
            r.reason = why;
        } else if (const auto unknown = unknown_names(x->m); !unknown.empty()) {
            std::string list;
            for (const std::string& u : unknown) list += (list.empty() ? "" : ", ") + dollars(u);
            r.reason =
                "unknown symbols " + list + ": not symbols of the model (--map can say what they stand for)";
        } else {
            not_judged(r, Role::Definition,
                       "the text's definition of " + shown(st->first) +
                           " (not a quantity of the model): compared where it is used");
        }
        return false;
    }
    used_stated_.clear();
    // An eigen-equation A · n = λ n: λ must be an eigenvalue of A.
    const auto& l = terms[0];
    const auto& rt = terms[1];
    if (l.size() == 1 && rt.size() == 1 && l[0].factors.size() >= 2 &&
        l[0].factors.back().kind == Factor::Name && rt[0].factors.back().kind == Factor::Name &&
        rt[0].factors.back().key == l[0].factors.back().key) {
        const std::string& key = l[0].factors.back().key;
        bool scalar_lambda = true, matrix = false;
        for (std::size_t k = 0; k + 1 < rt[0].factors.size(); ++k)
            scalar_lambda = scalar_lambda && rt[0].factors[k].kind == Factor::Scalar;
        for (std::size_t k = 0; k + 1 < l[0].factors.size(); ++k)
            matrix = matrix || l[0].factors[k].kind != Factor::Scalar;
        if (scalar_lambda && matrix)
            return judge_eigen_equation(key, left, bases[0], l[0].factors.back().begin, right, bases[1],
                                        rt[0].factors.back().begin, cmp, r);
    }
    bool reference[2] = {false, false};
    std::optional<Value> v[2];
    for (int k = 0; k < 2; ++k) {
        v[k] = read(sides[k]->source, bases[k], cmp, &why, &reference[k]);
        if (!v[k]) {
            r.reason = why;
            return false;
        }
    }
    // `M = \begin{pmatrix} … \end{pmatrix}` with M a plain letter (a scalar to the reader): the model's matrix the
    // letter answers to, chosen for the text's matrix.
    std::string named_what;
    for (int k = 0; k < 2 && model_matrix_; ++k) {
        const auto& t = terms[k];
        if (v[1 - k]->scalar || t.size() != 1 || t[0].negative || t[0].factors.size() != 1) continue;
        std::string key;
        if (t[0].factors[0].kind == Factor::Name) {  // `\mathbf{T} = …`
            key = t[0].factors[0].key;
        } else if (v[k]->scalar && !reference[k] && sides[k]->ok && GiNaC::is_a<GiNaC::symbol>(sides[k]->value)) {
            const FreeName* f = ctx_.free_name_of(sides[k]->value);  // `M = …`, a plain letter
            if (f) key = f->name;
        }
        if (key.empty()) continue;
        if (auto n = model_matrix_(key, &v[1 - k]->m)) {
            v[k]->m = n->value;
            v[k]->scalar = false;
            reference[k] = true;
            named_what = n->what;
        }
    }
    if (!named_what.empty()) r.compared_with = named_what;
    // Shapes: a row against a column of the same entries is the same vector.
    GiNaC::matrix a = v[0]->m, b = v[1]->m;
    if (!v[0]->scalar && !v[1]->scalar && a.rows() == b.cols() && a.cols() == b.rows() &&
        (a.rows() == 1 || a.cols() == 1))
        b = b.transpose();
    if (v[0]->scalar != v[1]->scalar && (v[0]->scalar ? a(0, 0) : b(0, 0)).is_zero()) {
        if (v[0]->scalar)
            a = GiNaC::matrix(b.rows(), b.cols());
        else
            b = GiNaC::matrix(a.rows(), a.cols());
    } else if (v[0]->scalar != v[1]->scalar && vector_judge_ && [&] {
                   // `e_1 = (1, 1, 1)`: a name the text gives a column vector.
                   const int k = v[0]->scalar ? 0 : 1;
                   const GiNaC::matrix& col = k == 0 ? b : a;
                   if (col.cols() != 1 || !sides[k]->ok || !GiNaC::is_a<GiNaC::symbol>(sides[k]->value)) return false;
                   const FreeName* f = ctx_.free_name_of(sides[k]->value);
                   if (!f || f->kind != NameKind::Unknown) return false;
                   std::vector<GiNaC::ex> entries;
                   for (unsigned i = 0; i < col.rows(); ++i) entries.push_back(col(i, 0));
                   return vector_judge_(entries, sides[k]->source, right_base + right.begin, r);
               }()) {
        return true;
    } else if (v[0]->scalar != v[1]->scalar || a.rows() != b.rows() || a.cols() != b.cols()) {
        const auto shape = [](const Value& x) {
            return x.scalar ? std::string("a scalar")
                            : (x.m.cols() == 1 ? "a " + std::to_string(x.m.rows()) + "-vector"
                                               : "a " + std::to_string(x.m.rows()) + "×" +
                                                     std::to_string(x.m.cols()) + " matrix");
        };
        r.reason = "the sides have different shapes: " + shape(*v[0]) + " and " + shape(*v[1]);
        return false;
    }
    const bool vector = !v[0]->scalar || !v[1]->scalar;
    std::vector<std::pair<unsigned, unsigned>> wrong;
    bool motion = false;  // an entry with accelerations that holds on the motion (holds_on_motion)
    for (unsigned i = 0; i < a.rows(); ++i)
        for (unsigned j = 0; j < a.cols(); ++j)
            if (!same(a(i, j), b(i, j), cmp, tol)) {
                if (holds_on_motion(a(i, j) - b(i, j), cmp, tol)) {
                    motion = true;
                    continue;
                }
                wrong.emplace_back(i, j);
            }
    std::vector<std::string> unknown = unknown_names(a);
    for (const std::string& u : unknown_names(b)) unknown.push_back(u);
    std::sort(unknown.begin(), unknown.end());
    unknown.erase(std::unique(unknown.begin(), unknown.end()), unknown.end());
    const bool coefficients = !coefficients_.empty() && [&] {
        for (const auto& [name, sym] : coefficients_)
            for (unsigned i = 0; i < a.rows(); ++i)
                for (unsigned j = 0; j < a.cols(); ++j)
                    if (a(i, j).has(sym) || b(i, j).has(sym)) return true;
        return false;
    }();
    auto eigen_note = [&] {
        std::set<std::string> keys;
        for (const Term& t : terms[0])
            for (const Factor& f : t.factors)
                if (f.kind == Factor::Name && eigen_.count(f.key)) keys.insert(f.key);
        for (const Term& t : terms[1])
            for (const Factor& f : t.factors)
                if (f.kind == Factor::Name && eigen_.count(f.key)) keys.insert(f.key);
        for (const Side* s : sides)
            if (s->ok)
                for (const auto& [key, names] : component_uses(s->value)) keys.insert(key);
        for (const std::string& key : used_stated_)
            if (!eigen_.count(key))
                r.notes.push_back("with " + shown(key) + " as the text states it (line " +
                                  std::to_string(stated_.at(key).line) + ")");
        for (const std::string& key : keys) {
            if (!eigen_.count(key)) continue;
            const Eigen& e = eigen_.at(key);
            if (e.basis.empty()) continue;
            r.notes.push_back(e.stated_fits
                                  ? "with " + shown(key) + " as the text states it (line " +
                                        std::to_string(stated_.at(key).line) + ")"
                                  : "with " + shown(key) + " any eigenvector of its eigen-equation (line " +
                                        std::to_string(e.line) + ")" +
                                        (coefficients ? ", $c_{k}$ its free coefficients" : ""));
        }
    };
    if (wrong.empty()) {
        r.verdict = Verdict::Agrees;
        r.compared_with = !named_what.empty() ? named_what
                          : reference[0] || reference[1]
                              ? (vector ? "the model's quantities, entry by entry" : "the model's quantity")
                              : "an identity";
        r.reason = vector ? "equal entry by entry" : "both sides are equal";
        if (motion) {
            r.compared_with = vector ? "the equations of motion, entry by entry" : "the equations of motion";
            r.reason = vector ? "equal entry by entry, the entries with accelerations on the equations of motion"
                              : "equal on the equations of motion";
        }
        if (!unknown.empty()) r.reason += " (in the text's own symbols)";
        eigen_note();
        return true;
    }
    if (!unknown.empty() && a.cols() == 1 && judge_rows(a, b, right_base + right.begin, cmp, r)) return true;
    if (!unknown.empty() && !vector && scalar_judge_ && scalar_judge_(a(0, 0), left, b(0, 0), right, r)) return true;
    if (!unknown.empty()) {
        std::string list;
        for (const std::string& u : unknown) list += (list.empty() ? "" : ", ") + dollars(u);
        r.reason =
            "unknown symbols " + list + ": not symbols of the model (--map can say what they stand for)";
        return false;
    }
    if (coefficients) {
        // Any multiple of an eigenvector: a relation homogeneous in its coefficients fails for them all, one
        // that is not (a normalization, n₁ × n₂ = −n₃) depends on the scale, which the text does not state.
        GiNaC::exmap zero;
        for (const auto& [name, sym] : coefficients_) zero[sym] = 0;
        bool real = false;
        for (const auto& [i, j] : wrong) {
            const ex d = a(i, j) - b(i, j);
            bool scaled = false;
            for (const auto& [name, sym] : coefficients_) scaled = scaled || d.has(sym);
            real = real || !scaled || same(d.subs(zero), 0, cmp, tol);
        }
        if (!real) {
            r.reason = "it depends on the length of an eigenvector that the text does not state as one";
            eigen_note();
            return false;
        }
    }
    r.verdict = Verdict::Disagrees;
    eigen_note();
    // The reference: the model's side. Without one, the two sides are shown and nothing is corrected.
    const int ref = reference[1] && !reference[0] ? 1 : 0;
    const GiNaC::matrix& R = ref == 0 ? a : b;
    const GiNaC::matrix& T = ref == 0 ? b : a;
    GiNaC::matrix diff(T.rows(), T.cols());
    for (unsigned i = 0; i < T.rows(); ++i)
        for (unsigned j = 0; j < T.cols(); ++j) diff(i, j) = GiNaC::normal(T(i, j) - R(i, j));
    r.difference = vector ? pmatrix_latex(diff, cmp) : cmp.latex(diff(0, 0));
    if (!reference[ref]) {
        r.compared_with = vector ? "the two sides, entry by entry" : "the two sides";
        for (const auto& [i, j] : wrong)
            r.wrong_terms.push_back((vector ? entry_name(T, i, j) + ": " : std::string()) +
                                    "the left side is " + dollars(cmp.latex(a(i, j))) + ", the right side " +
                                    dollars(cmp.latex(b(i, j))));
        return true;
    }
    r.compared_with = named_what.empty() ? "the model's quantities, entry by entry" : named_what;
    const std::string corrected =
        corrected_side(sides[1 - ref]->source, bases[1 - ref], terms[1 - ref], T, R, vector, wrong, cmp, r);
    r.corrected = ref == 0 ? left.source + " = " + corrected : corrected + " = " + right.source;
    return true;
}

std::string LinearAlgebra::corrected_side(const std::string& source, std::size_t base,
                                          const std::vector<Term>& terms, const GiNaC::matrix& text,
                                          const GiNaC::matrix& right, bool vector,
                                          const std::vector<std::pair<unsigned, unsigned>>& wrong,
                                          Comparisons& cmp, EquationCheck& r) {
    // s · [array] or s · (tuple): the right cell in the array's own scale, s the product of the scalar
    // factors.
    const int arr = single_array(terms);
    ex scale = 1;
    if (arr >= 0)
        for (std::size_t k = 0; k < terms[0].factors.size(); ++k) {
            if (int(k) == arr) continue;
            const Factor& f = terms[0].factors[k];
            const Side s = parse_expression(source.substr(f.begin, f.end - f.begin), ctx_);
            const ScalarReading x = s.ok ? evaluate_(s, base + f.begin) : ScalarReading{};
            scale = x.ok ? scale * x.value : ex(0);
        }
    const Cells* cells = nullptr;
    if (arr >= 0 && vector && !scale.is_zero()) {
        const Cells& c = terms[0].factors[std::size_t(arr)].cells;
        if (c.size() == text.rows() && c[0].size() == (text.cols() == 1 ? 1 : text.cols())) cells = &c;
    }
    std::vector<std::pair<std::pair<std::size_t, std::size_t>, std::string>> splices;
    for (const auto& [i, j] : wrong) {
        const std::string where = vector ? entry_name(text, i, j) + ": " : "";
        if (!cells) {
            r.wrong_terms.push_back(where + dollars(cmp.latex(text(i, j))) + " where " +
                                    dollars(cmp.latex(right(i, j))) + " belongs");
            continue;
        }
        const auto& cell = (*cells)[i][text.cols() == 1 ? 0 : j];
        const std::string right_cell = cmp.latex(GiNaC::normal(right(i, j) / scale));
        r.wrong_terms.push_back(where + "the text's entry " +
                                dollars(source.substr(cell.first, cell.second - cell.first)) + " where " +
                                dollars(right_cell) + " belongs" +
                                (scale.is_equal(1) ? "" : " (times " + dollars(cmp.latex(scale)) + ")"));
        splices.push_back({cell, right_cell});
    }
    if (!cells) return vector ? pmatrix_latex(right, cmp) : cmp.latex(right(0, 0));
    std::string corrected = source;
    std::sort(splices.begin(), splices.end());
    for (auto it = splices.rbegin(); it != splices.rend(); ++it)
        corrected.replace(it->first.first, it->first.second - it->first.first, it->second);
    return corrected;
}

bool LinearAlgebra::judge_eigen_equation(const std::string& key, const Side& left, std::size_t left_base,
                                         std::size_t name_at, const Side& right, std::size_t right_base,
                                         std::size_t right_name_at, Comparisons& cmp, EquationCheck& r) {
    std::string why;
    const auto A = read(left.source.substr(0, name_at), left_base, cmp, &why, nullptr);
    std::optional<Value> l;
    const std::string lambda_source = right.source.substr(0, right_name_at);
    if (blank(lambda_source))
        l = Value{GiNaC::matrix{{1}}, true};
    else
        l = read(lambda_source, right_base, cmp, &why, nullptr);
    if (!A || !l) {
        r.reason = why;
        return false;
    }
    if (A->scalar || A->m.rows() != A->m.cols() || !l->scalar) {
        r.reason = "not an eigen-equation: a square matrix times a vector, a scalar times the vector";
        return false;
    }
    std::vector<std::string> unknown = unknown_names(A->m);
    for (const std::string& u : unknown_names(l->m)) unknown.push_back(u);
    if (!unknown.empty()) {
        std::string list;
        for (const std::string& u : unknown) list += (list.empty() ? "" : ", ") + dollars(u);
        r.reason =
            "unknown symbols " + list + ": not symbols of the model (--map can say what they stand for)";
        return false;
    }
    if (!small(A->m, &r.reason)) return false;
    const ex lambda = l->m(0, 0);
    GiNaC::matrix s = A->m;
    for (unsigned i = 0; i < s.rows(); ++i) s(i, i) -= lambda;
    const ex det = GiNaC::normal(s.determinant());
    std::string matrix_source = left.source.substr(0, name_at);
    const auto t = trimmed(matrix_source, 0, matrix_source.size());
    matrix_source = matrix_source.substr(t.first, t.second - t.first);
    matrix_source = without_trailing_operators(matrix_source);
    r.compared_with = "the eigenvalues of " + dollars(matrix_source);
    const Eigen* e = eigen(key, cmp);
    const bool stated = stated_.count(key) != 0;
    if (same(det, 0, cmp, 1e-9)) {
        r.verdict = Verdict::Agrees;
        r.reason = dollars(cmp.latex(lambda)) + " is an eigenvalue: $\\det(A - \\lambda 1) = 0$";
        if (e && e->stated_fits && e->used_lambda.is_equal(lambda))
            r.notes.push_back(shown(key) + " as the text states it (line " +
                              std::to_string(stated_.at(key).line) + ") satisfies it");
        else if (stated && e && !e->stated_fits)
            r.notes.push_back(shown(key) + " as the text states it (line " +
                              std::to_string(stated_.at(key).line) + ") does not satisfy it");
        return true;
    }
    r.verdict = Verdict::Disagrees;
    r.difference = "\\det(A - \\lambda 1) = " + cmp.latex(det);
    const std::string written = without_trailing_operators(lambda_source);
    r.wrong_terms.push_back(dollars(written) + " (" + dollars(cmp.latex(lambda)) +
                            ") is not an eigenvalue: $\\det(A - \\lambda 1) = " + cmp.latex(det) +
                            " \\neq 0$");
    if (e && e->stated_eigenvalue) {
        r.wrong_terms.push_back(
            shown(key) + " as the text states it (line " + std::to_string(stated_.at(key).line) +
            ") is an eigenvector with the eigenvalue " + dollars(cmp.latex(e->used_lambda)));
        r.corrected =
            left.source + " = " + cmp.latex(e->used_lambda) + " " + right.source.substr(right_name_at);
    }
    return true;
}

bool LinearAlgebra::judge_definition(const std::string& key, const Side& side, std::size_t base,
                                     const std::vector<Term>& terms, Comparisons& cmp, EquationCheck& r) {
    std::string why;
    const auto v = read(side.source, base, cmp, &why, nullptr);
    if (!v) {
        r.reason = why;
        return false;
    }
    const std::vector<std::string> unknown = unknown_names(v->m);
    if (!unknown.empty()) {
        std::string list;
        for (const std::string& u : unknown) list += (list.empty() ? "" : ", ") + dollars(u);
        r.reason = "the components of " + shown(key) + " are written in unknown symbols " + list;
        return false;
    }
    Eigen* e = eigen(key, cmp);
    if (!e || e->basis.empty()) {
        r.reason =
            "the eigenvector " + shown(key) + " cannot be compared: " + (e ? e->why_not : std::string());
        return false;
    }
    const unsigned n = e->A.rows();
    if (v->scalar || v->m.cols() != 1 || v->m.rows() != n) {
        r.reason = shown(key) + " is not a vector of " + std::to_string(n) + " components";
        return false;
    }
    r.compared_with = "the eigenvectors of its eigen-equation (line " + std::to_string(e->line) + ") for " +
                      dollars(cmp.latex(e->used_lambda));
    const GiNaC::matrix& x = v->m;
    GiNaC::matrix s = e->A;
    for (unsigned i = 0; i < n; ++i) s(i, i) -= e->used_lambda;
    const GiNaC::matrix res = s.mul(x);
    bool zero = true, nonzero = false;
    for (unsigned i = 0; i < n; ++i) {
        zero = zero && same(res(i, 0), 0, cmp, 1e-9);
        nonzero = nonzero || !GiNaC::normal(x(i, 0)).is_zero();
    }
    if (zero && nonzero) {
        r.verdict = Verdict::Agrees;
        r.reason =
            "an eigenvector: $(A - \\lambda 1) n = 0$ with $\\lambda = " + cmp.latex(e->used_lambda) + "$";
        return true;
    }
    r.verdict = Verdict::Disagrees;
    r.difference = "(A - \\lambda 1) n = " + pmatrix_latex(res, cmp);
    if (e->basis.size() != 1 || !nonzero) {
        for (unsigned i = 0; i < n; ++i)
            if (!same(res(i, 0), 0, cmp, 1e-9))
                r.wrong_terms.push_back(entry_name(res, i, 0) + " of $(A - \\lambda 1) n$ is " +
                                        dollars(cmp.latex(res(i, 0))) + ", not 0");
        return true;
    }
    // One eigenvector up to scale: the scale most components agree with (unit length breaking ties).
    const GiNaC::matrix& basis = e->basis[0];
    ex best = 0;
    int best_matches = -1;
    bool best_unit = false;
    for (unsigned i = 0; i < n; ++i) {
        if (GiNaC::normal(basis(i, 0)).is_zero()) continue;
        const ex c = GiNaC::normal(x(i, 0) / basis(i, 0));
        if (c.is_zero()) continue;
        int matches = 0;
        for (unsigned k = 0; k < n; ++k) matches += same(x(k, 0), c * basis(k, 0), cmp, 1e-9) ? 1 : 0;
        ex norm2 = 0;
        for (unsigned k = 0; k < n; ++k) norm2 += GiNaC::pow(c * basis(k, 0), 2);
        const bool unit = same(norm2, 1, cmp, 1e-9);
        if (matches > best_matches || (matches == best_matches && unit && !best_unit)) {
            best = c;
            best_matches = matches;
            best_unit = unit;
        }
    }
    if (best.is_zero()) best = 1;
    GiNaC::matrix right(n, 1);
    for (unsigned i = 0; i < n; ++i) right(i, 0) = GiNaC::normal(best * basis(i, 0));
    std::vector<std::pair<unsigned, unsigned>> wrong;
    for (unsigned i = 0; i < n; ++i)
        if (!same(x(i, 0), right(i, 0), cmp, 1e-9)) wrong.emplace_back(i, 0);
    const std::string corrected = corrected_side(side.source, base, terms, x, right, true, wrong, cmp, r);
    r.corrected = r.equation.substr(0, r.equation.find(" = ")) + " = " + corrected;
    return true;
}

void LinearAlgebra::flag_block(const Side& left, std::size_t left_base, const Side& right,
                               std::size_t right_base, Comparisons& cmp, EquationCheck& r) {
    const MathRow* row = row_at(left_base + left.begin);
    if (!row || !row->display) return;
    std::string subject;
    int subject_line = 0;
    for (const auto& [key, e] : eigen_)
        if (e.block == row->block && (subject.empty() || e.line < subject_line)) {
            subject = key;
            subject_line = e.line;
        }
    if (subject.empty()) return;
    std::map<std::string, std::vector<std::string>> uses;
    for (const Side* s : {&left, &right})
        if (s->ok)
            for (const auto& [k, names] : component_uses(s->value))
                uses[k].insert(uses[k].end(), names.begin(), names.end());
    const auto u = subject.find("_{");
    if (u == std::string::npos) return;
    const std::string sub_subject = subject.substr(u + 2, subject.size() - u - 3);
    // Component names inside arrays are not in the sides' values: read them from the sources.
    for (const Side* s : {&left, &right}) {
        if (s->ok) continue;
        for (const auto& [name, fn] : ctx_.free_names) {
            std::string key;
            int index = 0;
            if (!component_of(name, &key, &index) || !eigen_.count(key)) continue;
            // The name as the text writes it, subscript with or without a space: n_{2 x} or n_{2x}.
            const std::string base = name.substr(0, name.find("_{"));
            const std::string sub = name.substr(name.find("_{") + 2, name.size() - name.find("_{") - 3);
            const std::string spaced = base + "_{" + sub.substr(0, sub.size() - 1) + " " + sub.back() + "}";
            if (s->source.find(name) != std::string::npos || s->source.find(spaced) != std::string::npos) {
                auto& v = uses[key];
                if (std::find(v.begin(), v.end(), name) == v.end()) v.push_back(name);
            }
        }
    }
    for (const auto& [key, names] : uses) {
        if (key == subject || key.find("_{") == std::string::npos) continue;
        std::string list;
        for (const std::string& n : names) list += (list.empty() ? "" : ", ") + dollars(n);
        r.notes.push_back("row " + std::to_string(row->row_in_block + 1) +
                          " of this display uses the components of " + shown(key) + " (" + list +
                          ") in the display about " + shown(subject) + " (its eigen-equation, line " +
                          std::to_string(subject_line) + ")");
        if (r.verdict != Verdict::Disagrees) continue;
        // The row with the subject's components instead: the correction when it holds.
        const std::string other = key.substr(key.find("_{") + 2, key.size() - key.find("_{") - 3);
        const std::string letter = key.substr(0, key.find("_{"));
        auto renamed = [&](std::string s) {
            const std::string from = letter + "_{" + other;
            for (std::size_t p = s.find(from); p != std::string::npos; p = s.find(from, p + 1)) {
                const std::size_t after = p + from.size();
                if (after < s.size() &&
                    (s[after] == ' ' || s[after] == 'x' || s[after] == 'y' || s[after] == 'z'))
                    s.replace(p + letter.size() + 2, other.size(), sub_subject);
            }
            return s;
        };
        const std::string fixed = renamed(left.source) + " = " + renamed(right.source);
        const std::vector<Chain> chains = parse_math(fixed, ctx_);
        if (chains.size() != 1 || chains[0].sides.size() != 2) continue;
        EquationCheck again;
        verifying_ = true;
        check(chains[0].sides[0], left_base, chains[0].sides[1], left_base, cmp, again);
        verifying_ = false;
        if (again.verdict == Verdict::Agrees) {
            r.corrected = fixed;
            r.wrong_terms.insert(r.wrong_terms.begin(),
                                 "the row holds with the components of " + shown(subject));
        }
    }
}

}  // namespace eomgen::checker
