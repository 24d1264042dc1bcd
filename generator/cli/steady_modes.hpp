/** @file steady_modes.hpp  `eomgen modes --steady NAME_dot=EXPR`: the linear equations about a steady motion
 * (mechanics/steady_motion.hpp), their split by a speed parameter, and a sweep of the eigenvalues. */
#pragma once

#include <map>
#include <string>
#include <vector>

namespace eomgen {
struct Model;
struct Equations;
}  // namespace eomgen

namespace eomgen::cli {

struct SteadyRequest {
    std::vector<std::string> steady;     ///< NAME_dot=EXPR
    std::string motion;                  ///< the model's [[motions]] entry they come from, or ""
    std::map<std::string, double> set;   ///< --set, SI
    std::map<std::string, double> at;    ///< --at
    std::string speed;                   ///< --speed: the parameter C and K are split by ("" : the one in --steady)
    std::string sweep;                   ///< --sweep NAME=START:STOP:COUNT
    std::string plot;                    ///< --plot FILE.png|svg: the sweep's root locus
    std::string format = "text";         ///< text or json
};

/// The report as text; throws ModesError for a bad request or a steady motion that cannot be found.
std::string steady_modes(const Model& model, const Equations& eq, const SteadyRequest& request);

}  // namespace eomgen::cli
