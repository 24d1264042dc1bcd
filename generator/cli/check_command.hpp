/** @file check_command.hpp  `eomgen check MODEL DERIVATION.md`: the subcommand's options and its run. */
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace CLI {
class App;
}

namespace eomgen::cli {

/// Exit code of `eomgen check` when the derivation disagrees with the model somewhere (docs/checker.md).
constexpr int kExitDisagrees = 5;

/**
 * Registers `check` on the `eomgen` command line:
 *
 *     eomgen check MODEL DERIVATION.md [--section TEXT]... [--format text|markdown|json]
 *                  [--map 'NAME=VALUE']... [--map-file FILE]... [--set NAME=VALUE]... [-o FILE]
 *
 * run() loads and derives the model (a ModelError propagates, as for `show`), checks the derivation and
 * prints the report; it returns 0 when nothing disagrees, kExitDisagrees when something does, 2 for a bad
 * --map, --map-file, --set or --section, 3 when the derivation or output file cannot be read or written.
 */
class CheckCommand {
  public:
    explicit CheckCommand(CLI::App& app);
    bool selected() const;
    int run() const;

  private:
    CLI::App* command_ = nullptr;
    std::string model_, derivation_, format_ = "text", output_;
    std::vector<std::string> sections_, maps_, map_files_, sets_;
};

}  // namespace eomgen::cli
