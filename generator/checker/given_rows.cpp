/** @file given_rows.cpp  Rows that give rather than claim: an instant the text considers (`t = 0`, `t = t_c`), a
 * coordinate's initial value it picks (`x_0 = 1`), and T split into named parts not all of which it gives a value
 * (`T = T_C + T_P`). Each is not judged, with its role (issue 28). */
#include "checker/checker_internals.hpp"

namespace eomgen::checker::detail {

bool Checker::given_value(const Prepared& a, const Prepared& b, EquationCheck& r) {
    if (names_an_instant(a.value, b.value, model_)) {  // conditions.hpp
        not_judged(r, Role::Condition, "an instant the text considers, not an equation of the motion");
        return true;
    }
    for (const auto& [name, value] : {std::pair(a.value, b.value), std::pair(b.value, a.value)})
        if (const FreeName* f = GiNaC::is_a<GiNaC::symbol>(name) ? ctx_.free_name_of(name) : nullptr;
            f && sets_initial_value(f->name, value, model_)) {
            // (The name is the coordinate's with `_{0}`, or it or its rate with `(0)`.)
            const bool at_zero = f->name.size() > 3 && f->name.compare(f->name.size() - 3, 3, "(0)") == 0;
            not_judged(r, Role::ChosenValue, "a value the text chooses: the initial value of " +
                                                 m(f->name.substr(0, f->name.size() - (at_zero ? 3 : 4))));
            return true;
        }
    return false;
}

bool Checker::names_parts(const PSide& L, const PSide& R, EquationCheck& r, bool valued) {
    const auto part_sum = [&](const PSide& x) {
        if (!x.side->ok || !GiNaC::is_a<GiNaC::add>(x.side->value)) return false;
        for (std::size_t q = 0; q < x.side->value.nops(); ++q)
            if (!is_part(x.side->value.op(q))) return false;
        return true;
    };
    const auto label = [&](const PSide& x) { return x.side->ok && truth_.count(x.side->value) != 0; };
    const bool right = part_sum(R) && label(L);
    if (!right && !(part_sum(L) && label(R))) return false;
    const PSide& whole = right ? L : R;
    const PSide& parts = right ? R : L;
    r.compared_with.clear();
    // (With every part given a value, a sum that misses eomgen's is a wrong part: judged where the text gives it.)
    not_judged(r, Role::Definition, "a definition: the text splits " + m(trimmed(whole.side->source)) +
                                        " into the parts " + m(trimmed(parts.side->source)) +
                                        (valued ? ", each judged where the text gives its value"
                                                : ", not all of which it gives a value"));
    return true;
}

std::optional<GiNaC::ex> Checker::expected_part(const GiNaC::ex& part) const {
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

}  // namespace eomgen::checker::detail
