/** @file linear_algebra_values.cpp  A side of a text's linear algebra read into a value: what its names stand for
 * (the model's declared tensors and vectors, its mass and stiffness matrices, the text's stated vectors and
 * eigenvectors), and products, sums and determinants of them. linear_algebra.cpp judges the links. */
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
        const std::string* name = lone_name(terms[k], terms[1 - k]);
        if (!name) continue;
        const std::string& key = *name;
        if (!stated_.count(key) && !builtin(key) && !declared(key) && !(model_matrix_ && model_matrix_(key, nullptr)))
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

bool LinearAlgebra::holds_on_motion(const ex& difference, Comparisons& cmp, double tol) const {
    bool accelerations = false;
    for (const Coordinate& q : model_.coordinates) accelerations = accelerations || difference.has(q.qdd);
    if (!accelerations) return false;
    return model_.constraints.empty() ? cmp.equation_of_motion(difference, tol)
                                      : cmp.vanishes_on_constrained_motion(difference, tol);
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
    // A scalar written `text`, read as if it stood at source offset b (the definitions in force there).
    auto scalar_text = [&](const std::string& text, std::size_t b) -> std::optional<ex> {
        const Side s = parse_expression(text, ctx_);
        if (!s.ok) {
            *why = "cannot read " + dollars(text) + ": " + s.error;
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
    auto scalar = [&](std::size_t b, std::size_t e) { return scalar_text(std::string(source.substr(b, e - b)), b); };
    // `\frac{d}{dt}` before an array or a tuple: the time derivative of each entry (a state-space form, d/dt (x, ẋ)).
    const auto time_derivative_order = [&](const Factor& f) {
        if (f.kind != Factor::Scalar) return 0;
        std::string op;
        for (const char c : source.substr(f.begin, f.end - f.begin))
            if (!std::isspace(static_cast<unsigned char>(c))) op += c;
        for (const char* one : {"\\frac{d}{dt}", "\\frac{\\mathrm{d}}{\\mathrm{d}t}", "\\frac{\\mathrm{d}}{dt}", "d/dt"})
            if (op == one) return 1;
        for (const char* two : {"\\frac{d^2}{dt^2}", "\\frac{d^{2}}{dt^{2}}", "\\frac{\\mathrm{d}^2}{\\mathrm{d}t^2}",
                                "\\frac{\\mathrm{d}^{2}}{\\mathrm{d}t^{2}}"})
            if (op == two) return 2;
        return 0;
    };
    std::optional<Value> total;
    for (const Term& t : terms) {
        ex coefficient = t.negative ? -1 : 1;
        std::optional<GiNaC::matrix> m;
        int differentiate = 0;  // the order of a d/dt just read, for the array after it
        for (std::size_t q = 0; q < t.factors.size(); ++q) {
            const Factor& f = t.factors[q];
            if (const int order = time_derivative_order(f);
                order > 0 && q + 1 < t.factors.size() &&
                (t.factors[q + 1].kind == Factor::Array || t.factors[q + 1].kind == Factor::Tuple)) {
                differentiate = order;
                continue;
            }
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
                        const auto [b, e] = f.cells[i][j];
                        std::optional<ex> x;
                        if (differentiate > 0) {  // each entry differentiated as `\frac{d}{dt}\left(…\right)` reads it
                            std::string text(source.substr(b, e - b));
                            for (int k = 0; k < differentiate; ++k) text = "\\frac{d}{dt}\\left(" + text + "\\right)";
                            x = scalar_text(text, b);
                        } else {
                            x = scalar(b, e);
                        }
                        if (!x) return std::nullopt;
                        a(i, j) = *x;
                    }
                differentiate = 0;
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
                if (!scan(source, f.inner_begin, f.inner_end, inner, why, f.letters)) return std::nullopt;
                const auto x = evaluate(inner, source, base, cmp, why);
                if (!x) return std::nullopt;
                v = *x;
                if (f.kind == Factor::Det) {
                    if (f.bars && !v.scalar && (v.m.rows() == 1 || v.m.cols() == 1)) {
                        *why = "the magnitude |v| of a vector is not read";
                        return std::nullopt;
                    }
                    if (v.scalar || v.m.rows() != v.m.cols()) {
                        *why = "the determinant of something that is not a square matrix";
                        return std::nullopt;
                    }
                    if (!small(v.m, why)) return std::nullopt;
                    v.m = GiNaC::matrix{{v.m.determinant()}};
                    v.scalar = true;
                }
            }
            if (f.transpose && !v.scalar && f.kind != Factor::Tuple) v.m = v.m.transpose();
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

}  // namespace eomgen::checker
