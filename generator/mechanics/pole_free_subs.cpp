/** @file pole_free_subs.cpp  Substituting values without dividing by zero inside GiNaC (pole_free_subs.hpp). */
#include "mechanics/pole_free_subs.hpp"

#include <exception>

namespace eomgen {

bool subs_divides_by_zero(const GiNaC::ex& e, const GiNaC::exmap& m, unsigned options) {
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (subs_divides_by_zero(e.op(i), m, options)) return true;
    if (!GiNaC::is_a<GiNaC::power>(e) || !e.op(1).info(GiNaC::info_flags::negative)) return false;
    try {
        return e.op(0).subs(m, options).expand().is_zero();
    } catch (const std::exception&) {
        return true;
    }
}

std::optional<GiNaC::ex> subs_unless_pole(const GiNaC::ex& e, const GiNaC::exmap& m, unsigned options) {
    if (subs_divides_by_zero(e, m, options)) return std::nullopt;
    try {
        return e.subs(m, options);
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

}  // namespace eomgen
