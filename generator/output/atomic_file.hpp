/** @file atomic_file.hpp  Files that appear whole or not at all: written to a temporary beside the target
 * and renamed over it, and the temporary removed when writing fails, throws, or the process is interrupted
 * (SIGINT, SIGTERM, SIGHUP) half way. */
#pragma once

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace eomgen::output {

/// A file could not be written or renamed into place; what() names it and why.
struct WriteError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/**
 * A file being written: open creates `<path>.tmp.<pid>`, write appends to it, commit renames it to `path`
 * (replacing an old file in one step, so a reader sees the old or the new file, never a mix). Until commit,
 * the temporary is removed by the destructor and by a handler of SIGINT, SIGTERM and SIGHUP, put in front
 * of what the signal did before (ending the process, or the program's own handler), which it then does.
 */
class AtomicFile {
  public:
    explicit AtomicFile(std::filesystem::path path);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    void write(const std::string& text);
    void commit();

    const std::filesystem::path& temporary() const { return tmp_; }

  private:
    std::filesystem::path path_, tmp_;
    std::ofstream out_;
    int slot_ = -1;
    bool committed_ = false;
};

/// Guards a temporary file that other code writes (the runtime's CsvWriter) as AtomicFile guards its own: until
/// release_temporary(path) it is removed on SIGINT, SIGTERM and SIGHUP. At most 16 at a time with AtomicFile's;
/// beyond that, or for a path of 4096 bytes or more, the file is written as before and only not removed on a signal.
void guard_temporary(const char* path);
void release_temporary(const char* path);

/// Points the runtime's eomgen::temporary_file_hooks() (runtime/eomgen/output.hpp) at the two above: for the
/// programs that write the runtime's CSV files (the eomgen command, eomgen-sim).
void guard_runtime_temporaries();

/// AtomicFile for one piece of text.
void write_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace eomgen::output
