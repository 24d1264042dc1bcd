/** @file steady_sweep.hpp  A steady motion's linear equations against a parameter: C and K split by the speed
 * (C = v C1, K = g K0 + v² K2, as the bicycle benchmark writes them), the eigenvalues over a range, and the
 * values where the stability changes, to the last bit. */
#pragma once

#include "mechanics/steady_motion.hpp"

#include <optional>
#include <string>
#include <vector>

namespace eomgen {

/// C = v C1 and K = g K0 + v² K2, from the linearizations at v, 0 and 2v (and at 0 with 2g), each form checked;
/// `notes` says where one does not hold (then C1 and K2 hold at this speed only).
struct SpeedSplit {
    std::string speed, gravity;  ///< gravity: "g" where the model has a parameter g, else ""
    double v = 0, g = 0;
    Eigen::MatrixXd C1, K0, K2, K_rest;  ///< K0 empty without g; K_rest = K at v = 0
    std::vector<std::string> notes;
};

/// Nothing where the second-order form is not decoupled; throws ModesError for an unknown parameter.
std::optional<SpeedSplit> split_by_speed(const Model& model, SteadyMotionSolver& solver,
                                         const SteadyMotionOptions& options, const SteadyMotion& base,
                                         const std::string& speed);

/// The eigenvalues at `count` values of a parameter from `start` to `stop`, each steady motion started from its
/// neighbour's, and where the largest real part changes sign, refined by the Illinois variant of regula falsi.
struct SteadySweep {
    std::string name;
    std::vector<double> values;
    std::vector<Eigen::VectorXcd> eigenvalues;
    std::vector<std::string> stability;
    struct Change {
        double value;
        std::string from, to;
    };
    std::vector<Change> changes;
};

SteadySweep sweep_steady_motion(const Model& model, SteadyMotionSolver& solver, const SteadyMotionOptions& options,
                                const SteadyMotion& base, const std::string& name, double start, double stop, long count);

}  // namespace eomgen
