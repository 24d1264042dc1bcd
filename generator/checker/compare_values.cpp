/** @file compare_values.cpp  The comparisons of one link a = b, in their order: an identity, an equation of motion
 * (with or without multipliers, on the motion the text considers), an integral of motion, a constraint, and what
 * it disagrees with when none holds (compare_link.cpp calls it). */
#include "checker/checker_internals.hpp"

namespace eomgen::checker::detail {

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

    // The exponent of `\varphi = e^{\lambda t}`: the characteristic equation about rest, and its roots.
    if (const ExponentialTrial* trial = discourse_->exponential_at(c.relation_offsets[j - 1]);
        trial && a.vectors.empty() && b.vectors.empty() && a.units.empty() && b.units.empty() &&
        !depends_on_state(a.value) && !depends_on_state(b.value) && !has_acceleration(a.value) &&
        !has_acceleration(b.value) && (a.value - b.value).has(trial->exponent) &&
        std::all_of(a.unknown.begin(), a.unknown.end(), [&](const FreeName* f) { return trial->exponent.is_equal(f->symbol); }) &&
        std::all_of(b.unknown.begin(), b.unknown.end(), [&](const FreeName* f) { return trial->exponent.is_equal(f->symbol); }))
        if (const std::optional<GiNaC::ex> p = characteristic_polynomial(motion_, model_, trial->exponent);
            p && check_characteristic(a.value, b.value, *trial, *p, *this, r))
            return;
    // The amplitudes of a trial solution (`x_j = A_j e^{i\omega t}`): rows of (K − ω² M) A = 0. After a normal
    // frequency, `A_2 = \sqrt{2} A_1` with none written: the names with the coordinates' subscripts are the amplitudes.
    const std::optional<GiNaC::ex> stated = discourse_->stated_frequency(c.relation_offsets[j - 1]);
    std::optional<TrialSolution> implied;
    const TrialSolution* trial = discourse_->trial_at(c.relation_offsets[j - 1]);
    const auto about_modes = [&] {  // "For the slower mode the amplitudes are in the ratio"
        const std::string prose = lead_in(d_, L.base + L.side->begin, 2);
        return prose.find("mode") != std::string::npos || prose.find("amplitude") != std::string::npos;
    };
    if (!trial && (stated || about_modes())) {
        std::vector<const FreeName*> names = a.unknown;
        names.insert(names.end(), b.unknown.begin(), b.unknown.end());
        if ((implied = implied_amplitudes(names, model_))) trial = &*implied;
    }
    if (trial && a.vectors.empty() && b.vectors.empty() && a.units.empty() && b.units.empty()) {
        // `m_1 = m_2 = m`: the frequencies and corrections in the text's terms, each in its last name.
        GiNaC::exmap assumed = parameter_assumptions(c.relation_offsets[j - 1]);
        for (int round = 0; round < 3; ++round)
            for (auto& [symbol, value] : assumed) value = value.subs(assumed);
        amplitudes_.assume(assumed);
        const bool judged = amplitudes_.check(a.value, b.value, L.side->source, R.side->source, written_names(L, R),
                                              *trial, stated, ctx_, *this, r);
        amplitudes_.assume({});
        if (judged) return;
    }
    // `… = l_2 - y_3 \Rightarrow y_3 = …`, `\Rightarrow m = -\frac{m_3}{4}`: a name the text solves for from the
    // relation before (implication.cpp), a definition or a name an assumption made known (the common value).
    if (i == 0 && L.side->ok && b.ok && b.vectors.empty() && GiNaC::is_a<GiNaC::symbol>(L.side->value))
        if (const FreeName* f = ctx_.free_name_of(L.side->value);
            f && after_implication(c) && check_implied_definition(c, i, j, L.side->value, f->name, b.value, r))
            return;
    // `t = 0`, `x_0 = 1`: an instant, an initial value (given_rows.cpp).
    if (given_value(a, b, r)) return;
    // `x_2 = x + l\sin\theta`: a coordinate of a point the model gives (point_positions.cpp).
    if (check_position(c, j, false, r)) return;
    // `s(t) = s_0\cos(\omega t)`: a solution the text claims for a coordinate, put into its equation of motion.
    if (a.vectors.empty() && b.vectors.empty() && a.units.empty() && b.units.empty()) {
        ClaimedMotion claim;
        if (check_claimed_solution(a.value, b.value, model_, eq_, motion_, ctx_, *this, r,
                                   discourse_->stated_frequencies(c.relation_offsets[j - 1]), &claim)) {
            claim.line = r.where.line;
            claim.source = L.side->source + " = " + R.side->source;
            claim.from = c.relation_offsets[j - 1];
            claim.until = c.section >= 0 ? d_.sections[std::size_t(c.section)].end : std::string::npos;
            claimed_motions_.push_back(std::move(claim));
            return;
        }
    }
    // `\rho^2\dot\varphi = c_0`, where the text introduces c_0 (named_constants.cpp).
    if (named_constants_.count(R.base + R.side->begin)) {
        // On a particular motion of the model ([[motions]]) the motion says which constant it is.
        if (a.vectors.empty() && b.vectors.empty() && a.units.empty() && b.units.empty() &&
            on_motion(c, i, j, a.value, b.value, tol, r))
            return;
        if (check_named_constant(L, R, a, tol, r)) return;
    }
    // `r_{eq} = l_0 + mg/k` at an equilibrium the text set up (equilibrium_values.cpp).
    if (check_value_at_point(L, R, a, b, tol, c.relation_offsets[j - 1], r)) return;
    // Free names: an identity still agrees, anything else cannot be judged.
    if (!a.comparable() || !b.comparable()) {
        // Vectors are not scalars: a×b = −b×a, so only identities in scalar unknowns are claimed.
        if (a.vectors.empty() && b.vectors.empty() && equal(a.value, b.value, tol) == Tri::Yes) {
            r.verdict = Verdict::Agrees;
            r.compared_with = "an identity";
            r.reason = "both sides are equal (in the text's own symbols)" + within;
            return;
        }
        // `T = T_C + T_P` with a part never given a value (given_rows.cpp).
        if (names_parts(L, R, r)) return;
        // `m_2 = m` in `m_1 = m_2 = m` (stated_names.cpp).
        if (names_common_value(c, j)) {
            not_judged(r, Role::Assumption,
                       "an assumption on the parameters, for the rest of its paragraph, that names their common value: "
                       "the equations that follow there are compared with it");
            return;
        }
        // `k = g/l`: a definition, used in the rest of its section (definitions.hpp), not a line of a motion.
        const std::string def = definitions_.defined_at(L.base + L.side->begin);
        if (def.empty() && a.vectors.empty() && b.vectors.empty() && a.units.empty() && b.units.empty() &&
            on_motion(c, i, j, a.value, b.value, tol, r))
            return;
        // `… = \lambda` with the s_0 of `s(t) = s_0\cos(\omega t)` before it: on the motion the text claimed.
        if (def.empty() && a.vectors.empty() && b.vectors.empty() && a.units.empty() && b.units.empty())
            if (const ClaimedMotion* claim =
                    claimed_motion_at(claimed_motions_, c.relation_offsets[j - 1], a.unknown, b.unknown);
                claim && check_on_claimed_motion(a.value, b.value, *claim, model_, eq_, multipliers_,
                                                 multiplier_sign_, *this, tol, r))
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
        auto join = [](const std::vector<std::string>& v) {
            std::string s;
            for (std::size_t k = 0; k < v.size(); ++k) s += (k ? ", " : "") + v[k];
            return s;
        };
        // A definition names its left side; what its value uses that the model does not know is said after it.
        // (A frequency the normal-mode check read as a claim and could not compare stays a claim.)
        // (One that explains the formula before it, "where $\omega^2 = k/m$", is the formula's abbreviation.)
        // (One its sentence introduces, "writing $\omega_0^2 = g/l$", is the text's name for what follows.)
        const auto frequency_note = [](const std::string& n) { return n.rfind("read as a normal frequency", 0) == 0; };
        const bool frequency_claim = !explains_formula_before(d_, L.base + L.side->begin) &&
                                     !introduces_name(d_, L.base + L.side->begin) &&
                                     std::any_of(r.notes.begin(), r.notes.end(), frequency_note);
        if (!def.empty() && !frequency_claim) {
            r.notes.erase(std::remove_if(r.notes.begin(), r.notes.end(), frequency_note), r.notes.end());
            describe(R, b);
            // ("lets $\ddot x = a_x$": the name it defines is no unknown of its value.)
            const std::string named = m(def.substr(0, def.find(" = ")));
            unknown.erase(std::remove_if(unknown.begin(), unknown.end(),
                                         [&](const std::string& u) { return u.rfind(named + " (", 0) == 0; }),
                          unknown.end());
            std::string reason = "a definition: the text's abbreviation $" + def + "$ for the rest of its " +
                                 (at_a_point_.count(L.base + L.side->begin)
                                      ? "paragraph (its value at the point the text considers)"
                                      : "section");
            if (!unknown.empty())
                reason += "; its value uses " + join(unknown) + ", which the model does not know";
            not_judged(r, Role::Definition, reason);
            definition_rows_[L.base + L.side->begin] = r.where;
            return;
        }
        describe(L, a);
        describe(R, b);
        if (!unknown.empty())
            r.reason = "unknown symbol" + std::string(unknown.size() > 1 ? "s " : " ") + join(unknown) +
                       ": not a symbol of the model (--map can say what it stands for)";
        else
            r.reason = "vector quantities (" + join(vectors) + ") are not compared";
        return;
    }
    // A number the text works out: units to SI, the parameters' values, its printed digits.
    if (check_number(a.value, b.value, {L.side->source, R.side->source}, c.relation_offsets[j - 1], model_, ctx_, d_,
                     parameter_values_, r))
        return;
    // A parameter the text set for this paragraph (`m_1 = 0`): the text's sides take it as eomgen's equations do
    // (the sample points hold it, Numbers::pin).
    // A condition stated again (`\theta = 0` at θ = 0) is not an identity: it is judged as the condition it is.
    const bool states_condition = discourse_->states_condition(c.relation_offsets[j - 1]);
    if (!numbers_.pinned().empty() && (states_condition || !condition_of(a.value, b.value, model_).empty()))
        numbers_.pin({});
    if (discourse_->states_assumption(c.relation_offsets[j - 1])) {
        not_judged(r, Role::Assumption,
                   "an assumption on the parameters, for the rest of its paragraph: the equations that follow there "
                   "are compared with it");
        return;
    }
    // `\dot r = \dot\theta` in `\dot r = \dot\theta = 0`: two quantities the chain sets to the value it ends with.
    if (states_condition && !has_acceleration(a.value - b.value) && condition_of(a.value, b.value, model_).empty()) {
        not_judged(r, Role::Condition,
                   "a condition: the point or motion the text considers, where both take the value its chain ends "
                   "with (not an equation of the motion, so not judged)");
        return;
    }
    // An acceleration the conditions of a motion set (`\ddot\theta = 0` after `\dot\theta = 0`).
    if (states_condition && has_acceleration(a.value - b.value) && condition_of(a.value, b.value, model_).empty()) {
        not_judged(r, Role::Condition,
                   "a condition: the acceleration of the motion the text considers (an equilibrium, a steady motion), "
                   "not an equation of the motion, so not judged");
        return;
    }
    if (!numbers_.pinned().empty()) {
        r.notes.insert(r.notes.end(), chosen_notes_.begin(), chosen_notes_.end());
        for (int round = 0; round < 3; ++round) {  // m_1 → m_2, m_2 → m
            a.value = subs_unless_pole(a.value, numbers_.pinned()).value_or(a.value);
            b.value = subs_unless_pole(b.value, numbers_.pinned()).value_or(b.value);
        }
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
    // 2a. With the multipliers written (compare_multipliers.cpp).
    if (check_multipliers(L, R, a.value, b.value, r_ex, tol, within, r)) return;
    // 2. An equation of motion: a combination of the Euler–Lagrange equations.
    if (has_acceleration(r_ex)) {
        int only = -1;
        std::string factor;
        std::vector<std::string> acting;
        // With the multipliers written (m ẍ = 2 x λ): the equations with the constraint forces, λ with eomgen's sign
        // (M q̈ = f + Aᵀλ, A from the constraint as the model writes it) or the opposite one.
        const bool with_lambda = std::any_of(multipliers_.begin(), multipliers_.end(),
                                             [&](const GiNaC::symbol& l) { return r_ex.has(l); });
        bool holds[2] = {false, false};
        for (int k = 0; k < 2 && with_lambda; ++k)
            holds[k] = euler_lagrange_combination(r_ex, std::max(tol, 1e-9), &only, &factor, nullptr, nullptr,
                                                  k == 0 ? 1 : -1) == Tri::Yes;
        for (int sign : {1, -1}) {
            if (!holds[sign > 0 ? 0 : 1]) continue;
            euler_lagrange_combination(r_ex, std::max(tol, 1e-9), &only, &factor, nullptr, nullptr, sign);
            if (!keeps_multiplier_sign(holds[0], holds[1], r)) {
                r.compared_with = "the Euler–Lagrange equations with the constraint forces";
                return;
            }
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
        // A side the text writes as the Euler–Lagrange expression of one coordinate (`\frac{\partial L}{\partial
        // \theta} - \frac{d}{dt}\frac{\partial L}{\partial \dot\theta}`, with eomgen's L or the text's own) is that
        // coordinate's: the other side must make that equation, not another one that also holds on the motion.
        int own = -1;
        const bool a_derived = a.has_truth_label || a.from_definition, b_derived = b.has_truth_label || b.from_definition;
        if (a_derived != b_derived) {
            const GiNaC::ex& written = a_derived ? a.value : b.value;
            for (std::size_t k = 0; k < model_.dof() && own < 0; ++k)
                if (equal(written, eq_.euler_lagrange[k], 1e-9) == Tri::Yes ||
                    equal(written, -eq_.euler_lagrange[k], 1e-9) == Tri::Yes)
                    own = int(k);
        }
        if (euler_lagrange_combination(r_ex, std::max(tol, 1e-9), &only, &factor, &acting) == Tri::Yes &&
            (own < 0 || only == own)) {
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
        if (const std::optional<bool> holds = holds_on_constrained_motion(r_ex, model_, eq_, tol, {}, 1, numbers_.pinned()); holds && *holds) {
            r.verdict = Verdict::Agrees;
            r.compared_with = "the equations of motion with the constraints";
            r.reason = "it holds on every motion: q'' from M q'' = f + A^T λ and the constraints, the constraint "
                       "forces eliminated (checked at sample states)" +
                       within;
            return;
        }
    }
    // 2c. On the motion the text considers (θ̇ = 0 and θ̈ = 0 stated before it): an Euler–Lagrange equation there,
    // times a factor free of the velocities (φ̇² = g/(l cos θ) for a conical pendulum).
    if (!has_acceleration(r_ex) && depends_on_state(r_ex))
        for (const auto& [symbol, value] : numbers_.pinned()) {
            if (!has_acceleration(symbol)) continue;
            for (std::size_t k = 0; k < model_.dof(); ++k) {
                const std::optional<GiNaC::ex> there = subs_unless_pole(motion_[k], numbers_.pinned());
                if (!there || equal(*there, 0, 1e-9) == Tri::Yes || has_acceleration(*there)) continue;
                GiNaC::ex factor;
                try {
                    factor = GiNaC::normal(*there / r_ex);
                } catch (...) {
                    continue;
                }
                if (has_velocity(factor) || has_acceleration(factor) || equal(factor, 0, 1e-9) == Tri::Yes) continue;
                r.verdict = Verdict::Agrees;
                r.compared_with = "the Euler–Lagrange equation for " + m(model_.coordinates[k].latex) +
                                  " on the motion the text considers";
                r.reason = "the same equation there, times a factor free of the velocities" + within;
                return;
            }
            break;
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
        if (const std::string w = lead_in_ends_with(d_, c.relation_offsets[j - 1], {"about", "around", "near"});
            !w.empty()) {
            r.reason = "the point the text expands about (“" + w +
                       "”), not a condition: the equations after it are compared to first order about it, not at it";
            return;
        }
        const std::string cue = condition_cue(d_, c.relation_offsets[j - 1]);
        not_judged(r, Role::Condition,
                   cue.empty() ? "a condition: the point or motion the text considers, where " + m(q) +
                                     " takes this value (not an equation of the motion, so not judged)"
                               : "a condition or a given value (after “" + cue +
                                     "”): it sets a value for what follows, not an equation of motion, and is not "
                                     "judged");
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
    if (check_derivative_of_definition(c, i, j, r)) return;  // `\dot{x_p} = …` after `x_p = …`
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
    // `\dot\phi \approx \frac{Mgl}{I_3\omega_3}` "for a fast top": an approximation that is no Taylor expansion
    // (approximation.cpp) holds on a motion and in a limit the text chose; a term it shares with the energy does
    // not make it a wrong energy.
    if (c.relations[j - 1] == Relation::Approx) {
        r.reason = "an approximation that is not an expansion in a small coordinate (the motion and the limit it "
                   "holds in are not read): not compared";
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
    // `I = m(kR)^2` where the symbol map says what the text's I stands for (stated_names.cpp).
    if (check_against_map(L, R, a, b, tol, r)) return;
    r.reason =
        "not an identity, and not an equation of this model (a condition or an assumption, such as a "
        "particular value)";
}

}  // namespace eomgen::checker::detail
