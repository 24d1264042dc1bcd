/**
 * @file generation_timings.hpp  The time and peak memory of each phase of generating a header (`eomgen generate
 * --timings`): deriving the equations, then each function's CSE and emission, so that a regression names itself.
 */
#pragma once

#include <string>
#include <vector>

namespace eomgen::codegen {

/// Phases in the order they ran, each with its wall time and the process's peak resident memory when it ended.
struct GenerationTimings {
    struct Phase {
        std::string name;
        double seconds = 0;
        double peak_mb = 0;  ///< the process's peak resident set so far (getrusage), in MB
    };
    std::vector<Phase> phases;

    /// Records a phase that has just ended.
    void add(std::string name, double seconds);
    /// A table of the phases, headed by `what` (the model file), with the total.
    std::string table(const std::string& what) const;
};

/// Times the phases of one header: `lap(name)` ends the phase begun at the previous lap (or at construction).
/// With no GenerationTimings to write into it does nothing.
class PhaseClock {
  public:
    explicit PhaseClock(GenerationTimings* out);
    void lap(const std::string& name);

  private:
    GenerationTimings* out_;
    double start_ = 0;
};

}  // namespace eomgen::codegen
