/** @file checker.cpp  Equation by equation: labels, identities, Euler–Lagrange equations, integrals of
 * motion. */
#include "checker/checker.hpp"
#include "checker/conditions.hpp"
#include "checker/constrained_motion.hpp"
#include "checker/coverage.hpp"

#include "checker/additive_constant.hpp"
#include "checker/amplitude_equations.hpp"
#include "checker/claimed_solution.hpp"
#include "checker/equivalent_lagrangian.hpp"
#include "checker/approximation.hpp"
#include "checker/budget.hpp"
#include "checker/correction_check.hpp"
#include "checker/definitions.hpp"
#include "checker/discourse.hpp"
#include "checker/hamiltonian_check.hpp"
#include "checker/labels.hpp"
#include "checker/meanings.hpp"
#include "checker/prose.hpp"
#include "checker/latex_normalize.hpp"
#include "checker/motions.hpp"
#include "checker/latex_parser.hpp"
#include "checker/linear_algebra.hpp"
#include "checker/normal_modes_check.hpp"
#include "checker/printed_numbers.hpp"
#include "codegen/cpp_emitter.hpp"
#include "codegen/math_printer.hpp"
#include "mechanics/pole_free_subs.hpp"
#include "mechanics/results.hpp"
#include "mechanics/trig_rewrite.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <functional>
#include <iomanip>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <sstream>

namespace eomgen::checker {

const char* verdict_name(Verdict v) {
    switch (v) {
        case Verdict::Agrees:
            return "agrees";
        case Verdict::Disagrees:
            return "disagrees";
        case Verdict::NotComparable:
            return "not comparable";
        case Verdict::NotRead:
            return "not read";
    }
    return "";
}

int CheckReport::count(Verdict v) const {
    return int(std::count_if(equations.begin(), equations.end(),
                             [v](const EquationCheck& e) { return e.verdict == v; }));
}

namespace {

using Complex = std::complex<double>;
using ExSet = std::set<GiNaC::ex, GiNaC::ex_is_less>;
template <class V>
using ExMap = std::map<GiNaC::ex, V, GiNaC::ex_is_less>;

std::string m(const std::string& latex) {
    return "$" + latex + "$";
}

enum class Tri { No, Yes, Unknown };

/// The exact rational a model's double default stands for ("0.3" is 3/10, not the binary float).
GiNaC::numeric exact_decimal(double v) {
    const std::string s = codegen::shortest_decimal(v);
    GiNaC::numeric mant(0);
    long exponent = 0;
    bool neg = false, point = false;
    std::size_t i = 0;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) neg = s[i++] == '-';
    for (; i < s.size(); ++i) {
        const char c = s[i];
        if (c >= '0' && c <= '9') {
            mant = mant * 10 + (c - '0');
            if (point) --exponent;
        } else if (c == '.') {
            point = true;
        } else if (c == 'e' || c == 'E') {
            exponent += std::strtol(s.c_str() + i + 1, nullptr, 10);
            break;
        }
    }
    GiNaC::numeric r = mant * GiNaC::pow(GiNaC::numeric(10), GiNaC::numeric(exponent));
    return neg ? -r : r;
}

bool has_integral(const GiNaC::ex& e) {
    if (GiNaC::is_a<GiNaC::integral>(e)) return true;
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (has_integral(e.op(i))) return true;
    return false;
}

std::optional<Complex> as_complex(const GiNaC::ex& v) {
    if (!GiNaC::is_a<GiNaC::numeric>(v)) return std::nullopt;
    const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(v);
    const Complex c(n.real().to_double(), n.imag().to_double());
    if (!std::isfinite(c.real()) || !std::isfinite(c.imag())) return std::nullopt;
    return c;
}

/**
 * ∫_a^b f(x) dx by tanh–sinh quadrature (Takahasi & Mori 1974), which copes with the integrable endpoint
 * singularities of derivations such as ∫ dψ/√(sin ψ). Nodes are placed by their distance from the nearer end
 * so that points next to a singular end are not rounded onto it.
 */
template <class F>
std::optional<Complex> tanh_sinh(F f, double a, double b) {
    const double half = (b - a) / 2, mid = (a + b) / 2;
    if (half == 0) return Complex(0);
    std::optional<Complex> previous;
    for (int level = 2; level <= 7; ++level) {
        const double h = std::ldexp(1.0, -level);
        Complex sum = 0;
        bool ok = true;
        for (double t = -4.0; t <= 4.0 + 1e-12; t += h) {
            const double u = M_PI / 2 * std::sinh(t);
            const double w = M_PI / 2 * std::cosh(t) / (std::cosh(u) * std::cosh(u));
            if (w < 1e-300) continue;
            const double dist = 2 / (std::exp(2 * std::abs(u)) + 1);  // 1 − tanh|u|, accurately
            const double x = t > 0 ? b - half * dist : (t < 0 ? a + half * dist : mid);
            if (x == a || x == b) continue;
            const std::optional<Complex> fx = f(x);
            if (!fx) {
                ok = false;
                break;
            }
            sum += w * *fx;
        }
        if (!ok) return std::nullopt;
        const Complex value = half * h * sum;
        if (previous && std::abs(value - *previous) <= 1e-11 * std::max(1.0, std::abs(value))) return value;
        previous = value;
    }
    return previous;
}

/// Numbers for the comparisons: random points for every symbol, values with integrals evaluated.
class Numbers {
  public:
    Numbers(const Model& model, const LatexContext& ctx) : model_(model), ctx_(ctx) {}

    /// Parameters (and free names) from `param_seed`, coordinates, velocities, accelerations and t from
    /// `state_seed`; each a rational in (0.5, 1.5).
    GiNaC::exmap point(unsigned param_seed, unsigned state_seed) const {
        GiNaC::exmap at;
        std::mt19937 pr(param_seed * 7919u + 17u), sr(state_seed * 104729u + 5u), flip(state_seed * 31u + 7u);
        std::uniform_int_distribution<int> pick(500, 1500);
        auto value = [&](std::mt19937& r) { return GiNaC::numeric(pick(r), 1000); };
        // Where abs, sign, max … of the state are compared, every other point gives the state values either sign:
        // at positive values alone θ'|θ'| and θ'² are one function.
        const bool signs = signed_state_ && state_seed % 2 == 0;
        auto state_value = [&] { return (signs && (flip() & 1u)) ? -value(sr) : value(sr); };
        for (const Parameter& p : model_.parameters) at[p.symbol] = value(pr);
        for (const auto& [name, f] : ctx_.free_names) at[f.symbol] = value(pr);
        at[model_.t] = value(sr);
        for (const Coordinate& c : model_.coordinates) {
            at[c.q] = state_value();
            at[c.qd] = state_value();
            at[c.qdd] = state_value();
        }
        for (const GiNaC::symbol& s : state_symbols_) at[s] = value(sr);
        for (const auto& [p, v] : pinned_) at[p] = v;
        return at;
    }
    /// A symbol that takes a value per state, as the coordinates do (a constraint's multiplier λ).
    void add_state_symbol(const GiNaC::symbol& s) { state_symbols_.push_back(s); }
    /// Whether the points give q, q', q'' either sign (at even state seeds): while a non-smooth function is compared.
    void sign_state(bool on) { signed_state_ = on; }
    /// Parameters and coordinates held at a value the text chose for its paragraph (`m_1 = 0`, `\\theta = \\pi/2`):
    /// every point uses it.
    void pin(const GiNaC::exmap& values) { pinned_ = values; }
    const GiNaC::exmap& pinned() const { return pinned_; }
    bool state_signed() const { return signed_state_; }
    GiNaC::exmap point(unsigned seed) const { return point(seed, seed); }

    std::optional<Complex> value(const GiNaC::ex& e, const GiNaC::exmap& at) {
        try {
            GiNaC::ex v = e.subs(at);
            v = integrals(v);
            return as_complex(GiNaC::evalf(v));
        } catch (...) {
            return std::nullopt;
        }
    }

    /// Σ |term| over the terms of e expanded: the scale against which a difference is small.
    double scale(const GiNaC::ex& e, const GiNaC::exmap& at) {
        GiNaC::ex x = e;
        try {
            x = e.expand();
        } catch (...) {
        }
        double s = 0;
        if (GiNaC::is_a<GiNaC::add>(x)) {
            for (const GiNaC::ex& t : x)
                if (auto v = value(t, at)) s += std::abs(*v);
        } else if (auto v = value(x, at)) {
            s = std::abs(*v);
        }
        return s;
    }

  private:
    std::vector<GiNaC::symbol> state_symbols_;
    GiNaC::exmap pinned_;
    bool signed_state_ = false;
    GiNaC::ex integrals(const GiNaC::ex& e) {
        if (!has_integral(e)) return e;
        if (GiNaC::is_a<GiNaC::integral>(e)) {
            auto hit = cache_.find(e);
            if (hit != cache_.end()) return hit->second;
            const GiNaC::ex x = e.op(0);
            const GiNaC::ex lo = integrals(e.op(1)), hi = integrals(e.op(2)), f = integrals(e.op(3));
            const auto a = as_complex(GiNaC::evalf(lo)), b = as_complex(GiNaC::evalf(hi));
            if (!a || !b || a->imag() != 0 || b->imag() != 0) throw std::runtime_error("limits");
            auto integrand = [&](double xv) -> std::optional<Complex> {
                try {
                    return as_complex(GiNaC::evalf(f.subs(x == GiNaC::numeric(xv))));
                } catch (...) {
                    return std::nullopt;
                }
            };
            const auto v = tanh_sinh(integrand, a->real(), b->real());
            if (!v) throw std::runtime_error("integral");
            const GiNaC::ex r = GiNaC::numeric(v->real()) + GiNaC::I * GiNaC::numeric(v->imag());
            cache_[e] = r;
            return r;
        }
        struct Each : GiNaC::map_function {
            Numbers* self;
            explicit Each(Numbers* n) : self(n) {}
            GiNaC::ex operator()(const GiNaC::ex& x) override { return self->integrals(x); }
        } each(this);
        return e.map(each);
    }

    const Model& model_;
    const LatexContext& ctx_;
    ExMap<GiNaC::ex> cache_;
};

/// A side of a link with where its row starts in the file.
struct PSide {
    const Side* side = nullptr;
    std::size_t base = 0;
};

/// A chain a = b = c, continued across rows that start with "=".
struct FullChain {
    std::vector<PSide> sides;
    std::vector<Relation> relations;
    std::vector<std::size_t> relation_offsets;  ///< file offsets
    int section = -1;
    bool display = false;
};

/// A side made ready for comparison: labels replaced, d/dt and ∂ evaluated, free names listed.
struct Prepared {
    bool ok = false;
    std::string problem;  ///< when !ok
    GiNaC::ex value;
    std::vector<const FreeName*> unknown, vectors, units;
    std::vector<GiNaC::ex> constants;  ///< `\text{const}`: an arbitrary additive constant
    bool has_truth_label = false;  ///< refers to eomgen's T, V, L, ...
    bool has_part = false;         ///< uses a part T_{x} whose value came from the text
    bool from_definition = false;  ///< differentiates a quantity the text defines (the step's reference)
    bool has_momenta = false;      ///< written in the momenta p_q (or ∂H/∂·): `value_p` is in them
    GiNaC::ex value_p;             ///< the value before p_q → p(q, q̇) (hamiltonian_check.hpp)
    std::vector<std::string> notes;
    bool comparable() const { return ok && unknown.empty() && vectors.empty(); }
};

/// Terms grouped by their monomial in the velocities and accelerations (the shape of a mechanics equation).
struct Group {
    GiNaC::ex monomial;
    std::vector<GiNaC::ex> terms;  ///< whole terms, monomial included
    GiNaC::ex coefficient = 0;     ///< Σ terms / monomial
};

struct Diagnosis {
    std::string difference;
    std::vector<std::string> lines;
};

class Checker : public Comparisons {
  public:
    // Comparisons, for the files of one capability (approximation, additive_constant).
    bool same(const GiNaC::ex& a, const GiNaC::ex& b, double tol) override { return equal(a, b, tol) == Tri::Yes; }
    bool equation_of_motion(const GiNaC::ex& r, double tol) override {
        int only = -1;
        std::string factor;
        return has_acceleration(r) && euler_lagrange_combination(r, tol, &only, &factor) == Tri::Yes;
    }
    std::vector<bool> euler_lagrange_terms(const GiNaC::ex& r, double tol) override {
        int only = -1;
        std::string factor;
        std::vector<bool> used;
        if (!has_acceleration(r) || euler_lagrange_combination(r, tol, &only, &factor, nullptr, &used) != Tri::Yes)
            return {};
        return used;
    }
    int closest_euler_lagrange(const GiNaC::ex& r, double tol) override {
        GiNaC::ex factor = 1;
        int groups = 0;
        const int i = has_acceleration(r) ? closest_euler_lagrange(r, tol, &factor, &groups) : -1;
        return groups >= 1 ? i : -1;
    }
    std::string latex(const GiNaC::ex& e) override;
    std::vector<std::string> wrong_terms(const GiNaC::ex& text, const GiNaC::ex& truth, double tol) override {
        return compare_to(text, truth, tol).lines;
    }

    Checker(const Model& model, const Equations& eq, const Derivation& d, const CheckOptions& options)
        : model_(model),
          eq_(eq),
          d_(d),
          options_(options),
          numbers_(model, ctx_),
          printer_table_(codegen::symbol_table(model)),
          hamilton_(model, eq),
          modes_(model, eq, d),
          parameter_values_(model, options.set),
          algebra_(model, d, ctx_, [this](const Side& s, std::size_t base) {
              const Prepared p = prepare(PSide{&s, base});
              return ScalarReading{p.ok, p.value, p.problem, p.has_truth_label};
          }) {
        hints_.other_angles = false;  // only the sines and cosines the author or the model wrote
        for (const Parameter& p : model.parameters) hints_.constants.insert(p.symbol);
    }

    CheckReport run();

  private:
    // ----- setup
    void add_name(const std::string& latex, const GiNaC::ex& value) {
        std::string c = canonical_name(latex);
        if (c.empty()) c = latex;
        ctx_.names.emplace(c, value);
    }
    void add_label(const std::string& name, const GiNaC::ex& truth, const std::string& what) {
        if (ctx_.names.count(name)) return;  // the model's own names come first
        const GiNaC::symbol s(name, name);
        ctx_.names[name] = s;
        truth_[s] = truth;
        label_what_[s] = what;
    }
    void setup_names();
    /// The map's entries for every line (line 0), or those scoped to the text's `line`.
    void apply_map(int line = 0);

    // ----- evaluation
    GiNaC::ex resolve_operators(const GiNaC::ex& e) const;
    Prepared prepare(const PSide& s, const GiNaC::ex* exclude_part = nullptr);
    std::string where(std::size_t file_offset) const {
        const SourcePos p = d_.position(file_offset);
        return std::to_string(p.line) + ":" + std::to_string(p.column);
    }
    bool is_part(const GiNaC::ex& e, std::string* name = nullptr, GiNaC::ex* whole = nullptr) const;

    Tri equal(const GiNaC::ex& a, const GiNaC::ex& b, double tol);
    std::vector<Complex> signature(const GiNaC::ex& e);
    bool same_signature(const std::vector<Complex>& a, const std::vector<Complex>& b, double tol) const;

    // ----- what an equation can be
    bool has_acceleration(const GiNaC::ex& e) const {
        for (const Coordinate& c : model_.coordinates)
            if (e.has(c.qdd)) return true;
        return false;
    }
    bool has_velocity(const GiNaC::ex& e) const {
        for (const Coordinate& c : model_.coordinates)
            if (e.has(c.qd)) return true;
        return false;
    }
    bool depends_on_state(const GiNaC::ex& e) const {
        for (const Coordinate& c : model_.coordinates)
            if (e.has(c.q) || e.has(c.qd)) return true;
        return false;
    }
    /// "the left side is k times the right side", from the factors the two sides do not share.
    std::vector<std::string> factor_analysis(const GiNaC::ex& a, const GiNaC::ex& b, double tol,
                                             std::string* ratio);
    /// r = Σ c_i EL_i with c from the acceleration coefficients: a consequence of the equations of motion.
    /// With `multipliers` (+1 or −1: the text's λ with eomgen's sign or the other), EL_i holds the constraint
    /// forces ± Σ_k A_ki λ_k, the text's λ being the constraints' multipliers.
    Tri euler_lagrange_combination(const GiNaC::ex& r, double tol, int* only, std::string* factor,
                                   std::vector<std::string>* acting = nullptr, std::vector<bool>* terms = nullptr,
                                   int multipliers = 0);
    /// The constraints solved for some coordinates and velocities (those `keep` does not use first), with
    /// the substitutions in LaTeX.
    ConstraintReduction reduction(const GiNaC::ex& keep, std::string* shown);
    /// r = k(q, t)·c with c the velocity form of constraint `index`, k ≠ 0 free of the velocities.
    bool proportional_to_constraint(const GiNaC::ex& r, std::size_t index, double tol);
    /// r is linear in the velocities (no products or powers of them) and has at least one.
    bool linear_in_velocities(const GiNaC::ex& r) const;
    /// r = c·target with c free of the state: the integral of motion written with the model's initial state.
    bool proportional_in_state(const GiNaC::ex& r, const GiNaC::ex& target, double tol, GiNaC::ex* c);

    // ----- diagnosis
    std::vector<Group> groups(const GiNaC::ex& e) const;
    std::string group_name(const GiNaC::ex& monomial) const;
    Diagnosis compare_to(const GiNaC::ex& text, const GiNaC::ex& truth, double tol);
    std::string pair_kind(const GiNaC::ex& t, const GiNaC::ex& u, double tol, int* score);
    /// The factor c making c·truth closest to text group by group; the number of groups that then agree.
    int best_factor(const GiNaC::ex& text, const GiNaC::ex& truth, double tol, GiNaC::ex* c);

    // ----- checking
    void collect_parts(const std::vector<FullChain>& chains);
    void check_chain(const FullChain& c, std::vector<EquationCheck>& out);
    EquationCheck check_link(const FullChain& c, std::size_t i, std::size_t j, bool bridge);
    /// check_link, with anything GiNaC throws on a strange input turned into a "not comparable" verdict.
    EquationCheck safe_check_link(const FullChain& c, std::size_t i, std::size_t j, bool bridge) {
        try {
            EquationCheck r = check_link(c, i, j, bridge);
            if (i == 0 && r.verdict == Verdict::Disagrees && !verifying_) {
                const std::size_t at = c.relation_offsets[j - 1];
                for (const TextMeaning& m : meanings_)
                    if (at >= m.begin && at < m.end) {
                        EquationCheck n;
                        n.where = r.where;
                        n.section = r.section;
                        n.equation = r.equation;
                        n.reason = "a definition: the text's $" + m.name + "$ is the " + m.noun + " here, not eomgen's $" +
                                   m.name + "$; read so from line " + std::to_string(m.line + 1) +
                                   " to the end of its section";
                        return n;
                    }
            }
            // (A label of eomgen's — V, T, L, p_θ — set to an expression in the state is a claim about it, whatever
            // the sentence's cue; set to a number, `T = 1` "the unit of time", it is the text's other meaning. The
            // amplitudes of a trial solution are not values the text sets either: `A_1 = A_2` "with ω² = 3k/m" is the
            // mode's shape, a claim.)
            const auto label_claim = [&](std::size_t label, std::size_t other) {
                return truth_.count(c.sides[label].side->value) && depends_on_state(prepare(c.sides[other]).value);
            };
            const auto amplitudes = [&] {
                const TrialSolution* t = discourse_->trial_at(c.relation_offsets[j - 1]);
                if (!t) return false;
                for (const GiNaC::ex& a : t->amplitude)
                    if (!a.is_zero() && (c.sides[i].side->value.has(a) || c.sides[j].side->value.has(a))) return true;
                return false;
            };
            if (r.verdict == Verdict::Disagrees && !verifying_ && c.sides[i].side->ok && c.sides[j].side->ok &&
                !label_claim(i, j) && !label_claim(j, i) && !amplitudes() &&
                sets_a_value(c.sides[i].side->value, c.sides[j].side->value, model_)) {
                // "started with θ̇ = 0", "with m₁ = m₂ = m": values set for what follows, not an equation of motion.
                const std::string cue = condition_cue(d_, c.relation_offsets[j - 1]);
                if (!cue.empty()) {
                    EquationCheck n;
                    n.where = r.where;
                    n.section = r.section;
                    n.equation = r.equation;
                    n.reason = "a condition or a given value (after “" + cue +
                               "”): it sets a value for what follows, not an equation of motion, and is not judged";
                    return n;
                }
            }
            if (r.verdict == Verdict::Disagrees && !verifying_) blame_definition(c, i, j, r);
            if (!r.corrected.empty() && !verifying_) verify_correction(c, j, r);
            if (!verifying_ && c.display) check_prose_label(c, i, j, r);
            return r;
        } catch (const std::exception& e) {
            EquationCheck r;
            r.where = d_.position(c.relation_offsets[j - 1]);
            if (c.section >= 0) r.section = d_.sections[std::size_t(c.section)].title;
            r.equation = c.sides[i].side->source + " = " + c.sides[j].side->source;
            r.reason = std::string("cannot be evaluated: ") + e.what();
            return r;
        }
    }
    /// A line that disagrees only through a name the text defined (`V = m g y` with the text's y of line 23), its
    /// other side eomgen's value: what the name would have to be for it to hold (apply_blames decides).
    struct Blame {
        std::string name;     ///< the defined name, canonical LaTeX
        GiNaC::ex needed;     ///< what the line needs it to be
        int definition_line;  ///< where the text defines it
        SourcePos where;      ///< the line's verdict
        std::string equation;
    };
    std::vector<Blame> blames_;
    void blame_definition(const FullChain& c, std::size_t i, std::size_t j, const EquationCheck& r);
    /// A definition that two or more lines blame alike is the slip: it disagrees (corrected to what they need), and
    /// they are not comparable, pointing to it.
    void apply_blames(std::vector<EquationCheck>& equations);
    /// The link compared with what the sentence before its display calls it (labels.hpp).
    void check_prose_label(const FullChain& c, std::size_t i, std::size_t j, EquationCheck& r);
    /// Parses r.corrected back with the names of its line and checks it (correction_check.hpp); a correction
    /// that does not agree is withheld, with a note.
    void verify_correction(const FullChain& c, std::size_t j, EquationCheck& r);
    /// a ≈ b compared with the Taylor expansion about q = 0 of the coordinates the text calls small (or, when
    /// `implied`, every coordinate it holds), to the order it keeps (approximation.hpp). False when it does
    /// not apply (no side is a polynomial in them).
    bool approximation(std::size_t at, const std::string& left, const std::string& right, const Prepared& a,
                       const Prepared& b, bool implied, EquationCheck& r);
    bool verifying_ = false;
    void check_part(const GiNaC::ex& part, const std::string& part_source, const Prepared& other, double tol,
                    EquationCheck& r);
    /// T (or V) minus the text's other parts of it, when the text defines other parts.
    std::optional<GiNaC::ex> expected_part(const GiNaC::ex& part) const {
        std::string name;
        GiNaC::ex whole;
        if (!is_part(part, &name, &whole)) return std::nullopt;
        GiNaC::ex others = 0;
        bool any = false;
        for (const auto& [sym, value] : part_value_) {
            std::string n2;
            if (sym.is_equal(part) || !is_part(sym, &n2) || n2[0] != name[0]) continue;
            others += value;
            any = true;
        }
        if (!any) return std::nullopt;
        return whole - others;
    }
    /// `V = -m g l \cos\theta + \text{const}`: agrees (true) when the sides differ by a constant; else
    /// the constants are dropped from a and b for the other comparisons (false).
    bool up_to_constant(Prepared& a, Prepared& b, double tol, EquationCheck& r) {
        if (a.constants.empty() && b.constants.empty()) return false;
        GiNaC::exmap zero;
        for (const Prepared* p : {&a, &b})
            for (const GiNaC::ex& k : p->constants) zero[k] = 0;
        a.value = a.value.subs(zero);
        b.value = b.value.subs(zero);
        if (!a.comparable() || !b.comparable() || !a.units.empty() || !b.units.empty()) return false;
        const int constant_side = a.value.is_zero() && !a.constants.empty()
                                      ? 0
                                      : (b.value.is_zero() && !b.constants.empty() ? 1 : -1);
        return check_additive_constant(a.value, b.value, constant_side, model_, *this, tol, r);
    }
    void check_values(const FullChain& c, std::size_t i, std::size_t j, const Prepared& a, const Prepared& b,
                      double tol, EquationCheck& r);
    bool diagnose_solved_acceleration(const PSide& left, const PSide& right, const GiNaC::ex& r, double tol,
                                      EquationCheck& out);
    void diagnose_euler_lagrange(const PSide& left, const PSide& right, const GiNaC::ex& r, double tol,
                                 EquationCheck& out);
    /// The coordinate whose Euler–Lagrange equation r matches best (the most groups of terms equal after the
    /// best factor, `factor`; `groups` of them).
    int closest_euler_lagrange(const GiNaC::ex& r, double tol, GiNaC::ex* factor, int* groups);

    const Model& model_;
    const Equations& eq_;
    const Derivation& d_;
    const CheckOptions& options_;
    /// The text's own meanings of label letters (meanings.hpp), as map entries scoped to the lines after their
    /// definition, and the rows that define them.
    std::vector<MapEntry> meaning_map_;
    std::vector<TextMeaning> meanings_;
    LatexContext ctx_;
    Numbers numbers_;
    codegen::SymbolTable printer_table_;
    trig::Hints hints_;  ///< what is printed is rewritten towards: the author's angle sums (set per link)
    ExMap<GiNaC::ex> truth_;          ///< label symbol → eomgen's value
    ExMap<std::string> label_what_;   ///< label symbol → what it is, for the report
    ExSet bare_only_;                 ///< labels that count only as a whole side (h, H)
    ExSet result_labels_;             ///< labels of the model's declared results
    ExMap<GiNaC::ex> part_value_;     ///< part symbol → its value in the text
    ExMap<std::string> part_origin_;  ///< part symbol → "line N"
    std::vector<GiNaC::ex> motion_;   ///< the equations of motion, = 0
    std::vector<GiNaC::symbol> multipliers_;  ///< λ_k per constraint, as a text names them (\lambda, \lambda_{1})
    std::vector<std::pair<GiNaC::ex, std::string>> integrals_of_motion_;
    ExMap<std::vector<Complex>> signatures_;
    TextDefinitions definitions_;   ///< K = ..., used where the text differentiates K
    std::size_t current_offset_ = 0;  ///< file offset of the side being prepared (definitions before it apply)
    void collect_definitions(const std::vector<FullChain>& chains);
    HamiltonianReading hamilton_;  ///< p_q as variables, H(q, p, t) inside ∂
    ParticularMotions motions_{model_, eq_, ctx_};  ///< [[motions]]: lines that hold on one motion
    /// a = b (link j of c) on the model's particular motion for its section (motions.hpp).
    bool on_motion(const FullChain& c, std::size_t i, std::size_t j, const GiNaC::ex& a, const GiNaC::ex& b,
                   double tol, EquationCheck& r) {
        if (motions_.empty()) return false;
        std::vector<std::string> titles;
        const std::size_t at = c.relation_offsets[j - 1];
        for (const Section& s : d_.sections)
            if (s.begin <= at && at < s.end) titles.push_back(s.title);
        return motions_.check(a, b, c.sides[i].side->source, titles, *this, tol, r);
    }
    NormalModesCheck modes_;       ///< ω² and secular equations against the model's normal modes
    AmplitudeEquations amplitudes_{model_, motion_};  ///< rows of (K − ω² M) A = 0 for a trial solution
    /// The rows' roles besides claims (discourse.hpp), read from all rows before any is compared.
    std::optional<Discourse> discourse_;
    ParameterValues parameter_values_;  ///< for the numbers the text works out
    static std::vector<std::string> written_names(const PSide& a, const PSide& b) {
        std::vector<std::string> out;
        for (const PSide* s : {&a, &b})
            for (const NameUse& u : s->side->uses) out.push_back(u.name);
        return out;
    }
    std::vector<std::string> chosen_notes_;  ///< "with $m_1 = 0$, the value the text chose on line 31" (check_link)
    std::set<std::string> not_parts_;  ///< T_… the text sets to a nonzero constant: a period, not a part of T
    std::set<std::size_t> at_a_point_;  ///< heads of definitions that hold at a point the text considers
    LinearAlgebra algebra_;             ///< arrays, tuples, eigen-equations: entry by entry
    int velocity_h_line_ = 0;       ///< the first line where the text writes H in velocities (0: none)
    std::size_t velocity_h_at_ = 0;  ///< its file offset
    /// The reference's value as a correction prints it: in the momenta when the text's side is written in them.
    std::string printed_value(const Prepared& ref, const PSide& ref_side, const Prepared& text) {
        const std::string in_velocities = latex(ref.value);
        std::optional<GiNaC::ex> in_p;
        if (text.has_momenta && ref.has_momenta) in_p = hamilton_.in_momenta(ref.value_p);
        if (text.has_momenta && ref_side.side->ok && hamilton_.is_hamiltonian(ref_side.side->value))
            in_p = hamilton_.hamiltonian();
        // In the momenta unless that is much longer (an inverse mass matrix GiNaC cannot simplify).
        if (in_p && expanded_terms(*in_p) <= kMaxExpandedTerms / 10) {
            const std::string shown = latex(*in_p);
            if (shown.size() <= 2 * in_velocities.size()) return shown;
        }
        return in_velocities;
    }
};

// ------------------------------------------------------------------------------------------------ setup

void Checker::setup_names() {
    ctx_.time = model_.t;
    ctx_.names["t"] = model_.t;
    for (const Coordinate& c : model_.coordinates) {
        add_name(c.latex, c.q);
        add_name("\\dot{" + c.latex + "}", c.qd);
        add_name("\\ddot{" + c.latex + "}", c.qdd);
    }
    for (const Parameter& p : model_.parameters) add_name(p.latex, p.symbol);
    // \ell is how many texts typeset a length l (add_name keeps a model's own \ell).
    if (auto l = ctx_.names.find("l"); l != ctx_.names.end()) add_name("\\ell", l->second);

    // Labels for eomgen's quantities, unless the model uses the letter for something of its own.
    add_label("T", eq_.T, "T");
    add_label("V", eq_.V, "V");
    // U: the letter many texts use for the potential energy (a model's own U comes first). K for the kinetic
    // energy is not read so (a spring constant as often); KE and PE, the blogs' abbreviations, are.
    add_label("U", eq_.V, "V");
    add_label("KE", eq_.T, "T");
    add_label("PE", eq_.V, "V");
    add_label("L", eq_.L, "L");
    add_label("\\mathcal{L}", eq_.L, "L");
    add_label("E", eq_.T + eq_.V, "E = T + V");
    add_label("H", eq_.energy, "h");
    add_label("h", eq_.energy, "h");
    for (const char* b : {"H", "h"})
        if (truth_.count(ctx_.names.at(b))) bare_only_.insert(ctx_.names.at(b));
    std::vector<GiNaC::ex> momentum_labels;  // a model's own p_{q} is not a label: set_labels skips it
    for (std::size_t i = 0; i < model_.dof(); ++i) {
        std::string c = canonical_name(model_.coordinates[i].latex);
        if (c.empty()) c = model_.coordinates[i].latex;
        // The key as the text's p_{\theta_1} reads (a subscript inside a subscript is flattened).
        std::string key = canonical_name("p_{" + c + "}");
        if (key.empty()) key = "p_{" + c + "}";
        add_label(key, eq_.momenta[i], "p_{" + c + "}");
        momentum_labels.push_back(ctx_.names.at(key));
    }
    // The conserved quantities of symmetries (mechanics/noether.hpp): L_z of a particle on a sphere written in x, y, z.
    for (const ConservedQuantity& c : eq_.conserved) {
        if (c.name == "h" || c.name.rfind("p_", 0) == 0) continue;
        std::string key = canonical_name(c.latex);
        add_label(key.empty() ? c.latex : key, c.value, c.latex);
    }
    hamilton_.set_labels(momentum_labels, truth_.count(ctx_.names.at("H")) ? ctx_.names.at("H") : GiNaC::ex(0));
    // Declared results ([[results]]): their LaTeX stands for their closed form, before eomgen's own labels
    // (a result written 'T' is the closed form), after the model's coordinates and parameters.
    for (const Result& res : model_.results) {
        std::string c = canonical_name(res.latex);
        if (c.empty()) c = res.latex;
        auto it = ctx_.names.find(c);
        if (it != ctx_.names.end() && !truth_.count(it->second)) continue;  // a coordinate or a parameter
        const GiNaC::symbol s(c, c);
        ctx_.names[c] = s;
        truth_[s] = res.expr.expr;
        result_labels_.insert(s);
        label_what_[s] = "the declared result " + res.name + " (" + m(res.latex + " = " + latex(res.expr.expr)) +
                         (res.equals.empty() ? std::string(")")
                                             : ", verified against " + result_target_name(res) +
                                                   (res.on_constraints ? " on the constraints)" : ")"));
    }

    // h(0) and p(0) at the model's initial state, for the integrals of motion a derivation writes out.
    GiNaC::exmap init;
    init[model_.t] = 0;
    for (const Coordinate& c : model_.coordinates) {
        init[c.q] = exact_decimal(c.initial);
        init[c.qd] = exact_decimal(c.rate);
    }
    for (const ConservedQuantity& c : eq_.conserved)
        integrals_of_motion_.push_back(
            {c.value - c.value.subs(init),
             "the conservation of " + m(c.latex) + " with the model's initial state (" + c.reason + ")"});
    // A holonomic constraint's name is its function g(q, t) (`\frac{\partial f}{\partial\varphi}` of the constraint f),
    // unless the model uses the name for something else.
    for (const ConstraintEquations& k : eq_.constraints)
        if (!k.position.is_zero() && !ctx_.names.count(canonical_name(k.name))) add_name(k.name, k.position);
    // The constraints' multipliers: \lambda where there is one constraint, \lambda_{k} and \lambda_{name} (the model's
    // own names first); each takes a value per state, as it is a function of the state.
    for (std::size_t k = 0; k < eq_.constraints.size(); ++k) {
        const std::string& name = eq_.constraints[k].name;
        const GiNaC::symbol s("lambda_" + name, "\\lambda_{" + name + "}");
        multipliers_.push_back(s);
        numbers_.add_state_symbol(s);
        if (eq_.constraints.size() == 1) add_name("\\lambda", s);
        add_name("\\lambda_{" + std::to_string(k + 1) + "}", s);
        add_name("\\lambda_{" + name + "}", s);
        add_name("\\lambda_{\\text{" + name + "}}", s);
    }
    // The equations of motion: d/dt(∂L/∂q̇) − ∂L/∂q − Q = 0 (Q: generalized and dissipative forces).
    for (std::size_t i = 0; i < model_.dof(); ++i)
        motion_.push_back(i < eq_.generalized_forces.size()
                              ? eq_.euler_lagrange[i] - eq_.generalized_forces[i]
                              : eq_.euler_lagrange[i]);
}

void Checker::apply_map(int line) {
    std::vector<MapEntry> entries = options_.map;
    const std::size_t given = entries.size();  // the user's entries; then the text's meanings (never an error)
    entries.insert(entries.end(), meaning_map_.begin(), meaning_map_.end());
    for (std::size_t k = 0; k < entries.size(); ++k) {
        const MapEntry& e = entries[k];
        if (k >= given) {
            if (line == 0 || line < e.first_line || line > e.last_line) continue;
            const Side s = parse_expression(e.value, ctx_);
            if (s.ok) ctx_.names[canonical_name(e.name)] = s.value;
            continue;
        }
        if (line == 0 ? e.first_line != 0 : (e.first_line == 0 || line < e.first_line || line > e.last_line))
            continue;
        std::string name = canonical_name(e.name);
        // A bare word stands for \text{word}: the map key "Trod" names the text's \text{ Trod }.
        if (name.empty() && !e.name.empty() && std::all_of(e.name.begin(), e.name.end(), [](char ch) {
                return std::isalpha(static_cast<unsigned char>(ch));
            }))
            name = e.name;
        if (name.empty())
            throw CheckError(e.origin + ": '" + e.name +
                             "' is not a single LaTeX name (such as I_{0} or \\omega_{a})");
        const Side s = parse_expression(e.value, ctx_);
        if (!s.ok)
            throw CheckError(e.origin + ": cannot read '" + e.value + "' at column " +
                             std::to_string(s.error_offset + 1) + ": " + s.error);
        ctx_.names[name] = s.value;
    }
}

// ------------------------------------------------------------------------------------------- evaluation

GiNaC::ex Checker::resolve_operators(const GiNaC::ex& e) const {
    // A name inside a derivative is its definition in the text, or the derivative cannot be evaluated.
    if (is_ex_the_function(e, ddt)) {
        const GiNaC::ex inner =
            hamilton_.in_velocities(resolve_operators(definitions_.expand(e.op(0), current_offset_)));
        if (TextDefinitions::has_vector(inner, ctx_)) return ddt(inner);  // kept: vectors are not compared
        TextDefinitions::require_defined(inner, ctx_, "time derivative");
        return time_derivative(inner, model_);
    }
    if (is_ex_the_function(e, pdiff)) {
        const GiNaC::ex inner = resolve_operators(definitions_.expand(e.op(0), current_offset_));
        if (!GiNaC::is_a<GiNaC::symbol>(e.op(1)))
            throw std::runtime_error("a derivative with respect to an expression");
        if (const FreeName* f = ctx_.free_name_of(e.op(1)))
            throw UndefinedInDerivative(f->name, "a partial derivative with respect to $" + f->name +
                                                     "$, which is not a coordinate, a velocity or a parameter "
                                                     "of the model");
        if (TextDefinitions::has_vector(inner, ctx_)) return pdiff(inner, e.op(1));
        if (hamilton_.has_hamiltonian(inner)) return hamilton_.derivative(inner, GiNaC::ex_to<GiNaC::symbol>(e.op(1)));
        TextDefinitions::require_defined(inner, ctx_, "partial derivative");
        return GiNaC::diff(inner, GiNaC::ex_to<GiNaC::symbol>(e.op(1)));
    }
    if (is_ex_the_function(e, pbracket))
        return hamilton_.poisson(resolve_operators(definitions_.expand(e.op(0), current_offset_)),
                                 resolve_operators(definitions_.expand(e.op(1), current_offset_)));
    if (e.nops() == 0) return e;
    struct Each : GiNaC::map_function {
        const Checker* self;
        explicit Each(const Checker* c) : self(c) {}
        GiNaC::ex operator()(const GiNaC::ex& x) override { return self->resolve_operators(x); }
    } each(this);
    return e.map(each);
}

bool Checker::is_part(const GiNaC::ex& e, std::string* name, GiNaC::ex* whole) const {
    const FreeName* f = ctx_.free_name_of(e);
    if (!f || f->kind != NameKind::Unknown) return false;
    const std::string& n = f->name;
    if (n.size() < 4 || (n[0] != 'T' && n[0] != 'V' && n[0] != 'U') || n[1] != '_') return false;
    // U_{1} is a part only where U is the potential energy (not a model's own name).
    if (n[0] == 'U') {
        const auto letter = ctx_.names.find(n.substr(0, 1));
        if (letter == ctx_.names.end() || !truth_.count(letter->second)) return false;
    }
    // V_{eff}, V_{\text{eff}}: the effective potential of a reduced problem, a quantity of its own, not a part of V.
    if (n.find("eff") != std::string::npos) return false;
    // T_0 = 2\pi\sqrt{l/g}: a period, which the text sets to a constant; no part of T is one.
    if (not_parts_.count(n)) return false;
    if (name) *name = n;
    if (whole) *whole = n[0] == 'T' ? eq_.T : eq_.V;
    return true;
}

Prepared Checker::prepare(const PSide& s, const GiNaC::ex* exclude_part) {
    Prepared p;
    const Side& side = *s.side;
    if (side.empty()) {
        p.problem = "a side is empty (an incomplete equation)";
        return p;
    }
    if (!side.ok) {
        p.problem =
            "cannot read " + m(side.source) + " at " + where(s.base + side.error_offset) + ": " + side.error;
        return p;
    }
    for (const std::string& n : side.notes) p.notes.push_back(n);
    // A letter the text has given another quantity's meaning (`p_\theta = L`): that quantity, outside ∂·/∂·.
    const GiNaC::ex value = discourse_ ? discourse_->renamed(side.value, s.base + side.begin, p.notes) : side.value;
    try {
        GiNaC::exmap subs;
        ExSet symbols;
        std::vector<GiNaC::ex> stack{value};
        while (!stack.empty()) {
            GiNaC::ex x = stack.back();
            stack.pop_back();
            if (GiNaC::is_a<GiNaC::symbol>(x)) symbols.insert(x);
            for (std::size_t i = 0; i < x.nops(); ++i) stack.push_back(x.op(i));
        }
        for (const GiNaC::ex& sym : symbols) {
            // The momenta stay variables while the text differentiates (∂H/∂p_θ), and H inside ∂ is H(q, p, t).
            if (hamilton_.is_momentum(sym) && truth_.count(sym)) {
                p.has_truth_label = p.has_truth_label || value.is_equal(sym);
                p.has_momenta = true;
                continue;
            }
            if (hamilton_.is_hamiltonian(sym) && !value.is_equal(sym)) continue;
            auto t = truth_.find(sym);
            // h and H are common letters (a height): they stand for the energy function only as a whole side.
            if (t != truth_.end() && bare_only_.count(sym) && !value.is_equal(sym)) {
                subs[sym] = ctx_.free_symbol(GiNaC::ex_to<GiNaC::symbol>(sym).get_name(), NameKind::Unknown);
                continue;
            }
            if (t != truth_.end()) {
                subs[sym] = t->second;
                // A declared result is the reference only as a whole side (`a = ...`); inside an expression
                // it is a value like a map entry's.
                const bool result = result_labels_.count(sym) != 0;
                p.has_truth_label = p.has_truth_label || !result || value.is_equal(sym);
                continue;
            }
            std::string pname;
            if (is_part(sym, &pname) && !(exclude_part && exclude_part->is_equal(sym))) {
                auto pv = part_value_.find(sym);
                if (pv != part_value_.end()) {
                    subs[sym] = pv->second;
                    p.has_part = true;
                    p.notes.push_back("uses " + m(pname) + " as the text gives it at " +
                                      part_origin_.at(sym));
                }
            }
        }
        GiNaC::ex v = subs.empty() ? value : value.subs(subs);
        current_offset_ = s.base + side.begin;
        definitions_.take_used();
        const bool H_inside = hamilton_.has_hamiltonian(v);
        // A Poisson bracket is eomgen's to compute: the side is a reference, like a label.
        if (v.has(pbracket(GiNaC::wild(0), GiNaC::wild(1)))) p.has_truth_label = p.has_momenta = true;
        v = resolve_operators(v);
        for (const std::string& n : definitions_.take_used()) {
            p.notes.push_back(n);
            p.from_definition = true;
        }
        // The text's abbreviations ("with \Omega = ..."), everywhere in the rest of their section.
        definitions_.take_abbreviations();
        v = definitions_.abbreviate(v, current_offset_);
        for (const std::string& n : definitions_.take_abbreviations()) p.notes.push_back(n);
        v = dotted_definitions(definitions_, v, current_offset_, ctx_, model_, p.notes);
        if (H_inside && !hamilton_.has_hamiltonian(v)) p.has_truth_label = p.has_momenta = true;
        if (hamilton_.has_hamiltonian(v))  // H outside a derivative, inside an expression: a letter (a height)
            v = v.subs(ctx_.names.at("H") == ctx_.free_symbol("H", NameKind::Unknown));
        p.value_p = v;
        v = hamilton_.in_velocities(v);
        // Every comparison expands or normalizes the side: refuse one too large for that up front.
        if (const double terms = expanded_terms(v); terms > kMaxExpandedTerms) {
            std::ostringstream os;
            os << "too large to compare within the budget: " << m(side.source) << " expands to up to "
               << std::setprecision(3) << terms << " terms (at most " << static_cast<long>(kMaxExpandedTerms) << ")";
            p.problem = os.str();
            return p;
        }
        p.value = v;
        // Free names left over.
        ExSet left;
        std::vector<GiNaC::ex> stack2{v};
        while (!stack2.empty()) {
            GiNaC::ex x = stack2.back();
            stack2.pop_back();
            if (GiNaC::is_a<GiNaC::symbol>(x)) left.insert(x);
            for (std::size_t i = 0; i < x.nops(); ++i) stack2.push_back(x.op(i));
        }
        for (const GiNaC::ex& sym : left) {
            const FreeName* f = ctx_.free_name_of(sym);
            if (!f) continue;
            if (exclude_part && exclude_part->is_equal(sym)) continue;
            if (f->kind == NameKind::Vector)
                p.vectors.push_back(f);
            else if (f->kind == NameKind::Unit)
                p.units.push_back(f);
            else if (is_constant_name(f->name))
                p.constants.push_back(sym);
            else
                p.unknown.push_back(f);
        }
        auto by_name = [](const FreeName* x, const FreeName* y) { return x->name < y->name; };
        std::sort(p.vectors.begin(), p.vectors.end(), by_name);
        std::sort(p.units.begin(), p.units.end(), by_name);
        std::sort(p.unknown.begin(), p.unknown.end(), by_name);
        std::sort(p.notes.begin(), p.notes.end());
        p.ok = true;
    } catch (const UndefinedInDerivative& u) {
        std::string at;
        for (const NameUse& use : side.uses)
            if (use.name == u.name) {
                at = " (" + where(s.base + use.offset) + ")";
                break;
            }
        std::string why = u.what();
        const std::string shown = "$" + u.name + "$";
        if (const std::size_t k = why.find(shown); k != std::string::npos) why.insert(k + shown.size(), at);
        p.problem = why;
    } catch (const std::exception& e) {
        p.problem = "cannot evaluate " + m(side.source) + ": " + e.what();
    }
    return p;
}

namespace {

/// Whether e holds abs, sign, heaviside, max or min (the model's, or GiNaC's abs and csgn from the text's |x|).
bool has_nonsmooth(const GiNaC::ex& e) {
    if (GiNaC::is_a<GiNaC::function>(e)) {
        static const char* const names[] = {"abs", "sign", "heaviside", "max", "min", "csgn", "step"};
        const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
        for (const char* n : names)
            if (name == n) return true;
    }
    for (const GiNaC::ex& op : e)
        if (has_nonsmooth(op)) return true;
    return false;
}

/// Signs the sample states while it lives, where the expressions compared are not smooth.
class SignedStates {
  public:
    template <class Numbers>
    SignedStates(Numbers& numbers, bool needed) : restore_([&numbers, was = numbers.state_signed()] { numbers.sign_state(was); }) {
        if (needed) numbers.sign_state(true);
    }
    ~SignedStates() { restore_(); }
    SignedStates(const SignedStates&) = delete;
    SignedStates& operator=(const SignedStates&) = delete;

  private:
    std::function<void()> restore_;
};

}  // namespace

std::vector<Complex> Checker::signature(const GiNaC::ex& e) {
    auto hit = signatures_.find(e);
    if (hit != signatures_.end()) return hit->second;
    std::vector<Complex> s;
    const SignedStates signed_states(numbers_, has_nonsmooth(e));
    for (unsigned seed = 201; seed <= 203; ++seed) {
        const auto v = numbers_.value(e, numbers_.point(seed));
        s.push_back(v ? *v : Complex(std::nan(""), 0));
    }
    signatures_[e] = s;
    return s;
}

bool Checker::same_signature(const std::vector<Complex>& a, const std::vector<Complex>& b, double tol) const {
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::isnan(a[i].real()) || std::isnan(b[i].real())) return false;
        if (std::abs(a[i] - b[i]) > tol * std::max({std::abs(a[i]), std::abs(b[i]), 1e-300})) return false;
    }
    return true;
}

Tri Checker::equal(const GiNaC::ex& a, const GiNaC::ex& b, double tol) {
    const SignedStates signed_states(numbers_, has_nonsmooth(a) || has_nonsmooth(b));
    const GiNaC::ex diff = a - b;
    if (tol <= 1e-9) {  // exact numbers: a symbolic zero settles it
        try {
            if (diff.expand().is_zero()) return Tri::Yes;
        } catch (...) {
        }
        try {
            if (GiNaC::normal(diff).is_zero()) return Tri::Yes;
        } catch (...) {
        }
    }
    int good = 0;
    for (unsigned seed = 1; seed <= 10 && good < 4; ++seed) {
        const GiNaC::exmap at = numbers_.point(seed);
        const auto va = numbers_.value(a, at), vb = numbers_.value(b, at);
        if (!va || !vb) continue;
        const double scale =
            std::max({numbers_.scale(a, at), numbers_.scale(b, at), std::abs(*va), std::abs(*vb)});
        if (std::abs(*va - *vb) > tol * scale + 1e-300) return Tri::No;
        ++good;
    }
    return good >= 2 ? Tri::Yes : Tri::Unknown;
}

Tri Checker::euler_lagrange_combination(const GiNaC::ex& r, double tol, int* only, std::string* factor,
                                            std::vector<std::string>* acting, std::vector<bool>* terms,
                                            int multipliers) {
    const std::size_t n = model_.dof();
    const SignedStates signed_states(numbers_, has_nonsmooth(r) || std::any_of(motion_.begin(), motion_.end(),
                                                                               [](const GiNaC::ex& e) { return has_nonsmooth(e); }));
    std::vector<GiNaC::ex> motion = motion_;  // = 0; with the multipliers, EL − Q − (±Aᵀλ)
    if (multipliers != 0) {
        acting = nullptr;  // the constraint forces are in the equations: none is missing
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t k = 0; k < eq_.constraints.size(); ++k)
                motion[i] -= multipliers * eq_.constraints[k].jacobian[i] * multipliers_[k];
    }
    std::vector<GiNaC::ex> a(n);
    for (std::size_t j = 0; j < n; ++j) {
        a[j] = GiNaC::diff(r, model_.coordinates[j].qdd);
        for (std::size_t k = 0; k < n; ++k)
            if (!GiNaC::diff(a[j], model_.coordinates[k].qdd).expand().is_zero())
                return Tri::No;  // not linear in q̈
    }
    int good = 0;
    std::vector<bool> used(n, false);
    std::vector<double> first_c;
    for (unsigned seed = 1; seed <= 10 && good < 3; ++seed) {
        const GiNaC::exmap at = numbers_.point(seed);
        Eigen::VectorXcd av(static_cast<Eigen::Index>(n));
        Eigen::MatrixXcd Mv(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
        bool ok = true;
        for (std::size_t j = 0; j < n && ok; ++j) {
            auto v = numbers_.value(a[j], at);
            ok = ok && v;
            if (v) av(Eigen::Index(j)) = *v;
            for (std::size_t k = 0; k < n && ok; ++k) {
                auto mv = numbers_.value(eq_.M(unsigned(j), unsigned(k)), at);
                ok = ok && mv;
                if (mv) Mv(Eigen::Index(j), Eigen::Index(k)) = *mv;
            }
        }
        if (!ok) continue;
        const Eigen::VectorXcd c = Mv.fullPivLu().solve(av);
        auto rv = numbers_.value(r, at);
        if (!rv) continue;
        Complex res = *rv;
        double scale = numbers_.scale(r, at);
        bool ok2 = true;
        for (std::size_t i = 0; i < n; ++i) {
            auto ev = numbers_.value(motion[i], at);
            if (!ev) {
                ok2 = false;
                break;
            }
            res -= c(Eigen::Index(i)) * *ev;
            scale += std::abs(c(Eigen::Index(i))) * numbers_.scale(motion[i], at);
        }
        if (!ok2) continue;
        if (std::abs(res) > tol * scale + 1e-300) return Tri::No;
        const double cmax = c.cwiseAbs().maxCoeff();
        if (cmax == 0) return Tri::No;
        // With constraints, Σ c_i EL_i = Σ_k (c·A_k) λ_k: the combination holds without multipliers only when
        // c·A_k = 0 for every constraint k.
        if (acting)
            for (const ConstraintEquations& k : eq_.constraints) {
                Complex dot = 0;
                double size = 0;
                for (std::size_t i = 0; i < n; ++i)
                    if (auto av = numbers_.value(k.jacobian[i], at)) {
                        dot += c(Eigen::Index(i)) * *av;
                        size += cmax * std::abs(*av);  // round-off in c must not count as a force
                    }
                if (std::abs(dot) > 1e-8 * std::max(size, 1e-300) &&
                    std::find(acting->begin(), acting->end(), k.name) == acting->end())
                    acting->push_back(k.name);
            }
        for (std::size_t i = 0; i < n; ++i)
            if (std::abs(c(Eigen::Index(i))) > 1e-9 * cmax) used[i] = true;
        ++good;
    }
    if (good < 2) return Tri::Unknown;
    if (terms) *terms = used;
    const auto count = std::count(used.begin(), used.end(), true);
    *only = -1;
    if (count == 1) *only = int(std::find(used.begin(), used.end(), true) - used.begin());
    if (*only >= 0) {
        // The factor, symbolically when it is simple: the ratio of the q̈_i coefficients.
        const GiNaC::symbol& qi = model_.coordinates[std::size_t(*only)].qdd;
        try {
            // sin² + cos² = 1 first: (m₁ + m₂)/(m₁ + m₂ sin² θ₁ + m₂ cos² θ₁) is 1, not a factor.
            const GiNaC::ex c = trig::readable_ratio(GiNaC::diff(r, qi),
                                                     GiNaC::diff(motion[std::size_t(*only)], qi), hints_);
            if (!c.is_equal(1)) *factor = latex(c);
        } catch (...) {
        }
    }
    return Tri::Yes;
}

bool Checker::proportional_in_state(const GiNaC::ex& r, const GiNaC::ex& target, double tol, GiNaC::ex* c) {
    const SignedStates signed_states(numbers_, has_nonsmooth(r) || has_nonsmooth(target));
    int settled = 0;
    for (unsigned ps = 1; ps <= 4 && settled < 2; ++ps) {
        std::vector<Complex> ratios;
        for (unsigned ss = 1; ss <= 6 && ratios.size() < 3; ++ss) {
            const GiNaC::exmap at = numbers_.point(ps, 100 + ss);
            const auto tv = numbers_.value(target, at), rv = numbers_.value(r, at);
            if (!tv || !rv) continue;
            const double ts = numbers_.scale(target, at);
            if (std::abs(*tv) <= 1e-9 * ts) continue;
            ratios.push_back(*rv / *tv);
        }
        if (ratios.size() < 3) continue;
        for (const Complex& q : ratios)
            if (std::abs(q - ratios[0]) > std::max(tol, 1e-8) * std::max(std::abs(ratios[0]), 1e-300))
                return false;
        if (std::abs(ratios[0]) < 1e-12) return false;
        ++settled;
    }
    if (settled < 2) return false;
    try {
        *c = GiNaC::normal(r / target);
        if (has_velocity(*c) || has_acceleration(*c)) *c = GiNaC::ex(1);
    } catch (...) {
        *c = 1;
    }
    return true;
}

ConstraintReduction Checker::reduction(const GiNaC::ex& keep, std::string* shown) {
    const ConstraintReduction red = reduce_on_constraints(model_, eq_, keep);
    std::string list;
    for (const Coordinate& c : model_.coordinates)
        for (const GiNaC::exmap* map : {&red.coordinates, &red.velocities})
            for (const GiNaC::symbol* s : {&c.q, &c.qd}) {
                auto it = map->find(*s);
                if (it == map->end()) continue;
                list += (list.empty() ? "" : ", ") + m(latex(*s) + " = " + latex(it->second));
            }
    if (shown) *shown = list;
    return red;
}

bool Checker::proportional_to_constraint(const GiNaC::ex& r, std::size_t index, double tol) {
    const GiNaC::ex& target = eq_.constraints[index].velocity;
    int settled = 0;
    for (unsigned base = 1; base <= 4 && settled < 2; ++base) {
        std::vector<Complex> ratios;
        for (unsigned v = 1; v <= 6 && ratios.size() < 3; ++v) {
            GiNaC::exmap at = numbers_.point(base);
            const GiNaC::exmap other = numbers_.point(base, 300 + v);
            for (const Coordinate& c : model_.coordinates) at[c.qd] = other.at(c.qd);
            const auto tv = numbers_.value(target, at), rv = numbers_.value(r, at);
            if (!tv || !rv || std::abs(*tv) <= 1e-9 * numbers_.scale(target, at)) continue;
            ratios.push_back(*rv / *tv);
        }
        if (ratios.size() < 3) continue;
        for (const Complex& q : ratios)
            if (std::abs(q - ratios[0]) > std::max(tol, 1e-8) * std::max(std::abs(ratios[0]), 1e-300)) return false;
        if (std::abs(ratios[0]) < 1e-12) return false;
        ++settled;
    }
    return settled >= 2;
}

bool Checker::linear_in_velocities(const GiNaC::ex& r) const {
    bool any = false;
    for (const Group& g : groups(r)) {
        int degree = 0;
        for (const Coordinate& c : model_.coordinates) degree += g.monomial.degree(c.qd) + g.monomial.degree(c.qdd);
        if (degree > 1) return false;
        any = any || degree == 1;
    }
    return any;
}

// -------------------------------------------------------------------------------------------- diagnosis

std::string Checker::latex(const GiNaC::ex& e) {
    // Integrals become placeholders printed from their parts, so that everything goes through the canonical
    // printer: GiNaC's own order changes from process to process.
    GiNaC::exmap placeholders;
    std::function<GiNaC::ex(const GiNaC::ex&)> hide = [&](const GiNaC::ex& x) -> GiNaC::ex {
        if (GiNaC::is_a<GiNaC::integral>(x)) {
            const std::string var = GiNaC::ex_to<GiNaC::symbol>(x.op(0)).get_TeX_name();
            const std::string text =
                "\\int_{" + latex(x.op(1)) + "}^{" + latex(x.op(2)) + "} " + latex(x.op(3)) + " \\, d" + var;
            return GiNaC::symbol(text, text);
        }
        if (x.nops() == 0) return x;
        GiNaC::ex out = x;
        struct Each : GiNaC::map_function {
            std::function<GiNaC::ex(const GiNaC::ex&)>& f;
            explicit Each(std::function<GiNaC::ex(const GiNaC::ex&)>& g) : f(g) {}
            GiNaC::ex operator()(const GiNaC::ex& y) override { return f(y); }
        } each(hide);
        return x.map(each);
    };
    try {
        const GiNaC::ex shown = has_integral(e) ? hide(e) : e;
        codegen::SymbolTable table = printer_table_;
        auto add = [&](const GiNaC::ex& sym, const std::string& name) {
            table.info.push_back(
                {codegen::SymbolKind::Constant, int(table.info.size()), name, name, name, name});
            table.exprs.push_back(sym);
        };
        for (const auto& [name, f] : ctx_.free_names) add(f.symbol, name);
        // Placeholders, bound variables of integrals and anything else the table does not know, by their TeX
        // names, in the order of those names (the table's order is the printed order).
        ExSet known(table.exprs.begin(), table.exprs.end());
        std::vector<std::pair<std::string, GiNaC::ex>> others;
        std::vector<GiNaC::ex> stack{shown};
        while (!stack.empty()) {
            const GiNaC::ex x = stack.back();
            stack.pop_back();
            if (GiNaC::is_a<GiNaC::symbol>(x) && !known.count(x)) {
                others.push_back({GiNaC::ex_to<GiNaC::symbol>(x).get_TeX_name(), x});
                known.insert(x);
            }
            for (std::size_t i = 0; i < x.nops(); ++i) stack.push_back(x.op(i));
        }
        std::sort(others.begin(), others.end(),
                  [](const auto& a, const auto& b) { return a.first < b.first; });
        for (const auto& [name, sym] : others) add(sym, name);
        codegen::MathPrinter printer(table);
        printer.prefer_angles(hints_.angles);
        return printer.print(trig::readable(shown, hints_), codegen::MathStyle::Latex);
    } catch (...) {
    }
    std::ostringstream os;
    os << GiNaC::latex << e;
    return os.str();
}

std::vector<Group> Checker::groups(const GiNaC::ex& e) const {
    std::vector<GiNaC::ex> terms;
    const GiNaC::ex x = e.expand();
    if (GiNaC::is_a<GiNaC::add>(x)) {
        for (const GiNaC::ex& t : x) terms.push_back(t);
    } else if (!x.is_zero()) {
        terms.push_back(x);
    }
    ExSet motion;
    for (const Coordinate& c : model_.coordinates) {
        motion.insert(c.qd);
        motion.insert(c.qdd);
    }
    auto is_motion = [&](const GiNaC::ex& f) {
        if (motion.count(f)) return true;
        return GiNaC::is_a<GiNaC::power>(f) && motion.count(f.op(0)) &&
               f.op(1).info(GiNaC::info_flags::integer);
    };
    std::vector<Group> out;
    for (const GiNaC::ex& t : terms) {
        GiNaC::ex mono = 1, coeff = 1;
        if (GiNaC::is_a<GiNaC::mul>(t)) {
            for (const GiNaC::ex& f : t) (is_motion(f) ? mono : coeff) *= f;
        } else if (is_motion(t)) {
            mono = t;
        } else {
            coeff = t;
        }
        auto it =
            std::find_if(out.begin(), out.end(), [&](const Group& g) { return g.monomial.is_equal(mono); });
        if (it == out.end()) {
            out.push_back({mono, {}, 0});
            it = out.end() - 1;
        }
        it->terms.push_back(t);
        it->coefficient += coeff;
    }
    // Accelerations first, then higher powers of velocities; coordinates in model order.
    auto key = [&](const GiNaC::ex& mono) {
        std::vector<int> k;
        int acc = 0, vel = 0;
        for (const Coordinate& c : model_.coordinates) {
            acc += mono.degree(c.qdd);
            vel += mono.degree(c.qd);
        }
        k.push_back(-acc);
        k.push_back(-vel);
        for (const Coordinate& c : model_.coordinates) {
            k.push_back(-mono.degree(c.qdd));
            k.push_back(-mono.degree(c.qd));
        }
        return k;
    };
    std::stable_sort(out.begin(), out.end(),
                     [&](const Group& a, const Group& b) { return key(a.monomial) < key(b.monomial); });
    return out;
}

std::string Checker::group_name(const GiNaC::ex& monomial) const {
    if (monomial.is_equal(1)) return "the terms without velocities";
    std::string s = const_cast<Checker*>(this)->latex(monomial);
    return "the " + m(s) + " terms";
}

std::string Checker::pair_kind(const GiNaC::ex& t, const GiNaC::ex& u, double tol, int* score) {
    const auto su = signature(u);
    if (same_signature(signature(-t), su, tol)) {
        *score = 1;
        return "a flipped sign";
    }
    // One sine or cosine at a time turned into the other.
    std::vector<std::pair<GiNaC::ex, std::string>> swaps;
    {
        ExSet trig;
        std::vector<GiNaC::ex> stack{t};
        while (!stack.empty()) {
            const GiNaC::ex x = stack.back();
            stack.pop_back();
            if (GiNaC::is_the_function<GiNaC::sin_SERIAL>(x) || GiNaC::is_the_function<GiNaC::cos_SERIAL>(x))
                trig.insert(x);
            for (std::size_t k = 0; k < x.nops(); ++k) stack.push_back(x.op(k));
        }
        for (const GiNaC::ex& f : trig) {
            const bool is_sin = GiNaC::is_the_function<GiNaC::sin_SERIAL>(f);
            const GiNaC::ex other = is_sin ? GiNaC::cos(f.op(0)) : GiNaC::sin(f.op(0));
            // a swap that divides by zero (1/(I_3 - I) with I for I_3) is no candidate
            if (const auto swapped = subs_unless_pole(t, GiNaC::exmap{{f, other}}))
                swaps.push_back({*swapped, is_sin ? m("\\sin") + " where " + m("\\cos") + " belongs"
                                                  : m("\\cos") + " where " + m("\\sin") + " belongs"});
        }
    }
    for (const auto& [x, what] : swaps) {
        if (x.is_equal(t)) continue;
        if (same_signature(signature(x), su, tol)) {
            *score = 2;
            return what;
        }
        if (same_signature(signature(-x), su, tol)) {
            *score = 2;
            return what + ", and a flipped sign";
        }
    }
    std::vector<std::pair<GiNaC::ex, std::string>> names;
    for (const Parameter& p : model_.parameters) names.push_back({p.symbol, p.latex});
    for (const Coordinate& c : model_.coordinates) names.push_back({c.q, c.latex});
    for (const auto& [a, la] : names)
        for (const auto& [b, lb] : names) {
            if (a.is_equal(b) || !t.has(a)) continue;
            const auto swapped = subs_unless_pole(t, GiNaC::exmap{{a, b}});
            if (swapped && same_signature(signature(*swapped), su, tol)) {
                *score = 2;
                return m(la) + " where " + m(lb) + " belongs";
            }
        }
    try {
        const GiNaC::ex q = GiNaC::normal(t / u);
        if (GiNaC::is_a<GiNaC::numeric>(q)) {
            *score = 3;
            return "off by a factor " + m(latex(q));
        }
    } catch (...) {
    }
    *score = 9;
    return "";
}

Diagnosis Checker::compare_to(const GiNaC::ex& text_as_read, const GiNaC::ex& truth_as_derived, double tol) {
    // Term by term in the author's sines and cosines: k sin(θ₁ − θ₂) where k cos(θ₁ − θ₂) belongs.
    trig::Hints terms_hints = hints_;
    terms_hints.collect = false;
    const GiNaC::ex text = trig::readable(text_as_read, terms_hints);
    const GiNaC::ex truth = trig::readable(truth_as_derived, terms_hints);
    Diagnosis d;
    const GiNaC::ex diff = (text - truth).expand();
    d.difference = latex(diff);
    const std::vector<Group> tg = groups(text), ug = groups(truth);
    std::vector<GiNaC::ex> keys;
    for (const Group& g : tg) keys.push_back(g.monomial);
    for (const Group& g : ug)
        if (std::none_of(keys.begin(), keys.end(),
                         [&](const GiNaC::ex& k) { return k.is_equal(g.monomial); }))
            keys.push_back(g.monomial);
    auto find = [](const std::vector<Group>& gs, const GiNaC::ex& k) -> const Group* {
        for (const Group& g : gs)
            if (g.monomial.is_equal(k)) return &g;
        return nullptr;
    };
    // Order keys as groups() would: use a combined expression of monomials.
    {
        GiNaC::ex probe = 0;
        GiNaC::symbol marker("__k");
        for (const GiNaC::ex& k : keys) probe += marker * k;
        std::vector<GiNaC::ex> sorted;
        for (const Group& g : groups(probe)) sorted.push_back(g.monomial);
        if (sorted.size() == keys.size()) keys = sorted;
    }
    for (const GiNaC::ex& k : keys) {
        const Group* a = find(tg, k);
        const Group* b = find(ug, k);
        const GiNaC::ex ca = a ? a->coefficient : GiNaC::ex(0), cb = b ? b->coefficient : GiNaC::ex(0);
        if (equal(ca * k, cb * k, tol) == Tri::Yes) continue;
        const std::string group = group_name(k);
        // The whole group off by a constant factor (a dropped 1/3, a flipped sign): say so once.
        if (a && b) {
            try {
                const GiNaC::ex q = GiNaC::normal(ca / cb);
                if (GiNaC::is_a<GiNaC::numeric>(q)) {
                    d.lines.push_back(
                        group + ": " + m(latex(ca * k)) + " where " + m(latex(cb * k)) + " belongs (" +
                        (q.is_equal(-1) ? std::string("a flipped sign") : "off by a factor " + m(latex(q))) +
                        ")");
                    continue;
                }
            } catch (...) {
            }
        }
        std::vector<GiNaC::ex> ts = a ? a->terms : std::vector<GiNaC::ex>{};
        std::vector<GiNaC::ex> us = b ? b->terms : std::vector<GiNaC::ex>{};
        // In a printed order, not GiNaC's (which changes from process to process).
        auto printed = [this](std::vector<GiNaC::ex>& v) {
            std::vector<std::pair<std::string, GiNaC::ex>> keyed;
            for (const GiNaC::ex& x : v) keyed.push_back({latex(x), x});
            std::stable_sort(keyed.begin(), keyed.end(),
                             [](const auto& x, const auto& y) { return x.first < y.first; });
            for (std::size_t i = 0; i < v.size(); ++i) v[i] = keyed[i].second;
        };
        printed(ts);
        printed(us);
        // Terms equal on both sides are not the problem.
        for (std::size_t i = 0; i < ts.size();) {
            bool removed = false;
            for (std::size_t j = 0; j < us.size(); ++j)
                if (same_signature(signature(ts[i]), signature(us[j]), std::max(tol, 1e-9))) {
                    us.erase(us.begin() + long(j));
                    ts.erase(ts.begin() + long(i));
                    removed = true;
                    break;
                }
            if (!removed) ++i;
        }
        // Pair what is left, best explanations first.
        struct Cand {
            int score;
            std::size_t i, j;
            std::string kind;
        };
        std::vector<Cand> cands;
        for (std::size_t i = 0; i < ts.size(); ++i)
            for (std::size_t j = 0; j < us.size(); ++j) {
                int score = 9;
                std::string kind = pair_kind(ts[i], us[j], std::max(tol, 1e-9), &score);
                cands.push_back({score, i, j, kind});
            }
        std::stable_sort(cands.begin(), cands.end(),
                         [](const Cand& x, const Cand& y) { return x.score < y.score; });
        std::vector<bool> ti(ts.size(), false), uj(us.size(), false);
        for (const Cand& c : cands) {
            if (ti[c.i] || uj[c.j]) continue;
            // A lone pair is explained even without a kind; among several, only recognised kinds pair up.
            if (c.score == 9 && !(ts.size() == 1 && us.size() == 1)) continue;
            ti[c.i] = uj[c.j] = true;
            d.lines.push_back(group + ": " + m(latex(ts[c.i])) + " where " + m(latex(us[c.j])) + " belongs" +
                              (c.kind.empty() ? "" : " (" + c.kind + ")"));
        }
        for (std::size_t j = 0; j < us.size(); ++j)
            if (!uj[j]) d.lines.push_back(group + ": missing " + m(latex(us[j])));
        for (std::size_t i = 0; i < ts.size(); ++i)
            if (!ti[i]) d.lines.push_back(group + ": " + m(latex(ts[i])) + " should not be there");
        if (ts.empty() && us.empty())  // equal term by term within the tolerance, not as a sum: say so
            d.lines.push_back(group + ": " + m(latex(ca * k)) + " where " + m(latex(cb * k)) + " belongs");
    }
    if (d.lines.empty()) d.lines.push_back("the two differ by " + m(d.difference));
    return d;
}

int Checker::best_factor(const GiNaC::ex& text, const GiNaC::ex& truth, double tol, GiNaC::ex* c) {
    const std::vector<Group> tg = groups(text), ug = groups(truth);
    std::vector<GiNaC::ex> candidates;
    for (const Group& a : tg)
        for (const Group& b : ug)
            if (a.monomial.is_equal(b.monomial)) {
                try {
                    const GiNaC::ex q = GiNaC::normal(a.coefficient / b.coefficient);
                    if (!q.is_zero()) candidates.push_back(q);
                } catch (...) {
                }
            }
    if (candidates.empty()) candidates.push_back(1);
    int best = -1;
    for (const GiNaC::ex& q : candidates) {
        int agree = 0;
        for (const Group& a : tg) {
            GiNaC::ex cb = 0;
            for (const Group& b : ug)
                if (b.monomial.is_equal(a.monomial)) cb = b.coefficient;
            if (equal(a.coefficient, q * cb, tol) == Tri::Yes) ++agree;
        }
        const bool better = agree > best || (agree == best && GiNaC::is_a<GiNaC::numeric>(q) &&
                                             !GiNaC::is_a<GiNaC::numeric>(*c));
        if (better) {
            best = agree;
            *c = q;
        }
    }
    return best;
}

// ---------------------------------------------------------------------------------------------- checking

void Checker::collect_definitions(const std::vector<FullChain>& chains) {
    // After a condition (`s = \frac{1}{2h}`: "halfway along the first turn"), a value free of the state that the
    // paragraph gives a name (`y = r\cos\pi`) is that name's value at the point, not its definition: it holds
    // to the end of the paragraph only.
    for (const FullChain& c : chains) {
        if (c.sides.size() < 2 || !c.sides[0].side->ok) continue;
        const GiNaC::ex head = c.sides[0].side->value;
        const FreeName* f = ctx_.free_name_of(head);
        if (!f || f->kind != NameKind::Unknown || is_part(head) || is_constant_name(f->name)) continue;
        for (std::size_t k = c.sides.size(); k-- > 1;) {
            // `\ell := m r^2 \dot\theta \equiv \mathrm{const}`: the constant says that it is conserved, it is
            // not the definition.
            if (c.sides[k].side->ok && GiNaC::is_a<GiNaC::symbol>(c.sides[k].side->value))
                if (const FreeName* g = ctx_.free_name_of(c.sides[k].side->value); g && is_constant_name(g->name))
                    continue;
            const Prepared p = prepare(c.sides[k]);
            if (!p.comparable() || !p.units.empty() || p.value.has(head)) continue;
            const std::size_t at = c.sides[k].base + c.sides[k].side->begin;
            std::size_t until = c.section >= 0 ? d_.sections[std::size_t(c.section)].end : std::string::npos;
            if (const std::size_t point = discourse_->condition_paragraph(at); point > 0 && !depends_on_state(p.value)) {
                until = std::min(until, point);
                at_a_point_.insert(c.sides[0].base + c.sides[0].side->begin);
            }
            definitions_.add(head, f->name, p.value, at, d_.position(at).line, until, c.sides[k].side->source,
                             c.sides[0].base + c.sides[0].side->begin);
            break;
        }
    }
}

void Checker::collect_parts(const std::vector<FullChain>& chains) {
    for (const FullChain& c : chains) {
        if (c.sides.size() < 2 || !c.sides[0].side->ok) continue;
        const GiNaC::ex head = c.sides[0].side->value;
        if (!is_part(head) || part_value_.count(head)) continue;
        for (std::size_t k = c.sides.size(); k-- > 1;) {
            Prepared p = prepare(c.sides[k], &head);
            if (!p.comparable() || !p.units.empty() || p.value.has(head) || p.has_part) continue;
            part_value_[head] = p.value;
            part_origin_[head] =
                "line " + std::to_string(d_.position(c.sides[k].base + c.sides[k].side->begin).line);
            break;
        }
    }
}

void Checker::check_chain(const FullChain& c, std::vector<EquationCheck>& out) {
    const std::size_t n = c.sides.size();
    std::vector<bool> comparable(n, false);
    for (std::size_t k = 0; k < n; ++k) {
        Prepared p = prepare(c.sides[k]);
        comparable[k] = p.comparable() || is_part(c.sides[k].side->value);
    }
    for (std::size_t k = 0; k + 1 < n; ++k) out.push_back(safe_check_link(c, k, k + 1, false));
    // Across sides that cannot be compared (an integral over a region, an unknown function): compare the
    // comparable sides on either side of them, so that a claim is not lost behind a step the checker cannot
    // read.
    std::size_t last = n;
    for (std::size_t k = 0; k < n; ++k) {
        if (!comparable[k]) continue;
        if (last != n && k > last + 1) {
            bool all_equal = true;
            for (std::size_t q = last; q < k; ++q)
                all_equal = all_equal && c.relations[q] != Relation::Inequality;
            if (all_equal) out.push_back(safe_check_link(c, last, k, true));
        }
        last = k;
    }
}

EquationCheck Checker::check_link(const FullChain& c, std::size_t i, std::size_t j, bool bridge) {
    EquationCheck r;
    const PSide& L = c.sides[i];
    const PSide& R = c.sides[j];
    const std::size_t rel_at = c.relation_offsets[j - 1];
    r.where = d_.position(bridge ? c.relation_offsets[i] : rel_at);
    hints_.angles = trig::angle_sums((L.side->ok ? L.side->value : 0) + (R.side->ok ? R.side->value : 0));
    if (c.section >= 0) r.section = d_.sections[std::size_t(c.section)].title;
    Relation rel = Relation::Equal;
    for (std::size_t q = i; q < j; ++q)
        if (c.relations[q] != Relation::Equal) rel = c.relations[q];
    const std::string sign =
        rel == Relation::Approx ? " \\approx " : (rel == Relation::Inequality ? " \\;?\\; " : " = ");
    r.equation = (L.side->source.empty() ? std::string("\\ldots") : L.side->source) + sign +
                 (R.side->source.empty() ? std::string("\\ldots") : R.side->source);
    if (bridge) r.notes.push_back("compared across the step(s) between them that cannot be compared");
    if (discourse_->sets_trial(rel_at) && j == i + 1) {
        r.reason = "a trial solution: not judged; the equations for its amplitudes that follow are compared with the "
                   "rows of $(K - \\omega^2 M) A = 0$ about rest";
        return r;
    }
    if (const Discourse::Naming* n = discourse_->naming_at(rel_at); n && j == i + 1) {
        r.reason = "a definition: the text names $" + n->quantity_latex + "$ $" + n->letter_latex +
                   "$ here, and reads so to the end of its section (outside ∂/∂, where $" + n->letter_latex +
                   "$ is still eomgen's)";
        return r;
    }
    if (rel == Relation::Inequality) {
        r.reason = "an inequality or a relation other than equality is not compared";
        return r;
    }
    if (rel == Relation::Equal && modes_.check(*L.side, *R.side, ctx_, *this, r)) return r;
    if (rel == Relation::Equal && algebra_.check(*L.side, L.base, *R.side, R.base, *this, r)) return r;
    // A part of T or V defined by this link: compare it with its share of eomgen's T or V.
    for (int side = 0; side < 2; ++side) {
        const PSide& P = side == 0 ? L : R;
        const PSide& O = side == 0 ? R : L;
        if (!P.side->ok || !is_part(P.side->value)) continue;
        const GiNaC::ex part = P.side->value;
        Prepared o = prepare(O, &part);
        if (!o.ok) {
            r.reason = o.problem;
            return r;
        }
        if (o.value.has(part)) break;  // T_{a} = T_{a}: an identity, handled below
        if (!o.comparable() || !o.units.empty()) break;
        const double tol = std::max(1e-9, L.side->rounding + R.side->rounding);
        r.notes.insert(r.notes.end(), o.notes.begin(), o.notes.end());
        check_part(part, P.side->source, o, tol, r);
        return r;
    }
    Prepared a = prepare(L), b = prepare(R);
    if (!a.ok || !b.ok) {
        r.reason = !a.ok ? a.problem : b.problem;
        return r;
    }
    // A parameter the text set for this paragraph (`m_1 = 0`): both the text and eomgen's equations take it.
    GiNaC::exmap chosen;
    chosen_notes_.clear();
    for (std::size_t k = 0; k < model_.parameters.size(); ++k)
        if (const auto [v, origin] = parameter_values_.at(k, rel_at); origin.rfind("chosen by the text", 0) == 0) {
            chosen[model_.parameters[k].symbol] = exact_decimal(v);
            chosen_notes_.push_back("with $" + (model_.parameters[k].latex.empty() ? model_.parameters[k].name
                                                                                : model_.parameters[k].latex) +
                                    " = " + latex(exact_decimal(v)) + "$, the value the text chose on line " +
                                    origin.substr(origin.rfind(' ') + 1));
        }
    for (const auto& [symbol, stated] : discourse_->conditions_at(rel_at)) {
        chosen[symbol] = stated.first;
        chosen_notes_.push_back("at $" + latex(symbol) + " = " + latex(stated.first) +
                                "$, the condition the text states on line " + std::to_string(stated.second));
    }
    struct Unpin {
        Numbers& n;
        ~Unpin() { n.pin({}); }
    } const unpin{numbers_};
    numbers_.pin(chosen);
    for (const Prepared* p : {&a, &b}) r.notes.insert(r.notes.end(), p->notes.begin(), p->notes.end());
    std::sort(r.notes.begin(), r.notes.end());
    r.notes.erase(std::unique(r.notes.begin(), r.notes.end()), r.notes.end());
    // Comparing the sides takes their difference and their ratio over a common denominator.
    if (const double terms = expanded_terms(a.value - b.value); terms > kMaxExpandedTerms) {
        std::ostringstream os;
        os << "too large to compare within the budget: the two sides over a common denominator expand to up to "
           << std::setprecision(3) << terms << " terms (at most " << static_cast<long>(kMaxExpandedTerms) << ")";
        r.reason = os.str();
        return r;
    }
    double tol = std::max(1e-9, L.side->rounding + R.side->rounding);
    if (rel == Relation::Approx) tol = std::max(tol, 1e-2);
    if (up_to_constant(a, b, tol, r)) return r;
    // \approx, \simeq: the Taylor expansion to the order the text keeps; "= ... for small θ" too, where it
    // would otherwise disagree.
    const bool approx = rel == Relation::Approx;
    if (approx && approximation(rel_at, L.side->source, R.side->source, a, b, true, r)) return r;
    check_values(c, i, j, a, b, tol, r);
    if (r.verdict == Verdict::Disagrees && r.compared_with == "$L$") {  // L + dF/dt: the same equations
        EquationCheck alt;
        alt.where = r.where;
        alt.section = r.section;
        alt.equation = r.equation;
        alt.notes = r.notes;
        if (check_equivalent_lagrangian(a.value, b.value, model_, *this, tol,
                                        says_total_derivative_dropped(d_, rel_at), alt))
            return alt;
        r.notes = alt.notes;
        // L = L_cm + L_rel: the text's L of the coordinates it keeps (a two-body problem's relative motion).
        const bool a_is_L = equal(a.value, eq_.L, 1e-9) == Tri::Yes, b_is_L = equal(b.value, eq_.L, 1e-9) == Tri::Yes;
        if (a_is_L != b_is_L &&
            check_separated_lagrangian(a_is_L ? b.value : a.value, eq_.L, model_, *this, alt))
            return alt;
    }
    // ∂H/∂θ after the text wrote H in velocities: the reading it set up (at fixed θ̇) when Hamilton's disagrees.
    if (r.verdict == Verdict::Disagrees && velocity_h_line_ > 0 && rel_at > velocity_h_at_ &&
        (hamilton_.has_hamiltonian(L.side->value) || hamilton_.has_hamiltonian(R.side->value))) {
        hamilton_.set_velocity_reading(true);
        Prepared va = prepare(L), vb = prepare(R);
        EquationCheck alt;
        alt.where = r.where;
        alt.section = r.section;
        alt.equation = r.equation;
        if (va.ok && vb.ok) check_values(c, i, j, va, vb, tol, alt);
        hamilton_.set_velocity_reading(false);
        if (alt.verdict == Verdict::Agrees) {
            alt.notes.push_back("read as the text set it up: H written in velocities (line " +
                                std::to_string(velocity_h_line_) +
                                ") and differentiated at fixed velocities; Hamilton's equations take ∂H/∂q at "
                                "fixed momenta, under which this line does not hold");
            return alt;
        }
    }
    if (!approx && r.verdict == Verdict::Disagrees) {
        EquationCheck alt;
        alt.where = r.where;
        alt.section = r.section;
        alt.equation = r.equation;
        if (approximation(rel_at, L.side->source, R.side->source, a, b, false, alt) && alt.verdict == Verdict::Agrees)
            return alt;
    }
    return r;
}

void Checker::check_prose_label(const FullChain& c, std::size_t i, std::size_t j, EquationCheck& r) {
    // A row in a letter the text has just given another meaning (`p_\theta = L`) is about that quantity, not
    // about what the sentence before the display names.
    for (const std::string& n : r.notes)
        if (n.find(", as the text names it on line ") != std::string::npos) return;
    const auto coordinate = [this](const std::string& latex) {
        LatexContext ctx = ctx_;
        const Side s = parse_expression(latex, ctx);
        for (std::size_t k = 0; s.ok && k < model_.dof(); ++k)
            if (s.value.is_equal(model_.coordinates[k].q)) return int(k);
        return -1;
    };
    // A chain that names its quantity on the left (`T &= …` under "the kinetic energy T and the potential energy
    // U are") is labelled by its own letter when the sentence names that quantity too, not by the last quantity
    // the sentence names. (A sentence that names only another one still disagrees with it.)
    static const std::pair<const char*, const char*> kSelfLabels[] = {
        {"T", "kinetic"},          {"K", "kinetic"},        {"V", "potential"},      {"U", "potential"},
        {"L", "lagrangian"},       {"H", "hamiltonian"},    {"E", "energy"},         {"\\mathcal{L}", "lagrangian"},
        {"\\mathscr{L}", "lagrangian"}};
    std::string head = c.sides[0].side->source;
    head.erase(0, std::min(head.find_first_not_of(" \t"), head.size()));
    head.erase(std::min(head.find_last_not_of(" \t") + 1, head.size()));
    bool self_labelled = false;
    for (const auto& [letter, noun] : kSelfLabels)
        if (head == letter) {
            self_labelled = lead_in(d_, c.relation_offsets[j - 1], 2).find(noun) != std::string::npos;
            break;
        }
    try {  // what GiNaC throws on a strange input leaves the verdict as it is
        const auto label = label_before(d_, c.relation_offsets[j - 1], coordinate, model_);
        if (!label) return;
        Prepared a = prepare(c.sides[i]), b = prepare(c.sides[j]);
        if (!a.comparable() || !b.comparable()) return;
        GiNaC::exmap zero;  // `= \text{const}`: any constant
        for (const Prepared* p : {&a, &b})
            for (const GiNaC::ex& k : p->constants) zero[k] = 0;
        const double tol = std::max(1e-9, c.sides[i].side->rounding + c.sides[j].side->rounding);
        EquationCheck labelled = r;
        check_label(*label, a.value.subs(zero), b.value.subs(zero), model_, eq_, *this, tol, labelled);
        if (self_labelled && labelled.verdict == Verdict::Disagrees && r.verdict != Verdict::Disagrees) return;
        r = std::move(labelled);
    } catch (const std::exception&) {
    }
}

bool Checker::approximation(std::size_t at, const std::string& left, const std::string& right, const Prepared& a,
                            const Prepared& b, bool implied, EquationCheck& r) {
    if (!a.comparable() || !b.comparable() || !a.units.empty() || !b.units.empty()) return false;
    const int ref_side = a.has_truth_label && !a.has_part ? 0 : (b.has_truth_label && !b.has_part ? 1 : -1);
    return check_approximation(d_, model_, motion_, at, {left, right}, a.value, b.value, ref_side, implied, *this, r);
}

void Checker::verify_correction(const FullChain& c, std::size_t j, EquationCheck& r) {
    const std::size_t at = c.relation_offsets[j - 1];
    const auto saved_names = ctx_.names;
    const auto saved_free = ctx_.free_names;
    verifying_ = true;
    apply_map(d_.position(at).line);
    std::string why;
    try {
        why = correction_problem(r.corrected, ctx_, [&](const Chain& ch, std::size_t a, std::size_t b) {
            FullChain f;
            f.section = c.section;
            f.display = c.display;
            for (const Side& s : ch.sides) f.sides.push_back({&s, at});
            f.relations = ch.relations;
            // Where the slip is: what holds there (definitions, conditions, a trial solution) holds for the correction.
            f.relation_offsets.assign(ch.relation_offsets.size(), at);
            return safe_check_link(f, a, b, false);
        });
    } catch (const std::exception& e) {
        why = std::string("it could not be checked: ") + e.what();
    }
    verifying_ = false;
    ctx_.names = saved_names;
    ctx_.free_names = saved_free;
    if (why.empty()) return;
    r.notes.push_back("no correction is printed: the one computed does not check (" + why + ")");
    r.corrected.clear();
}

std::vector<std::string> Checker::factor_analysis(const GiNaC::ex& a, const GiNaC::ex& b, double tol,
                                                  std::string* ratio) {
    std::vector<std::string> out;
    auto factors = [](const GiNaC::ex& e) {
        std::vector<GiNaC::ex> f;
        if (GiNaC::is_a<GiNaC::mul>(e))
            for (const GiNaC::ex& x : e) f.push_back(x);
        else
            f.push_back(e);
        return f;
    };
    std::vector<GiNaC::ex> fa = factors(a), fb = factors(b);
    // Factors equal on both sides (numerically: two integrals with the same value count as equal) cancel.
    for (std::size_t i = 0; i < fa.size();) {
        bool removed = false;
        for (std::size_t j = 0; j < fb.size(); ++j)
            if (same_signature(signature(fa[i]), signature(fb[j]), std::max(tol, 1e-9))) {
                fa.erase(fa.begin() + long(i));
                fb.erase(fb.begin() + long(j));
                removed = true;
                break;
            }
        if (!removed) ++i;
    }
    GiNaC::ex A = 1, B = 1;
    for (const GiNaC::ex& x : fa) A *= x;
    for (const GiNaC::ex& x : fb) B *= x;
    try {
        // A number?
        const auto sa = signature(A / B);
        bool constant = !std::isnan(sa[0].real());
        for (const Complex& v : sa) constant = constant && std::abs(v - sa[0]) <= 1e-9 * std::abs(sa[0]);
        if (constant && std::abs(sa[0].imag()) < 1e-12 * std::abs(sa[0])) {
            const double k = sa[0].real();
            std::ostringstream os;
            os.precision(6);
            os << k;
            const bool minus_one = std::abs(k + 1) <= std::max(tol, 1e-9);
            out.push_back(minus_one
                              ? std::string("the two sides have opposite signs") +
                                    (std::abs(k + 1) > 1e-9 ? " (the left side is " + os.str() +
                                                                  " times the right side; equal in size "
                                                                  "within the rounding of the numbers)"
                                                            : "")
                              : "the left side is " + os.str() + " times the right side");
            *ratio = minus_one ? "-" : os.str();
            return out;
        }
        GiNaC::ex q = GiNaC::normal(A / B);
        std::string shown;
        if (!has_root(q) && !has_integral(q)) {
            shown = latex(q);
        } else {
            const GiNaC::ex q2 = GiNaC::normal(GiNaC::pow(A / B, 2));
            if (!has_root(q2) && !has_integral(q2)) shown = "\\sqrt{" + latex(q2) + "}";
        }
        if (!shown.empty()) {
            out.push_back("the left side is " + m(shown) + " times the right side");
            *ratio = shown;
        }
        if (fa.size() == 1 && fb.size() == 1)
            out.push_back("the factor " + m(latex(fa[0])) + " where the right side has " + m(latex(fb[0])));
    } catch (...) {
    }
    return out;
}

void Checker::check_part(const GiNaC::ex& part, const std::string& part_source, const Prepared& other,
                         double tol, EquationCheck& r) {
    std::string name;
    GiNaC::ex whole;
    is_part(part, &name, &whole);
    const std::string whole_name = name.substr(0, 1);
    r.compared_with = m(name) + ", a part of " + m(whole_name);
    // Its terms are terms of T (or V): then it is a part of it.
    std::vector<GiNaC::ex> wt, pt;
    const GiNaC::ex we = whole.expand(), pe = other.value.expand();
    if (GiNaC::is_a<GiNaC::add>(we))
        for (const GiNaC::ex& t : we) wt.push_back(t);
    else
        wt.push_back(we);
    if (GiNaC::is_a<GiNaC::add>(pe))
        for (const GiNaC::ex& t : pe) pt.push_back(t);
    else
        pt.push_back(pe);
    bool subset = !pe.is_zero();
    std::vector<bool> used(wt.size(), false);
    for (const GiNaC::ex& t : pt) {
        bool found = false;
        for (std::size_t k = 0; k < wt.size() && !found; ++k)
            if (!used[k] && same_signature(signature(t), signature(wt[k]), tol)) found = used[k] = true;
        subset = subset && found;
    }
    if (subset) {
        r.verdict = Verdict::Agrees;
        r.reason = "its terms are terms of eomgen's " + m(whole_name);
        return;
    }
    // Otherwise it should be T minus the other parts the text defines.
    GiNaC::ex others = 0;
    std::vector<std::string> names;
    for (const auto& [sym, value] : part_value_) {
        std::string n2;
        GiNaC::ex w2;
        if (sym.is_equal(part) || !is_part(sym, &n2, &w2) || n2[0] != name[0]) continue;
        others += value;
        names.push_back(m(n2) + " (" + part_origin_.at(sym) + ")");
    }
    std::sort(names.begin(), names.end());
    GiNaC::ex expected;
    if (!names.empty()) {
        expected = whole - others;
        std::string list;
        for (std::size_t k = 0; k < names.size(); ++k) list += (k ? ", " : "") + names[k];
        if (equal(other.value, expected, tol) == Tri::Yes) {
            r.verdict = Verdict::Agrees;
            r.reason = "it is eomgen's " + m(whole_name) + " minus the text's other parts: " + list;
            return;
        }
        r.notes.push_back("compared with eomgen's " + m(whole_name) +
                          " minus the text's other parts: " + list);
    } else {
        // No other parts: its share of T is the terms of T of the same kinds (velocity monomials).
        expected = 0;
        for (const Group& g : groups(whole))
            for (const Group& h : groups(other.value))
                if (g.monomial.is_equal(h.monomial)) expected += g.coefficient * g.monomial;
        r.notes.push_back("compared with the terms of eomgen's " + m(whole_name) + " of the same kinds");
    }
    r.verdict = Verdict::Disagrees;
    const Diagnosis dg = compare_to(other.value, expected, tol);
    r.difference = dg.difference;
    r.wrong_terms = dg.lines;
    r.corrected = part_source + " = " + latex(expected);
}

void Checker::check_values(const FullChain& c, std::size_t i, std::size_t j, const Prepared& a_read,
                           const Prepared& b_read, double tol, EquationCheck& r) {
    Prepared a = a_read, b = b_read;
    const PSide& L = c.sides[i];
    const PSide& R = c.sides[j];
    auto label_of = [&](const PSide& s) -> std::string {
        if (!s.side->ok) return "";
        std::vector<std::string> unused;
        auto it = label_what_.find(discourse_->renamed(s.side->value, s.base + s.side->begin, unused));
        return it == label_what_.end() ? "" : it->second;
    };
    const std::string ll = label_of(L), rl = label_of(R);
    // A declared result is described in words (with its LaTeX inside), eomgen's labels are LaTeX.
    auto shown = [](const std::string& what) {
        return what.rfind("the declared result", 0) == 0 ? what : m(what);
    };
    r.compared_with = !ll.empty() ? shown(ll) : (!rl.empty() ? shown(rl) : "");
    const bool rounded = tol > 1e-9;
    const std::string within = rounded ? " within the rounding of its numbers (" +
                                             [&] {
                                                 std::ostringstream os;
                                                 os.precision(2);
                                                 os << tol * 100 << "%)";
                                                 return os.str();
                                             }()
                                       : "";

    // The amplitudes of a trial solution (`x_j = A_j e^{i\omega t}`): rows of (K − ω² M) A = 0.
    if (const TrialSolution* trial = discourse_->trial_at(c.relation_offsets[j - 1]);
        trial && a.vectors.empty() && b.vectors.empty() && a.units.empty() && b.units.empty() &&
        amplitudes_.check(a.value, b.value, L.side->source, R.side->source, written_names(L, R), *trial,
                          discourse_->stated_frequency(c.relation_offsets[j - 1]), ctx_, *this, r))
        return;
    // `s(t) = s_0\cos(\omega t)`: a solution the text claims for a coordinate, put into its equation of motion.
    if (a.vectors.empty() && b.vectors.empty() && a.units.empty() && b.units.empty() &&
        check_claimed_solution(a.value, b.value, model_, eq_, motion_, ctx_, *this, r,
                               discourse_->stated_frequencies(c.relation_offsets[j - 1])))
        return;
    // Free names: an identity still agrees, anything else cannot be judged.
    if (!a.comparable() || !b.comparable()) {
        // Vectors are not scalars: a×b = −b×a, so only identities in scalar unknowns are claimed.
        if (a.vectors.empty() && b.vectors.empty() && equal(a.value, b.value, tol) == Tri::Yes) {
            r.verdict = Verdict::Agrees;
            r.compared_with = "an identity";
            r.reason = "both sides are equal (in the text's own symbols)" + within;
            return;
        }
        // `k = g/l`: a definition, used in the rest of its section (definitions.hpp), not a line of a motion.
        const std::string def = definitions_.defined_at(L.base + L.side->begin);
        if (def.empty() && a.vectors.empty() && b.vectors.empty() && a.units.empty() && b.units.empty() &&
            on_motion(c, i, j, a.value, b.value, tol, r))
            return;
        std::vector<std::string> unknown, vectors;
        auto describe = [&](const PSide& s, const Prepared& p) {
            for (const FreeName* f : p.vectors) {
                const std::string x = m(f->name);
                if (std::find(vectors.begin(), vectors.end(), x) == vectors.end()) vectors.push_back(x);
            }
            for (const FreeName* f : p.unknown) {
                std::string x = m(f->name);
                for (const NameUse& u : s.side->uses)
                    if (u.name == f->name) {
                        x += " (" + where(s.base + u.offset) + ")";
                        break;
                    }
                if (f->name == "d") x += " (a differential?)";
                if (std::find(unknown.begin(), unknown.end(), x) == unknown.end()) unknown.push_back(x);
            }
        };
        describe(L, a);
        describe(R, b);
        auto join = [](const std::vector<std::string>& v) {
            std::string s;
            for (std::size_t k = 0; k < v.size(); ++k) s += (k ? ", " : "") + v[k];
            return s;
        };
        if (!unknown.empty())
            r.reason = "unknown symbol" + std::string(unknown.size() > 1 ? "s " : " ") + join(unknown) +
                       ": not a symbol of the model (--map can say what it stands for)";
        else
            r.reason = "vector quantities (" + join(vectors) + ") are not compared";
        if (!def.empty())
            r.reason += "; a definition: the text's abbreviation $" + def + "$ for the rest of its " +
                        (at_a_point_.count(L.base + L.side->begin) ? "paragraph (its value at the point the text considers)"
                                                                   : "section");
        return;
    }
    // A number the text works out: units to SI, the parameters' values, its printed digits.
    if (check_number(a.value, b.value, {L.side->source, R.side->source}, c.relation_offsets[j - 1], model_, ctx_, d_,
                     parameter_values_, r))
        return;
    // A parameter the text set for this paragraph (`m_1 = 0`): the text's sides take it as eomgen's equations do
    // (the sample points hold it, Numbers::pin).
    // A condition stated again (`\theta = 0` at θ = 0) is not an identity: it is judged as the condition it is.
    if (!numbers_.pinned().empty() && !condition_of(a.value, b.value, model_).empty()) numbers_.pin({});
    if (!numbers_.pinned().empty()) {
        r.notes.insert(r.notes.end(), chosen_notes_.begin(), chosen_notes_.end());
        a.value = subs_unless_pole(a.value, numbers_.pinned()).value_or(a.value);
        b.value = subs_unless_pole(b.value, numbers_.pinned()).value_or(b.value);
    }
    if (!a.units.empty() || !b.units.empty()) {
        if (equal(a.value, b.value, tol) == Tri::Yes) {
            r.verdict = Verdict::Agrees;
            r.compared_with = "an identity";
            r.reason = "both sides are equal, units included" + within;
            return;
        }
        r.reason = "a quantity with units that do not cancel";
        return;
    }
    const GiNaC::ex r_ex = a.value - b.value;
    // 1. An identity: equal as they stand (a label and its value, two steps of a chain, T = T_{1} + T_{2}).
    const Tri same = equal(a.value, b.value, tol);
    if (same == Tri::Yes && (has_root(a.value) || has_root(b.value))) {
        // ṙ = √(2/m (E − V)): equal where the sampled velocities are positive, but a root has no sign. With every
        // velocity reversed the sides must still agree, or a ± is missing.
        GiNaC::exmap reversed;
        std::string names;  // the velocities of the side without the root (both sides' when both have one)
        const GiNaC::ex& bare = !has_root(a.value) ? a.value : !has_root(b.value) ? b.value : r_ex;
        int named = 0;
        for (const Coordinate& q : model_.coordinates) {
            if (r_ex.has(q.qd)) reversed[q.qd] = -q.qd;
            if (bare.has(q.qd)) {
                names += (names.empty() ? "" : ", ") + m(latex(q.qd));
                ++named;
            }
        }
        if (!reversed.empty() && equal(a.value.subs(reversed), b.value.subs(reversed), tol) == Tri::No) {
            r.verdict = Verdict::Disagrees;
            r.compared_with = "the same line with the velocities reversed";
            r.reason = "the sides are equal only while " + names + (named > 1 ? " have" : " has") +
                       " the sign of the square root: a root is never negative, so a ± (or the sign of the "
                       "velocity) is missing";
            return;
        }
    }
    if (same == Tri::Yes) {
        r.verdict = Verdict::Agrees;
        if (r.compared_with.empty()) r.compared_with = "an identity";
        r.reason = (ll.empty() && rl.empty() ? std::string("both sides are equal")
                                             : "equal to " + [&] {
                                                   const std::string& w = ll.empty() ? rl : ll;
                                                   return w.rfind("the declared result", 0) == 0 ? w : "eomgen's " + m(w);
                                               }()) +
                   within;
        return;
    }
    if (same == Tri::Unknown) {
        r.reason = "could not be evaluated at enough points to decide";
        return;
    }
    // 2a. With the multipliers, written on the constraints (φ = ωt put in: cos ωt for cos φ, ω for φ̇, φ̈ = 0): it
    // holds at states on them, λ from the constrained equations.
    if (std::any_of(multipliers_.begin(), multipliers_.end(), [&](const GiNaC::symbol& l) { return r_ex.has(l); }))
        for (int sign : {1, -1}) {
            const std::optional<bool> holds = holds_on_constrained_motion(r_ex, model_, eq_, tol, multipliers_, sign);
            if (!holds || !*holds) continue;
            r.verdict = Verdict::Agrees;
            r.compared_with = "the equations of motion with the constraint forces";
            r.reason = std::string("it holds on every motion, with the constraints put in (checked at sample states)") +
                       (sign < 0 ? ", the multiplier taken with the opposite sign to eomgen's (M q'' = f + A^T λ)" : "") +
                       within;
            return;
        }
    // 2. An equation of motion: a combination of the Euler–Lagrange equations.
    if (has_acceleration(r_ex)) {
        int only = -1;
        std::string factor;
        std::vector<std::string> acting;
        // With the multipliers written (m ẍ = 2 x λ): the equations with the constraint forces, λ with eomgen's sign
        // (M q̈ = f + Aᵀλ, A from the constraint as the model writes it) or the opposite one.
        const bool with_lambda = std::any_of(multipliers_.begin(), multipliers_.end(),
                                             [&](const GiNaC::symbol& l) { return r_ex.has(l); });
        for (int sign : {1, -1}) {
            if (!with_lambda) break;
            if (euler_lagrange_combination(r_ex, std::max(tol, 1e-9), &only, &factor, nullptr, nullptr, sign) !=
                Tri::Yes)
                continue;
            r.verdict = Verdict::Agrees;
            r.compared_with = (only >= 0 ? "the Euler–Lagrange equation for " +
                                               m(model_.coordinates[std::size_t(only)].latex)
                                         : std::string("the Euler–Lagrange equations")) +
                              " with the constraint forces";
            r.reason = (factor.empty() ? std::string(only >= 0 ? "the same equation" : "a combination of them")
                                       : "the same equation times " + m(factor)) +
                       (sign < 0 ? ", the multiplier taken with the opposite sign to eomgen's (M q'' = f + A^T λ)"
                                 : "") +
                       within;
            return;
        }
        if (euler_lagrange_combination(r_ex, std::max(tol, 1e-9), &only, &factor, &acting) == Tri::Yes) {
            if (!acting.empty()) {
                std::string names;
                for (std::size_t k = 0; k < acting.size(); ++k) names += (k ? ", " : "") + ("'" + acting[k] + "'");
                r.compared_with = only >= 0 ? "the Euler–Lagrange equation for " +
                                                  m(model_.coordinates[std::size_t(only)].latex)
                                            : "the Euler–Lagrange equations";
                r.reason = "it is that equation without the forces of the constraint" +
                           std::string(acting.size() > 1 ? "s " : " ") + names + ", which act along it";
                if (only >= 0) {
                    GiNaC::ex force = 0;
                    for (std::size_t k = 0; k < eq_.constraints.size(); ++k)
                        force += eq_.constraints[k].jacobian[std::size_t(only)] * multipliers_[k];
                    r.verdict = Verdict::Disagrees;
                    r.reason += ": the constraint force " + m(latex(force)) + " is missing (" +
                                m("\\lambda") + " with eomgen's sign, M q'' = f + A^T λ)";
                } else {
                    r.reason += ": the true equations hold their multipliers";
                }
                return;
            }
            r.verdict = Verdict::Agrees;
            if (only >= 0) {
                r.compared_with =
                    "the Euler–Lagrange equation for " + m(model_.coordinates[std::size_t(only)].latex);
                r.reason = factor.empty() ? "the same equation" + within
                                          : "the same equation times " + m(factor) + within;
            } else {
                r.compared_with = "the Euler–Lagrange equations";
                r.reason = "a combination of them" + within;
            }
            return;
        }
    }
    // 2b. With constraints, no multipliers written: an equation that holds on every motion (a constraint
    // differentiated twice, or the equations with the constraint forces eliminated).
    if (has_acceleration(r_ex) && !eq_.constraints.empty() &&
        std::none_of(multipliers_.begin(), multipliers_.end(), [&](const GiNaC::symbol& l) { return r_ex.has(l); })) {
        if (const std::optional<bool> holds = holds_on_constrained_motion(r_ex, model_, eq_, tol); holds && *holds) {
            r.verdict = Verdict::Agrees;
            r.compared_with = "the equations of motion with the constraints";
            r.reason = "it holds on every motion: q'' from M q'' = f + A^T λ and the constraints, the constraint "
                       "forces eliminated (checked at sample states)" +
                       within;
            return;
        }
    }
    // 3. An integral of motion with the model's initial state (also after squaring a square root).
    if (!has_acceleration(r_ex) && depends_on_state(r_ex)) {
        std::vector<std::pair<GiNaC::ex, std::string>> forms{{r_ex, ""}};
        if ((has_root(a.value) || has_root(b.value)) &&
            expanded_terms(a.value * a.value - b.value * b.value) <= kMaxExpandedTerms)
            forms.push_back({(a.value * a.value - b.value * b.value).expand(),
                             " after squaring both sides (the sign of the root is not checked)"});
        for (const auto& [form, how] : forms)
            for (const auto& [target, what] : integrals_of_motion_) {
                GiNaC::ex factor;
                if (proportional_in_state(form, target, tol, &factor)) {
                    r.verdict = Verdict::Agrees;
                    r.compared_with = what;
                    r.reason = "proportional to it" + how + within;
                    return;
                }
            }
    }
    // 3b. With constraints: a constraint (up to a non-zero factor, at position or velocity level), or an
    // equation that holds once the constraints are solved for some coordinates and velocities.
    if (!eq_.constraints.empty() && !has_acceleration(r_ex)) {
        for (std::size_t k = 0; k < eq_.constraints.size(); ++k) {
            const ConstraintEquations& ck = eq_.constraints[k];
            const bool position = ck.kind == ConstraintKind::Holonomic && !has_velocity(r_ex);
            const GiNaC::ex& target = position ? ck.position : ck.velocity;
            GiNaC::ex factor;
            const bool same = position ? depends_on_state(r_ex) && equal(r_ex, target, tol) == Tri::Yes
                                       : has_velocity(r_ex) && proportional_to_constraint(r_ex, k, tol);
            const bool scaled = !same && position && depends_on_state(r_ex) &&
                                proportional_in_state(r_ex, target, tol, &factor);
            if (same || scaled) {
                r.verdict = Verdict::Agrees;
                r.compared_with = "the constraint '" + ck.name + "' (" + m(latex(target) + " = 0") + ")";
                r.reason = "the same constraint" + std::string(position ? "" : ", up to a factor free of the velocities") + within;
                return;
            }
        }
        const bool labelled = a.has_truth_label || b.has_truth_label;
        std::string shown;
        const ConstraintReduction red = reduction(labelled ? (a.has_truth_label ? b.value : a.value) : r_ex, &shown);
        if (!red.solved.empty() && depends_on_state(r_ex) &&
            equal(red.apply(a.value), red.apply(b.value), tol) == Tri::Yes) {
            r.verdict = Verdict::Agrees;
            if (r.compared_with.empty()) r.compared_with = "the constraints";
            r.reason = "equal on the constraints (" + shown + ")" + within;
            return;
        }
    }
    if (const std::string q = condition_of(a.value, b.value, model_); !q.empty()) {
        const std::string cue = condition_cue(d_, c.relation_offsets[j - 1]);
        r.reason = cue.empty() ? "a condition: the point or motion the text considers, where " + m(q) +
                                     " takes this value (not an equation of the motion, so not judged)"
                               : "a condition or a given value (after “" + cue +
                                     "”): it sets a value for what follows, not an equation of motion, and is not "
                                     "judged";
        return;
    }
    // A formula set equal to a number that is not a worked-out number (printed_numbers: no single decimal or
    // number with units, such as the Earth's (I_3 - I)/I \approx 3 \times 10^{-3}) is particular data.
    auto constant = [&](const GiNaC::ex& x) {
        for (const Parameter& p : model_.parameters)
            if (x.has(p.symbol)) return false;
        return !depends_on_state(x) && !has_acceleration(x) && !x.has(model_.t);
    };
    const GiNaC::ex& varying = constant(a.value) ? b.value : a.value;
    if (constant(a.value) != constant(b.value) && !(constant(a.value) ? a.value : b.value).is_zero() &&
        !has_velocity(varying) && !has_acceleration(varying)) {
        r.reason = "a value for particular data: not compared (only a printed decimal or a number with units is "
                   "worked out with the model's values)";
        return;
    }
    // 4. It disagrees with what it tries to be.
    const bool left_ref = (a.has_truth_label || a.from_definition) && !a.has_part;
    const bool right_ref = !left_ref && (b.has_truth_label || b.from_definition) && !b.has_part;
    if (left_ref || right_ref) {
        const bool left_is_truth = left_ref;
        const PSide& ref = left_is_truth ? L : R;
        const Prepared& truth = left_is_truth ? a : b;
        const Prepared& text = left_is_truth ? b : a;
        if (has_acceleration(r_ex) && !has_acceleration(truth.value)) {
            // "... = 0" against d/dt(∂L/∂q̇) − ∂L/∂q written with L: fall through to the equation-of-motion
            // check.
        } else {
            r.verdict = Verdict::Disagrees;
            if (r.compared_with.empty())
                r.compared_with = truth.has_truth_label ? "eomgen's value of " + m(ref.side->source)
                                                        : m(ref.side->source) + " from the text's definition";
            const Diagnosis dg = compare_to(text.value, truth.value, tol);
            r.difference = dg.difference;
            // A text in momenta, in velocities: sin² + cos² = 1 may shorten the difference a lot.
            if (text.has_momenta)
                if (const std::string s = latex(shorter_trig((text.value - truth.value).expand()));
                    s.size() < r.difference.size())
                    r.difference = s;
            r.wrong_terms = dg.lines;
            r.corrected = ref.side->source + " = " + printed_value(truth, ref, text);
            return;
        }
    }
    if (on_motion(c, i, j, a.value, b.value, tol, r)) return;
    if (has_acceleration(r_ex)) {
        diagnose_euler_lagrange(L, R, r_ex, tol, r);
        return;
    }
    // A velocity-level equation in a model with constraints: the constraint it matches best.
    if (!eq_.constraints.empty() && linear_in_velocities(r_ex) && groups(r_ex).size() >= 2) {
        int best = 0;
        std::size_t best_k = 0;
        GiNaC::ex best_c = 1;
        for (std::size_t k = 0; k < eq_.constraints.size(); ++k) {
            GiNaC::ex cf = 1;
            const int count = best_factor(r_ex, eq_.constraints[k].velocity, tol, &cf);
            if (count > best) {
                best = count;
                best_k = k;
                best_c = cf;
            }
        }
        if (best >= 1) {
            const ConstraintEquations& ck = eq_.constraints[best_k];
            const GiNaC::ex truth = (best_c * ck.velocity).expand();
            r.verdict = Verdict::Disagrees;
            r.compared_with = "the constraint '" + ck.name + "' (" + m(latex(ck.velocity) + " = 0") + ")";
            if (!best_c.is_equal(1)) r.notes.push_back("compared after scaling the constraint by " + m(latex(best_c)));
            const Diagnosis dg = compare_to(r_ex, truth, tol);
            r.difference = dg.difference;
            r.wrong_terms = dg.lines;
            r.corrected = latex(truth) + " = 0";
            return;
        }
    }
    const bool chain_link = c.sides.size() >= 3;
    if (chain_link) {
        r.verdict = Verdict::Disagrees;
        r.compared_with = "the previous step of the chain";
        const bool sums =
            GiNaC::is_a<GiNaC::add>(a.value.expand()) || GiNaC::is_a<GiNaC::add>(b.value.expand());
        // What the chain is about (T = ..., T_{disk} = ...): when the right side equals it, the slip is on
        // the left.
        bool slip_left = false;
        if (c.sides[0].side->ok) {
            std::optional<GiNaC::ex> subject;
            auto t = truth_.find(c.sides[0].side->value);
            if (t != truth_.end()) subject = t->second;
            if (!subject && is_part(c.sides[0].side->value)) subject = expected_part(c.sides[0].side->value);
            if (subject && equal(b.value, *subject, tol) == Tri::Yes) {
                slip_left = true;
                r.notes.push_back("the right side is right (it equals eomgen's value of " +
                                  m(c.sides[0].side->source) + "): the slip is in the left side");
            }
        }
        std::string ratio;
        const std::vector<std::string> factors =
            sums ? std::vector<std::string>{} : factor_analysis(a.value, b.value, tol, &ratio);
        const Diagnosis dg =
            slip_left ? compare_to(a.value, b.value, tol) : compare_to(b.value, a.value, tol);
        r.difference = dg.difference;
        r.wrong_terms = factors;
        if (factors.empty()) r.wrong_terms.insert(r.wrong_terms.end(), dg.lines.begin(), dg.lines.end());
        if (slip_left)
            r.corrected = latex(b.value) + " = " + R.side->source;
        else
            r.corrected = !scaled_step(L.side->source, ratio, R.side->source).empty()
                              ? scaled_step(L.side->source, ratio, R.side->source)
                              : L.side->source + " = " + printed_value(a, L, b);
        return;
    }
    if (has_velocity(r_ex) && !integrals_of_motion_.empty()) {
        GiNaC::ex cf = 1;
        const GiNaC::ex target = integrals_of_motion_.front().first;
        if (best_factor(r_ex, target, tol, &cf) >= 1) {
            r.verdict = Verdict::Disagrees;
            r.compared_with = integrals_of_motion_.front().second;
            const Diagnosis dg = compare_to(r_ex, (cf * target).expand(), tol);
            r.difference = dg.difference;
            r.wrong_terms = dg.lines;
            r.corrected = latex((cf * target).expand()) + " = 0";
            return;
        }
    }
    r.reason =
        "not an identity, and not an equation of this model (a condition or an assumption, such as a "
        "particular value)";
}

int Checker::closest_euler_lagrange(const GiNaC::ex& r, double tol, GiNaC::ex* factor, int* groups) {
    int best_i = -1, best_count = -1;
    for (std::size_t i = 0; i < model_.dof(); ++i) {
        GiNaC::ex c = 1;
        const int count = best_factor(r, motion_[i], tol, &c);
        // Ties: the coordinate whose own acceleration the text's equation has.
        const bool better = count > best_count || (count == best_count && r.has(model_.coordinates[i].qdd) &&
                                                   !r.has(model_.coordinates[std::size_t(best_i)].qdd));
        if (better) {
            best_count = count;
            best_i = int(i);
            *factor = c;
        }
    }
    if (groups) *groups = best_count;
    return best_i;
}

void Checker::diagnose_euler_lagrange(const PSide& left, const PSide& right, const GiNaC::ex& r, double tol,
                                      EquationCheck& out) {
    (void)left;
    (void)right;
    if (diagnose_solved_acceleration(left, right, r, tol, out)) return;
    GiNaC::ex best_c = 1;
    const std::size_t i = std::size_t(closest_euler_lagrange(r, tol, &best_c, nullptr));
    const Coordinate& q = model_.coordinates[i];
    out.verdict = Verdict::Disagrees;
    out.compared_with = "the Euler–Lagrange equation for " + m(q.latex);
    if (!best_c.is_equal(1))
        out.notes.push_back("compared after scaling eomgen's equation by " + m(latex(best_c)));
    const GiNaC::ex truth = (best_c * motion_[i]).expand();
    const Diagnosis dg = compare_to(r, truth, tol);
    out.difference = dg.difference;
    out.wrong_terms = dg.lines;
    out.corrected = latex(truth) + " = 0";
    // d/dt(X) − (Y) = 0 written out: say which of ∂L/∂q̇ and ∂L/∂q is wrong.
    for (const PSide* s : {&left, &right}) {
        if (!s->side->ok) continue;
        std::vector<GiNaC::ex> found;
        std::vector<GiNaC::ex> stack{s->side->value};
        while (!stack.empty()) {
            GiNaC::ex x = stack.back();
            stack.pop_back();
            if (is_ex_the_function(x, ddt)) found.push_back(x);
            for (std::size_t k = 0; k < x.nops(); ++k) stack.push_back(x.op(k));
        }
        if (found.size() != 1) continue;
        try {
            const GiNaC::ex D = found[0];
            const GiNaC::symbol z("__d");
            GiNaC::exmap labels;
            for (const auto& [sym, val] : truth_) labels[sym] = val;
            const GiNaC::ex side_z = s->side->value.subs(D == z).subs(labels);
            const GiNaC::ex k = GiNaC::diff(side_z, z);
            if (has_velocity(k) || k.has(z)) continue;
            const double sign = s == &left ? 1 : -1;
            const GiNaC::ex X = resolve_operators(D.op(0).subs(labels));
            const GiNaC::ex rest = resolve_operators(side_z.subs(z == 0));
            const GiNaC::ex other = resolve_operators(prepare(s == &left ? right : left).value);
            // side = k·d/dt X + rest. With sign +1 on the left, −1 on the right, the equation matches
            // c·(d/dt p − ∂L/∂q) when sign·k·X = c·p and −sign·(rest − other side) = c·∂L/∂q.
            const GiNaC::ex p_text = (sign * k * X).expand();
            const GiNaC::ex dLdq_text = (-sign * (rest - other)).expand();
            // d/dt(c p) is c d/dt(p) only for a constant c: a factor that depends on the state stays outside.
            const GiNaC::ex c = depends_on_state(best_c) || best_c.has(model_.t) ? GiNaC::ex(1) : best_c;
            const GiNaC::ex p_true = (c * eq_.momenta[i]).expand();
            const GiNaC::ex dLdq_true = (c * (time_derivative(eq_.momenta[i], model_) - motion_[i])).expand();
            const std::string pl = m("\\partial L/\\partial \\dot{" + q.latex + "}");
            const std::string ql = m("\\partial L/\\partial " + q.latex);
            if (equal(p_text, p_true, tol) == Tri::Yes) {
                out.notes.push_back("inside " + m("\\frac{d}{dt}") + ": the text's " + pl + " agrees");
            } else {
                const Diagnosis dp = compare_to(p_text, p_true, tol);
                for (const std::string& line : dp.lines)
                    out.wrong_terms.push_back("inside " + m("\\frac{d}{dt}") + " (" + pl + "), " + line);
            }
            if (equal(dLdq_text, dLdq_true, tol) == Tri::Yes) {
                out.notes.push_back("the text's " + ql + " agrees");
            } else {
                const Diagnosis dq = compare_to(dLdq_text, dLdq_true, tol);
                for (const std::string& line : dq.lines) out.wrong_terms.push_back("in " + ql + ", " + line);
            }
            out.corrected = lagrange_form(latex(p_true), latex(dLdq_true));
        } catch (...) {
        }
    }
}

bool Checker::diagnose_solved_acceleration(const PSide& left, const PSide& right, const GiNaC::ex& r, double tol,
                                           EquationCheck& out) {
    // `\ddot x_2 = …` with the other accelerations eliminated, in a model of 2 to 4 unconstrained coordinates:
    // compared with q''_i solved from M q'' = f, not with the Euler–Lagrange equation that still holds the others.
    const std::size_t n = model_.dof();
    if (n < 2 || n > 4 || !eq_.constraints.empty()) return false;
    int solved = -1;
    for (std::size_t k = 0; k < n; ++k)
        if (r.has(model_.coordinates[k].qdd)) {
            if (solved >= 0) return false;
            solved = int(k);
        }
    if (solved < 0) return false;
    const std::size_t i = std::size_t(solved);
    const GiNaC::symbol& qdd = model_.coordinates[i].qdd;
    const PSide* alone = nullptr;  // the side that is q''_i itself
    for (const PSide* s : {&left, &right})
        if (s->side->ok && s->side->value.is_equal(qdd)) alone = s;
    if (!alone) return false;
    GiNaC::ex value;
    try {
        GiNaC::matrix x(unsigned(n), 1), rhs(unsigned(n), 1);
        std::vector<GiNaC::symbol> unknowns(n);
        for (std::size_t k = 0; k < n; ++k) {
            x(unsigned(k), 0) = unknowns[k];
            rhs(unsigned(k), 0) = eq_.f[k];
        }
        const GiNaC::matrix sol = eq_.M.solve(x, rhs, GiNaC::solve_algo::gauss);
        value = GiNaC::normal(sol(unsigned(i), 0));
        if (!numbers_.pinned().empty()) value = GiNaC::normal(subs_unless_pole(value, numbers_.pinned()).value_or(value));
    } catch (...) {
        return false;
    }
    if (expanded_terms(value) > kMaxExpandedTerms) return false;
    const GiNaC::ex truth_r = alone == &left ? GiNaC::ex(qdd - value) : GiNaC::ex(value - qdd);
    out.verdict = Verdict::Disagrees;
    out.compared_with = m("\\ddot{" + model_.coordinates[i].latex + "}") + " solved from the Euler–Lagrange equations";
    const Diagnosis dg = compare_to(r, truth_r, tol);
    out.difference = dg.difference;
    out.wrong_terms = dg.lines;
    out.corrected = alone == &left ? alone->side->source + " = " + latex(value)
                                   : latex(value) + " = " + alone->side->source;
    return true;
}

void Checker::blame_definition(const FullChain& c, std::size_t i, std::size_t j, const EquationCheck& r) {
    const PSide* sides[2] = {&c.sides[i], &c.sides[j]};
    // The one defined name the link uses, on one side only.
    int text_side = -1;
    const FreeName* name = nullptr;
    int line = 0;
    GiNaC::ex definition;
    for (int k = 0; k < 2; ++k) {
        const PSide& s = *sides[k];
        if (!s.side->ok) return;
        std::vector<GiNaC::ex> stack{s.side->value};
        while (!stack.empty()) {
            const GiNaC::ex e = stack.back();
            stack.pop_back();
            for (std::size_t q = 0; q < e.nops(); ++q) stack.push_back(e.op(q));
            const FreeName* f = ctx_.free_name_of(e);
            int at_line = 0;
            const GiNaC::ex* value = f ? definitions_.value_at(e, s.base + s.side->begin, &at_line) : nullptr;
            if (!value) continue;
            if (name && (name != f || text_side != k)) return;  // two names, or on both sides
            name = f;
            text_side = k;
            line = at_line;
            definition = *value;
        }
    }
    if (!name) return;
    // The other side is eomgen's value: a label, or the chain's right side that equals what the chain is about.
    const Prepared trusted = prepare(*sides[1 - text_side]);
    const bool right_is_right = std::any_of(r.notes.begin(), r.notes.end(), [](const std::string& n) {
        return n.rfind("the right side is right", 0) == 0;
    });
    if (!trusted.comparable() || !(trusted.has_truth_label || (right_is_right && text_side == 0))) return;
    definitions_.suspend(name->name);
    const Prepared free = prepare(*sides[text_side]);
    definitions_.resume();
    if (!free.ok) return;
    try {
        const GiNaC::ex e = (free.value - trusted.value).expand();
        if (e.degree(name->symbol) != 1) return;
        const GiNaC::ex needed = GiNaC::normal(-e.coeff(name->symbol, 0) / e.coeff(name->symbol, 1));
        if (needed.has(name->symbol) || equal(needed, definition, 1e-9) == Tri::Yes) return;
        blames_.push_back({name->name, needed, line, r.where, r.equation});
    } catch (...) {
    }
}

void Checker::apply_blames(std::vector<EquationCheck>& equations) {
    std::set<std::string> names;
    for (const Blame& b : blames_) names.insert(b.name);
    for (const std::string& name : names) {
        std::vector<const Blame*> these;
        for (const Blame& b : blames_)
            if (b.name == name) these.push_back(&b);
        if (these.size() < 2) continue;
        bool alike = true;
        for (const Blame* b : these) alike = alike && equal(b->needed, these.front()->needed, 1e-9) == Tri::Yes;
        if (!alike) continue;
        const Blame& first = *these.front();
        const std::string prefix = "a definition: the text's abbreviation $" + name + " = ";
        EquationCheck* def = nullptr;
        for (EquationCheck& e : equations)
            if (e.where.line == first.definition_line && e.reason.find(prefix) != std::string::npos) def = &e;
        if (!def) continue;
        std::string lines;
        for (const Blame* b : these) {
            const std::string l = std::to_string(b->where.line);
            if (lines.find(l) == std::string::npos) lines += (lines.empty() ? "" : ", ") + l;
        }
        const std::string needed = latex(first.needed);
        def->verdict = Verdict::Disagrees;
        def->reason = "the text's definition of $" + name + "$, which its uses make wrong";
        def->compared_with = "what its uses on line " + lines + " need, where the other side is eomgen's";
        def->wrong_terms = {"with this $" + name + "$ the lines that use it disagree with eomgen; they hold with $" +
                            name + " = " + needed + "$"};
        def->corrected = name + " = " + needed;
        for (const Blame* b : these)
            for (EquationCheck& e : equations)
                if (e.where.line == b->where.line && e.where.column == b->where.column && e.equation == b->equation &&
                    e.verdict == Verdict::Disagrees) {
                    e.verdict = Verdict::NotComparable;
                    e.reason = "it holds with $" + name + " = " + needed + "$: the text's $" + name + "$ of line " +
                               std::to_string(first.definition_line) + " is what disagrees (see there)";
                    e.difference.clear();
                    e.wrong_terms.clear();
                    e.corrected.clear();
                }
    }
}

CheckReport Checker::run() {
    CheckReport report;
    report.model_path = model_.path;
    report.model_title = model_.title;
    report.derivation_path = d_.path;
    report.map = options_.map;
    const std::vector<int> selected = select_sections(d_, options_.sections);
    if (!options_.sections.empty() && selected.empty()) {
        std::string list;
        for (const Section& s : d_.sections) list += "\n  " + s.title;
        throw CheckError("no heading of " + d_.path + " contains '" + options_.sections.front() +
                         "'; headings:" + list);
    }
    const bool whole = options_.sections.empty();
    if (!whole)
        for (int k : selected) report.sections.push_back(d_.sections[std::size_t(k)].title);

    setup_names();
    apply_map();
    {  // "with L = m r² θ̇", in a sentence about the angular momentum: L is that from the next line on
        std::vector<const MathRow*> rows;
        for (const MathRow& row : d_.rows)
            if (row_selected(d_, row, selected, whole)) rows.push_back(&row);
        meanings_ = text_meanings(d_, rows);
        for (const TextMeaning& m : meanings_)
            meaning_map_.push_back({m.name, m.value, "the text, line " + std::to_string(m.line), m.line + 1,
                                    std::max(m.line + 1, m.last_line)});
    }

    // Pass 1: parse every selected row; rows that start with "=" continue the chain above them.
    struct Parsed {
        const MathRow* row;
        std::vector<Chain> chains;
    };
    std::vector<Parsed> parsed;
    for (const MathRow& row : d_.rows) {
        if (!row_selected(d_, row, selected, whole)) continue;
        // Entries scoped to some lines of the text apply while their rows are read.
        const std::size_t lead = std::min(row.text.find_first_not_of(" \t\r\n"), row.text.size());
        const int line = d_.position(row.offset + lead).line;
        const auto in_scope = [&](const MapEntry& e) {
            return e.first_line != 0 && line >= e.first_line && line <= e.last_line;
        };
        const bool scoped = std::any_of(options_.map.begin(), options_.map.end(), in_scope) ||
                            std::any_of(meaning_map_.begin(), meaning_map_.end(), in_scope);
        if (!scoped) {
            parsed.push_back({&row, parse_math(row.text, ctx_)});
            continue;
        }
        const auto saved = ctx_.names;
        apply_map(line);
        parsed.push_back({&row, parse_math(row.text, ctx_)});
        ctx_.names = saved;
    }
    std::vector<FullChain> chains;
    const MathRow* previous_display = nullptr;
    for (const Parsed& p : parsed) {
        for (std::size_t k = 0; k < p.chains.size(); ++k) {
            const Chain& ch = p.chains[k];
            const bool continues =
                k == 0 && p.row->display && ch.sides.size() >= 2 && ch.sides[0].empty() && previous_display &&
                !chains.empty() && chains.back().display && chains.back().section == p.row->section && [&] {
                    const std::size_t from = previous_display->offset + previous_display->text.size();
                    for (std::size_t q = from; q < p.row->offset && q < d_.text.size(); ++q)
                        if (!std::isspace(static_cast<unsigned char>(d_.text[q])) &&
                            std::string("$\\[]").find(d_.text[q]) == std::string::npos)
                            return false;
                    return true;
                }();
            if (!continues) {
                FullChain f;
                f.section = p.row->section;
                f.display = p.row->display;
                f.sides.push_back({&ch.sides[0], p.row->offset});
                chains.push_back(f);
            }
            FullChain& f = chains.back();
            for (std::size_t s = 1; s < ch.sides.size(); ++s) {
                f.sides.push_back({&ch.sides[s], p.row->offset});
                f.relations.push_back(ch.relations[s - 1]);
                f.relation_offsets.push_back(p.row->offset + ch.relation_offsets[s - 1]);
            }
        }
        if (p.row->display) previous_display = p.row;
    }
    for (const TextProblem& tp : d_.problems) {
        MathRow at;
        at.offset = tp.offset;
        if (row_selected(d_, at, selected, whole)) report.problems.push_back({d_.position(tp.offset), tp.message});
    }
    {
        std::vector<DiscourseLink> links;
        for (const FullChain& c : chains)
            for (std::size_t k = 0; k + 1 < c.sides.size(); ++k) {
                const std::size_t at = c.relation_offsets[k];
                const std::size_t blank = d_.text.find("\n\n", at);
                links.push_back({c.sides[k].side, c.sides[k + 1].side, c.relations[k], at,
                                 c.section >= 0 ? d_.sections[std::size_t(c.section)].end : d_.text.size(),
                                 blank == std::string::npos ? d_.text.size() : blank,
                                 c.sides[k].base + c.sides[k].side->begin});
            }
        LabelView labels;
        labels.value = [this](const GiNaC::ex& x) -> std::optional<GiNaC::ex> {
            const auto it = truth_.find(x);
            return it == truth_.end() ? std::nullopt : std::optional<GiNaC::ex>(it->second);
        };
        labels.is_momentum = [this](const GiNaC::ex& x) { return hamilton_.is_momentum(x); };
        labels.same = [this](const GiNaC::ex& x, const GiNaC::ex& y) { return equal(x, y, 1e-9) == Tri::Yes; };
        discourse_.emplace(links, model_, ctx_, d_, labels);
    }
    for (const FullChain& c : chains) {  // T_0 = 2\pi\sqrt{l/g}: a period, not a part of T
        if (c.sides.size() < 2 || !c.sides[0].side->ok) continue;
        std::string name;
        if (!is_part(c.sides[0].side->value, &name) || name[0] != 'T') continue;
        for (std::size_t k = 1; k < c.sides.size(); ++k) {
            const Side& v = *c.sides[k].side;
            bool constant = v.ok && !v.value.is_zero() && !depends_on_state(v.value) && !has_acceleration(v.value);
            std::vector<GiNaC::ex> stack{v.ok ? v.value : GiNaC::ex(0)};
            while (constant && !stack.empty()) {
                const GiNaC::ex e = stack.back();
                stack.pop_back();
                if (ctx_.free_name_of(e) || truth_.count(e)) constant = false;
                for (std::size_t q = 0; q < e.nops(); ++q) stack.push_back(e.op(q));
            }
            if (constant) not_parts_.insert(name);
        }
    }
    collect_definitions(chains);
    for (const FullChain& c : chains)  // stated vectors and eigen-equations, used before and after their line
        for (std::size_t k = 0; k + 1 < c.sides.size(); ++k)
            if (c.relations[k] == Relation::Equal)
                algebra_.note_link(*c.sides[k].side, c.sides[k].base, *c.sides[k + 1].side, c.sides[k + 1].base);
    // Where the text first writes H = (an expression in velocities, without momenta).
    for (const FullChain& c : chains) {
        if (c.sides.size() < 2 || !c.sides[0].side->ok || !hamilton_.is_hamiltonian(c.sides[0].side->value)) continue;
        const Prepared p = prepare(c.sides.back());
        if (!p.comparable() || p.has_momenta || !has_velocity(p.value)) continue;
        velocity_h_at_ = c.relation_offsets.front();
        velocity_h_line_ = d_.position(velocity_h_at_).line;
        break;
    }
    collect_parts(chains);
    for (const FullChain& c : chains) {
        if (c.sides.size() < 2) continue;  // an expression, not an equation
        check_chain(c, report.equations);
    }
    apply_blames(report.equations);
    {  // never silent: a row with a relation that gave no equation is "not read", with the reason
        std::vector<const MathRow*> read;
        for (const Parsed& p : parsed) read.push_back(p.row);
        for (EquationCheck& e : unread_rows(d_, read, report.equations)) report.equations.push_back(std::move(e));
    }
    std::stable_sort(report.equations.begin(), report.equations.end(),
                     [](const EquationCheck& x, const EquationCheck& y) {
                         return std::make_pair(x.where.line, x.where.column) <
                                std::make_pair(y.where.line, y.where.column);
                     });
    return report;
}

}  // namespace

CheckReport check_derivation(const Model& model, const Equations& eq, const Derivation& derivation,
                             const CheckOptions& options) {
    Checker c(model, eq, derivation, options);
    return c.run();
}

}  // namespace eomgen::checker
