/** @file point_positions.hpp  The points whose positions a model file gives (its [[draw]] entries' points in space
 * axes and its bodies' centres of mass), and the text's names for a point's coordinates (`x_2`, `y`, `z_{bob}`): what
 * the checker compares the kinematics of a derivation with ("the bob at $x_2 = x + l\sin\theta$, $y_2 = -l\cos\theta$";
 * point_positions.cpp). Plain data, read from the model once. */
#pragma once

#include "checker/latex_parser.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace eomgen::checker {

/// A point of the model in space axes, in the coordinates, the parameters and t.
struct ModelPoint {
    std::array<GiNaC::ex, 3> r;
    bool planar = false;  ///< given as (x, y): shown with two components
    std::string what;     ///< where the file gives it: "[[draw]] at FILE:L:C", "the centre of mass of body 'rod'"
};

/// Every point of [[draw]] that is not a body's (point, trace, circle centre, link and spring ends) and every body's
/// centre of mass, in file order, each once.
std::vector<ModelPoint> model_points(const Model& model);

// PositionName and position_name(), the text's names for a point's coordinates, are latex_parser.hpp's (names).

/// What the checker found for one row of a point's coordinates (point_positions.cpp).
struct PositionMatch {
    bool matched = false;
    int axis = -1;     ///< the coordinate the row gives; -1 for a position vector
    std::string text;  ///< the point matched, or the note
    /// A coordinate at a point the text considers (`x, y, z = 0, 0, 0` where s = 0) of a point the text's own
    /// formulas match: what the model's point has there, when the row says otherwise (then `disagrees`).
    bool disagrees = false;
    GiNaC::ex expected;
};

/// A row of the text that gives a point's coordinate (`x_2 = x + l\sin\theta`) or its position vector.
struct PositionRow {
    std::size_t at;  ///< the relation's file offset
    std::string name;
    std::vector<std::pair<int, GiNaC::ex>> components;  ///< (axis, value): one for `x_2 = …`, all for a vector
};

/// The axis (0, 1, 2) of a unit vector's canonical name: `\hat{x}`, `\mathbf{j}`, `\vec{k}`, `\hat{e}_{z}`, `\mathbf{e}_{1}`.
std::optional<int> unit_vector_axis(const std::string& canonical);

}  // namespace eomgen::checker
