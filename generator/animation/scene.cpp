/** @file scene.cpp  The primitives of a model's animation: [[draw]], bodies, springs, contacts' ground. */
#include "animation/scene.hpp"

#include "mechanics/kinematics.hpp"

#include <algorithm>

namespace eomgen::animation {
namespace {

using GiNaC::ex;

void push_point(std::vector<ex>& values, const std::array<ex, 3>& p) {
    for (const ex& c : p) values.push_back(c);
}

std::array<ex, 3> column3(const GiNaC::matrix& m) { return {m(0, 0), m(1, 0), m(2, 0)}; }

std::string draw_what(const DrawItem& d) {
    static const char* names[] = {"point", "link", "spring", "circle", "trace", "ground", "body"};
    std::string s = std::string("the [[draw]] ") + names[int(d.kind)];
    if (!d.label.empty()) s += " '" + d.label + "'";
    else if (d.kind == DrawKind::Body) s += " '" + d.body + "'";
    return s;
}

/// The centre and Aᵀ (body → space) of a body, then its solid's dimensions.
Primitive solid_of(const Body& body, DrawSolid solid, const std::array<ex, 3>& size) {
    Primitive p;
    p.kind = PrimitiveKind::Solid;  // unlabelled: a [[draw]] entry for the body may give it a label
    p.where = body.where;
    p.what = "body '" + body.name + "'";
    push_point(p.values, body.centre);
    const GiNaC::matrix A = body_rotation(body);
    for (unsigned r = 0; r < 3; ++r)
        for (unsigned c = 0; c < 3; ++c) p.values.push_back(A(c, r));  // Aᵀ row by row
    auto dims = [&](std::initializer_list<ex> d) { p.values.insert(p.values.end(), d.begin(), d.end()); };
    if (solid == DrawSolid::Box) {
        p.shape = SolidShape::Box;
        dims({size[0], size[1], size[2]});
        return p;
    }
    if (solid == DrawSolid::Ellipsoid) {
        p.shape = SolidShape::Ellipsoid;
        dims({size[0], size[1], size[2]});
        return p;
    }
    const std::vector<ex>& d = body.dimensions;
    const std::string& s = body.shape;
    if (s == "thin_rod") {
        p.shape = SolidShape::Rod;
        dims({d[0]});
    } else if (s == "thin_disk") {
        p.shape = SolidShape::Disk;
        dims({d[0]});
    } else if (s == "ring") {
        p.shape = SolidShape::Ring;
        dims({d[0]});
    } else if (s == "solid_sphere" || s == "hollow_sphere") {
        p.shape = SolidShape::Ellipsoid;
        dims({d[0], d[0], d[0]});
    } else if (s == "solid_cone") {
        p.shape = SolidShape::Cone;
        dims({d[0], d[1]});
    } else if (s == "cylinder") {
        p.shape = SolidShape::Cylinder;
        dims({d[0], d[1]});
    } else if (s == "box") {
        p.shape = SolidShape::Box;
        dims({d[0], d[1], d[2]});
    } else if (s == "rectangular_plate") {
        p.shape = SolidShape::Box;
        dims({d[0], d[1], 0});
    } else if (s == "right_triangle_plate") {
        p.shape = SolidShape::Triangle;
        dims({d[0], d[1]});
    } else {  // an inertia tensor: the uniform ellipsoid with its principal moments (frames.cpp)
        p.shape = SolidShape::InertiaEllipsoid;
        dims({body.inertia(0, 0), body.inertia(1, 1), body.inertia(2, 2), body.mass});
    }
    return p;
}

const Body* find_body(const Model& model, const std::string& name) {
    for (const Body& b : model.bodies)
        if (b.name == name) return &b;
    return nullptr;
}

/// A point in space axes: `point` itself, or where `body` is named, the point of that body at `point` in its axes.
std::array<ex, 3> space_point(const Model& model, const std::array<ex, 3>& point, const std::string& body) {
    if (body.empty()) return point;
    const Body& b = *find_body(model, body);
    GiNaC::matrix rho(3, 1);
    for (unsigned i = 0; i < 3; ++i) rho(i, 0) = point[i];
    GiNaC::matrix c(3, 1);
    for (unsigned i = 0; i < 3; ++i) c(i, 0) = b.centre[i];
    return column3(point_position(c, body_rotation(b), rho));
}

/// A wheel's rim (a Ring about the contact's axis): the body's Aᵀ with its columns taken so that the ring's own
/// z is the wheel's axis (a cyclic permutation, which keeps the axes right-handed).
Primitive rim_of(const Body& body, const RollingContact& contact) {
    Primitive p = solid_of(body, DrawSolid::Box, {0, 0, 0});
    const int z = contact.axis - 'x', x = (z + 1) % 3, y = (z + 2) % 3;
    std::vector<ex> rotated(p.values.begin(), p.values.begin() + 3);
    for (int r = 0; r < 3; ++r)
        for (int c : {x, y, z}) rotated.push_back(p.values[3 + 3 * r + c]);
    rotated.push_back(contact.radius + contact.tube);
    p.values = rotated;
    p.shape = SolidShape::Ring;
    return p;
}

}  // namespace

Scene build_scene(const Model& model) {
    Scene scene;
    std::vector<std::string> drawn_bodies;
    for (const DrawItem& d : model.drawing)
        if (d.kind == DrawKind::Body) drawn_bodies.push_back(d.body);
    // The bodies first (a [[draw]] entry naming one replaces its default solid, or hides it).
    for (const Body& b : model.bodies) {
        if (std::find(drawn_bodies.begin(), drawn_bodies.end(), b.name) != drawn_bodies.end()) continue;
        // A body of no mass and no inertia is a frame others are placed in: nothing to see.
        const bool massless = b.mass.is_zero() && b.shape.empty() && b.inertia.is_zero_matrix();
        const auto contact = std::find_if(model.contacts.begin(), model.contacts.end(),
                                          [&](const RollingContact& c) { return c.body == b.name; });
        if (contact != model.contacts.end())
            scene.items.push_back(rim_of(b, *contact));
        else if (!massless)
            scene.items.push_back(solid_of(b, DrawSolid::FromBody, {0, 0, 0}));
    }
    for (const DrawItem& d : model.drawing) {
        Primitive p;
        p.label = d.label;
        p.colour = d.colour;
        p.where = d.where;
        p.what = draw_what(d);
        switch (d.kind) {
            case DrawKind::Point:
            case DrawKind::Trace:
                p.kind = d.kind == DrawKind::Point ? PrimitiveKind::Point : PrimitiveKind::Trace;
                push_point(p.values, space_point(model, d.points[0], d.point_bodies[0]));
                if (d.kind == DrawKind::Point && !d.radius.is_zero()) {
                    p.has_radius = true;
                    p.values.push_back(d.radius);
                }
                break;
            case DrawKind::Link:
            case DrawKind::Spring:
                p.kind = d.kind == DrawKind::Link ? PrimitiveKind::Polyline : PrimitiveKind::Spring;
                for (std::size_t i = 0; i < d.points.size(); ++i)
                    push_point(p.values, space_point(model, d.points[i], d.point_bodies[i]));
                p.coils = d.coils;
                break;
            case DrawKind::Circle:
                p.kind = PrimitiveKind::Circle;
                push_point(p.values, space_point(model, d.points[0], d.point_bodies[0]));
                push_point(p.values, d.normal);
                p.values.push_back(d.radius);
                p.fill = d.fill;
                break;
            case DrawKind::Ground:
                p.kind = PrimitiveKind::Ground;
                p.ground_axis = d.ground_axis;
                p.values.push_back(d.height);
                break;
            case DrawKind::Body: {
                if (d.hidden) continue;
                const Primitive s = solid_of(*find_body(model, d.body), d.solid, d.size);
                p.kind = s.kind;
                p.shape = s.shape;
                p.values = s.values;
                break;
            }
        }
        scene.items.push_back(std::move(p));
    }
    for (const Spring& s : model.springs) {
        Primitive p;
        p.kind = PrimitiveKind::Spring;
        push_point(p.values, space_point(model, s.from.point, s.from.body));
        push_point(p.values, space_point(model, s.to.point, s.to.body));
        p.label = s.name;
        p.where = s.where;
        p.what = "spring '" + s.name + "'";
        scene.items.push_back(std::move(p));
    }
    const bool has_ground = std::any_of(model.drawing.begin(), model.drawing.end(),
                                        [](const DrawItem& d) { return d.kind == DrawKind::Ground; });
    if (!model.contacts.empty() && !has_ground) {  // the plane the first wheel rolls on
        const RollingContact& c = model.contacts.front();
        Primitive p;
        p.kind = PrimitiveKind::Ground;
        p.ground_axis = c.normal;
        p.values.push_back(c.height);
        p.where = c.where;
        p.what = "the plane of contact '" + c.name + "'";
        scene.items.push_back(std::move(p));
    }
    if (scene.items.empty() ||
        std::all_of(scene.items.begin(), scene.items.end(),
                    [](const Primitive& p) { return p.kind == PrimitiveKind::Ground; }))
        throw ModelError({model.path, 0, 0},
                         "nothing to animate: the model has no [[draw]] entries, bodies or springs; add [[draw]] "
                         "entries (a point, a link ... in the coordinates: docs/model_files.md, Drawing)");

    // Planar: every position's z and every circle's tilt vanish identically, and no solids.
    scene.planar = std::all_of(scene.items.begin(), scene.items.end(), [](const Primitive& p) {
        switch (p.kind) {
            case PrimitiveKind::Solid: return false;
            case PrimitiveKind::Ground: return p.ground_axis == 'y';
            case PrimitiveKind::Circle:
                return p.values[2].is_zero() && p.values[3].is_zero() && p.values[4].is_zero();
            default: {  // points: every third number is a z (a ball's radius follows its point)
                const std::size_t coordinates = p.values.size() - (p.has_radius ? 1 : 0);
                for (std::size_t k = 2; k < coordinates; k += 3)
                    if (!p.values[k].is_zero()) return false;
                return true;
            }
        }
    });
    if (!(model.gravity[0].is_zero() && model.gravity[1].is_zero() && model.gravity[2].is_zero()))
        scene.up = {-model.gravity[0], -model.gravity[1], -model.gravity[2]};
    return scene;
}

}  // namespace eomgen::animation
