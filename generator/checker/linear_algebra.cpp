/** @file linear_algebra.cpp  A text's vectors and matrices: arrays, tuples, products, determinants and
 * eigen-equations, compared entry by entry with the model's quantities. */
#include "checker/linear_algebra.hpp"

#include "mechanics/bodies.hpp"

#include <algorithm>
#include <cstring>
#include <cctype>
#include <set>
#include <stdexcept>

namespace eomgen::checker {

using GiNaC::ex;

struct LinearAlgebra::Value {
    GiNaC::matrix m{1, 1};
    bool scalar = true;
};

namespace {

using namespace matrix_latex;

std::string dollars(const std::string& latex) {
    return "$" + latex + "$";
}

/// A vector's name as the report shows it: `n_{1}` → `$\\mathbf{n}_{1}$`.
std::string shown(const std::string& key) {
    if (key == "1" || key.rfind("\\hat{", 0) == 0) return dollars(key == "1" ? "\\mathbf{1}" : key);
    std::size_t end = key.find("_{");
    if (end == std::string::npos) end = key.find('\'');
    if (end == std::string::npos) end = key.size();
    const std::string bold =
        key[0] == '\\' ? "\\boldsymbol{" : "\\mathbf{";  // \mathbf does not make Greek bold
    return dollars(bold + key.substr(0, end) + "}" + key.substr(end));
}

/// a = b exactly (normal) or at random points.
bool same(const ex& a, const ex& b, Comparisons& cmp, double tol) {
    try {
        if (GiNaC::normal((a - b).expand()).is_zero()) return true;
    } catch (const std::exception&) {
    }
    return cmp.same(a, b, tol);
}

/// Determinants and eigenvalues are expanded symbolically for matrices up to 4×4 (a derivation's tensors and
/// mass matrices); a larger one is refused, with `why`, rather than expanded without bound.
bool small(const GiNaC::matrix& m, std::string* why) {
    if (m.rows() <= 4) return true;
    *why = "the determinant of a " + std::to_string(m.rows()) + "×" + std::to_string(m.cols()) +
           " matrix is not expanded (at most 4×4)";
    return false;
}

/// The names every text shares: the identity `\\mathbf{1}` and the unit vectors of the axes, `\\hat{i}`,
/// `\\hat{j}`,
/// `\\hat{k}` and `\\hat{x}`, `\\hat{y}`, `\\hat{z}`.
std::optional<GiNaC::matrix> builtin(const std::string& key) {
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
std::vector<GiNaC::matrix> null_space(GiNaC::matrix m) {
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

std::string entry_name(const GiNaC::matrix& m, unsigned i, unsigned j) {
    if (m.cols() == 1) {
        std::string s = "row " + std::to_string(i + 1);
        if (m.rows() == 3) s += std::string(" (") + char('x' + i) + ")";
        return s;
    }
    return "row " + std::to_string(i + 1) + ", column " + std::to_string(j + 1);
}

std::string pmatrix_latex(const GiNaC::matrix& m, Comparisons& cmp) {
    std::string s = "\\begin{pmatrix} ";
    for (unsigned i = 0; i < m.rows(); ++i) {
        for (unsigned j = 0; j < m.cols(); ++j) s += (j ? " & " : "") + cmp.latex(m(i, j));
        s += i + 1 < m.rows() ? " \\\\ " : " ";
    }
    return s + "\\end{pmatrix}";
}

}  // namespace

bool reads_as_array(const Side& side) {
    if (side.ok) return false;
    for (const char* e : {"a vector or tuple", "a matrix or array", "the function 'det'"})
        if (side.error.find(e) != std::string::npos) return true;
    return false;
}

const MathRow* LinearAlgebra::row_at(std::size_t offset) const {
    const MathRow* best = nullptr;
    for (const MathRow& r : d_.rows)
        if (r.offset <= offset && offset <= r.offset + r.text.size()) best = &r;
    return best;
}

bool LinearAlgebra::any_declared(const std::string& key) const {
    for (const Result& r : model_.results) {
        std::string c = canonical_name(r.latex);
        if (c.empty()) c = r.latex;
        if (c.rfind(key + "_{", 0) == 0) return true;
    }
    return false;
}

std::optional<GiNaC::matrix> LinearAlgebra::declared(const std::string& key) const {
    if (key.find('_') != std::string::npos) return std::nullopt;
    auto result = [&](const std::string& sub) -> std::optional<ex> {
        for (const Result& r : model_.results) {
            std::string c = canonical_name(r.latex);
            if (c.empty()) c = r.latex;
            if (c == key + "_{" + sub + "}") return r.expr.expr;
        }
        return std::nullopt;
    };
    GiNaC::matrix t(3, 3);
    bool tensor = true;
    for (int i = 0; i < 3 && tensor; ++i)
        for (int j = i; j < 3 && tensor; ++j) {
            const std::string a{char('x' + i), char('x' + j)}, b{char('x' + j), char('x' + i)};
            auto v = result(a);
            if (!v) v = result(b);
            if (!v)
                tensor = false;
            else
                t(unsigned(i), unsigned(j)) = t(unsigned(j), unsigned(i)) = *v;
        }
    if (tensor) return t;
    // Not declared: the inertia tensor of the model's one body, when its centre of mass stays at the origin
    // (about the centre of mass is then about the fixed point, in body axes: no other reading of I).
    if (key == "I" && model_.bodies.size() == 1 && !any_declared(key)) {
        const Body& b = model_.bodies[0];
        bool fixed = true;
        for (const ex& c : b.centre) fixed = fixed && c.is_zero();
        if (fixed) return body_inertia(b);
    }
    GiNaC::matrix v(3, 1);
    for (int i = 0; i < 3; ++i) {
        const auto x = result(std::string(1, char('x' + i)));
        if (!x) return std::nullopt;
        v(unsigned(i), 0) = *x;
    }
    return v;
}

void LinearAlgebra::note_link(const Side& left, std::size_t left_base, const Side& right,
                              std::size_t right_base) {
    const Side* sides[2] = {&left, &right};
    const std::size_t bases[2] = {left_base, right_base};
    std::vector<Term> terms[2];
    for (int k = 0; k < 2; ++k) {
        std::string why;
        if (sides[k]->empty() || !scan(sides[k]->source, 0, sides[k]->source.size(), terms[k], &why)) return;
    }
    // A stated vector: one side is its name alone.
    for (int k = 0; k < 2; ++k) {
        const auto& t = terms[k];
        if (t.size() != 1 || t[0].negative || t[0].factors.size() != 1 ||
            t[0].factors[0].kind != Factor::Name)
            continue;
        const std::string& key = t[0].factors[0].key;
        bool self = false;
        for (const Term& o : terms[1 - k])
            for (const Factor& f : o.factors) self = self || (f.kind == Factor::Name && f.key == key);
        if (!self && !stated_.count(key) && !builtin(key) && !declared(key) &&
            !(model_matrix_ && model_matrix_(key, nullptr)))
            stated_[key] = {sides[1 - k]->source, bases[1 - k] + sides[1 - k]->begin, sides[1 - k],
                            d_.position(bases[1 - k] + sides[1 - k]->begin).line};
    }
    // An eigen-equation: A · n = λ n.
    const auto& l = terms[0];
    const auto& r = terms[1];
    if (l.size() != 1 || r.size() != 1 || l[0].factors.size() < 2) return;
    const Factor& n = l[0].factors.back();
    if (n.kind != Factor::Name || r[0].factors.back().kind != Factor::Name ||
        r[0].factors.back().key != n.key)
        return;
    for (std::size_t k = 0; k + 1 < r[0].factors.size(); ++k)
        if (r[0].factors[k].kind != Factor::Scalar) return;
    bool matrix = false;
    for (std::size_t k = 0; k + 1 < l[0].factors.size(); ++k)
        matrix = matrix || l[0].factors[k].kind != Factor::Scalar;
    if (!matrix || eigen_.count(n.key)) return;
    Eigen e;
    e.line = d_.position(right_base + right.begin).line;
    const MathRow* row = row_at(left_base + left.begin);
    e.block = row && row->display ? row->block : -1;
    // A and λ are read when first needed (the names they use may be stated later in the text).
    eigen_sources_[n.key] = {left.source.substr(0, n.begin), left_base + left.begin,
                             right.source.substr(0, r[0].factors.back().begin), right_base + right.begin};
    eigen_[n.key] = e;
}

std::optional<LinearAlgebra::Value> LinearAlgebra::read(std::string_view source, std::size_t base,
                                                        Comparisons& cmp, std::string* why, bool* reference) {
    std::vector<Term> terms;
    if (!scan(source, 0, source.size(), terms, why)) return std::nullopt;
    if (reference) {
        *reference = false;
        if (terms.size() == 1 && terms[0].factors.size() == 1 && !terms[0].negative) {
            const Factor& f = terms[0].factors[0];
            if (f.kind == Factor::Name)
                *reference = declared(f.key).has_value() || (model_matrix_ && model_matrix_(f.key, nullptr));
            if (f.kind == Factor::Tuple || f.kind == Factor::Array) {
                bool all = true;
                for (const auto& row : f.cells)
                    for (const auto& [b, e] : row) {
                        LatexContext scratch = ctx_;
                        const Side s = parse_expression(source.substr(b, e - b), scratch);
                        all = all && s.ok && evaluate_(s, base + b).reference;
                    }
                *reference = all;
            }
        }
    }
    return evaluate(terms, source, base, cmp, why);
}

std::optional<LinearAlgebra::Value> LinearAlgebra::evaluate(const std::vector<Term>& terms,
                                                            std::string_view source, std::size_t base,
                                                            Comparisons& cmp, std::string* why) {
    auto scalar = [&](std::size_t b, std::size_t e) -> std::optional<ex> {
        const Side s = parse_expression(source.substr(b, e - b), ctx_);
        if (!s.ok) {
            *why = "cannot read " + dollars(std::string(source.substr(b, e - b))) + ": " + s.error;
            return std::nullopt;
        }
        const ScalarReading v = evaluate_(s, base + b);
        if (!v.ok) {
            *why = v.problem;
            return std::nullopt;
        }
        for (const auto& [name, fn] : ctx_.free_names)
            if (fn.kind == NameKind::Vector && v.value.has(fn.symbol)) {
                *why = "a vector inside a scalar expression (" + dollars(name) +
                       " in a derivative, a magnitude or a function) is not compared";
                return std::nullopt;
            }
        return v.value.subs(component_values(v.value, cmp));
    };
    std::optional<Value> total;
    for (const Term& t : terms) {
        ex coefficient = t.negative ? -1 : 1;
        std::optional<GiNaC::matrix> m;
        for (const Factor& f : t.factors) {
            Value v;
            if (f.kind == Factor::Scalar) {
                const auto x = scalar(f.begin, f.end);
                if (!x) return std::nullopt;
                v.m(0, 0) = *x;
            } else if (f.kind == Factor::Array || f.kind == Factor::Tuple || f.kind == Factor::DetArray) {
                const unsigned rows = unsigned(f.cells.size()), cols = unsigned(f.cells[0].size());
                for (const auto& row : f.cells)
                    if (row.size() != cols) {
                        *why = "the rows of an array have different lengths";
                        return std::nullopt;
                    }
                GiNaC::matrix a(rows, cols);
                for (unsigned i = 0; i < rows; ++i)
                    for (unsigned j = 0; j < cols; ++j) {
                        const auto x = scalar(f.cells[i][j].first, f.cells[i][j].second);
                        if (!x) return std::nullopt;
                        a(i, j) = *x;
                    }
                v.m = a;
                v.scalar = false;
                if (f.kind == Factor::DetArray) {
                    if (rows != cols) {
                        *why = "the determinant of a matrix that is not square";
                        return std::nullopt;
                    }
                    if (!small(a, why)) return std::nullopt;
                    v.m = GiNaC::matrix{{a.determinant()}};
                    v.scalar = true;
                }
            } else if (f.kind == Factor::Name) {
                const auto x = named(f.key, cmp, why);
                if (!x) return std::nullopt;
                v.m = *x;
                v.scalar = false;
            } else {  // Group, Det
                std::vector<Term> inner;
                if (!scan(source, f.inner_begin, f.inner_end, inner, why)) return std::nullopt;
                const auto x = evaluate(inner, source, base, cmp, why);
                if (!x) return std::nullopt;
                v = *x;
                if (f.kind == Factor::Det) {
                    if (v.scalar || v.m.rows() != v.m.cols()) {
                        *why = "the determinant of something that is not a square matrix";
                        return std::nullopt;
                    }
                    if (!small(v.m, why)) return std::nullopt;
                    v.m = GiNaC::matrix{{v.m.determinant()}};
                    v.scalar = true;
                }
            }
            if (v.scalar) {
                coefficient *= v.m(0, 0);
                continue;
            }
            if (!m) {
                m = v.m;
                continue;
            }
            const auto shape = [](const GiNaC::matrix& x) {
                return std::to_string(x.rows()) + "×" + std::to_string(x.cols());
            };
            if (f.op == Factor::Cross) {
                if (m->rows() != 3 || m->cols() != 1 || v.m.rows() != 3 || v.m.cols() != 1) {
                    *why = "a cross product of a " + shape(*m) + " and a " + shape(v.m) +
                           " (it needs two 3-vectors)";
                    return std::nullopt;
                }
                const GiNaC::matrix& a = *m;
                const GiNaC::matrix& b = v.m;
                m = GiNaC::matrix{{a(1, 0) * b(2, 0) - a(2, 0) * b(1, 0)},
                                  {a(2, 0) * b(0, 0) - a(0, 0) * b(2, 0)},
                                  {a(0, 0) * b(1, 0) - a(1, 0) * b(0, 0)}};
            } else if (f.op == Factor::Dot && m->cols() == 1 && v.m.cols() == 1 && m->rows() == v.m.rows()) {
                coefficient *= m->transpose().mul(v.m)(0, 0);
                m.reset();
            } else if (m->cols() == v.m.rows()) {
                m = m->mul(v.m);
            } else if (f.op == Factor::Dot && m->cols() == 1 && m->rows() == v.m.rows()) {
                m = m->transpose().mul(v.m);  // n · A: the vector as a row
            } else {
                *why = "a " + shape(*m) + " matrix times a " + shape(v.m) + " one";
                return std::nullopt;
            }
        }
        Value tv;
        if (m && m->rows() == 1 && m->cols() == 1) {
            coefficient *= (*m)(0, 0);
            m.reset();
        }
        if (m) {
            tv.m = m->mul_scalar(coefficient);
            tv.scalar = false;
        } else {
            tv.m(0, 0) = coefficient;
        }
        if (!total) {
            total = tv;
        } else if (total->scalar != tv.scalar || total->m.rows() != tv.m.rows() ||
                   total->m.cols() != tv.m.cols()) {
            *why = "a sum of a scalar, vectors or matrices of different shapes";
            return std::nullopt;
        } else {
            total->m = total->m.add(tv.m);
        }
    }
    return total;
}

std::optional<GiNaC::matrix> LinearAlgebra::named(const std::string& key, Comparisons& cmp,
                                                  std::string* why) {
    if (auto b = builtin(key)) return b;
    if (auto d = declared(key)) return d;
    if (model_matrix_)
        if (auto n = model_matrix_(key, nullptr)) return n->value;
    if (resolving_.count(key)) {
        *why = "the vector " + shown(key) + " is defined by itself";
        return std::nullopt;
    }
    resolving_.insert(key);
    struct Done {
        std::set<std::string>& s;
        const std::string& k;
        ~Done() { s.erase(k); }
    } done{resolving_, key};
    if (eigen_.count(key)) {
        Eigen* e = eigen(key, cmp);
        if (e && !e->basis.empty()) {
            if (e->stated_fits) return e->stated;
            GiNaC::matrix v(e->basis[0].rows(), 1);
            for (std::size_t k = 0; k < e->basis.size(); ++k) {
                const std::string name = "c_{" + std::to_string(k + 1) + "}";
                auto it = coefficients_.find(name);
                if (it == coefficients_.end())
                    it = coefficients_.emplace(name, GiNaC::symbol(name, name)).first;
                v = v.add(e->basis[k].mul_scalar(it->second));
            }
            return v;
        }
        *why = "the eigenvector " + shown(key) +
               " is not known: " + (e ? e->why_not : std::string("its eigen-equation cannot be read"));
        return std::nullopt;
    }
    auto s = stated_.find(key);
    if (s != stated_.end()) {
        // Read once: a stated vector may use others, each of which is read once too.
        auto memo = stated_values_.find(key);
        if (memo == stated_values_.end()) {
            std::string inner;
            const auto v = read(s->second.source, s->second.base, cmp, &inner, nullptr);
            std::optional<GiNaC::matrix> value;
            if (v && !v->scalar && unknown_names(v->m).empty()) value = v->m;
            // Read inside another vector's reading, a value may miss that vector: kept only when final.
            if (resolving_.size() == 1 || value)
                memo = stated_values_.emplace(key, value).first;
            else
                memo = stated_values_.end();
        }
        if (memo != stated_values_.end() && memo->second) {
            used_stated_.insert(key);
            return memo->second;
        }
    }
    *why = "the vector " + shown(key) +
           " is not known (the model declares no components of it, and the text "
           "states no value of it)";
    return std::nullopt;
}

std::vector<std::string> LinearAlgebra::unknown_names(const GiNaC::matrix& m) const {
    std::set<std::string> out;
    std::vector<ex> stack;
    for (unsigned i = 0; i < m.rows(); ++i)
        for (unsigned j = 0; j < m.cols(); ++j) stack.push_back(m(i, j));
    while (!stack.empty()) {
        const ex x = stack.back();
        stack.pop_back();
        if (GiNaC::is_a<GiNaC::symbol>(x)) {
            if (const FreeName* f = ctx_.free_name_of(x)) out.insert(f->name);
        }
        for (std::size_t k = 0; k < x.nops(); ++k) stack.push_back(x.op(k));
    }
    return {out.begin(), out.end()};
}

LinearAlgebra::Eigen* LinearAlgebra::eigen(const std::string& key, Comparisons& cmp) {
    auto it = eigen_.find(key);
    if (it == eigen_.end()) return nullptr;
    Eigen& e = it->second;
    if (e.judged) return &e;
    e.judged = true;
    const EigenSources& src = eigen_sources_.at(key);
    std::string why;
    const auto A = read(src.matrix, src.matrix_base, cmp, &why, nullptr);
    if (!A || A->scalar || A->m.rows() != A->m.cols()) {
        e.why_not = A ? "its matrix is not square" : why;
        return &e;
    }
    e.A = A->m;
    ex lambda = 1;
    if (!blank(src.lambda)) {
        const auto l = read(src.lambda, src.lambda_base, cmp, &why, nullptr);
        if (!l || !l->scalar) {
            e.why_not = l ? "its eigenvalue is not a scalar" : why;
            return &e;
        }
        lambda = l->m(0, 0);
    }
    e.lambda = lambda;
    if (!unknown_names(e.A).empty() || !unknown_names(GiNaC::matrix{{lambda}}).empty()) {
        e.why_not =
            "its eigen-equation (line " + std::to_string(e.line) + ") has symbols that are not the model's";
        return &e;
    }
    const unsigned n = e.A.rows();
    auto shifted = [&](const ex& x) {
        GiNaC::matrix s = e.A;
        for (unsigned i = 0; i < n; ++i) s(i, i) -= x;
        return s;
    };
    if (!small(e.A, &e.why_not)) return &e;
    e.valid = same(shifted(lambda).determinant(), 0, cmp, 1e-9);
    // The vector the text states, if any (read without itself: the eigen-equation is not used for it).
    std::optional<GiNaC::matrix> v;
    if (auto s = stated_.find(key); s != stated_.end()) {
        const auto x = read(s->second.source, s->second.base, cmp, &why, nullptr);
        if (x && !x->scalar && x->m.cols() == 1 && x->m.rows() == n && unknown_names(x->m).empty()) v = x->m;
    }
    e.used_lambda = lambda;
    if (!e.valid && v) {
        // λ is no eigenvalue: the stated vector's own, if it is an eigenvector.
        const GiNaC::matrix u = e.A.mul(*v);
        for (unsigned i = 0; i < n; ++i) {
            if (GiNaC::normal((*v)(i, 0)).is_zero()) continue;
            const ex mu = GiNaC::normal(u(i, 0) / (*v)(i, 0));
            bool all = true;
            for (unsigned k = 0; k < n; ++k) all = all && same(u(k, 0), mu * (*v)(k, 0), cmp, 1e-9);
            if (all) {
                e.used_lambda = mu;
                e.stated_eigenvalue = true;
            }
            break;
        }
        if (!e.stated_eigenvalue) {
            e.why_not = "its eigenvalue " + dollars(cmp.latex(lambda)) + " (line " + std::to_string(e.line) +
                        ") is not one of the matrix's, and the vector the text states is no eigenvector";
            return &e;
        }
    } else if (!e.valid) {
        e.why_not = "its eigenvalue " + dollars(cmp.latex(lambda)) + " (line " + std::to_string(e.line) +
                    ") is not one of the matrix's";
        return &e;
    }
    e.basis = null_space(shifted(e.used_lambda));
    if (e.basis.empty()) {
        e.why_not = "no eigenvector found";
        return &e;
    }
    if (v) {
        const GiNaC::matrix res = shifted(e.used_lambda).mul(*v);
        bool zero = true;
        for (unsigned i = 0; i < n; ++i) zero = zero && same(res(i, 0), 0, cmp, 1e-9);
        bool nonzero = false;
        for (unsigned i = 0; i < n; ++i) nonzero = nonzero || !GiNaC::normal((*v)(i, 0)).is_zero();
        if (zero && nonzero) {
            e.stated = *v;
            e.stated_fits = true;
        }
    }
    return &e;
}

std::map<std::string, std::vector<std::string>> LinearAlgebra::component_uses(const GiNaC::ex& e) const {
    std::map<std::string, std::vector<std::string>> out;
    std::vector<ex> stack{e};
    while (!stack.empty()) {
        const ex x = stack.back();
        stack.pop_back();
        if (GiNaC::is_a<GiNaC::symbol>(x)) {
            const FreeName* f = ctx_.free_name_of(x);
            std::string key;
            int index = 0;
            if (f && f->kind == NameKind::Unknown && component_of(f->name, &key, &index) &&
                (eigen_.count(key) || stated_.count(key))) {
                auto& v = out[key];
                if (std::find(v.begin(), v.end(), f->name) == v.end()) v.push_back(f->name);
            }
        }
        for (std::size_t k = 0; k < x.nops(); ++k) stack.push_back(x.op(k));
    }
    return out;
}

GiNaC::exmap LinearAlgebra::component_values(const GiNaC::ex& e, Comparisons& cmp) {
    GiNaC::exmap out;
    for (const auto& [key, names] : component_uses(e)) {
        if (resolving_.count(key)) continue;
        std::string why;
        const auto v = named(key, cmp, &why);
        if (!v || v->cols() != 1 || v->rows() != 3) continue;
        for (const std::string& name : names) {
            std::string k;
            int index = 0;
            component_of(name, &k, &index);
            out[ctx_.free_names.at(name).symbol] = (*v)(unsigned(index), 0);
        }
    }
    return out;
}

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
    for (int k = 0; k < 2; ++k) {
        const auto& t = terms[k];
        if (t.size() != 1 || t[0].negative || t[0].factors.size() != 1 ||
            t[0].factors[0].kind != Factor::Name)
            continue;
        const std::string& key = t[0].factors[0].key;
        bool self = false;
        for (const Term& o : terms[1 - k])
            for (const Factor& f : o.factors) self = self || (f.kind == Factor::Name && f.key == key);
        if (!self && eigen_.count(key))
            return judge_definition(key, *sides[1 - k], bases[1 - k], terms[1 - k], cmp, r);
    }
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
            r.reason = "the text's definition of " + shown(st->first) +
                       " (not a quantity of the model): compared where it is used";
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
    for (unsigned i = 0; i < a.rows(); ++i)
        for (unsigned j = 0; j < a.cols(); ++j)
            if (!same(a(i, j), b(i, j), cmp, tol)) wrong.emplace_back(i, j);
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
        if (!unknown.empty()) r.reason += " (in the text's own symbols)";
        eigen_note();
        return true;
    }
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
