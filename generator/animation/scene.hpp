/** @file scene.hpp  What an animation draws, as expressions: the model's [[draw]] entries, its bodies' solids,
 * its springs and the ground its wheels roll on, each a primitive whose numbers per frame are expressions in
 * the coordinates, parameters and t (frames.hpp evaluates them at a run's samples). */
#pragma once

#include "model/model.hpp"

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace eomgen::animation {

enum class PrimitiveKind { Point, Polyline, Spring, Circle, Trace, Ground, Solid };

/// A body's solid in its own axes, about its centre of mass (mechanics/inertia.hpp's shapes).
enum class SolidShape {
    Box,        ///< sides a, b, c along x, y, z (a plate: c = 0)
    Ellipsoid,  ///< semi-axes a, b, c
    Rod,        ///< length l along z
    Disk,       ///< radius r in the x-y plane, with spokes (a wheel shows its turning)
    Ring,       ///< radius r in the x-y plane, with spokes
    Cylinder,   ///< radius r, height h along z
    Cone,       ///< base radius r, height h along z; the base h/4 below the centre of mass
    Triangle,   ///< right-angle plate, legs a along x and b along y; the right angle at (−a/3, −b/3)
    InertiaEllipsoid  ///< the uniform ellipsoid of principal moments I1, I2, I3 and mass m (dims: I1, I2, I3, m)
};

struct Primitive {
    PrimitiveKind kind = PrimitiveKind::Point;
    /// Its numbers per frame: points 3 each (Point, Trace: 1; Polyline: k; Spring: 2); Circle: centre, normal,
    /// radius (7); Solid: centre (3), the rotation body → space Aᵀ row by row (9), then its dimensions.
    std::vector<GiNaC::ex> values;
    SolidShape shape = SolidShape::Box;
    bool fill = false;       ///< Circle: a disk
    int coils = 8;           ///< Spring
    char ground_axis = 'z';  ///< Ground: the plane n·r = height (values: the height)
    bool has_radius = false; ///< Point: values[3] is a ball's radius in model units
    std::string label;
    std::string colour;      ///< "#rrggbb" or "" (the player's palette)
    SourceLocation where;    ///< the [[draw]] entry or the body it comes from
    std::string what;        ///< "the [[draw]] point 'bob'", "body 'door'": for messages
};

struct Scene {
    std::vector<Primitive> items;
    /// Everything lies in the x-y plane (every z ≡ 0, no solids, circles facing z): drawn in 2-D.
    bool planar = false;
    /// The direction drawn upward in 3-D (−gravity where the model has gravity, else z), space axes.
    std::array<GiNaC::ex, 3> up{0, 0, 1};
};

/// The scene of `model`; a ModelError at the model file when there is nothing to draw (no [[draw]], no bodies,
/// no springs) or a [[draw]] body's solid cannot be found.
Scene build_scene(const Model& model);

}  // namespace eomgen::animation
