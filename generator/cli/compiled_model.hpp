/**
 * @file compiled_model.hpp  A generated header compiled into a shared object for `eomgen run`, cached.
 *
 * The compiler ($CXX, else c++) is started with an argument vector, never through a shell. The cache lives
 * in $XDG_CACHE_HOME/eomgen (default ~/.cache/eomgen), created with mode 0700; a cache directory that is
 * not ours or is writable by others, and an entry that is a symbolic link, are refused. An entry is
 * <key>.so, holding the model's functions only (model_table.hpp: the driver is eomgen's own), where the key hashes the model file, eomgen (version, executable's size and time), the runtime's
 * headers, the compiler (path, size, time) and the flags, so that a cached run neither derives nor compiles; it is built in a mkdtemp directory and renamed into place, so concurrent or interrupted
 * runs never leave a broken entry, and it is loaded only when the key it carries matches.
 */
#pragma once

#include "eomgen/model_table.hpp"

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>

namespace eomgen::cli {

/// The compiler is missing or failed: the command as run and the path of its full log (exit 4).
struct CompileError : std::runtime_error {
    CompileError(const std::string& what, std::string command, std::string log)
        : std::runtime_error(what), command(std::move(command)), log(std::move(log)) {}
    std::string command, log;
};

/// The cache directory cannot be used safely or at all (exit 3).
struct CacheError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// A compiled model: its functions (model_table.hpp), integrated by the driver compiled into eomgen.
struct CompiledModel {
    const eomgen::ModelTable* table = nullptr;
    bool from_cache = false;   ///< true when no compiler was started
    std::string path;          ///< the shared object loaded
    double compile_seconds = 0;
};

struct CompileRequest {
    std::string model_text;   ///< the model file's bytes: with eomgen itself, what the cache key hashes
    std::string model_name;   ///< the namespace of its generated code, eomgen::models::<name>
    std::function<std::string()> header;  ///< derives and emits the header: called only when compiling
    bool use_cache = true;
    std::function<void(const std::string&)> progress;  ///< "compiling ..." messages, may be empty
    bool jacobian = false;  ///< compile the table's Jacobian too (--method radau5): a separate cache entry
};

/// 128 bits of FNV-1a of `text` in hex (the cache key's hash): what identifies a model file in a table's metadata.
std::string text_hash(const std::string& text);

/// The cache directory, created (0700) and checked; throws CacheError when unsafe.
std::filesystem::path cache_directory();

/// Loads the model's shared object from the cache, or compiles it (and caches it unless use_cache is false).
CompiledModel compile_model(const CompileRequest& request);

/// Removes every entry, temporary directory and log of the cache; returns how many files it removed.
std::size_t clear_cache();

}  // namespace eomgen::cli
