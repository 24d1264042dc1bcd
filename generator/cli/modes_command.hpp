/** @file modes_command.hpp  `eomgen modes MODEL.toml`: equilibria, linearization, normal modes, stability. */
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace eomgen {
struct Model;
struct Equations;
struct ModesResult;
}  // namespace eomgen

namespace eomgen::cli {

/// The modes as `eomgen modes --format markdown` writes them (also a section of `eomgen report`).
std::string modes_markdown(const Model& model, const ModesResult& result);

/// One line per equilibrium, as plain text (for the report's LaTeX form, which escapes it).
std::vector<std::string> modes_summary(const Model& model, const ModesResult& result);

/// `eomgen show`'s section: the equilibria with the model's values, their stability and frequencies, one line
/// each; or why there are none to show (a moving or nonholonomic constraint, more than 8 coordinates: then it
/// points to `eomgen modes`).
std::string modes_show_section(const Model& model, const Equations& eq);

/**
 * Registers `modes` on the `eomgen` command line:
 *
 *     eomgen modes MODEL.toml [--set p=v ...] [--at q=v[,q2=v ...] ...] [--momentum p_q=v ...]
 *                  [--input PARAM ...] [--format text|markdown|json] [-o FILE]
 *     eomgen modes MODEL.toml (--steady NAME_dot=EXPR ... | --motion NAME) [--speed P] [--sweep P=START:STOP:COUNT [--plot FILE]] [--set ...] [--at ...]
 *
 * run() derives the model (a ModelError propagates: exit 1), finds its equilibria and linearizes about each
 * (mechanics/small_oscillations.hpp) and prints them; with --steady, about that steady motion instead
 * (mechanics/steady_motion.hpp, cli/steady_modes.hpp). Returns 0; 2 for a bad option or a model it cannot
 * linearize (the message says why); 3 when the output file cannot be written.
 */
class ModesCommand {
  public:
    explicit ModesCommand(CLI::App& app);
    bool selected() const;
    int run() const;

  private:
    CLI::App* command_ = nullptr;
    std::string model_, format_ = "text", output_;
    std::vector<std::string> set_, at_, momentum_, inputs_, steady_;
    std::string speed_, sweep_, plot_, motion_;
};

}  // namespace eomgen::cli
