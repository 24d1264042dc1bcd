/** @file approximation.cpp  Taylor expansions about q = 0 (or the point a change of variable sets) to the order
 * the text keeps. */
#include "checker/approximation.hpp"

#include "checker/linear_solve.hpp"
#include "mechanics/pole_free_subs.hpp"

#include <stdexcept>

#include <algorithm>
#include <cctype>
#include <optional>

namespace eomgen::checker {
namespace {

/// The Taylor polynomial of e in ε to `order`, with ε then set to 1; nullopt when it cannot be expanded.
std::optional<GiNaC::ex> taylor(const GiNaC::ex& e, const GiNaC::symbol& eps, int order) {
    try {
        const GiNaC::ex s = e.series(eps == 0, order + 1);
        GiNaC::ex p = GiNaC::series_to_poly(s);
        return p.subs(eps == 1).expand();
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

/// The degree in ε of a side that is a polynomial in it, else −1.
int polynomial_degree(const GiNaC::ex& e, const GiNaC::symbol& eps) {
    try {
        const GiNaC::ex x = e.expand();
        if (!x.is_polynomial(eps)) return -1;
        return x.degree(eps);
    } catch (const std::exception&) {
        return -1;
    }
}

/// Whether `text` holds `name` as a whole name: not inside a longer word or command (`r` in "for", `\rho` in
/// `\rhod`).
bool names(const std::string& text, const std::string& name) {
    const auto letter = [](char ch) { return std::isalpha(static_cast<unsigned char>(ch)) != 0; };
    for (std::size_t k = text.find(name); k != std::string::npos; k = text.find(name, k + 1)) {
        const bool starts = k == 0 || !letter(text[k - 1]) || name[0] == '\\';
        const bool ends = k + name.size() >= text.size() || !letter(text[k + name.size()]) || !letter(name.back());
        if (starts && ends) return true;
    }
    return false;
}

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

}  // namespace

std::string ordinal(int order) {
    switch (order) {
        case 1:
            return "first";
        case 2:
            return "second";
        case 3:
            return "third";
        default:
            return std::to_string(order) + "th";
    }
}

std::vector<std::size_t> small_coordinates_in_prose(const Derivation& d, std::size_t at, const Model& model,
                                                    const ExpansionPoints& points) {
    const std::string& s = d.text;
    if (at > s.size()) return {};
    std::size_t begin = s.rfind("\n\n", at);
    begin = begin == std::string::npos ? 0 : begin;
    std::size_t end = s.find("\n\n", at);
    end = end == std::string::npos ? s.size() : end;
    const std::string window = lower(s.substr(begin, end - begin));
    std::vector<std::size_t> out;
    for (std::size_t k = window.find("small"); k != std::string::npos; k = window.find("small", k + 5)) {
        const std::string after = window.substr(k + 5, 40);
        if (after.find("oscillation") != std::string::npos || after.find("angle") != std::string::npos ||
            after.find("amplitude") != std::string::npos) {
            for (std::size_t i = 0; i < model.coordinates.size(); ++i) out.push_back(i);
            break;
        }
        // "with $\rho$ and $\theta$ small": the names before it in its clause, as whole names.
        std::size_t from = k > 60 ? k - 60 : 0;
        for (const char* stop : {". ", ";", ":", "\n"})
            if (const std::size_t at_stop = window.rfind(stop, k); at_stop != std::string::npos && at_stop >= from)
                from = at_stop + 1;
        const std::string before = window.substr(from, k - from);
        for (std::size_t i = 0; i < model.coordinates.size(); ++i) {
            const Coordinate& c = model.coordinates[i];
            const std::string deviation = i < points.deviation.size() ? lower(points.deviation[i]) : "";
            for (const std::string& spelled : {lower(c.latex), lower(c.name), deviation})
                if (!spelled.empty() && (names(after, spelled) || names(before, spelled)) &&
                    std::find(out.begin(), out.end(), i) == out.end())
                    out.push_back(i);
        }
    }
    // "linearizing about $\theta = 0$": the coordinates it names at 0 are small (every coordinate when it names none).
    for (const char* cue : {"lineariz", "linearis"}) {
        const std::size_t k = window.find(cue);
        if (k == std::string::npos) continue;
        const std::string after = window.substr(k, 60);
        const std::size_t about = std::min(after.find("about"), after.find("around"));
        bool named = false;
        if (about != std::string::npos)
            for (std::size_t i = 0; i < model.coordinates.size(); ++i) {
                const Coordinate& c = model.coordinates[i];
                for (const std::string& spelled : {lower(c.latex), lower(c.name)}) {
                    const std::size_t at_name = spelled.empty() ? std::string::npos : after.find(spelled, about);
                    if (at_name == std::string::npos) continue;
                    std::string rest = after.substr(at_name + spelled.size(), 8);
                    rest.erase(std::remove(rest.begin(), rest.end(), ' '), rest.end());
                    if (rest.rfind("=0", 0) != 0) continue;
                    named = true;
                    if (std::find(out.begin(), out.end(), i) == out.end()) out.push_back(i);
                }
            }
        if (!named && about == std::string::npos)
            for (std::size_t i = 0; i < model.coordinates.size(); ++i)
                if (std::find(out.begin(), out.end(), i) == out.end()) out.push_back(i);
    }
    return out;
}

std::optional<std::size_t> small_motion_stated_before(const Derivation& d, std::size_t at) {
    const std::string s = lower(d.text.substr(0, std::min(at, d.text.size())));
    for (std::size_t k = s.find("small"); k != std::string::npos; k = s.find("small", k + 5)) {
        const std::string after = s.substr(k + 5, 24);
        for (const char* what : {"oscillation", "angle", "amplitude", "vibration", "displacement"})
            if (after.find(what) != std::string::npos) return k;
    }
    // "approximating $\sin(\varphi) = \varphi$", "with the approximation $\sin\theta \approx \theta$": the text makes
    // the angle small from there on.
    for (std::size_t k = s.find("approximat"); k != std::string::npos; k = s.find("approximat", k + 10)) {
        const std::string after = s.substr(k + 10, 40);
        for (const char* trig : {"sin", "cos", "tan"})
            if (after.find(trig) != std::string::npos) return k;
    }
    return std::nullopt;
}

ApproxVerdict compare_approximation(const GiNaC::ex& a, const GiNaC::ex& b, int reference_side, const Model& model,
                                    const std::vector<GiNaC::ex>& motion, const std::vector<std::size_t>& small,
                                    const std::function<bool(const GiNaC::ex&, const GiNaC::ex&)>& same,
                                    const ExpansionPoints& points) {
    ApproxVerdict v;
    if (small.empty()) return v;
    const GiNaC::symbol eps("__eps");
    GiNaC::exmap scale, at_zero;
    bool own_point = false;
    for (std::size_t i : small) {
        const Coordinate& c = model.coordinates[i];
        const GiNaC::ex p = points.point(i);
        scale[c.q] = p + eps * (c.q - p);
        scale[c.qd] = eps * c.qd;
        scale[c.qdd] = eps * c.qdd;
        at_zero[c.q] = p;
        at_zero[c.qd] = 0;
        own_point = own_point || points.own_point(i);
    }
    // The reference's terms of order 0 are left out where the text, about a point of its own, writes none.
    const auto leave_out_order_0 = [&](const GiNaC::ex& text_scaled) {
        if (!own_point) return false;
        const auto t0 = taylor(text_scaled, eps, 0);
        return t0 && same(*t0, 0);
    };
    const GiNaC::ex A = a.subs(scale), B = b.subs(scale);
    int k = std::max(polynomial_degree(A, eps), polynomial_degree(B, eps));
    // `\cos\alpha \approx 1`: a constant for a function of small coordinates holds to first order (its first-order
    // terms vanish), the order such approximations are made to.
    if (k == 0 && (A - B).has(eps)) k = 1;
    if (k <= 0 || k > 6) return v;
    const auto R = taylor(A - B, eps, k);
    if (!R) return v;
    v.applies = true;
    v.order = k;
    v.text = *R;
    const bool drop_0 = leave_out_order_0(A - B);
    // The lowest order at which x and y differ (x, y scaled), or 0.
    auto first_difference = [&](const GiNaC::ex& x, const GiNaC::ex& y) {
        for (int o = drop_0 ? 1 : 0; o <= k; ++o) {
            const auto tx = taylor(x, eps, o), ty = taylor(y, eps, o);
            if (!tx || !ty || !same(*tx, *ty)) return o;
        }
        return 0;
    };
    if (same(*R, 0)) {
        v.agrees = true;
        return v;
    }
    bool accelerations = false;
    for (const Coordinate& c : model.coordinates) accelerations = accelerations || R->has(c.qdd);
    if (accelerations) {
        // c·EL_i to order k, c constant: the ratio of the q̈_i coefficients at q = 0. The equation whose
        // acceleration the text has, the best match first.
        std::size_t closest = 0;
        for (std::size_t i = 0; i < motion.size(); ++i) {
            const GiNaC::symbol& qdd = model.coordinates[i].qdd;
            if (!R->has(qdd)) continue;
            GiNaC::ex E = motion[i].subs(scale);
            if (drop_0)
                if (const auto E0 = taylor(E, eps, 0)) E = E - *E0;
            const auto Ek = taylor(E, eps, k);
            if (!Ek) continue;
            GiNaC::ex c;
            try {
                const std::optional<GiNaC::ex> den_at = subs_unless_pole(GiNaC::diff(*Ek, qdd), at_zero),
                                               num_at = subs_unless_pole(GiNaC::diff(*R, qdd), at_zero);
                if (!den_at || !num_at) continue;
                const GiNaC::ex den = den_at->expand();
                if (den.is_zero()) continue;
                c = GiNaC::normal(*num_at / den);
            } catch (const std::exception&) {
                continue;
            }
            const GiNaC::ex ref = (c * *Ek).expand();
            // The equation it is closest to (the fewest terms apart), when it agrees with none.
            const GiNaC::ex apart = (*R - ref).expand();
            const std::size_t distance = GiNaC::is_a<GiNaC::add>(apart) ? apart.nops() : (apart.is_zero() ? 0 : 1);
            if (v.equation < 0 || distance < closest || same(*R, ref)) {
                v.equation = int(i);
                v.reference = ref;
                v.wrong_order = first_difference((A - B), c * E);
                v.dropped_order_0 = drop_0;
                closest = distance;
            }
            if (same(*R, ref)) {
                v.agrees = true;
                return v;
            }
        }
        // One acceleration alone, the others eliminated (θ̈ ≈ −(M+m)g θ/(M l) for a pendulum on a free cart): q̈_i
        // solved from the equations, expanded. (Up to 4 coordinates, where the symbolic solve is cheap.)
        std::size_t only = motion.size(), count = 0;
        for (std::size_t i = 0; i < motion.size(); ++i)
            if (R->has(model.coordinates[i].qdd)) {
                only = i;
                ++count;
            }
        if (count == 1 && motion.size() >= 2 && motion.size() <= 4) {
            try {
                const unsigned n = static_cast<unsigned>(motion.size());
                GiNaC::matrix Mm(n, n), rhs(n, 1);
                GiNaC::exmap no_acc;
                for (const Coordinate& c : model.coordinates) no_acc[c.qdd] = 0;
                for (unsigned i = 0; i < n; ++i) {
                    for (unsigned j = 0; j < n; ++j) Mm(i, j) = GiNaC::diff(motion[i], model.coordinates[j].qdd);
                    rhs(i, 0) = -motion[i].subs(no_acc);
                }
                const std::optional<GiNaC::ex> solved_at = solved_unknown(Mm, rhs, unsigned(only));
                if (!solved_at) throw std::runtime_error("singular");
                const GiNaC::ex solved = *solved_at;
                const GiNaC::symbol& qdd = model.coordinates[only].qdd;
                GiNaC::ex E = (qdd - solved).subs(scale);
                if (drop_0)
                    if (const auto E0 = taylor(E, eps, 0)) E = E - *E0;
                if (const auto Ek = taylor(E, eps, k)) {
                    const std::optional<GiNaC::ex> c_at = subs_unless_pole(GiNaC::diff(*R, qdd), at_zero);
                    if (!c_at) throw std::runtime_error("pole");
                    const GiNaC::ex c = GiNaC::normal(*c_at);
                    const GiNaC::ex ref = (c * *Ek).expand();
                    // The text eliminated the other accelerations: this is what it should be, right or wrong.
                    v.equation = int(only);
                    v.solved = true;
                    v.dropped_order_0 = drop_0;
                    v.reference = ref;
                    v.wrong_order = first_difference((A - B), c * E);
                    if (same(*R, ref)) {
                        v.agrees = true;
                        return v;
                    }
                }
            } catch (const std::exception&) {
            }
        }
        return v;
    }
    if (reference_side == 0 || reference_side == 1) {
        const GiNaC::ex ref = reference_side == 0 ? A : B, text = reference_side == 0 ? B : A;
        const auto rk = taylor(ref, eps, k), tk = taylor(text, eps, k);
        if (rk && tk) {
            v.text = *tk;
            v.reference = *rk;
            v.wrong_order = first_difference(text, ref);
        }
    }
    return v;
}

bool check_approximation(const Derivation& d, const Model& model, const std::vector<GiNaC::ex>& motion, std::size_t at,
                         const std::pair<std::string, std::string>& sources, const GiNaC::ex& a, const GiNaC::ex& b,
                         int reference_side, bool implied, Comparisons& cmp, EquationCheck& r,
                         const ExpansionPoints& points) {
    std::vector<std::size_t> small = small_coordinates_in_prose(d, at, model, points);
    std::string said = small.empty() ? "" : " (the text says it is small)";
    // "… makes small oscillations" in the statement of the problem: what it derives after is about them.
    if (small.empty() && !implied)
        if (const std::optional<std::size_t> cue = small_motion_stated_before(d, at)) {
            for (std::size_t k = 0; k < model.dof(); ++k) small.push_back(k);
            said = " (the text says on line " + std::to_string(d.position(*cue).line) + " that the motion is small)";
        }
    // `\ddot\eta = -\omega^2\sin^2\alpha_0\,\eta` after "writing α = α₀ + η": written in the deviation from a point,
    // an expansion about it.
    if (small.empty())
        for (std::size_t k = 0; k < model.dof() && k < points.deviation.size(); ++k)
            if (!points.deviation[k].empty() && (sources.first.find(points.deviation[k]) != std::string::npos ||
                                                 sources.second.find(points.deviation[k]) != std::string::npos))
                small.push_back(k);
    if (small.empty() && implied)  // implied: every coordinate the equation holds
        for (std::size_t k = 0; k < model.dof(); ++k)
            if ((a - b).has(model.coordinates[k].q) || (a - b).has(model.coordinates[k].qd)) small.push_back(k);
    const ApproxVerdict v = compare_approximation(
        a, b, reference_side, model, motion, small,
        [&](const GiNaC::ex& x, const GiNaC::ex& y) { return cmp.same(x, y, 1e-9); }, points);
    if (!v.applies) return false;
    auto m = [](const std::string& latex) { return "$" + latex + "$"; };
    std::string vars, point;
    for (std::size_t k : small) {
        const bool moved = k < points.deviation.size() && !points.deviation[k].empty();
        vars += (vars.empty() ? "" : ", ") + m(moved ? points.deviation[k] : model.coordinates[k].latex);
        point += (point.empty() ? "" : ", ") + model.coordinates[k].latex + " = " + (moved ? points.latex[k] : "0");
    }
    const std::string about = " about " + m(point) + said;
    if (v.agrees || !v.reference.is_zero() || v.equation >= 0)
        r.compared_with = v.equation >= 0 ? (v.solved ? m("\\ddot{" + model.coordinates[std::size_t(v.equation)].latex + "}") +
                                                             " solved from the Euler–Lagrange equations, expanded"
                                                       : "the Euler–Lagrange equation for " +
                                                             m(model.coordinates[std::size_t(v.equation)].latex) +
                                                             ", expanded") +
                                                about
                                          : "the Taylor expansion" + about;
    if (v.dropped_order_0)
        r.notes.push_back("the terms of order 0 left out: the text writes none, taking its point where they vanish "
                          "(an equilibrium)");
    if (v.agrees) {
        r.verdict = Verdict::Agrees;
        r.reason = "agrees to " + ordinal(v.order) + " order in " + vars;
        return true;
    }
    if (v.reference.is_zero() && v.equation < 0) return false;  // nothing to say what it should be
    r.verdict = Verdict::Disagrees;
    r.reason = "disagrees at " + ordinal(std::max(v.wrong_order, 1)) + " order in " + vars +
               " (the text keeps order " + std::to_string(v.order) + ")";
    // In the text's deviations where it writes them (`\tilde\phi` for φ − φ₀).
    const auto shown = [&](const GiNaC::ex& e) { return points.in_text.empty() ? e : e.subs(points.in_text).expand(); };
    const GiNaC::ex text = shown(v.text), reference = shown(v.reference);
    r.difference = cmp.latex((text - reference).expand());
    r.wrong_terms = cmp.wrong_terms(text, reference, 1e-9);
    r.corrected = v.equation >= 0 ? cmp.latex(reference) + " \\approx 0"
                                  : (reference_side == 0 ? sources.first : sources.second) + " \\approx " +
                                        cmp.latex(reference);
    return true;
}

}  // namespace eomgen::checker
