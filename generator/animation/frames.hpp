/** @file frames.hpp  A scene's numbers at each sample of a run: the primitives' positions, orientations and
 * sizes, evaluated in doubles from the run's CSV (t, the coordinates, their rates). */
#pragma once

#include "animation/scene.hpp"
#include "output/sample_table.hpp"

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace eomgen::animation {

/// A run's samples (output/sample_table.hpp).
using output::SampleTable;
using output::read_sample_table;

/// The scene's numbers at every row of `samples`.
struct Frames {
    std::vector<double> t;
    std::vector<Primitive> items;  ///< the scene's, an inertia ellipsoid turned into an Ellipsoid of semi-axes
    /// Per item, frame after frame, its numbers (Primitive::values' count each; an inertia ellipsoid's 16
    /// become the ellipsoid's 15).
    std::vector<std::vector<double>> values;
    std::array<double, 3> up{0, 0, 1};  ///< unit
    bool planar = false;
};

/// The scene at the samples, with the parameters' values (SI, every parameter of the model). Throws
/// std::runtime_error naming the primitive, its place in the model file and the time where a number is not
/// finite or a column the scene needs is missing.
Frames evaluate_frames(const Scene& scene, const Model& model, const std::map<std::string, double>& parameters,
                       const SampleTable& samples);

}  // namespace eomgen::animation
