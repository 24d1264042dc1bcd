/** @file compiled_model.cpp  Compiling generated code with the system compiler, caching, loading (dlopen). */
#include "cli/compiled_model.hpp"

#include "cli/process.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include <dlfcn.h>
#include <sys/stat.h>
#include <unistd.h>

#ifndef EOMGEN_VERSION
#define EOMGEN_VERSION "0.0.0"
#endif
#ifndef EOMGEN_RUNTIME_INCLUDE_DIR
#error "EOMGEN_RUNTIME_INCLUDE_DIR must name the runtime's include directory"
#endif
#ifndef EOMGEN_EIGEN_INCLUDE_DIR
#error "EOMGEN_EIGEN_INCLUDE_DIR must name Eigen's include directory"
#endif

namespace eomgen::cli {
namespace fs = std::filesystem;
namespace {

/// The file that holds this code: the eomgen executable, or the Python module (python/) that links it. A
/// rebuilt generator is a new cache key; the executable is named by /proc/self/exe, which is canonical.
fs::path generator_binary() {
    Dl_info info{};
    std::error_code ec;
    if (::dladdr(reinterpret_cast<void*>(&generator_binary), &info) != 0 && info.dli_fname != nullptr &&
        info.dli_fname[0] == '/') {
        const fs::path self = fs::canonical(info.dli_fname, ec);
        if (!ec) return self;
    }
    return fs::read_symlink("/proc/self/exe", ec);
}

/// The runtime's headers: beside an installed eomgen (<prefix>/bin/eomgen or
/// <prefix>/lib/python3.X/dist-packages/eomgen/_eomgen*.so, with <prefix>/include/eomgen/), else those of the source
/// tree this eomgen was built from.
const std::string& runtime_include_dir() {
    static const std::string dir = [] {
        std::error_code ec;
        const auto has_runtime = [&ec](const fs::path& include) {
            return fs::exists(include / "eomgen" / "model_table.hpp", ec);
        };
        const auto ancestor = [](fs::path p, int levels) {
            while (levels-- > 0) p = p.parent_path();
            return p;
        };
        const fs::path exe = fs::read_symlink("/proc/self/exe", ec), module = generator_binary();
        if (has_runtime(ancestor(exe, 2) / "include")) return (ancestor(exe, 2) / "include").string();
        if (module != exe && has_runtime(ancestor(module, 5) / "include"))  // the Python module, installed
            return (ancestor(module, 5) / "include").string();
        return std::string(EOMGEN_RUNTIME_INCLUDE_DIR);
    }();
    return dir;
}

const std::vector<std::string> kFlags = {"-std=c++17", "-O2", "-DNDEBUG", "-fPIC", "-shared",
                                         "-fvisibility=hidden"};

/// 128 bits of FNV-1a (two 64-bit streams with different offsets): a cache key, not a signature; what
/// guards the cache against others is its 0700 mode and the ownership checks.
class Hasher {
  public:
    void add(std::string_view s) {
        for (const char c : s) {
            a_ = (a_ ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
            b_ = (b_ ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
        }
        a_ = (a_ ^ 0xff) * 0x100000001b3ULL;  // field separator
        b_ = (b_ ^ 0xfe) * 0x100000001b3ULL;
    }
    std::string hex() const {
        char buf[40];
        std::snprintf(buf, sizeof buf, "%016llx%016llx", static_cast<unsigned long long>(a_),
                      static_cast<unsigned long long>(b_));
        return buf;
    }

  private:
    std::uint64_t a_ = 0xcbf29ce484222325ULL, b_ = 0x84222325cbf29ce4ULL;
};

/// $CXX split at blanks (no shell: quotes and $ are ordinary characters), else "c++".
std::vector<std::string> compiler_command() {
    std::vector<std::string> words;
    const char* cxx = std::getenv("CXX");
    std::istringstream in(cxx && *cxx ? cxx : "c++");
    for (std::string w; in >> w;) words.push_back(w);
    if (words.empty()) words.push_back("c++");
    return words;
}

/// Where a program name resolves on $PATH (or the name itself when it holds a slash or is not found).
std::string resolve(const std::string& program) {
    if (program.find('/') != std::string::npos) return program;
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "/usr/bin:/bin");
    for (std::string d; std::getline(dirs, d, ':');) {
        const fs::path p = fs::path(d.empty() ? "." : d) / program;
        if (::access(p.c_str(), X_OK) == 0) return p.string();
    }
    return program;
}

std::string describe_file(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return path + " (missing)";
    return path + " " + std::to_string(st.st_size) + " " + std::to_string(st.st_mtime);
}

/// Everything the compiled code depends on: the model file, eomgen, the runtime's headers, the compiler, flags.
std::string cache_key(const CompileRequest& r, const std::vector<std::string>& compiler) {
    Hasher h;
    h.add(EOMGEN_VERSION);
    h.add(describe_file(generator_binary().string()));  // a rebuilt generator
    h.add(r.model_text);
    h.add(r.model_name);
    h.add(r.jacobian ? "with jacobian" : "");
    std::vector<fs::path> runtime;
    for (const auto& e : fs::directory_iterator(fs::path(runtime_include_dir()) / "eomgen"))
        runtime.push_back(e.path());
    std::sort(runtime.begin(), runtime.end());
    for (const fs::path& p : runtime) {
        h.add(p.filename().string());
        h.add(read_file(p));
    }
    for (const std::string& w : compiler) h.add(w);
    h.add(describe_file(resolve(compiler.front())));
    for (const std::string& f : kFlags) h.add(f);
    h.add(EOMGEN_EIGEN_INCLUDE_DIR);
    return h.hex();
}

std::string entry_source(const std::string& model_name, const std::string& key, bool jacobian) {
    return "// eomgen run: the generated model's functions as a table (eomgen/model_table.hpp); the driver is eomgen's.\n"
           "#include \"model.hpp\"\n#include \"eomgen/model_table.hpp\"\n\n"
           "extern \"C\" __attribute__((visibility(\"default\"))) const char eomgen_entry_key[] = \"" + key + "\";\n"
           "extern \"C\" __attribute__((visibility(\"default\"))) const eomgen::ModelTable* eomgen_model_table() {\n"
           "    return &eomgen::model_table<eomgen::models::" + model_name + "::Model<double>" +
           (jacobian ? ", true" : "") + ">();\n}\n";
}

void write_file(const fs::path& p, const std::string& text) {
    std::ofstream out(p, std::ios::binary);
    out << text;
    out.flush();
    if (!out) throw CacheError("cannot write " + p.string());
}

std::string joined(const std::vector<std::string>& argv) {
    std::string s;
    for (const std::string& a : argv) s += (s.empty() ? "" : " ") + a;
    return s;
}

/// Refuses a path that is a symbolic link or not owned by us, and a directory others may write.
void check_safe(const fs::path& p, bool directory) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0) throw CacheError("cannot inspect " + p.string() + ": " + std::strerror(errno));
    if (S_ISLNK(st.st_mode)) throw CacheError(p.string() + " is a symbolic link; eomgen refuses to use it");
    if (st.st_uid != ::geteuid()) throw CacheError(p.string() + " belongs to another user; eomgen refuses to use it");
    if (directory && (st.st_mode & (S_IWGRP | S_IWOTH)))
        throw CacheError(p.string() + " is writable by other users; eomgen refuses to use it (chmod 700 it)");
}

CompiledModel load(const fs::path& so, const std::string& key) {
    void* handle = ::dlopen(so.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) throw CacheError("cannot load " + so.string() + ": " + ::dlerror());
    const auto* stored = static_cast<const char*>(::dlsym(handle, "eomgen_entry_key"));
    using TableEntry = const eomgen::ModelTable* (*)();
    auto* entry = reinterpret_cast<TableEntry>(::dlsym(handle, "eomgen_model_table"));
    if (!stored || !entry || key != stored) {
        ::dlclose(handle);
        throw CacheError(so.string() + " is not the entry for this model (its key does not match)");
    }
    return {entry(), false, so.string(), 0};
}

/// Compiles the request into `dir`/model.so; returns the compiler's time. On failure the log is kept as
/// `logs`/<key>.log (the directory itself goes with its owner) and CompileError names it.
double build(const CompileRequest& r, const std::string& key, const fs::path& dir, const fs::path& logs) {
    write_file(dir / "model.hpp", r.header());
    write_file(dir / "model.cpp", entry_source(r.model_name, key, r.jacobian));
    std::vector<std::string> argv = compiler_command();
    argv.insert(argv.end(), kFlags.begin(), kFlags.end());
    for (const std::string& inc : {runtime_include_dir(), std::string(EOMGEN_EIGEN_INCLUDE_DIR)})
        argv.push_back("-I" + inc);
    argv.push_back("-o");
    argv.push_back((dir / "model.so").string());
    argv.push_back((dir / "model.cpp").string());
    const fs::path log = dir / "compile.log";
    if (r.progress) r.progress("compiling " + r.model_name + " (" + argv.front() + ")");
    const auto start = std::chrono::steady_clock::now();
    int status = 0;
    try {
        status = run_program(argv, log);
    } catch (const ProgramNotStarted& e) {
        throw CompileError("cannot start the C++ compiler '" + argv[0] + "': " + e.what() +
                               " (set CXX to a C++17 compiler, or install g++)",
                           joined(argv), log.string());
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (status != 0 || !fs::exists(dir / "model.so")) {
        std::error_code ec;
        fs::create_directories(logs, ec);
        const fs::path kept = logs / (key + ".log");
        fs::rename(log, kept, ec);
        throw CompileError("the C++ compiler failed (exit " + std::to_string(status) + ")", joined(argv),
                           (ec ? log : kept).string());
    }
    return seconds;
}

}  // namespace

std::string text_hash(const std::string& text) {
    Hasher h;
    h.add(text);
    return h.hex();
}

fs::path cache_directory() {
    fs::path base;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg == '/')
        base = xdg;
    else if (const char* home = std::getenv("HOME"); home && *home)
        base = fs::path(home) / ".cache";
    else
        throw CacheError("neither XDG_CACHE_HOME nor HOME is set: no place for the cache (use --no-cache)");
    std::error_code ec;
    fs::create_directories(base, ec);
    const fs::path dir = base / "eomgen";
    if (::mkdir(dir.c_str(), 0700) != 0 && errno != EEXIST)
        throw CacheError("cannot create " + dir.string() + ": " + std::strerror(errno));
    check_safe(dir, true);
    return dir;
}

CompiledModel compile_model(const CompileRequest& r) {
    const std::string key = cache_key(r, compiler_command());
    if (!r.use_cache) {
        const char* tmp = std::getenv("TMPDIR");
        const fs::path parent = tmp && *tmp ? tmp : "/tmp";
        TempDir dir(parent, "eomgen-run.");
        const double seconds = build(r, key, dir.path(), parent);
        CompiledModel m = load(dir.path() / "model.so", key);  // stays mapped when the directory goes
        m.compile_seconds = seconds;
        return m;
    }
    const fs::path cache = cache_directory();
    const fs::path entry = cache / (key + ".so");
    struct stat st {};
    if (::lstat(entry.c_str(), &st) == 0) {
        check_safe(entry, false);
        CompiledModel m = load(entry, key);
        m.from_cache = true;
        return m;
    }
    double seconds = 0;
    {
        TempDir dir(cache, "tmp.");
        seconds = build(r, key, dir.path(), cache / "logs");
        std::error_code ec;
        fs::rename(dir.path() / "model.so", entry, ec);  // atomic: another run may have put the same entry first
    }
    CompiledModel m = load(entry, key);
    m.compile_seconds = seconds;
    return m;
}

std::size_t clear_cache() {
    const fs::path cache = cache_directory();
    std::size_t removed = 0;
    for (const auto& e : fs::directory_iterator(cache)) {
        const std::string name = e.path().filename().string();
        const bool ours = name == "logs" || name.rfind("tmp.", 0) == 0 ||
                          (name.size() == 35 && name.substr(32) == ".so");
        if (!ours) continue;
        std::error_code ec;
        removed += static_cast<std::size_t>(fs::remove_all(e.path(), ec));
    }
    return removed;
}

}  // namespace eomgen::cli
