/** @file point_positions.cpp  The kinematics of a derivation, `x_2 = x + l\sin\theta`, `y_2 = -l\cos\theta`, against
 * the points the model file gives (issue 28): the coordinates the text writes for one point (one subscript, one
 * section) agree where one point of the model has all of them. Where none has, the text may have placed its axes
 * otherwise than the file (y down, another origin), so nothing is claimed: the rows stay what they were (the text's
 * abbreviations), with a note listing the model's points. */
#include "checker/point_positions.hpp"

#include "checker/checker_internals.hpp"

#include <map>
#include <set>

namespace eomgen::checker {

std::vector<ModelPoint> model_points(const Model& model) {
    std::vector<ModelPoint> out;
    const auto add = [&](const std::array<GiNaC::ex, 3>& r, bool planar, const std::string& what) {
        for (const ModelPoint& p : out)
            if (p.r[0].is_equal(r[0]) && p.r[1].is_equal(r[1]) && p.r[2].is_equal(r[2])) return;
        out.push_back(ModelPoint{r, planar, what});
    };
    for (const DrawItem& d : model.drawing)
        for (std::size_t k = 0; k < d.points.size(); ++k)
            if (k >= d.point_bodies.size() || d.point_bodies[k].empty())
                add(d.points[k], d.planar_given, "[[draw]] at " + d.where.str());
    for (const Body& b : model.bodies)
        add(b.centre, false, "the centre of mass of body '" + b.name + "' at " + b.where.str());
    return out;
}


std::optional<int> unit_vector_axis(const std::string& canonical) {
    // \hat{x}, \mathbf{i}, \vec{k}, \hat{\imath}; \hat{e}_{x}, \mathbf{e}_{y}, \vec{e}_{z} (and e_{1}, e_{2}, e_{3}).
    static const char* const decorations[] = {"\\hat", "\\mathbf", "\\vec", "\\boldsymbol", "\\bm", "\\widehat"};
    for (const char* d : decorations) {
        const std::string open = std::string(d) + "{";
        if (canonical.rfind(open, 0) != 0) continue;
        const std::size_t close = canonical.find('}', open.size());
        if (close == std::string::npos) return std::nullopt;
        const std::string inner = canonical.substr(open.size(), close - open.size());
        const std::string after = canonical.substr(close + 1);
        if (after.empty()) {
            for (int a = 0; a < 3; ++a)
                if (inner == std::string(1, char('x' + a)) || inner == std::string(1, char('i' + a)))
                    return a;
            if (inner == "\\imath") return 0;
            if (inner == "\\jmath") return 1;
            return std::nullopt;
        }
        if (inner != "e") return std::nullopt;
        for (int a = 0; a < 3; ++a)
            if (after == "_{" + std::string(1, char('x' + a)) + "}" || after == "_{" + std::to_string(a + 1) + "}") return a;
        return std::nullopt;
    }
    return std::nullopt;
}

namespace detail {

void Checker::collect_positions(const std::vector<FullChain>& chains) {
    const std::vector<ModelPoint> points = model_points(model_);
    using Row = PositionRow;
    const auto plain = [&](const Prepared& v) {
        return v.ok && v.unknown.empty() && v.units.empty() && v.constants.empty() && !has_velocity(v.value) &&
               !has_acceleration(v.value);
    };
    // (section, point) → its rows, in text order; the values at a point the text considers (`y = r\cos\pi` after
    // "halfway along the first turn, $s = \frac{1}{2h}$") apart, by the end of that point's paragraph.
    std::map<std::pair<int, std::string>, std::vector<Row>> groups;
    PointRows at_points;
    // The conditions in force at `at`, as a key: a paragraph may take more than one point in turn ("when $s = 0$,
    // … Halfway along the first turn, $s = \frac{1}{2h}$, …").
    const auto conditions_key = [&](std::size_t at) {
        std::string key;
        for (const auto& [symbol, value_line] : discourse_->conditions_at(at))
            for (const Coordinate& q : model_.coordinates)  // the point's coordinates (not `x = l` read as l's value)
                if (symbol.is_equal(q.q)) key += latex(symbol) + "=" + latex(value_line.first) + ";";
        return key;
    };
    for (const FullChain& c : chains)
        for (std::size_t k = 0; k + 1 < c.sides.size(); ++k) {
            const Side& s = *c.sides[k].side;
            if (c.relations[k] != Relation::Equal || !s.ok || !GiNaC::is_a<GiNaC::symbol>(s.value)) continue;
            const std::size_t point_paragraph =
                at_a_point_.count(c.sides[k].base + s.begin)
                    ? discourse_->condition_paragraph(c.sides[k + 1].base + c.sides[k + 1].side->begin)
                    : 0;
            const FreeName* f = ctx_.free_name_of(s.value);
            if (!f) continue;
            const std::optional<PositionName> p = f->kind == NameKind::Unknown ? position_name(f->name) : std::nullopt;
            if (p) {
                const Prepared v = prepare(c.sides[k + 1]);
                if (!plain(v) || !v.vectors.empty()) continue;
                const Row row{c.relation_offsets[k], f->name, {{p->axis, v.value}}};
                if (point_paragraph > 0)
                    at_points[{c.section, p->point, point_paragraph, conditions_key(row.at)}].push_back(row);
                else
                    groups[{c.section, p->point}].push_back(row);
            } else if (f->kind == NameKind::Vector && point_paragraph == 0) {
                // `\vec{r}_m = (x + l\sin\theta)\hat{x} - l\cos\theta\,\hat{y}`: components along the axes' unit vectors.
                const Prepared v = prepare(c.sides[k + 1]);
                if (!plain(v) || v.vectors.empty()) continue;
                const std::optional<std::vector<std::pair<int, GiNaC::ex>>> comps = unit_components(v);
                if (comps) groups[{c.section, "\\vec " + f->name}].push_back(Row{c.relation_offsets[k], f->name, *comps});
            }
        }
    const auto shown = [&](const ModelPoint& p) {
        std::string s = "$(";
        for (int a = 0; a < (p.planar ? 2 : 3); ++a) s += (a ? ", " : "") + latex(p.r[a]);
        return s + ")$ (" + p.what + ")";
    };
    const auto matches = [&](const Row& row, const ModelPoint& p) {
        // Under the text's assumptions on the parameters there ("take $l_1 = l_2 = l$", then `x_2 = x_1 + l\sin\theta_2`).
        numbers_.pin(parameter_assumptions(row.at));
        bool all = true;
        for (const auto& [axis, value] : row.components) all = all && equal(value, p.r[axis], 1e-9) == Tri::Yes;
        numbers_.pin({});
        return all;
    };
    std::map<std::pair<int, std::string>, const ModelPoint*> matched_points;  // the point each group matched
    for (const auto& [key, rows] : groups) {
        std::set<int> axes;
        for (const Row& row : rows)
            for (const auto& comp : row.components) axes.insert(comp.first);
        // The point that the most rows match, among those matching a row of every axis the text gives (a text that
        // writes y twice, the second time for z, still has its x and first y matched).
        const ModelPoint* match = nullptr;
        std::size_t best = 0;
        for (const ModelPoint& p : points) {
            std::set<int> matched_axes;
            std::size_t n = 0;
            for (const Row& row : rows)
                if (matches(row, p)) {
                    for (const auto& comp : row.components) matched_axes.insert(comp.first);
                    ++n;
                }
            if (matched_axes == axes && n > best) {
                match = &p;
                best = n;
            }
        }
        if (match) matched_points[key] = match;
        std::string names;  // the text's names for the point, each once
        std::set<std::string> seen;
        for (const Row& row : rows)
            if (seen.insert(row.name).second) names += (names.empty() ? "" : ", ") + m(row.name);
        for (std::size_t q = 0; q < rows.size(); ++q) {
            PositionMatch& pm = positions_[rows[q].at];
            pm.axis = rows[q].components.size() == 1 ? rows[q].components[0].first : -1;
            if (match) {
                pm.matched = matches(rows[q], *match);
                pm.text = pm.matched ? shown(*match)
                                     : "the model's point the text's other coordinates of " + names + " match is " +
                                           shown(*match);
                continue;
            }
            // Said once, at the point's first row, and only for a point the text gives two coordinates of (a lone
            // `x = l - l_0` is as likely an extension as an abscissa).
            if (q != 0 || axes.size() < 2) continue;
            if (points.empty()) {
                pm.text = "the text places a point (" + names + "); the model file gives no points to compare it with "
                          "([[draw]] entries or [[bodies]] would)";
                continue;
            }
            pm.text = "no point the model file gives has the coordinates the text writes (" + names +
                      ") in its axes; the file's points:";
            for (const ModelPoint& p : points) pm.text += " " + shown(p) + ";";
            pm.text.pop_back();
        }
    }
    collect_positions_at_points(at_points, matched_points, points);
}

void Checker::collect_positions_at_points(
    const PointRows& at_points,
    const std::map<std::pair<int, std::string>, const ModelPoint*>& matched_points,
    const std::vector<ModelPoint>& points) {
    // The coordinates a paragraph gives at a point the text considers: compared with the model's point there (its
    // coordinates with the text's conditions put in). The point is the one the text's own formulas for it match in
    // the section (then a coordinate that differs is a slip: the text's axes are the model's, it says so
    // elsewhere); without such formulas, one point that every coordinate given there matches, or nothing is said.
    for (const auto& [key, rows] : at_points) {
        const auto& [section, name, paragraph, in_force] = key;
        const auto conditions = discourse_->conditions_at(rows.front().at);
        GiNaC::exmap at;
        std::string where;
        for (const auto& [symbol, value_line] : conditions) {
            at[symbol] = value_line.first;
            where += std::string(where.empty() ? "" : ", ") + latex(symbol) + " = " + latex(value_line.first);
        }
        if (at.empty()) continue;
        const int line = conditions.begin()->second.second;
        const auto there = [&](const GiNaC::ex& e) { return e.subs(at); };
        const auto matches = [&](const PositionRow& row, const ModelPoint& p) {
            for (const auto& [axis, value] : row.components)
                if (equal(there(value), there(p.r[axis]), 1e-9) != Tri::Yes) return false;
            return true;
        };
        const ModelPoint* anchor = nullptr;
        bool own_formulas = false;
        if (const auto it = matched_points.find({section, name}); it != matched_points.end()) {
            anchor = it->second;
            own_formulas = true;
        } else {
            for (const ModelPoint& p : points)
                if (std::all_of(rows.begin(), rows.end(), [&](const PositionRow& r) { return matches(r, p); })) {
                    anchor = &p;
                    break;
                }
        }
        if (!anchor) continue;
        std::string shown = "$(";
        for (int a = 0; a < (anchor->planar ? 2 : 3); ++a)
            shown += (a ? ", " : "") + latex(GiNaC::normal(there(anchor->r[a])));
        shown += ")$ where $" + where + "$ (the condition on line " + std::to_string(line) + "; " + anchor->what + ")";
        for (const PositionRow& row : rows) {
            PositionMatch& pm = positions_[row.at];
            pm.axis = row.components.size() == 1 ? row.components[0].first : -1;
            pm.matched = matches(row, *anchor);
            pm.text = shown;
            if (!pm.matched && own_formulas && pm.axis >= 0) {
                pm.disagrees = true;
                pm.expected = GiNaC::normal(there(anchor->r[pm.axis]));
            }
        }
    }
}

std::optional<std::vector<std::pair<int, GiNaC::ex>>> Checker::unit_components(const Prepared& v) const {
    GiNaC::ex units[3];
    for (const FreeName* f : v.vectors) {
        const std::optional<int> axis = unit_vector_axis(f->name);
        if (!axis || !units[*axis].is_zero()) return std::nullopt;
        units[*axis] = f->symbol;
    }
    const GiNaC::ex e = GiNaC::expand(v.value);
    GiNaC::ex rest = e;
    std::vector<std::pair<int, GiNaC::ex>> out;
    for (int a = 0; a < 3; ++a) {
        const GiNaC::ex c = units[a].is_zero() ? GiNaC::ex(0) : e.coeff(units[a], 1);
        for (const GiNaC::ex& u : units)
            if (!u.is_zero() && c.has(u)) return std::nullopt;  // a product of unit vectors
        if (!units[a].is_zero()) rest -= c * units[a];
        out.emplace_back(a, c);
    }
    if (!GiNaC::expand(rest).is_zero()) return std::nullopt;  // a term along no axis (a scalar, a power)
    return out;
}

bool Checker::check_position(const FullChain& c, std::size_t j, bool vector, EquationCheck& r) {
    const auto it = positions_.find(c.relation_offsets[j - 1]);
    if (it == positions_.end() || (it->second.axis < 0) != vector) return false;
    static const char* const axis[] = {"x", "y", "z"};
    if (it->second.disagrees) {
        const Prepared v = prepare(c.sides[j]);
        const std::string name = trimmed(c.sides[j - 1].side->source);
        r.verdict = Verdict::Disagrees;
        r.compared_with = "the position of the model's point " + it->second.text;
        r.reason = "the model's point, which the text's own formulas for it match, has " +
                   m(std::string(axis[it->second.axis]) + " = " + latex(it->second.expected)) + " there";
        if (v.ok) r.difference = latex((v.value - it->second.expected).expand());
        r.corrected = name + " = " + latex(it->second.expected);
        // (The correction holds at the point only: read alone, without the condition, it could not be checked.)
        solved_corrections_.insert({r.where.line, r.where.column});
        return true;
    }
    if (!it->second.matched) {
        if (!it->second.text.empty()) r.notes.push_back(it->second.text);
        return false;
    }
    r.verdict = Verdict::Agrees;
    r.compared_with = "the position of the model's point " + it->second.text;
    r.reason = it->second.axis < 0 ? "equal to that point's position vector, component by component"
                                   : "equal to that point's " + std::string(axis[it->second.axis]) + " coordinate";
    return true;
}

}  // namespace detail
}  // namespace eomgen::checker
