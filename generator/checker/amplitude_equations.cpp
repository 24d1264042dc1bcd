/** @file amplitude_equations.cpp  Trial solutions and the amplitude equations they give. */
#include "checker/amplitude_equations.hpp"

#include "mechanics/pole_free_subs.hpp"

#include <algorithm>
#include <tuple>
#include <utility>

namespace eomgen::checker {

namespace {

/// "x_{j}" → {"x", "j"}; {"", ""} when the name is not a letter with one subscript.
std::pair<std::string, std::string> split_subscript(const std::string& name) {
    const std::size_t u = name.find("_{");
    if (u == std::string::npos || u == 0 || name.back() != '}') return {"", ""};
    const std::string sub = name.substr(u + 2, name.size() - u - 3);
    if (sub.empty() || sub.find_first_of("{}_^") != std::string::npos) return {"", ""};
    return {name.substr(0, u), sub};
}

bool is_index_letter(const std::string& s) { return s.size() == 1 && std::isalpha(static_cast<unsigned char>(s[0])); }

void symbols_of(const GiNaC::ex& e, std::vector<GiNaC::ex>& out) {
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
        if (std::none_of(out.begin(), out.end(), [&](const GiNaC::ex& x) { return x.is_equal(e); })) out.push_back(e);
        return;
    }
    for (std::size_t i = 0; i < e.nops(); ++i) symbols_of(e.op(i), out);
}

/// e without its factors in t (`e^{i w t}`, `\cos\omega t`), term by term; std::nullopt when t is left over.
std::optional<GiNaC::ex> without_time_factors(const GiNaC::ex& e, const GiNaC::ex& t) {
    GiNaC::ex x;
    try {
        x = e.expand();
    } catch (...) {
        return std::nullopt;
    }
    auto strip = [&](const GiNaC::ex& term) -> GiNaC::ex {
        if (!term.has(t)) return term;
        if (!GiNaC::is_a<GiNaC::mul>(term)) return 1;
        GiNaC::ex kept = 1;
        for (const GiNaC::ex& f : term)
            if (!f.has(t)) kept *= f;
        return kept;
    };
    GiNaC::ex out = 0;
    if (GiNaC::is_a<GiNaC::add>(x))
        for (const GiNaC::ex& term : x) out += strip(term);
    else
        out = strip(x);
    if (out.has(t)) return std::nullopt;
    return out;
}

}  // namespace

std::optional<TrialSolution> trial_solution(const GiNaC::ex& left, const GiNaC::ex& right, const Model& model,
                                            LatexContext& ctx) {
    for (const auto& [x, y] : {std::pair(left, right), std::pair(right, left)}) {
        if (!y.has(ctx.time)) continue;
        // The coordinates x names: one (x_1), or every coordinate with its letter (x_j).
        std::vector<std::size_t> coords;
        std::string index;
        for (std::size_t k = 0; k < model.coordinates.size(); ++k)
            if (x.is_equal(model.coordinates[k].q)) coords.push_back(k);
        if (coords.empty()) {
            const FreeName* f = ctx.free_name_of(x);
            if (!f || f->kind != NameKind::Unknown) continue;
            const auto [base, sub] = split_subscript(f->name);
            if (base.empty() || !is_index_letter(sub)) continue;
            for (std::size_t k = 0; k < model.coordinates.size(); ++k)
                if (split_subscript(canonical_name(model.coordinates[k].latex)).first == base) coords.push_back(k);
            if (coords.empty()) continue;
            index = sub;
        }
        // y = A g(t): A a free name of degree 1, g holding t.
        std::vector<GiNaC::ex> names;
        symbols_of(y, names);
        for (const GiNaC::ex& a : names) {
            const FreeName* fa = ctx.free_name_of(a);
            if (!fa || fa->kind != NameKind::Unknown) continue;
            GiNaC::ex g;
            try {
                if (y.expand().degree(a) != 1 || y.expand().ldegree(a) != 1) continue;
                g = GiNaC::normal(y / a);
            } catch (...) {
                continue;
            }
            if (g.has(a) || !g.has(ctx.time)) continue;
            const auto [abase, asub] = split_subscript(fa->name);
            if (!index.empty() && (abase.empty() || asub != index)) continue;
            // The frequency: a free name of g, `\omega…` first.
            std::vector<GiNaC::ex> in_g;
            symbols_of(g, in_g);
            GiNaC::ex omega = 0;
            for (const GiNaC::ex& s : in_g) {
                const FreeName* fs = ctx.free_name_of(s);
                if (!fs || fs->kind != NameKind::Unknown || fs->name == "e" || fs->name == "i") continue;
                if (omega.is_zero() || fs->name.rfind("\\omega", 0) == 0) omega = s;
            }
            if (omega.is_zero()) continue;
            TrialSolution trial;
            trial.amplitude.assign(model.coordinates.size(), 0);
            trial.omega = omega;
            for (std::size_t k : coords) {
                if (index.empty()) {
                    trial.amplitude[k] = a;
                } else {
                    const std::string sub = split_subscript(canonical_name(model.coordinates[k].latex)).second;
                    trial.amplitude[k] = ctx.free_symbol(abase + "_{" + sub + "}", NameKind::Unknown);
                }
            }
            return trial;
        }
    }
    return std::nullopt;
}

namespace {

/// √d with its even powers taken out, d a discriminant of K₀ and M₀, whose symbols are all parameters (the model's
/// or the text's names for them: lengths, masses, taken positive): √(8 g² l²) = 2 g l √2.
GiNaC::ex positive_root(const GiNaC::ex& d) {
    GiNaC::ex outside = 1, inside = 1;
    const auto take = [&](const GiNaC::ex& f) {
        if (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::symbol>(f.op(0)) &&
            GiNaC::is_a<GiNaC::numeric>(f.op(1)) && GiNaC::ex_to<GiNaC::numeric>(f.op(1)).is_even()) {
            outside *= GiNaC::pow(f.op(0), f.op(1) / 2);
            return;
        }
        if (GiNaC::is_a<GiNaC::numeric>(f) && GiNaC::ex_to<GiNaC::numeric>(f).is_pos_integer() &&
            GiNaC::ex_to<GiNaC::numeric>(f) < 1000000) {
            long n = GiNaC::ex_to<GiNaC::numeric>(f).to_long(), k = 1;
            for (long q = 2; q * q <= n; ++q)
                while (n % (q * q) == 0) {
                    n /= q * q;
                    k *= q;
                }
            outside *= k;
            inside *= n;
            return;
        }
        inside *= f;
    };
    for (const GiNaC::ex& f : GiNaC::is_a<GiNaC::mul>(d) ? d : GiNaC::lst{d}) take(f);
    return outside * GiNaC::sqrt(inside);
}

}  // namespace

std::optional<TrialSolution> implied_amplitudes(const std::vector<const FreeName*>& names, const Model& model) {
    const std::size_t n = model.coordinates.size();
    if (n < 2) return std::nullopt;
    std::string base;
    std::vector<GiNaC::ex> amplitude(n, 0);
    std::size_t named = 0;
    for (const FreeName* f : names) {
        if (!f || f->kind != NameKind::Unknown) return std::nullopt;
        const auto [b, sub] = split_subscript(f->name);
        if (b.empty() || (!base.empty() && b != base)) return std::nullopt;
        base = b;
        // The coordinate with this subscript (θ_{2} for A_{2}), else the sub-th coordinate of subscript-free ones.
        std::size_t k = n;
        for (std::size_t q = 0; q < n; ++q)
            if (split_subscript(canonical_name(model.coordinates[q].latex)).second == sub) k = q;
        if (k == n && sub.size() == 1 && sub[0] >= '1' && sub[0] <= '9' &&
            std::none_of(model.coordinates.begin(), model.coordinates.end(), [](const Coordinate& c) {
                return !split_subscript(canonical_name(c.latex)).first.empty();
            }))
            k = std::size_t(sub[0] - '1');
        if (k >= n) return std::nullopt;
        if (amplitude[k].is_zero()) ++named;
        amplitude[k] = f->symbol;
    }
    if (named < 2) return std::nullopt;
    TrialSolution trial;
    trial.amplitude = std::move(amplitude);
    std::string coordinates;
    for (std::size_t k = 0; k < n; ++k)
        if (!trial.amplitude[k].is_zero())
            coordinates += std::string(coordinates.empty() ? "" : ", ") + "$" + model.coordinates[k].latex + "$";
    trial.what = "the amplitudes $" + base + "_k$ read as those of " + coordinates + " (no trial solution written)";
    return trial;
}

std::optional<std::vector<GiNaC::ex>> AmplitudeEquations::mode_shape(const GiNaC::ex& w2) const {
    // (K − w M) v = 0 with one component fixed to 1: drop a row and that column, solve the square rest, and
    // keep the first solution that satisfies the dropped row too (a null space of dimension 1).
    const std::size_t n = model_.dof();
    for (std::size_t f = 0; f < n; ++f)
        for (std::size_t dropped = 0; dropped < n; ++dropped) {
            try {
                const unsigned m = static_cast<unsigned>(n - 1);
                GiNaC::matrix A(m, m), b(m, 1), x(m, 1);
                std::vector<GiNaC::symbol> unknowns(n - 1);
                for (unsigned i = 0, ri = 0; i < n; ++i) {
                    if (i == dropped) continue;
                    for (unsigned k = 0, ck = 0; k < n; ++k) {
                        const GiNaC::ex e = GiNaC::normal(K_(i, k) - w2 * M_(i, k));
                        if (k == f)
                            b(ri, 0) = -e;
                        else
                            A(ri, ck++) = e;
                    }
                    ++ri;
                }
                for (unsigned k = 0; k < m; ++k) x(k, 0) = unknowns[k];
                const GiNaC::matrix sol = A.solve(x, b, GiNaC::solve_algo::gauss);
                std::vector<GiNaC::ex> v(n);
                for (unsigned k = 0, ck = 0; k < n; ++k) v[k] = k == f ? GiNaC::ex(1) : GiNaC::normal(sol(ck++, 0));
                GiNaC::ex check = 0;
                for (unsigned k = 0; k < n; ++k) check += (K_(unsigned(dropped), k) - w2 * M_(unsigned(dropped), k)) * v[k];
                if (GiNaC::normal(check).is_zero()) return v;
            } catch (...) {
            }
        }
    return std::nullopt;
}

bool AmplitudeEquations::ratio_correction(const GiNaC::ex& left, const GiNaC::ex& right, const std::string& left_source,
                                          const std::string& right_source, const TrialSolution& trial,
                                          const std::vector<GiNaC::ex>& c, const GiNaC::ex& w2, Comparisons& cmp,
                                          EquationCheck& out) const {
    const std::size_t n = model_.dof();
    std::vector<std::size_t> support;
    for (std::size_t k = 0; k < n; ++k)
        if (!trial.amplitude[k].is_zero() && !cmp.same(c[k], 0, 1e-9)) support.push_back(k);
    if (support.size() != 2) return false;
    const std::optional<std::vector<GiNaC::ex>> v = mode_shape(w2);
    if (!v) return false;
    const std::size_t i = support[0], j = support[1];
    // The side that is an amplitude alone is solved for; else A_i.
    std::size_t lhs = i, rhs = j;
    std::string shown;
    for (const auto& [side, source] : {std::pair(left, left_source), std::pair(right, right_source)})
        for (std::size_t k : support)
            if (shown.empty() && side.is_equal(trial.amplitude[k])) {
                lhs = k;
                rhs = k == i ? j : i;
                shown = source;
            }
    if (cmp.same((*v)[rhs], 0, 1e-9)) return false;
    const GiNaC::ex ratio = GiNaC::normal((*v)[lhs] / (*v)[rhs]);
    const GiNaC::ex text_ratio = GiNaC::normal(-c[rhs] / c[lhs]);
    const std::string a = "$" + cmp.latex(trial.amplitude[lhs]) + "$", b = "$" + cmp.latex(trial.amplitude[rhs]) + "$";
    out.verdict = Verdict::Disagrees;
    out.compared_with = "the mode of " + trial.described() + " at the normal frequency $\\omega^2 = " + cmp.latex(w2) + "$";
    out.wrong_terms = {"in this mode " + a + " is $" + cmp.latex(ratio) + "$ times " + b + ", not $" +
                       cmp.latex(text_ratio) + "$ times"};
    out.corrected = (shown.empty() ? cmp.latex(trial.amplitude[lhs]) : shown) + " = " +
                    cmp.latex(ratio * trial.amplitude[rhs]);
    out.notes.push_back("the mode's shape: the null vector of $K - \\omega^2 M$ there");
    return true;
}

bool AmplitudeEquations::check_shape(const std::vector<GiNaC::ex>& v, const std::string& name,
                                     const TrialSolution& trial, const std::optional<GiNaC::ex>& stated,
                                     Comparisons& cmp, EquationCheck& out) {
    const std::size_t n = model_.dof();
    if (!stated || v.size() != n || !prepare(cmp)) return false;
    const std::optional<std::vector<GiNaC::ex>> shape = mode_shape(*stated);
    if (!shape) return false;
    // The scale: the entry the text normalizes to 1, else the one that leaves the fewest entries wrong.
    const auto scaled_at = [&](std::size_t ref) {
        std::vector<GiNaC::ex> s(n);
        for (std::size_t k = 0; k < n; ++k)
            s[k] = ref == n ? (*shape)[k] : GiNaC::normal((*shape)[k] * v[ref] / (*shape)[ref]);
        return s;
    };
    const auto wrong_at = [&](const std::vector<GiNaC::ex>& s, std::size_t ref) {
        std::vector<std::size_t> w;
        for (std::size_t k = 0; k < n; ++k)
            if (ref == n || !cmp.same(v[k], s[k], 1e-9)) w.push_back(k);
        return w;
    };
    std::size_t ref = n;
    std::vector<std::size_t> wrong = wrong_at(scaled_at(n), n);
    bool unit = false;
    for (std::size_t k = 0; k < n; ++k) {
        if (cmp.same((*shape)[k], 0, 1e-9) || cmp.same(v[k], 0, 1e-9)) continue;
        const std::vector<std::size_t> w = wrong_at(scaled_at(k), k);
        const bool one = cmp.same(v[k], 1, 1e-12);
        if (ref == n || (one && !unit) || (one == unit && w.size() < wrong.size())) {
            ref = k;
            wrong = w;
            unit = one;
        }
    }
    const std::vector<GiNaC::ex> scaled = scaled_at(ref);
    out.compared_with = "the mode of " + trial.described() + " at the normal frequency $\\omega^2 = " +
                        cmp.latex(*stated) + "$";
    out.notes.push_back("the mode's shape: the null vector of $K - \\omega^2 M$ there, up to its scale");
    if (wrong.empty()) {
        out.verdict = Verdict::Agrees;
        out.reason = "the mode's shape, a multiple of it";
        return true;
    }
    out.verdict = Verdict::Disagrees;
    std::string corrected = name + " = \\begin{bmatrix} ";
    for (std::size_t k = 0; k < n; ++k) corrected += (k ? " \\\\ " : "") + cmp.latex(scaled[k]);
    out.corrected = corrected + " \\end{bmatrix}";
    for (const std::size_t k : wrong)
        out.wrong_terms.push_back("entry " + std::to_string(k + 1) + " (for $" + model_.coordinates[k].latex + "$) is $" +
                                  cmp.latex(v[k]) + "$ where the mode has $" + cmp.latex(scaled[k]) + "$");
    return true;
}

bool AmplitudeEquations::prepare(Comparisons& cmp) {
    if (prepared_) return usable_;
    prepared_ = true;
    const std::size_t n = model_.dof();
    GiNaC::exmap rest;
    for (const Coordinate& c : model_.coordinates) {
        rest[c.q] = 0;
        rest[c.qd] = 0;
        rest[c.qdd] = 0;
    }
    K_ = GiNaC::matrix(unsigned(n), unsigned(n));
    M_ = GiNaC::matrix(unsigned(n), unsigned(n));
    try {
        for (std::size_t i = 0; i < n; ++i) {
            if (motion_[i].has(model_.t)) return false;
            const auto at_rest = subs_unless_pole(motion_[i], rest);
            if (!at_rest) return false;
            GiNaC::ex linear = *at_rest;  // the equation's linear part about q = 0
            for (std::size_t k = 0; k < n; ++k) {
                const auto kk = subs_unless_pole(GiNaC::diff(motion_[i], model_.coordinates[k].q), rest);
                const auto mk = subs_unless_pole(GiNaC::diff(motion_[i], model_.coordinates[k].qdd), rest);
                const auto ck = subs_unless_pole(GiNaC::diff(motion_[i], model_.coordinates[k].qd), rest);
                if (!kk || !mk || !ck || !cmp.same(*ck, 0, 1e-9)) return false;  // velocity terms about rest
                K_(unsigned(i), unsigned(k)) = GiNaC::normal(*kk);
                M_(unsigned(i), unsigned(k)) = GiNaC::normal(*mk);
                linear += *kk * model_.coordinates[k].q + *mk * model_.coordinates[k].qdd;
            }
            // About an equilibrium at q = 0, or anywhere for linear equations (springs with rest lengths: x
            // measured from another mark than rest; K and M are the same about every point).
            if (!cmp.same(*at_rest, 0, 1e-9) && !cmp.same(linear, motion_[i], 1e-9)) return false;
        }
    } catch (...) {
        return false;
    }
    usable_ = true;
    return true;
}

bool AmplitudeEquations::check(const GiNaC::ex& left, const GiNaC::ex& right, const std::string& left_source,
                               const std::string& right_source, const std::vector<std::string>& written,
                               const TrialSolution& trial, const std::optional<GiNaC::ex>& stated,
                               const LatexContext& ctx, Comparisons& cmp, EquationCheck& out) {
    const std::size_t n = model_.dof();
    const GiNaC::ex r = left - right;
    for (const Coordinate& c : model_.coordinates)
        if (r.has(c.q) || r.has(c.qd) || r.has(c.qdd)) return false;
    if (std::none_of(trial.amplitude.begin(), trial.amplitude.end(),
                     [&](const GiNaC::ex& a) { return !a.is_zero() && r.has(a); }))
        return false;
    const std::optional<GiNaC::ex> s = without_time_factors(r, ctx.time);
    if (!s) return false;
    // No other name of the text: those would be constants of unknown value.
    std::vector<GiNaC::ex> names;
    symbols_of(*s, names);
    for (const GiNaC::ex& x : names) {
        const FreeName* f = ctx.free_name_of(x);
        if (!f) continue;
        const bool ours = x.is_equal(trial.omega) || std::any_of(trial.amplitude.begin(), trial.amplitude.end(),
                                                                 [&](const GiNaC::ex& a) { return a.is_equal(x); });
        if (!ours) return false;
    }
    if (!prepare(cmp)) return false;
    // K₀ and M₀ with the text's assumptions put in, for this check only.
    struct Restore {
        GiNaC::matrix &K, &M, K0, M0;
        ~Restore() {
            K = K0;
            M = M0;
        }
    } restore{K_, M_, K_, M_};
    if (!assumed_.empty()) {
        K_ = GiNaC::ex_to<GiNaC::matrix>(K_.subs(assumed_));
        M_ = GiNaC::ex_to<GiNaC::matrix>(M_.subs(assumed_));
    }
    // r = c0 + Σ c_k A_k, the c free of the amplitudes.
    std::vector<GiNaC::ex> c(n, 0);
    GiNaC::exmap none;
    for (std::size_t k = 0; k < n; ++k)
        if (!trial.amplitude[k].is_zero()) {
            if (s->degree(trial.amplitude[k]) > 1) return false;
            c[k] = s->coeff(trial.amplitude[k], 1);
            none[trial.amplitude[k]] = 0;
        }
    for (std::size_t k = 0; k < n; ++k)
        for (const auto& [a, zero] : none)
            if (c[k].has(a)) return false;  // A_1 A_2
    const std::optional<GiNaC::ex> c0_at = subs_unless_pole(*s, none);
    if (!c0_at) return false;
    const GiNaC::ex c0 = *c0_at;
    const bool homogeneous = cmp.same(c0, 0, 1e-9);
    const GiNaC::ex w = trial.omega;
    const bool has_omega = !w.is_zero() && s->has(w);
    auto row = [&](std::size_t i, const GiNaC::ex& w2, std::size_t k) {
        return K_(unsigned(i), unsigned(k)) - w2 * M_(unsigned(i), unsigned(k));
    };
    auto row_latex = [&](std::size_t i, const GiNaC::ex& scale, const GiNaC::ex& w2) {
        GiNaC::ex e = 0;
        for (std::size_t k = 0; k < n; ++k)
            if (!trial.amplitude[k].is_zero()) e += GiNaC::normal(scale * row(i, w2, k)) * trial.amplitude[k];
        return e;
    };
    const std::string trial_at = trial.described();
    auto name = [&](std::size_t i) { return "$" + model_.coordinates[i].latex + "$"; };
    // c ∥ row i: c_k row_l = c_l row_k for every pair.
    auto parallel = [&](std::size_t i, const GiNaC::ex& w2) {
        bool any = false;
        for (std::size_t k = 0; k < n; ++k) {
            if (trial.amplitude[k].is_zero()) {
                if (!cmp.same(row(i, w2, k), 0, 1e-9)) return false;  // the row needs an amplitude the text lacks
                continue;
            }
            any = any || !cmp.same(c[k], 0, 1e-9);
            for (std::size_t l = k + 1; l < n; ++l)
                if (!trial.amplitude[l].is_zero() && !cmp.same(c[k] * row(i, w2, l), c[l] * row(i, w2, k), 1e-9))
                    return false;
        }
        return any;
    };
    // The frequencies of the modes: roots of det(K₀ − w M₀) from its linear and quadratic factors (a double
    // pendulum's two, (2 ± √2) g/l with equal bobs, are no rational expressions).
    const GiNaC::symbol wv("w");
    std::vector<GiNaC::ex> roots;
    if (!has_omega) {
        try {
            GiNaC::matrix A(static_cast<unsigned>(n), static_cast<unsigned>(n));
            for (std::size_t i = 0; i < n; ++i)
                for (std::size_t k = 0; k < n; ++k) A(unsigned(i), unsigned(k)) = row(i, wv, k);
            const GiNaC::ex det = GiNaC::factor(A.determinant().expand());
            std::vector<GiNaC::ex> factors;
            if (GiNaC::is_a<GiNaC::mul>(det))
                for (const GiNaC::ex& f : det) factors.push_back(f);
            else
                factors.push_back(det);
            for (GiNaC::ex f : factors) {
                if (GiNaC::is_a<GiNaC::power>(f)) f = f.op(0);
                if (!f.has(wv) || f.degree(wv) > 2) continue;
                if (f.degree(wv) == 1) {
                    roots.push_back(GiNaC::normal(-f.coeff(wv, 0) / f.coeff(wv, 1)));
                    continue;
                }
                const GiNaC::ex a = f.coeff(wv, 2), b = f.coeff(wv, 1), c = f.coeff(wv, 0);
                const GiNaC::ex root = positive_root(GiNaC::factor(GiNaC::normal(b * b - 4 * a * c)));
                for (int sign : {-1, 1}) roots.push_back(GiNaC::normal((-b + sign * root) / (2 * a)));
            }
        } catch (...) {
        }
    }
    // The frequency the text has just stated (`put \omega_3^2 = … into`), when it is one of the model's.
    if (stated && !has_omega)
        for (const GiNaC::ex& w2 : roots)
            if (cmp.same(w2, *stated, 1e-9)) {
                roots = {w2};
                break;
            }
    if (homogeneous) {
        for (std::size_t i = 0; i < n; ++i) {
            if (has_omega && parallel(i, w * w)) {
                out.verdict = Verdict::Agrees;
                out.compared_with = "the amplitude equation for " + name(i) + " of " + trial_at;
                out.reason = "a multiple of row " + std::to_string(i + 1) + " of $(K - \\omega^2 M) A = 0$ (about " +
                             "rest), the factors in $t$ taken out";
                return true;
            }
            if (!has_omega)
                for (const GiNaC::ex& w2 : roots)
                    if (parallel(i, w2)) {
                        out.verdict = Verdict::Agrees;
                        out.compared_with = "the amplitude equation for " + name(i) + " of " + trial_at +
                                            " at the normal frequency $\\omega^2 = " + cmp.latex(w2) + "$";
                        out.reason = "a multiple of row " + std::to_string(i + 1) + " of $(K - \\omega^2 M) A = 0$ there";
                        return true;
                    }
        }
        // At a normal frequency K − ω² M is singular: a combination of its rows (`A_1 = -A_3` once `A_2 = 0`) is
        // a consequence, and no longer every linear equation.
        if (!has_omega)
            for (const GiNaC::ex& w2 : roots) {
                try {
                    GiNaC::matrix rows(static_cast<unsigned>(n), static_cast<unsigned>(n));
                    GiNaC::matrix with(static_cast<unsigned>(n + 1), static_cast<unsigned>(n));
                    for (std::size_t i = 0; i < n; ++i)
                        for (std::size_t k = 0; k < n; ++k) {
                            rows(unsigned(i), unsigned(k)) = GiNaC::normal(row(i, w2, k));
                            with(unsigned(i), unsigned(k)) = rows(unsigned(i), unsigned(k));
                        }
                    for (std::size_t k = 0; k < n; ++k) with(unsigned(n), unsigned(k)) = GiNaC::normal(c[k]);
                    if (rows.rank() == n || with.rank() != rows.rank()) continue;
                } catch (...) {
                    continue;
                }
                out.verdict = Verdict::Agrees;
                out.compared_with = "the amplitude equations of " + trial_at + " at the normal frequency $\\omega^2 = " +
                                    cmp.latex(w2) + "$";
                out.reason = "a combination of the rows of $(K - \\omega^2 M) A = 0$ there";
                return true;
            }
    }
    // `A_1 = A_3` at the one frequency the text states: the ratio of the two amplitudes in that mode.
    if (!has_omega && homogeneous && roots.size() == 1 && stated)
        if (ratio_correction(left, right, left_source, right_source, trial, c, roots[0], cmp, out)) return true;
    // It disagrees: with the row (and frequency) it matches best, entry by entry after the best factor.
    std::vector<GiNaC::ex> frequencies = has_omega ? std::vector<GiNaC::ex>{w * w} : roots;
    if (frequencies.empty()) return false;
    // A term that lost its amplitude A_l: (−M ω² + k) where (−M ω² + k) A_3 belongs, A_3 not written.
    auto lost = [&](std::size_t i, const GiNaC::ex& w2, const GiNaC::ex& scale, std::size_t l) {
        if (homogeneous || trial.amplitude[l].is_zero() || !cmp.same(c[l], 0, 1e-9) || cmp.same(row(i, w2, l), 0, 1e-9))
            return false;
        const FreeName* f = ctx.free_name_of(trial.amplitude[l]);
        if (f && std::find(written.begin(), written.end(), f->name) != written.end()) return false;
        return cmp.same(c0, scale * row(i, w2, l), 1e-9);
    };
    int best = -1;
    std::size_t best_size = 0;
    std::size_t best_i = 0;
    GiNaC::ex best_scale = 1, best_w2 = 0;
    for (const GiNaC::ex& w2 : frequencies)
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t k = 0; k < n; ++k) {
                if (trial.amplitude[k].is_zero() || cmp.same(row(i, w2, k), 0, 1e-9)) continue;
                GiNaC::ex scale;
                try {
                    scale = GiNaC::normal(c[k] / row(i, w2, k));
                } catch (...) {
                    continue;
                }
                if (cmp.same(scale, 0, 1e-9)) continue;
                int score = 0;
                for (std::size_t l = 0; l < n; ++l)
                    if (!trial.amplitude[l].is_zero() && cmp.same(c[l], scale * row(i, w2, l), 1e-9)) ++score;
                for (std::size_t l = 0; l < n; ++l)
                    if (lost(i, w2, scale, l)) ++score;
                // Ties: the simpler factor (1 rather than the ratio of a wrong coefficient).
                const std::size_t size = cmp.latex(scale).size();
                if (score > best || (score == best && size < best_size)) {
                    best_size = size;
                    best = score;
                    best_i = i;
                    best_scale = scale;
                    best_w2 = w2;
                }
            }
    if (best < 1) return false;
    const GiNaC::ex truth = row_latex(best_i, best_scale, best_w2);
    out.verdict = Verdict::Disagrees;
    out.compared_with = "the amplitude equation for " + name(best_i) + " of " + trial_at +
                        (has_omega ? std::string() : " at the normal frequency $\\omega^2 = " + cmp.latex(best_w2) + "$");
    out.difference = cmp.latex((*s - truth).expand());
    out.wrong_terms.clear();
    bool lost_one = false;
    for (std::size_t l = 0; l < n; ++l)
        if (lost(best_i, best_w2, best_scale, l)) {
            lost_one = true;
            out.wrong_terms.push_back("$" + cmp.latex(c0) + "$ without its amplitude $" +
                                      cmp.latex(trial.amplitude[l]) + "$");
        }
    for (std::size_t l = 0; l < n; ++l) {
        if (trial.amplitude[l].is_zero()) continue;
        const GiNaC::ex want = GiNaC::normal(best_scale * row(best_i, best_w2, l));
        if (cmp.same(c[l], want, 1e-9) || (lost_one && lost(best_i, best_w2, best_scale, l))) continue;
        const std::string a = "$" + cmp.latex(trial.amplitude[l]) + "$";
        out.wrong_terms.push_back(cmp.same(want, 0, 1e-9) ? "the " + a + " term $" + cmp.latex(c[l] * trial.amplitude[l]) +
                                                                "$ should not be there"
                                  : cmp.same(c[l], 0, 1e-9) ? "the " + a + " term is missing: $" +
                                                                  cmp.latex(want * trial.amplitude[l]) + "$"
                                                            : "the coefficient of " + a + " should be $" + cmp.latex(want) +
                                                                  "$, not $" + cmp.latex(GiNaC::normal(c[l])) + "$");
    }
    if (!homogeneous && !lost_one) out.wrong_terms.push_back("$" + cmp.latex(c0) + "$ should not be there");
    out.corrected = cmp.latex(truth) + " = 0";
    // `A_1 = …`: the correction solved for the amplitude the text holds alone on a side.
    for (std::size_t k = 0; k < n; ++k)
        for (const auto& [side, source, other] :
             {std::tuple(left, left_source, right_source), std::tuple(right, right_source, left_source)})
            if (!trial.amplitude[k].is_zero() && side.is_equal(trial.amplitude[k])) {
                const GiNaC::ex a = truth.coeff(trial.amplitude[k], 1);
                if (cmp.same(a, 0, 1e-9)) continue;
                const GiNaC::ex solved =
                    GiNaC::normal(-(truth - a * trial.amplitude[k]).expand() / a);
                out.corrected = side.is_equal(left) && source == left_source ? source + " = " + cmp.latex(solved)
                                                                             : cmp.latex(solved) + " = " + source;
                (void)other;
            }
    out.notes.push_back("compared as row " + std::to_string(best_i + 1) + " of $(K - \\omega^2 M) A = 0$ about rest" +
                        (GiNaC::ex(*s).is_equal(r) ? "" : ", the factors in $t$ taken out"));
    return true;
}

}  // namespace eomgen::checker
