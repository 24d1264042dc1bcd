/** @file cartesian_reading.cpp  A second reading of a link that is not comparable for the text's Cartesian x and y,
 * in a model of polar (or cylindrical) coordinates: x = r cos φ, y = r sin φ, where the text does not define them
 * (the paraboloid's constraint x² + y² = a z, and m ÿ = 2 y λ). The convention of the angle is a guess, so the
 * reading is taken only where it makes the link agree; otherwise the link stays not comparable, as before. */
#include "checker/checker_internals.hpp"

namespace eomgen::checker::detail {

namespace {

bool named(const Coordinate& q, std::initializer_list<const char*> names) {
    for (const char* n : names)
        if (q.name == n) return true;
    return false;
}

}  // namespace

void Checker::check_cartesian_reading(const FullChain& c, std::size_t i, std::size_t j, bool bridge, EquationCheck& r) {
    const Coordinate *radial = nullptr, *angle = nullptr;
    int angles = 0;
    for (const Coordinate& q : model_.coordinates) {
        if (named(q, {"x", "y"})) return;  // the model's own x or y
        if (named(q, {"r", "rho"})) radial = &q;
        if (named(q, {"phi", "varphi", "theta"})) {
            angle = &q;
            ++angles;
        }
    }
    if (!radial || angles != 1) return;  // spherical (θ and φ) or no polar pair: which angle would be a guess
    const std::size_t at = c.relation_offsets[j - 1];
    std::vector<std::pair<const FreeName*, GiNaC::ex>> cartesian;
    for (const auto& [name, value] : {std::pair<const char*, GiNaC::ex>{"x", radial->q * GiNaC::cos(angle->q)},
                                      std::pair<const char*, GiNaC::ex>{"y", radial->q * GiNaC::sin(angle->q)}}) {
        const auto f = ctx_.free_names.find(name);
        if (f == ctx_.free_names.end() || f->second.kind != NameKind::Unknown) continue;
        if (definitions_.value_at(f->second.symbol, at)) return;  // the text's own x
        cartesian.emplace_back(&f->second, value);
    }
    if (cartesian.empty()) return;
    // The attempt leaves nothing behind but its verdict when it agrees (as the forward reading, definition_uses.cpp).
    const TextDefinitions saved = definitions_;
    const std::size_t blames = blames_.size(), disagreeing = disagreeing_uses_.size();
    const int sign = multiplier_sign_, sign_line = multiplier_sign_line_;
    const std::string sign_section = multiplier_sign_section_;
    const int line = d_.position(at).line;
    for (const auto& [f, value] : cartesian) definitions_.add(f->symbol, f->name, value, 0, line);
    EquationCheck cart = safe_check_link(c, i, j, bridge);
    definitions_ = saved;
    blames_.resize(blames);
    disagreeing_uses_.resize(disagreeing);
    if (cart.verdict != Verdict::Agrees) {
        multiplier_sign_ = sign;
        multiplier_sign_line_ = sign_line;
        multiplier_sign_section_ = sign_section;
        return;
    }
    // Its own note instead of the definitions' ("using $x = …$ (line n)"), which the text does not make.
    cart.notes.erase(std::remove_if(cart.notes.begin(), cart.notes.end(),
                                    [](const std::string& n) {
                                        return n.rfind("using $x = ", 0) == 0 || n.rfind("using $y = ", 0) == 0 ||
                                               n.find("$x$ as the text defines it") != std::string::npos ||
                                               n.find("$y$ as the text defines it") != std::string::npos;
                                    }),
                     cart.notes.end());
    const std::string r_ = m(radial->latex), a_ = m(angle->latex);
    cart.notes.push_back("with the text's Cartesian $x = " + radial->latex + " \\cos " + angle->latex + "$, $y = " +
                         radial->latex + " \\sin " + angle->latex + "$ in the model's polar coordinates " + r_ + ", " +
                         a_ + " (the text does not define x and y; read so only because the line then holds)");
    r = std::move(cart);
}

}  // namespace eomgen::checker::detail
