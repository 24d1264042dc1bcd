/** @file named_constants.cpp  A quantity of the motion set equal to a name the text introduces there:
 * `\rho^2\dot\varphi = c_0`, `m r^2 \dot\theta = l`, `\frac12 m v^2 + \dots = C`. The name stands for that quantity
 * in the rest of its section (`\dot\theta = \frac{l}{m r^2}` is then compared), and the row itself says that the
 * quantity is conserved when the model's equations of motion make it so; otherwise it is the text's name for it,
 * a definition, and nothing is claimed. */
#include "checker/additive_constant.hpp"
#include "checker/checker_internals.hpp"

#include <map>
#include <optional>

namespace eomgen::checker::detail {

namespace {

/// True when `e` holds a velocity of the model and is more than one velocity alone (`\dot\varphi = \omega` names a
/// rate the text chooses; `\rho^2 \dot\varphi = c_0` names a quantity of the motion).
bool quantity_of_motion(const GiNaC::ex& e, const Model& model) {
    bool velocity = false;
    for (const Coordinate& q : model.coordinates) {
        if (e.is_equal(q.qd)) return false;
        velocity = velocity || e.has(q.qd);
    }
    return velocity;
}

}  // namespace

std::optional<Checker::IntroducedName> Checker::introduced_name(const PSide& side) {
    if (!side.side->ok) return std::nullopt;
    // `= c_0`: the name alone.
    if (GiNaC::is_a<GiNaC::symbol>(side.side->value)) {
        const FreeName* f = ctx_.free_name_of(side.side->value);
        if (!f || f->kind != NameKind::Unknown || is_part(side.side->value) || is_constant_name(f->name))
            return std::nullopt;
        return IntroducedName{side.side->value, f, 1};
    }
    // `= I_3\omega_3`: the name times a factor the checker can evaluate, the only name in the side it does not know.
    const Prepared p = prepare(side);
    if (!p.ok || p.unknown.size() != 1 || !p.vectors.empty() || !p.units.empty() || p.has_part) return std::nullopt;
    const FreeName* f = p.unknown.front();
    if (is_part(f->symbol) || is_constant_name(f->name)) return std::nullopt;
    const GiNaC::ex name = f->symbol;
    const GiNaC::ex factor = p.value.diff(GiNaC::ex_to<GiNaC::symbol>(name));
    if (factor.has(name) || !(p.value - factor * name).expand().is_zero() || factor.is_zero()) return std::nullopt;
    return IntroducedName{name, f, factor};
}

void Checker::collect_named_constants(const std::vector<FullChain>& chains) {
    // Where the text first writes each name (math alone too: "a circular orbit of radius $r_0$").
    std::map<std::string, std::size_t> first_use;
    for (const FullChain& c : chains)
        for (const PSide& s : c.sides)
            for (const NameUse& u : s.side->uses) {
                const auto it = first_use.find(u.name);
                if (it == first_use.end() || s.base + u.offset < it->second) first_use[u.name] = s.base + u.offset;
            }
    for (const FullChain& c : chains) {
        if (c.sides.size() < 2) continue;
        // The last side (`\rho^2\dot\varphi = c_0`), or the one before a last that says it is constant
        // (`p_\psi = I_3(\dot\psi + \dot\phi\cos\theta) = I_3\omega_3 = \text{const}`).
        std::size_t k = c.sides.size() - 1;
        if (k >= 2 && c.sides[k].side->ok && GiNaC::is_a<GiNaC::symbol>(c.sides[k].side->value))
            if (const FreeName* g = ctx_.free_name_of(c.sides[k].side->value); g && is_constant_name(g->name)) --k;
        if (c.relations[k - 1] != Relation::Equal) continue;
        const PSide& last = c.sides[k];
        const std::optional<IntroducedName> named = introduced_name(last);
        if (!named) continue;
        const GiNaC::ex name = named->symbol;
        const FreeName* f = named->name;
        const std::size_t at = last.base + last.side->begin;
        // A name times a factor is introduced only where the text first writes it (`m k r_0` after "of radius
        // $r_0$" is a claim about that radius, not its name for ℓ²/(mk)).
        if (!named->factor.is_equal(1))
            if (const auto it = first_use.find(f->name); it != first_use.end() && it->second < at) continue;
        // A use of a name the text defined otherwise; but `= C` again, after an earlier `= C`, is the text's
        // constant once more (another quantity said to be conserved, or the same one approximated).
        bool again = false;
        for (const auto& [offset, known] : named_constants_) again = again || known == f->name;
        // (Or defined in an earlier section: `… = F_x` after a section "Forces" that gave F_x.)
        definitions_.set_backward(true);
        const bool defined = definitions_.value_at(name, at) != nullptr;
        definitions_.set_backward(false);
        if (defined && !again) continue;
        const PSide& quantity = c.sides[k - 1];
        const Prepared p = prepare(quantity);
        if (!p.comparable() || !p.units.empty() || p.value.has(name) || !quantity_of_motion(p.value, model_)) continue;
        const std::size_t until = c.section >= 0 ? d_.sections[std::size_t(c.section)].end : std::string::npos;
        const bool alone = named->factor.is_equal(1);
        const GiNaC::ex value = alone ? p.value : GiNaC::ex(p.value / named->factor);
        const std::string source = alone ? quantity.side->source : latex(value);
        definitions_.add(name, f->name, value, at, d_.position(at).line, until, source, at,
                         conserved_on_motion(value));
        named_constants_[at] = f->name;
    }
}

bool Checker::check_named_constant(const PSide& quantity, const PSide& name, const Prepared& value, double tol,
                                   EquationCheck& r) {
    const auto it = named_constants_.find(name.base + name.side->begin);
    if (it == named_constants_.end() || !value.comparable()) return false;
    EquationCheck conserved = r;
    check_additive_constant(value.value, 0, 1, model_, *this, tol, conserved);
    if (conserved.verdict == Verdict::Agrees) {
        r = std::move(conserved);
        r.reason += " (the text names its value " + m(it->second) + ")";
    } else {
        r.verdict = Verdict::NotComparable;
        r.compared_with = "";
        r.reason = "a definition: the text's name " + m(it->second) + " for $" + quantity.side->source +
                   "$ for the rest of its section; its time derivative does not vanish on the equations of motion "
                   "(if it is meant as a constant, it is not one of this model's motion)";
    }
    return true;
}

bool Checker::up_to_constant(Prepared& a, Prepared& b, double tol, EquationCheck& r) {
    // `V(x_1, x_2) = k x_1^2 + \dots + f`: a name the text never defines, added alone (±) to a potential, a
    // Lagrangian or an energy (quantities defined up to a constant), is that constant.
    for (auto [truth, other] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
        if (!truth->has_truth_label || !truth->comparable() || other->unknown.empty() || !other->vectors.empty())
            continue;
        bool defined_up_to_constant = false;
        for (const GiNaC::ex& q : {eq_.V, eq_.L, eq_.energy})
            defined_up_to_constant = defined_up_to_constant || equal(truth->value, q, 1e-9) == Tri::Yes;
        if (!defined_up_to_constant) continue;
        std::vector<const FreeName*> still;
        for (const FreeName* f : other->unknown) {
            const GiNaC::ex slope = GiNaC::diff(other->value, f->symbol).expand();
            if (names_a_constant(f->name) && (slope.is_equal(1) || slope.is_equal(-1))) {
                other->constants.push_back(f->symbol);
                r.notes.push_back("reads $" + f->name + "$, added alone, as the additive constant");
            } else {
                still.push_back(f);
            }
        }
        other->unknown = std::move(still);
    }
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

}  // namespace eomgen::checker::detail
