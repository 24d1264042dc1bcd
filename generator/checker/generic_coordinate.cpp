/** @file generic_coordinate.cpp  The Euler–Lagrange equation stated for a generic coordinate, as most texts state
 * it before using it (`\frac{d}{dt}\frac{\partial L}{\partial \dot q} - \frac{\partial L}{\partial q} = 0`, q_i, p):
 * q is no coordinate of the model, so the link cannot be compared as written; read with q as each of the model's
 * coordinates in turn, it is a claim about every one of them, true or false. */
#include "checker/checker_internals.hpp"

#include <cstring>

namespace eomgen::checker::detail {

namespace {

/// The names the text differentiates by that are none of the model's (free names inside ∂/∂·), without their dots.
void generic_names(const GiNaC::ex& e, const LatexContext& ctx, std::set<std::string>& out) {
    if (is_ex_the_function(e, pdiff) && GiNaC::is_a<GiNaC::symbol>(e.op(1)))
        if (const FreeName* f = ctx.free_name_of(e.op(1)); f && f->kind == NameKind::Unknown) {
            std::string n = f->name;
            for (const char* dot : {"\\dot{", "\\ddot{"})
                if (n.rfind(dot, 0) == 0 && n.back() == '}') n = n.substr(std::strlen(dot), n.size() - std::strlen(dot) - 1);
            out.insert(n);
        }
    for (std::size_t k = 0; k < e.nops(); ++k) generic_names(e.op(k), ctx, out);
}

}  // namespace

bool Checker::check_generic_coordinate(const FullChain& c, std::size_t i, std::size_t j, bool bridge,
                                       EquationCheck& r) {
    if (model_.coordinates.empty() || !c.sides[i].side->ok || !c.sides[j].side->ok) return false;
    std::set<std::string> names;
    generic_names(c.sides[i].side->value, ctx_, names);
    generic_names(c.sides[j].side->value, ctx_, names);
    // One generic coordinate, which must be differentiated by both as a coordinate and as a velocity somewhere in
    // the link (`\partial L/\partial q` alone may be a parameter's name the model lacks).
    if (names.size() != 1) return false;
    const std::string q = *names.begin();
    const auto find = [&](const std::string& n) -> const FreeName* {
        const auto it = ctx_.free_names.find(n);
        return it == ctx_.free_names.end() ? nullptr : &it->second;
    };
    const FreeName* fq = find(q);
    const FreeName* fqd = find("\\dot{" + q + "}");
    if (!fq || !fqd) return false;
    const FreeName* fqdd = find("\\ddot{" + q + "}");
    std::vector<EquationCheck> each;
    std::string coordinates;
    for (const Coordinate& k : model_.coordinates) {
        GiNaC::exmap as{{fq->symbol, k.q}, {fqd->symbol, k.qd}};
        if (fqdd) as[fqdd->symbol] = k.qdd;
        Side a = *c.sides[i].side, b = *c.sides[j].side;
        a.value = a.value.subs(as);
        b.value = b.value.subs(as);
        FullChain one = c;
        one.sides[i].side = &a;
        one.sides[j].side = &b;
        each.push_back(safe_check_link(one, i, j, bridge));
        coordinates += (coordinates.empty() ? "" : ", ") + m(k.latex);
        if (each.back().verdict != Verdict::Agrees) {
            if (each.back().verdict != Verdict::Disagrees) return false;
            // Wrong for this coordinate: the verdict says for which, and what the equation is for it.
            r = each.back();
            r.notes.insert(r.notes.begin(), "the text's $" + q + "$ is a generic coordinate: read as " + m(k.latex) +
                                                " (the model's coordinates: " + m(model_.coordinates.front().latex) +
                                                (model_.coordinates.size() > 1 ? ", …" : "") + ")");
            r.corrected.clear();  // a correction for one coordinate is not the general equation's
            return true;
        }
    }
    r = each.front();
    r.compared_with = "the Euler–Lagrange equation for each coordinate";
    r.reason = "with the text's generic coordinate $" + q + "$ read as each of the model's in turn (" + coordinates +
               "), it holds every time";
    r.notes.clear();
    return true;
}

}  // namespace eomgen::checker::detail
