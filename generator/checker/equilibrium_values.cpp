/** @file equilibrium_values.cpp  `r_{eq} = l_0 + \frac{mg}{k}`, `\theta_0 = \arccos\frac{g}{\omega^2 R}`: a coordinate's
 * value at the point the text considers, under the conditions it stated there (`\dot r = \dot\theta = 0`, `\ddot r =
 * \ddot\theta = 0`, `\theta = 0`), named by the coordinate's letter with a subscript. The equations of motion must
 * hold there: with the conditions and the coordinate at that value, each Euler–Lagrange equation must leave 0. */
#include "checker/checker_internals.hpp"

namespace eomgen::checker::detail {

namespace {

/// The coordinate whose letter `name` is with a subscript (`r_{eq}` → r, `\theta_{0}` → θ), or nullptr.
const Coordinate* subscripted_coordinate(const std::string& name, const Model& model) {
    const std::size_t under = name.find('_');
    if (under == std::string::npos || under + 1 >= name.size()) return nullptr;
    const std::string base = name.substr(0, under);
    for (const Coordinate& c : model.coordinates)
        if (base == c.latex || base == c.name) return &c;
    return nullptr;
}

}  // namespace

bool Checker::check_value_at_point(const PSide& L, const PSide& R, const Prepared& a, const Prepared& b, double tol,
                                   std::size_t at, EquationCheck& r) {
    for (const auto& [name_side, value_side, named, value] :
         {std::tuple(&L, &R, &a, &b), std::tuple(&R, &L, &b, &a)}) {
        if (!named->ok || named->unknown.size() != 1 || !value->comparable() || !value->units.empty() ||
            depends_on_state(value->value) || has_acceleration(value->value) || value->value.has(model_.t))
            continue;
        // The name alone, or a sine, cosine or tangent of it (`\cos\alpha_0 = \frac{g}{\omega^2 R}`): its value.
        const GiNaC::ex name = named->unknown.front()->symbol;
        GiNaC::ex at_point;
        std::string shown = value_side->side->source;
        if (named->value.is_equal(name)) {
            at_point = value->value;
        } else if (named->value.nops() == 1 && named->value.op(0).is_equal(name)) {
            if (GiNaC::is_the_function<GiNaC::cos_SERIAL>(named->value))
                at_point = GiNaC::acos(value->value);
            else if (GiNaC::is_the_function<GiNaC::sin_SERIAL>(named->value))
                at_point = GiNaC::asin(value->value);
            else if (GiNaC::is_the_function<GiNaC::tan_SERIAL>(named->value))
                at_point = GiNaC::atan(value->value);
            else
                continue;
            shown = latex(at_point);
        } else {
            continue;
        }
        const Coordinate* q = subscripted_coordinate(named->unknown.front()->name, model_);
        if (!q) continue;
        // Only at a point the text has set up: an acceleration stated (an equilibrium, a steady motion).
        const auto conditions = discourse_->conditions_at(at);
        bool steady = false;
        int line = 0;
        GiNaC::exmap point;
        for (const auto& [symbol, stated] : conditions) {
            point[symbol] = stated.first;
            line = std::max(line, stated.second);
            for (const Coordinate& c : model_.coordinates) steady = steady || symbol.is_equal(c.qdd);
        }
        // "θ₀ is the equilibrium position": without stated conditions, the sentence's equilibrium is one where
        // every velocity and acceleration vanishes.
        if (!steady) {
            const std::string sentence = lead_in(d_, at, 1);
            if (sentence.find("equilibri") == std::string::npos && sentence.find("at rest") == std::string::npos &&
                sentence.find("rest position") == std::string::npos)
                return false;
            for (const Coordinate& c : model_.coordinates) {
                if (!point.count(c.qd)) point[c.qd] = 0;
                if (!point.count(c.qdd)) point[c.qdd] = 0;
            }
            line = d_.position(at).line;
        }
        point[q->q] = at_point;  // its own point: another value the text gave the coordinate (`\alpha = 0`) is another
        std::vector<GiNaC::ex> left;
        try {
            for (const GiNaC::ex& e : motion_) left.push_back(GiNaC::normal(e.subs(point)));
        } catch (const std::exception&) {
            return false;
        }
        for (const GiNaC::ex& e : left)
            if (depends_on_state(e) || has_acceleration(e) || e.has(model_.t)) return false;  // the point is not set
        const std::string where = (steady ? "at the point the text considers (its conditions, line " +
                                               std::to_string(line) + ")"
                                          : std::string("at rest (the equilibrium its sentence names)")) +
                                  " with " + m(q->latex + " = " + shown);
        r.compared_with = "the equations of motion " + where;
        for (std::size_t i = 0; i < left.size(); ++i)
            if (equal(left[i], 0, tol) != Tri::Yes) {
                r.verdict = Verdict::Disagrees;
                r.reason = "the equation of motion for " + m(model_.coordinates[i].latex) + " does not hold there";
                r.difference = latex(left[i]);
                r.wrong_terms = {"the Euler–Lagrange equation for " + m(model_.coordinates[i].latex) + " leaves " +
                                 m(latex(left[i])) + " (not 0) " + where};
                // Where that equation is linear in the coordinate, the value it needs.
                try {
                    GiNaC::exmap others = point;
                    others.erase(q->q);
                    const GiNaC::ex e = GiNaC::expand(GiNaC::numer(GiNaC::normal(motion_[i].subs(others))));
                    const GiNaC::ex c1 = e.coeff(q->q, 1), c0 = e.coeff(q->q, 0);
                    if (e.degree(q->q) == 1 && !c1.has(q->q) && !c0.has(q->q) && !depends_on_state(c1) &&
                        !depends_on_state(c0) && !c1.is_zero())
                        r.corrected = name_side->side->source + " = " + latex(GiNaC::normal(-c0 / c1));
                } catch (const std::exception&) {
                }
                return true;
            }
        r.verdict = Verdict::Agrees;
        r.reason = "the equations of motion hold there: " + m(named->unknown.front()->name) + " is " +
                   m(q->latex) + " at that point";
        return true;
    }
    return false;
}

}  // namespace eomgen::checker::detail
