/** @file process.hpp  Programs started without a shell, and private temporary directories, for `eomgen run`. */
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace eomgen::cli {

/// The program could not be started at all (not found, not executable): `reason` says why.
struct ProgramNotStarted : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/**
 * Runs argv[0] (looked up on $PATH) with the arguments argv[1..], never through a shell, standard input
 * from /dev/null, standard output and error into `log` (created 0600). Returns its exit status (128 + the
 * signal when killed); throws ProgramNotStarted when it cannot be started.
 */
int run_program(const std::vector<std::string>& argv, const std::filesystem::path& log);

/// The bytes of a file ("" when it cannot be read): logs and headers for messages and hashes.
std::string read_file(const std::filesystem::path& path);

/// A temporary directory could not be made.
struct TempDirError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// A new directory `parent/<prefix>XXXXXX` made by mkdtemp (mode 0700), removed with what it holds when the
/// object goes. Throws TempDirError.
class TempDir {
  public:
    TempDir(const std::filesystem::path& parent, const std::string& prefix);
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    ~TempDir();
    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
};

}  // namespace eomgen::cli
