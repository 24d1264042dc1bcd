/** @file drawing.hpp  What `eomgen run --animate` shows of a model: the [[draw]] entries of its file, as plain
 * data (expressions in the coordinates, parameters and t). The scene a player draws adds the bodies, springs
 * and contacts the file declares (animation/scene.hpp). */
#pragma once

#include "model/source_location.hpp"

#include <ginac/ginac.h>

#include <array>
#include <string>
#include <vector>

namespace eomgen {

/// The shape a [[draw]] entry names: exactly one of its keys point, link, spring, circle, trace, ground, body.
enum class DrawKind { Point, Link, Spring, Circle, Trace, Ground, Body };

/// A body's solid as drawn: from its `shape` (a rod, a disk, a box ...) or, with `inertia`, the uniform
/// ellipsoid of the same principal moments; or the box or ellipsoid a [[draw]] entry gives.
enum class DrawSolid { FromBody, Box, Ellipsoid };

struct DrawItem {
    DrawKind kind = DrawKind::Point;
    SourceLocation where;  ///< of the shape's key
    /// Points: point, trace and circle (its centre) have one, spring two, link two or more. In space axes, or
    /// in the axes of the body of the same index in `point_bodies` (from its centre of mass) where that is not "".
    std::vector<std::array<GiNaC::ex, 3>> points;
    std::vector<std::string> point_bodies;
    bool planar_given = false;   ///< the file gave (x, y): z = 0
    GiNaC::ex radius = 0;        ///< circle: its radius; point: a ball's radius (0: a dot of a few pixels)
    std::array<GiNaC::ex, 3> normal{0, 0, 1};  ///< circle: the normal of its plane, space axes
    bool fill = false;           ///< circle: drawn as a disk
    int coils = 8;               ///< spring: zig-zags
    std::string body;            ///< body: the body of [[bodies]] drawn
    DrawSolid solid = DrawSolid::FromBody;
    std::array<GiNaC::ex, 3> size{0, 0, 0};  ///< body: a box's sides or an ellipsoid's semi-axes, body axes
    bool hidden = false;         ///< body: `hide = true` leaves it out of the scene
    char ground_axis = 'z';      ///< ground: the plane n·r = height, n a space axis
    GiNaC::ex height = 0;
    std::string label;           ///< shown beside it ("" for none)
    std::string colour;          ///< "#rrggbb" ("" for the player's choice)
};

}  // namespace eomgen
