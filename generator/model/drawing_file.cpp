/** @file drawing_file.cpp  [[draw]]: points, links, springs, circles, traces, the ground and bodies' solids. */
#include "model/drawing_file.hpp"

#include "model/names.hpp"

#include <algorithm>
#include <cctype>
#include <map>

namespace eomgen {
namespace {

const std::vector<std::string> kShapes = {"point", "link", "spring", "circle", "trace", "ground", "body"};

/// The keys beside the shape's, and the shapes each belongs to.
const std::map<std::string, std::vector<std::string>> kOptions = {
    {"label", kShapes},          {"colour", kShapes},         {"color", kShapes},
    {"radius", {"point", "circle"}}, {"normal", {"circle"}},  {"fill", {"circle"}},
    {"coils", {"spring"}},       {"height", {"ground"}},      {"box", {"body"}},
    {"ellipsoid", {"body"}},     {"hide", {"body"}}};

/// CSS colour names a drawing may use besides #rgb and #rrggbb, with their values.
const std::map<std::string, std::string> kColourNames = {
    {"black", "#000000"}, {"white", "#ffffff"}, {"gray", "#808080"},  {"grey", "#808080"},
    {"red", "#d62728"},   {"green", "#2ca02c"}, {"blue", "#1f77b4"},  {"orange", "#ff7f0e"},
    {"purple", "#9467bd"}, {"brown", "#8c564b"}, {"pink", "#e377c2"}, {"olive", "#bcbd22"},
    {"cyan", "#17becf"},  {"yellow", "#e6c229"}, {"magenta", "#ff00ff"}, {"navy", "#1f3a93"},
    {"teal", "#138d90"},  {"maroon", "#800000"}};

class DrawingReader {
public:
    DrawingReader(const FileReading& file, const SymbolTable& symbols, const Model& model)
        : file_(file), symbols_(symbols), model_(model) {
        placement_.forbid_velocities = "a drawing is in the coordinates, the parameters and t, without velocities";
    }

    DrawItem read(const toml::table& t) {
        std::vector<std::string> allowed = kShapes;
        for (const auto& [key, shapes] : kOptions) allowed.push_back(key);
        file_.check_keys(t, allowed, "in [[draw]]");
        std::string shape;
        const toml::node* shape_node = nullptr;
        for (const std::string& s : kShapes)
            if (const toml::node* n = t.get(s)) {
                if (shape_node)
                    file_.fail(file_.at(*n), "a [[draw]] entry draws one thing: this one has both '" + shape +
                                                 "' and '" + s + "' (write a second [[draw]])");
                shape = s;
                shape_node = n;
            }
        if (!shape_node)
            file_.fail(file_.at(t), "a [[draw]] entry needs what it draws: one of the keys point, link, spring, "
                                    "circle, trace, ground, body");
        for (auto&& [key, node] : t) {
            const auto it = kOptions.find(std::string(key.str()));
            if (it == kOptions.end()) continue;
            if (std::find(it->second.begin(), it->second.end(), shape) == it->second.end()) {
                std::string owners;
                for (const std::string& s : it->second) owners += (owners.empty() ? "" : " or ") + s;
                file_.fail(file_.at(node), "'" + std::string(key.str()) + "' belongs to a " + owners + ", not a " +
                                               shape);
            }
        }
        DrawItem item;
        item.where = file_.at(*shape_node);
        if (shape == "point" || shape == "trace") {
            item.kind = shape == "point" ? DrawKind::Point : DrawKind::Trace;
            item.points.push_back(point(*shape_node, shape, item));
        } else if (shape == "link" || shape == "spring") {
            item.kind = shape == "link" ? DrawKind::Link : DrawKind::Spring;
            const toml::array* list = shape_node->as_array();
            const bool of_points = list && !list->empty() && (list->front().as_array() || list->front().as_table());
            if (!of_points)
                file_.fail(item.where, "'" + shape + "' is an array of points, such as [[\"0\", \"0\"], "
                                       "[\"l*sin(theta)\", \"-l*cos(theta)\"]]");
            for (const toml::node& p : *list) item.points.push_back(point(p, shape, item));
            if (shape == "link" && item.points.size() < 2)
                file_.fail(item.where, "a link joins two or more points, not " + std::to_string(item.points.size()));
            if (shape == "spring" && item.points.size() != 2)
                file_.fail(item.where, "a spring joins two points, not " + std::to_string(item.points.size()));
        } else if (shape == "circle") {
            item.kind = DrawKind::Circle;
            item.points.push_back(point(*shape_node, "circle (its centre)", item));
            const toml::node* r = t.get("radius");
            if (!r) file_.fail(file_.at(t), "missing key 'radius' in the [[draw]] circle");
            item.radius = file_.scalar(*r, "radius", symbols_, placement_);
            if (const toml::node* n = t.get("normal")) {
                const std::vector<GiNaC::ex> v = file_.scalars(*n, "normal", 3, symbols_, placement_);
                item.normal = {v[0], v[1], v[2]};
            }
            item.fill = boolean(t, "fill");
        } else if (shape == "ground") {
            const std::string axis = file_.string_value(*shape_node, "ground");
            if (axis != "x" && axis != "y" && axis != "z")
                file_.fail(file_.string_start(*shape_node),
                           "'ground' is the axis normal to the ground plane: \"x\", \"y\" or \"z\", not '" + axis + "'");
            item.kind = DrawKind::Ground;
            item.ground_axis = axis[0];
            if (const toml::node* h = t.get("height")) item.height = file_.scalar(*h, "height", symbols_, placement_);
        } else {
            item.kind = DrawKind::Body;
            item.body = body_name(*shape_node);
            const toml::node* box = t.get("box");
            const toml::node* ellipsoid = t.get("ellipsoid");
            if (box && ellipsoid)
                file_.fail(file_.at(*ellipsoid), "a body is drawn as a box or an ellipsoid, not both");
            if (box || ellipsoid) {
                const std::vector<GiNaC::ex> v = file_.scalars(box ? *box : *ellipsoid, box ? "box" : "ellipsoid", 3,
                                                               symbols_, placement_);
                item.size = {v[0], v[1], v[2]};
                item.solid = box ? DrawSolid::Box : DrawSolid::Ellipsoid;
            }
            item.hidden = boolean(t, "hide");
        }
        if (const toml::node* r = t.get("radius"); r && item.kind == DrawKind::Point)
            item.radius = file_.scalar(*r, "radius", symbols_, placement_);
        if (const toml::node* c = t.get("coils")) {
            const auto* i = c->as_integer();
            if (!i || i->get() < 1 || i->get() > 200)
                file_.fail(file_.at(*c), "'coils' is a whole number of zig-zags from 1 to 200");
            item.coils = int(i->get());
        }
        if (const toml::node* l = t.get("label")) item.label = file_.string_value(*l, "label");
        const toml::node* c1 = t.get("colour");
        const toml::node* c2 = t.get("color");
        if (c1 && c2) file_.fail(file_.at(*c2), "'colour' and 'color' are the same key: give one");
        if (const toml::node* c = c1 ? c1 : c2) item.colour = colour(*c);
        return item;
    }

private:
    /// [x, y] (z = 0), [x, y, z], or { body = "B", point = [x, y, z] } (B's axes, from its centre; default its
    /// centre); the body, or "", goes to item.point_bodies.
    std::array<GiNaC::ex, 3> point(const toml::node& node, const std::string& what, DrawItem& item) const {
        if (const toml::table* t = node.as_table()) {
            file_.check_keys(*t, {"body", "point"}, "in a point of the " + what);
            const toml::node* body = t->get("body");
            if (!body) file_.fail(file_.at(*t), "missing key 'body' in a point { body = \"name\", point = [x, y, z] }");
            item.point_bodies.push_back(body_name(*body));
            if (const toml::node* p = t->get("point")) {
                const std::vector<GiNaC::ex> v = file_.scalars(*p, "point", 3, symbols_, placement_);
                return {v[0], v[1], v[2]};
            }
            return {0, 0, 0};
        }
        const toml::array* a = node.as_array();
        if (!a || (a->size() != 2 && a->size() != 3))
            file_.fail(file_.at(node), "a point of the " + what + " is [x, y], [x, y, z] (expressions in the "
                                       "coordinates and parameters) or { body = \"name\", point = [x, y, z] }");
        const std::vector<GiNaC::ex> v = file_.scalars(node, what, 0, symbols_, placement_);
        if (v.size() == 2) item.planar_given = true;
        item.point_bodies.push_back("");
        return {v[0], v[1], v.size() == 3 ? v[2] : GiNaC::ex(0)};
    }

    /// The name of a body of [[bodies]], else a ModelError where it is written.
    std::string body_name(const toml::node& node) const {
        const std::string name = file_.string_value(node, "body");
        if (std::none_of(model_.bodies.begin(), model_.bodies.end(), [&](const Body& b) { return b.name == name; })) {
            std::vector<std::string> names;
            for (const Body& b : model_.bodies) names.push_back(b.name);
            const std::string best = closest_name(name, names);
            file_.fail(file_.string_start(node), "no body named '" + name + "' in [[bodies]]" +
                                                     (best.empty() ? std::string() : "; did you mean '" + best + "'?"));
        }
        return name;
    }

    bool boolean(const toml::table& t, const std::string& key) const {
        const toml::node* n = t.get(key);
        if (!n) return false;
        const auto* b = n->as_boolean();
        if (!b) file_.fail(file_.at(*n), "'" + key + "' is true or false");
        return b->get();
    }

    /// "#rgb", "#rrggbb" or a name of kColourNames, as "#rrggbb".
    std::string colour(const toml::node& node) const {
        std::string s = file_.string_value(node, "colour");
        std::string lower = s;
        std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
        if (const auto it = kColourNames.find(lower); it != kColourNames.end()) return it->second;
        const bool hex = (lower.size() == 4 || lower.size() == 7) && lower[0] == '#' &&
                         std::all_of(lower.begin() + 1, lower.end(), [](unsigned char ch) { return std::isxdigit(ch); });
        if (!hex) {
            std::string names;
            for (const auto& [name, value] : kColourNames) names += (names.empty() ? "" : ", ") + name;
            file_.fail(file_.string_start(node), "a colour is \"#rgb\", \"#rrggbb\" or one of " + names + "; not '" +
                                                     s + "'");
        }
        if (lower.size() == 4) return std::string("#") + lower[1] + lower[1] + lower[2] + lower[2] + lower[3] + lower[3];
        return lower;
    }

    const FileReading& file_;
    const SymbolTable& symbols_;
    const Model& model_;
    ParseOptions placement_;
};

}  // namespace

std::vector<DrawItem> read_drawing(const toml::table& root, const FileReading& file, const SymbolTable& symbols,
                                   const Model& model) {
    const toml::node* node = root.get("draw");
    if (!node) return {};
    const toml::array* list = node->as_array();
    if (!list || !list->is_array_of_tables())
        file.fail(file.at(*node), "'draw' is an array of tables, written [[draw]] (docs/model_files.md, Drawing)");
    DrawingReader reader(file, symbols, model);
    std::vector<DrawItem> out;
    for (const toml::node& entry : *list) out.push_back(reader.read(*entry.as_table()));
    return out;
}

}  // namespace eomgen
