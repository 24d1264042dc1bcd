/** @file time_dependence.cpp  ∂e/∂t ≡ 0, after the given parameter values. */
#include "mechanics/time_dependence.hpp"

#include "mechanics/lagrangian.hpp"

namespace eomgen {

bool depends_on_time(const GiNaC::ex& e, const Model& model, const GiNaC::exmap& fixed) {
    const GiNaC::ex at = fixed.empty() ? e : e.subs(fixed, GiNaC::subs_options::no_pattern);
    if (!at.has(model.t)) return false;
    return !is_zero(GiNaC::diff(at, model.t), model);
}

std::optional<GiNaC::ex> without_time(const GiNaC::ex& e, const Model& model, const GiNaC::exmap& fixed) {
    if (!e.has(model.t)) return e;
    const GiNaC::exmap t0{{model.t, 0}};
    if (!depends_on_time(e, model)) return e.subs(t0, GiNaC::subs_options::no_pattern);
    if (fixed.empty() || depends_on_time(e, model, fixed)) return std::nullopt;
    return e.subs(fixed, GiNaC::subs_options::no_pattern).subs(t0, GiNaC::subs_options::no_pattern);
}

}  // namespace eomgen
