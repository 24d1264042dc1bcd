/** @file normal_modes_check.cpp  Normal frequencies and secular equations against det(K₀ − ω² M₀). */
#include "checker/normal_modes_check.hpp"

#include "checker/budget.hpp"
#include "mechanics/small_oscillations.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace eomgen::checker {

namespace {

using GiNaC::ex;

std::string m(const std::string& latex) {
    return "$" + latex + "$";
}

/// `\omega` or `\omega_{...}`: the canonical names of a frequency.
bool is_frequency_name(const std::string& name) {
    return name == "\\omega" || name.rfind("\\omega_", 0) == 0;
}

/// s with `\pm` read as `upper ? + : −` and `\mp` as the opposite sign.
std::string one_sign(const std::string& s, bool upper) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const bool pm = s.compare(i, 3, "\\pm") == 0, mp = s.compare(i, 3, "\\mp") == 0;
        const bool word_ends = i + 3 >= s.size() || !std::isalpha(static_cast<unsigned char>(s[i + 3]));
        if ((pm || mp) && word_ends) {
            out += (pm == upper) ? " + " : " - ";
            i += 2;
        } else {
            out += s[i];
        }
    }
    return out;
}

/// The entries of `\begin{vmatrix} a & b \\ c & d \end{vmatrix}` (also `\det` before a pmatrix or bmatrix)
/// when that is the whole of s, by rows; empty otherwise.
std::vector<std::vector<std::string>> determinant_entries(const std::string& s) {
    std::size_t b = s.find_first_not_of(" \t\r\n");
    if (b == std::string::npos) return {};
    std::string env;
    if (s.compare(b, 15, "\\begin{vmatrix}") == 0) {
        env = "vmatrix";
    } else if (s.compare(b, 4, "\\det") == 0) {
        b = s.find_first_not_of(" \t\r\n", b + 4);
        for (const char* e : {"pmatrix", "bmatrix"})
            if (b != std::string::npos && s.compare(b, 8 + std::string(e).size(), "\\begin{" + std::string(e) + "}") == 0)
                env = e;
    }
    if (env.empty()) return {};
    const std::string open = "\\begin{" + env + "}", close = "\\end{" + env + "}";
    const std::size_t body = b + open.size(), end = s.find(close, body);
    if (end == std::string::npos || s.find_first_not_of(" \t\r\n", end + close.size()) != std::string::npos ||
        s.find("\\begin", body) < end)
        return {};
    std::vector<std::vector<std::string>> rows(1, std::vector<std::string>(1));
    int depth = 0;
    for (std::size_t i = body; i < end; ++i) {
        const char c = s[i];
        if (c == '{') ++depth;
        if (c == '}') --depth;
        if (depth == 0 && c == '\\' && i + 1 < end && s[i + 1] == '\\') {
            rows.emplace_back(1);
            ++i;
        } else if (depth == 0 && c == '&') {
            rows.back().emplace_back();
        } else {
            rows.back().back() += c;
        }
    }
    // A trailing \\ leaves an empty last row.
    if (rows.size() > 1 && rows.back().size() == 1 &&
        rows.back()[0].find_first_not_of(" \t\r\n") == std::string::npos)
        rows.pop_back();
    for (const auto& row : rows)
        if (row.size() != rows.size()) return {};
    return rows;
}

/// What a side reads as: itself; its upper and lower signs (`\pm`, `\mp`); the determinant of a matrix.
/// Empty when it cannot be read so.
std::vector<ex> readings(const Side& s, LatexContext& ctx) {
    if (s.ok) return {s.value};
    if (s.empty()) return {};
    if (one_sign(s.source, true) != s.source) {
        std::vector<ex> out;
        for (bool upper : {true, false}) {
            const Side branch = parse_expression(one_sign(s.source, upper), ctx);
            if (!branch.ok) return {};
            out.push_back(branch.value);
        }
        return out;
    }
    const auto entries = determinant_entries(s.source);
    if (entries.empty()) return {};
    const auto n = static_cast<unsigned>(entries.size());
    GiNaC::matrix A(n, n);
    for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < n; ++j) {
            const Side entry = parse_expression(entries[i][j], ctx);
            if (!entry.ok) return {};
            A(i, j) = entry.value;
        }
    return {A.determinant()};
}

/// The coefficients of p in w, lowest first, each normalized.
std::vector<ex> coefficients(const ex& p, const GiNaC::symbol& w) {
    const ex e = p.expand();
    std::vector<ex> c;
    for (int k = 0; k <= e.degree(w); ++k) c.push_back(GiNaC::normal(e.coeff(w, k)));
    while (c.size() > 1 && c.back().is_zero()) c.pop_back();
    return c;
}

/// x = 0: exactly (normal()), else at random parameter values; `how` says which, "" when neither.
bool vanishes(const ex& x, Comparisons& cmp, double tol, std::string& how) {
    try {
        if (GiNaC::normal(x.expand()).is_zero()) {
            if (how.empty()) how = "exactly";
            return true;
        }
    } catch (const std::exception&) {
    }
    if (!cmp.same(x, 0, tol)) return false;
    how = "numerically, at random parameter values to a relative " + [&] {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.0e", tol);
        return std::string(buf);
    }();
    return true;
}

bool has_parameters(const ex& e, const Model& model) {
    return std::any_of(model.parameters.begin(), model.parameters.end(),
                       [&](const Parameter& p) { return e.has(p.symbol); });
}

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

/// A closed form for reading: the squares of positive parameters (at the model's values) and of integers taken
/// out of square roots (√(8 g² l²) → 2√2 g l), then normal(). Equal to e where those parameters are positive.
ex tidy(const ex& e, const GiNaC::exmap& values) {
    struct Pull : GiNaC::map_function {
        const GiNaC::exmap& values;
        explicit Pull(const GiNaC::exmap& v) : values(v) {}
        bool positive(const ex& x) const {
            const auto it = values.find(x);
            return it != values.end() && GiNaC::is_a<GiNaC::numeric>(it->second) &&
                   GiNaC::ex_to<GiNaC::numeric>(it->second).is_positive();
        }
        ex operator()(const ex& x) override {
            if (!GiNaC::is_a<GiNaC::power>(x) || !x.op(1).is_equal(GiNaC::numeric(1, 2))) return x.map(*this);
            ex base = x.op(0).map(*this);
            try {
                base = GiNaC::factor(base.expand());
            } catch (const std::exception&) {
            }
            std::vector<ex> fs;
            if (GiNaC::is_a<GiNaC::mul>(base))
                for (std::size_t i = 0; i < base.nops(); ++i) fs.push_back(base.op(i));
            else
                fs.push_back(base);
            ex out = 1, in = 1;
            for (const ex& f : fs) {
                if (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::symbol>(f.op(0)) && positive(f.op(0)) &&
                    f.op(1).info(GiNaC::info_flags::posint)) {
                    const long k = GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_long();
                    out *= GiNaC::pow(f.op(0), k / 2);
                    in *= GiNaC::pow(f.op(0), k % 2);
                } else if (f.info(GiNaC::info_flags::posint) && GiNaC::ex_to<GiNaC::numeric>(f) < 1000000) {
                    long n = GiNaC::ex_to<GiNaC::numeric>(f).to_long();
                    for (long d = 2; d * d <= n; ++d)
                        while (n % (d * d) == 0) {
                            out *= d;
                            n /= d * d;
                        }
                    in *= n;
                } else {
                    in *= f;
                }
            }
            return out * GiNaC::sqrt(in);
        }
    } pull(values);
    try {
        return GiNaC::normal(pull(e));
    } catch (const std::exception&) {
        return e;
    }
}

}  // namespace

void NormalModesCheck::compute(Comparisons& cmp) {
    computed_ = true;
    for (const Parameter& p : model_.parameters) values_[p.symbol] = GiNaC::numeric(p.value);
    ModesResult modes;
    try {
        modes = small_oscillations(model_, eq_, ModesOptions{});
    } catch (const std::exception& e) {
        why_not_ = std::string("the model's normal modes cannot be computed: ") + e.what();
        return;
    }
    bool any = false, damped = false;
    for (const Equilibrium& e : modes.equilibria) {
        if (e.stability == Stability::Unstable) continue;
        any = true;
        if (e.damped || e.gyroscopic) {
            damped = true;
            continue;
        }
        Rest rest;
        // (A point found in numbers on a continuum of equilibria, a free translation, shows its round-off as 0.)
        for (std::size_t i = 0; i < modes.latex.size(); ++i)
            rest.at += (i ? ", " : "") +
                       m(modes.latex[i] + " = " +
                         (e.exact[i] ? cmp.latex(*e.exact[i]) : number(std::abs(e.q[i]) < 1e-11 ? 0.0 : e.q[i])));
        for (const NormalMode& mode : e.modes) {
            rest.omega2.push_back(mode.omega2);
            rest.omega2_exact.push_back(mode.omega2_exact);
        }
        if (!e.M_exact.empty()) {
            const auto n = static_cast<unsigned>(e.M_exact.size());
            GiNaC::matrix A(n, n), M0(n, n), K0(n, n);
            for (unsigned i = 0; i < n; ++i)
                for (unsigned j = 0; j < n; ++j) {
                    A(i, j) = e.K_exact[i][j] - w_ * e.M_exact[i][j];
                    M0(i, j) = e.M_exact[i][j];
                    K0(i, j) = e.K_exact[i][j];
                }
            rest.M = M0;
            rest.K = K0;
            try {
                ex p = 0;
                const std::vector<ex> c = coefficients(A.determinant(), w_);
                for (std::size_t k = 0; k < c.size(); ++k) p += c[k] * GiNaC::pow(w_, int(k));
                rest.poly = p;
            } catch (const std::exception&) {
            }
        }
        rests_.push_back(std::move(rest));
    }
    if (rests_.empty() || std::all_of(rests_.begin(), rests_.end(), [](const Rest& r) { return r.omega2.empty(); })) {
        rests_.clear();
        if (damped)
            why_not_ = "at the model's stable equilibria damping or gyroscopic terms act: its motion there is not a "
                       "set of normal modes of $\\det(K_0 - \\omega^2 M_0) = 0$";
        else
            why_not_ = any ? "the model's frequencies could not be evaluated"
                           : (modes.equilibria.empty() ? "no equilibrium of the model was found"
                                                       : "the model has no stable equilibrium");
    }
}

std::optional<ex> NormalModesCheck::polynomial(const ex& a, const ex& b, const GiNaC::symbol& omega) const {
    try {
        // ω = expr: ω² = expr². A frequency written so is a root (√(g/l)) or a number; ω equal to a rational
        // expression (ω_∥ = ω₃) is an angular velocity, not a claim about the modes.
        for (int side = 0; side < 2; ++side) {
            const ex& s = side == 0 ? a : b;
            const ex& o = side == 0 ? b : a;
            if ((s.is_equal(omega) || s.is_equal(-omega)) && !o.has(omega)) {
                if (!GiNaC::is_a<GiNaC::numeric>(o) && !has_root(o)) return std::nullopt;
                return (w_ - GiNaC::pow(o, 2)).expand();
            }
        }
        const ex n = GiNaC::normal(a - b).numer().expand();
        if (!n.is_polynomial(omega) || n.degree(omega) < 1) return std::nullopt;
        ex p = 0;
        for (int k = n.ldegree(omega); k <= n.degree(omega); ++k) {
            const ex c = n.coeff(omega, k);
            if (c.is_zero()) continue;
            if (k % 2 != 0) return std::nullopt;
            p += c * GiNaC::pow(w_, k / 2);
        }
        return p.expand();
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

std::string NormalModesCheck::frequencies(const Rest& rest, const std::string& omega, Comparisons& cmp) const {
    std::string out;
    for (std::size_t k = 0; k < rest.omega2.size(); ++k) {
        const std::string value =
            rest.omega2_exact[k] ? cmp.latex(tidy(*rest.omega2_exact[k], values_)) : number(rest.omega2[k]);
        out += (k ? " or " : "") + m(omega + "^{2} = " + value);
    }
    return out;
}

NormalModesCheck::Judgement NormalModesCheck::judge(const Rest& rest, const ex& P, const std::string& omega,
                                                    double tol, Comparisons& cmp) const {
    Judgement j;
    const int modes_n = int(rest.omega2.size());
    const std::vector<ex> text = coefficients(P, w_);
    const int degree = int(text.size()) - 1;
    if (degree > modes_n) {
        j.wrong = "of degree " + std::to_string(degree) + " in " + m(omega + "^{2}") + ", but the model has " +
                  std::to_string(modes_n) + " normal mode" + (modes_n == 1 ? "" : "s");
        return j;
    }
    if (degree == 1) {
        // The mode nearest to its root, by their values at the model's parameters.
        const ex root = GiNaC::evalf((-text[0] / text[1]).subs(values_));
        if (GiNaC::is_a<GiNaC::numeric>(root) && modes_n > 0) {
            const double v = GiNaC::ex_to<GiNaC::numeric>(root).real().to_double();
            j.mode = 0;
            for (int i = 1; i < modes_n; ++i)
                if (std::abs(rest.omega2[std::size_t(i)] - v) < std::abs(rest.omega2[std::size_t(j.mode)] - v)) j.mode = i;
        }
    }
    j.what = degree == 1 ? std::string(modes_n == 1 ? "the normal frequency of the model" : "a normal frequency of the model")
             : degree == modes_n
                 ? "the secular equation (the same polynomial in " + m(omega + "^{2}") + " up to a factor)"
                 : "a factor of the characteristic polynomial (its roots are normal frequencies of the model)";
    if (rest.poly && has_parameters(P, model_)) {
        const std::vector<ex> model = coefficients(*rest.poly, w_);
        bool ok = true;
        if (degree == int(model.size()) - 1) {
            for (std::size_t i = 0; i < text.size() && ok; ++i)
                ok = vanishes(text[i] * model.back() - model[i] * text.back(), cmp, tol, j.how);
        } else if (degree == 1) {
            ok = vanishes(rest.poly->subs(w_ == -text[0] / text[1]), cmp, tol, j.how);
        } else {
            const ex rem = GiNaC::prem(*rest.poly, P, w_, false);
            for (const ex& c : coefficients(rem, w_)) ok = ok && vanishes(c, cmp, tol, j.how);
        }
        j.agrees = ok;
        return j;
    }
    // The text in the parameters against an equilibrium known in numbers only: values that happen to coincide
    // at the model's parameters (l = 1) would pass, so it is not compared.
    if (has_parameters(P, model_)) {
        j.comparable = false;
        return j;
    }
    // The text's numbers: the roots at the model's parameter values, each to the relative tolerance against the
    // largest term of P there (for ω² = c: |ω²_k − c| ≤ tol·max(ω²_k, c)).
    std::vector<double> at;
    for (const ex& c : text) {
        const ex v = GiNaC::evalf(c.subs(values_));
        if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) {
            j.comparable = false;
            return j;
        }
        at.push_back(GiNaC::ex_to<GiNaC::numeric>(v).to_double());
    }
    int roots = 0;
    for (const double w2 : rest.omega2) {
        double value = 0, scale = 0, power = 1;
        for (std::size_t i = 0; i < at.size(); ++i, power *= w2) {
            value += at[i] * power;
            scale = std::max(scale, std::abs(at[i] * power));
        }
        if (std::abs(value) <= std::max(tol, 1e-9) * scale) ++roots;
    }
    j.agrees = roots >= degree;
    j.how = "in numbers, at the model's parameter values" + std::string(tol > 1e-10 ? " within the text's rounding" : "");
    return j;
}

bool NormalModesCheck::frequencies_in(const std::vector<ex>& values, const LatexContext& ctx,
                                      std::map<std::string, GiNaC::symbol>& out) const {
    std::vector<ex> stack = values;
    while (!stack.empty()) {
        const ex x = stack.back();
        stack.pop_back();
        for (std::size_t i = 0; i < x.nops(); ++i) stack.push_back(x.op(i));
        if (!GiNaC::is_a<GiNaC::symbol>(x)) continue;
        if (std::any_of(model_.parameters.begin(), model_.parameters.end(),
                        [&](const Parameter& p) { return x.is_equal(p.symbol); }))
            continue;
        const FreeName* f = ctx.free_name_of(x);
        if (!f || f->kind != NameKind::Unknown || !is_frequency_name(f->name)) return false;
        out.emplace(f->name, f->symbol);
    }
    return true;
}

void NormalModesCheck::find_abbreviations(const LatexContext& ctx) {
    scanned_ = true;
    LatexContext copy = ctx;  // the rows were parsed already: their names are known, nothing new is added
    std::map<std::string, Abbreviation> defined;
    std::map<std::string, int> shared;  // frequency → the last line where it appears with another frequency
    for (const MathRow& row : d_.rows)
        for (const Chain& c : parse_math(row.text, copy))
            for (std::size_t j = 1; j < c.sides.size(); ++j) {
                if (c.relations[j - 1] != Relation::Equal) continue;
                const std::vector<ex> A = readings(c.sides[j - 1], copy), B = readings(c.sides[j], copy);
                std::vector<ex> all = A;
                all.insert(all.end(), B.begin(), B.end());
                std::map<std::string, GiNaC::symbol> f;
                if (A.empty() || B.empty() || !frequencies_in(all, copy, f)) continue;
                const int line = d_.position(row.offset + c.relation_offsets[j - 1]).line;
                if (f.size() >= 2)
                    for (const auto& [name, symbol] : f) shared[name] = std::max(shared[name], line);
                if (f.size() != 1 || defined.count(f.begin()->first)) continue;
                if (A.size() != 1 || B.size() != 1) continue;
                if (const auto p = polynomial(A[0], B[0], f.begin()->second)) {
                    const std::vector<ex> k = coefficients(*p, w_);
                    if (k.size() == 2) defined[f.begin()->first] = {-k[0] / k[1], line, 0};
                }
            }
    for (const auto& [name, a] : defined)
        if (shared.count(name) && shared.at(name) > a.line) abbreviations_[name] = {a.omega2, a.line, shared.at(name)};
}

bool NormalModesCheck::check(const Side& left, const Side& right, LatexContext& ctx, Comparisons& cmp,
                             EquationCheck& r) {
    std::vector<ex> L = readings(left, ctx), R = readings(right, ctx);
    if (L.empty() || R.empty() || (L.size() != R.size() && L.size() != 1 && R.size() != 1)) return false;
    if (!scanned_) find_abbreviations(ctx);
    // Every name a parameter of the model or a frequency; each reading with one frequency, once the text's
    // abbreviations are replaced by their values.
    const std::size_t n = std::max(L.size(), R.size());
    L.resize(n, L.back());
    R.resize(n, R.back());
    std::vector<GiNaC::symbol> omega(n);
    std::vector<std::string> omega_name(n);
    std::vector<std::string> used;
    for (std::size_t k = 0; k < n; ++k) {
        std::map<std::string, GiNaC::symbol> found;
        if (!frequencies_in({L[k], R[k]}, ctx, found) || found.empty()) return false;
        if (found.size() == 1 && abbreviations_.count(found.begin()->first)) {
            const auto& [name, a] = *abbreviations_.find(found.begin()->first);
            r.notes.push_back("read as an abbreviation, not as a normal frequency: the text uses " + m(name) +
                              " in the frequency at line " + std::to_string(a.used_at));
            return false;
        }
        GiNaC::exmap values;
        for (const auto& [name, symbol] : found)
            if (const auto a = abbreviations_.find(name); a != abbreviations_.end() && found.size() > 1) {
                values[symbol] = GiNaC::sqrt(a->second.omega2);
                const std::string note = "uses " + m(name + "^{2} = " + cmp.latex(a->second.omega2)) +
                                         " as the text defines it at line " + std::to_string(a->second.line);
                if (std::find(used.begin(), used.end(), note) == used.end()) used.push_back(note);
            }
        if (found.size() - values.size() != 1) return false;
        for (const auto& [name, symbol] : found)
            if (!values.count(symbol)) {
                omega[k] = symbol;
                omega_name[k] = name;
            }
        L[k] = L[k].subs(values);
        R[k] = R[k].subs(values);
    }
    std::vector<ex> P(n);
    for (std::size_t k = 0; k < n; ++k) {
        // Too large to normalize within the budget: the caller says so.
        if (expanded_terms(L[k] - R[k]) > kMaxExpandedTerms) return false;
        const auto p = polynomial(L[k], R[k], omega[k]);
        if (!p) return false;  // ω, but not an equation in ω² (an angular velocity): compared as usual
        P[k] = *p;
    }
    if (!computed_) compute(cmp);
    // Without modes to compare with, ω may as well be an angular velocity the text has not defined: the link
    // is compared as usual (an unknown symbol), with why it is not compared as a frequency.
    if (!why_not_.empty()) {
        r.notes.push_back("read as a normal frequency, " + m(omega_name[0]) + " is not compared: " + why_not_);
        return false;
    }
    const std::string secular = "the secular equation " + m("\\det(K_0 - \\omega^2 M_0) = 0");
    r.notes.insert(r.notes.end(), used.begin(), used.end());
    const double tol = std::max(1e-10, left.rounding + right.rounding);

    // Every reading must agree with one and the same equilibrium.
    for (const Rest& rest : rests_) {
        std::vector<Judgement> js;
        for (std::size_t k = 0; k < n; ++k) js.push_back(judge(rest, P[k], omega_name[k], tol, cmp));
        if (!std::all_of(js.begin(), js.end(), [](const Judgement& j) { return j.agrees; })) continue;
        r.verdict = Verdict::Agrees;
        r.compared_with = secular + " at the equilibrium " + rest.at;
        std::string modes, values;
        for (std::size_t k = 0; k < n && js[k].mode >= 0; ++k) {
            modes += (k ? " and " : "") + std::to_string(js[k].mode + 1);
            values += (k ? " and " : "") + m("\\omega^{2} = " + number(rest.omega2[std::size_t(js[k].mode)]));
        }
        std::string what = js[0].what;
        if (js[0].mode >= 0)
            what += " (mode" + std::string(n > 1 ? "s " : " ") + modes + " of " + std::to_string(rest.omega2.size()) +
                    ", " + values + " at the model's parameter values)";
        std::string how = js[0].how;
        for (const Judgement& j : js)
            if (j.how.rfind("numerically", 0) == 0) how = j.how;
        if (n > 1 && js[0].mode >= 0) what.replace(0, std::string("a normal frequency").size(), "normal frequencies");
        r.reason = (n > 1 ? "both signs give " + what : what) + ", " + how;
        return true;
    }
    // Disagrees: compared with the first equilibrium the model lists (where the comparison could be made).
    const auto first = std::find_if(rests_.begin(), rests_.end(), [&](const Rest& rest) {
        for (std::size_t k = 0; k < n; ++k)
            if (!judge(rest, P[k], omega_name[k], tol, cmp).comparable) return false;
        return true;
    });
    if (first == rests_.end()) {
        r.notes.push_back("read as a normal frequency, " + m(omega_name[0]) + " is not compared: the model's stable "
                          "equilibria are known in numbers only (no closed form), and a frequency in the parameters "
                          "is compared with closed forms only (numbers are compared with numbers)");
        return false;
    }
    const Rest& rest = *first;
    r.verdict = Verdict::Disagrees;
    r.compared_with = secular + " at the equilibrium " + rest.at;
    r.reason = "its roots are not the model's normal frequencies there, " + frequencies(rest, omega_name[0], cmp);
    if (rests_.size() == 2) r.reason += " (nor at its other stable equilibrium)";
    if (rests_.size() > 2) r.reason += " (nor at its other " + std::to_string(rests_.size() - 1) + " stable equilibria)";
    for (std::size_t k = 0; k < n; ++k) {
        const Judgement j = judge(rest, P[k], omega_name[k], tol, cmp);
        if (j.agrees) continue;
        const std::string which = n > 1 ? (k == 0 ? " (the upper sign)" : " (the lower sign)") : "";
        const std::vector<ex> text = coefficients(P[k], w_);
        const int degree = int(text.size()) - 1;
        const ex w2 = GiNaC::pow(omega[k], 2);
        if (!j.wrong.empty()) {
            r.wrong_terms.push_back("the equation" + which + " is " + j.wrong);
        } else if (degree == 1) {
            const ex root = -text[0] / text[1];
            std::string line = (n > 1 ? "with " + which.substr(2, which.size() - 3) + ", " : std::string()) +
                               m(omega_name[k] + "^{2}") + " is not a normal frequency of the model";
            const ex value = GiNaC::evalf(root.subs(values_));
            if (j.mode >= 0 && GiNaC::is_a<GiNaC::numeric>(value))
                line += ": at the model's parameter values it is " +
                        number(GiNaC::ex_to<GiNaC::numeric>(value).real().to_double()) + ", the nearest mode (" +
                        std::to_string(j.mode + 1) + " of " + std::to_string(rest.omega2.size()) + ") has " +
                        m("\\omega^{2} = " + number(rest.omega2[std::size_t(j.mode)]));
            r.wrong_terms.push_back(line);
            const auto& exact = rest.omega2_exact[std::size_t(std::max(j.mode, 0))];
            // text − the nearest mode (of the first sign that is wrong); a correction for a single equation only
            // (the checker does not read \pm back).
            if (r.difference.empty() && j.mode >= 0 && exact) {
                r.difference = cmp.latex(tidy(root - *exact, values_));
                if (n == 1) r.corrected = cmp.latex(w2) + " = " + cmp.latex(tidy(*exact, values_));
            } else if (r.difference.empty() && j.mode >= 0 && GiNaC::is_a<GiNaC::numeric>(value)) {
                // In numbers: the text's and the nearest mode's ω² at the model's parameter values.
                const double mode = rest.omega2[std::size_t(j.mode)];
                r.difference = number(GiNaC::ex_to<GiNaC::numeric>(value).real().to_double() - mode);
                if (n == 1) r.corrected = cmp.latex(w2) + " = " + number(mode);
            }
        } else if (rest.poly && degree == int(coefficients(*rest.poly, w_).size()) - 1) {
            // The model's polynomial scaled to the text's leading coefficient.
            const std::vector<ex> model = coefficients(*rest.poly, w_);
            const ex scaled = GiNaC::normal(rest.poly->subs(w_ == w2) * text.back() / model.back());
            r.wrong_terms.push_back("the equation" + which + " is not the model's secular equation " +
                                    m(cmp.latex(scaled) + " = 0"));
            if (r.difference.empty()) {
                r.difference = cmp.latex(GiNaC::normal(P[k].subs(w_ == w2) - scaled));
                if (n == 1) r.corrected = cmp.latex(scaled) + " = 0";
            }
        } else {
            r.wrong_terms.push_back("the equation" + which + " is not a factor of the model's characteristic polynomial");
        }
    }
    return true;
}

}  // namespace eomgen::checker
