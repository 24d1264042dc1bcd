/**
 * @file ensemble_design.hpp  Which members an `eomgen run` ensemble has: a grid of --sweep values (the
 * cartesian product, the first --sweep outermost) or --sample N members drawn from --dist distributions
 * with --seed. A member's values are a function of its index alone, so any thread or MPI rank makes the
 * same member i, and a seeded Monte Carlo run is the same table whatever the threads.
 *
 *     --sweep NAME=START:STOP:COUNT   COUNT values from START to STOP, evenly spaced (COUNT = 1: START)
 *     --sweep NAME=v1,v2,...          these values
 *     --sample N --dist NAME=uniform(a,b) --dist NAME=normal(mu,sigma) [--seed S]
 *
 * NAME is a parameter or a state (a coordinate q, or q_dot) of the model; numbers as sim::parse_value
 * reads them (-pi/2, 1e-3). Member i's draw of the k-th --dist comes from a SplitMix64 stream seeded by
 * (S, i, k), uniform from its top 53 bits, normal by Box–Muller: the same on every platform, unlike the
 * standard library's distributions.
 */
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace eomgen::cli {

/// What a model lets an ensemble vary: its parameter and state names.
struct EnsembleNames {
    std::vector<std::string> params, states;
};

/// A swept or sampled quantity: parameter `index`, or state `index` (its initial value).
struct EnsembleVariable {
    std::string name;
    bool is_state = false;
    int index = 0;
};

/// The members of an ensemble, from the command line's --sweep, --sample, --dist and --seed.
class EnsembleDesign {
  public:
    struct Request {
        std::vector<std::string> sweeps;  ///< each NAME=START:STOP:COUNT or NAME=v1,v2,...
        long long sample = -1;            ///< --sample N (-1: not given)
        std::vector<std::string> dists;   ///< each NAME=uniform(a,b) or NAME=normal(mu,sigma)
        std::uint64_t seed = 0;
        bool seed_given = false;
    };

    /// Reads the request against the model's names; throws sim::UsageError with the option and the reason
    /// (unknown name with "did you mean", malformed range, COUNT 0, a name given twice, ...).
    EnsembleDesign(const Request& request, const EnsembleNames& names);

    /// True when the request names an ensemble at all (some --sweep, --sample or --dist).
    static bool requested(const Request& request) {
        return !request.sweeps.empty() || request.sample != -1 || !request.dists.empty();
    }

    std::size_t size() const { return size_; }
    const std::vector<EnsembleVariable>& variables() const { return variables_; }

    /// Member i's value of each variable, in the order of variables().
    std::vector<double> values(std::size_t member) const;

    /// "grid 3 x 4 over theta, w" or "1000 samples of m, g (seed 7)".
    std::string describe() const;

  private:
    struct Distribution {
        bool normal = false;
        double a = 0, b = 0;  ///< uniform on [a, b), or normal with mean a and deviation b
    };
    std::vector<EnsembleVariable> variables_;
    std::vector<std::vector<double>> grid_;  ///< one list of values per variable (grid)
    std::vector<Distribution> dists_;        ///< one per variable (sample)
    std::uint64_t seed_ = 0;
    std::size_t size_ = 0;
};

/// SplitMix64's output function (Steele, Lea, Flood 2014): a 64-bit mix, used to seed and step the draws.
std::uint64_t splitmix64(std::uint64_t x);

}  // namespace eomgen::cli
