/** @file animate.hpp  `eomgen run --animate FILE.html`: a run's samples drawn as the model's scene, written as
 * one page (animation/). */
#pragma once

#include "animation/scene.hpp"
#include "cli/ensemble_design.hpp"
#include "eomgen/simulation_options.hpp"
#include "model/model.hpp"

#include <functional>
#include <string>

namespace eomgen::cli {

/// Why `--animate path --fps fps` cannot be done ("" when it can): the file must end in .html or .htm, the
/// frame rate be in (0, 1000].
std::string animation_request_problem(const std::string& path, double fps);

/// The most frames an animation holds: an hour of simulated time at 10 frames per second.
constexpr int kMaxAnimationFrames = 36000;

/// The sample intervals an animation of [0, t_end] needs at `fps` (at most kMaxAnimationFrames).
int animation_samples(double t_end, double fps);

/// Draws the samples in `options.csv` (the run just made with `options`) and writes the page to `path`,
/// atomically. Returns 0, or the exit code after saying why on stderr (after `command`): 2 where the scene is not finite at a
/// sample (its place in the model file and the time), 3 where the file cannot be written.
int write_animation(const Model& model, const animation::Scene& scene, const eomgen::sim::Options& options,
                    const std::string& path, const std::string& command = "eomgen run");

/// The most members an animated ensemble overlays (each in its own colour).
constexpr std::size_t kMaxAnimatedMembers = 12;

/// Runs one member with `options` (their own CSV, nothing printed): 0 or its exit code, with its errors.
using RunMember = std::function<int(const eomgen::sim::Options& options, std::string& errors)>;

/// The members of `design` run one by one with `run` (each `base` plus its --set and --init values) and
/// overlaid in one page at `path`, each in its colour, with a legend of their values. 2 with a message where
/// the ensemble has more than kMaxAnimatedMembers or a member fails, 3 where the page cannot be written.
int write_ensemble_animation(const Model& model, const animation::Scene& scene, const eomgen::sim::Options& base,
                             const EnsembleDesign& design, const std::string& path, const RunMember& run);

}  // namespace eomgen::cli
