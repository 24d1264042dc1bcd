/** @file eomgen_process.hpp  The eomgen executable run as a user runs it, for the CLI tests: started without a
 * shell, with extra environment variables, its stdout and stderr together; and the CSV it writes. */
#pragma once

#include "test_paths.hpp"
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

extern char** environ;

namespace eomgen_test {

namespace fs = std::filesystem;

struct Result {
    int code = -1;
    std::string output;  // stdout and stderr together
};

inline std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// Writes `text` to `dir`/`name` whole, by a rename: ctest -j runs a file's test cases side by side, and two of
/// them may write the same model while the other's eomgen reads it.
inline fs::path write_whole(const fs::path& dir, const std::string& name, const std::string& text) {
    fs::create_directories(dir);
    const fs::path p = dir / name;
    const fs::path tmp = dir / (name + "." + std::to_string(::getpid()) + ".tmp");
    {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        REQUIRE(out.flush());
    }
    fs::rename(tmp, p);
    return p;
}

/// Starts eomgen with `args` and extra environment variables; returns the pid (output to `log`).
inline pid_t start(const std::vector<std::string>& args, const std::map<std::string, std::string>& env, const fs::path& log) {
    std::vector<std::string> argv = {eomgen_test::eomgen_exe()};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<std::string> envs;
    for (char** e = environ; *e; ++e) {
        const std::string kv = *e;
        if (!env.count(kv.substr(0, kv.find('=')))) envs.push_back(kv);
    }
    for (const auto& [k, v] : env) envs.push_back(k + "=" + v);
    std::vector<char*> a, en;
    for (auto& s : argv) a.push_back(s.data());
    a.push_back(nullptr);
    for (auto& s : envs) en.push_back(s.data());
    en.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&fa, 1, 2);
    pid_t pid = 0;
    REQUIRE(posix_spawn(&pid, a[0], &fa, nullptr, a.data(), en.data()) == 0);
    posix_spawn_file_actions_destroy(&fa);
    return pid;
}

inline Result finish(pid_t pid, const fs::path& log) {
    int status = 0;
    waitpid(pid, &status, 0);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : 128, read(log)};
}

/// eomgen with `args`, its cache in `work`/cache unless `env` names one; waits for it.
inline Result run_eomgen(const fs::path& work, const std::vector<std::string>& args,
                         std::map<std::string, std::string> env = {}) {
    fs::create_directories(work);
    if (!env.count("XDG_CACHE_HOME")) env["XDG_CACHE_HOME"] = (work / "cache").string();
    // One log per test process: ctest -j runs a file's test cases side by side in the same `work`.
    const fs::path log = work / ("last." + std::to_string(::getpid()) + ".log");
    Result r = finish(start(args, env, log), log);
    std::error_code ec;
    fs::remove(log, ec);
    return r;
}

inline std::vector<std::vector<std::string>> read_csv(const fs::path& p) {
    std::vector<std::vector<std::string>> rows;
    std::ifstream in(p);
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> row;
        std::istringstream fields(line);
        for (std::string f; std::getline(fields, f, ',');) row.push_back(f);
        rows.push_back(row);
    }
    return rows;
}

/// The name of a CSV column whose header carries a unit: "psi [rad]" → "psi" (written here, apart from the runtime).
inline std::string column_name(const std::string& header) {
    const std::size_t open = header.rfind(" [");
    return open != std::string::npos && !header.empty() && header.back() == ']' ? header.substr(0, open) : header;
}

/// The index of column `name` ("psi" finds "psi [rad]" too).
inline int column(const std::vector<std::string>& header, const std::string& name) {
    for (std::size_t i = 0; i < header.size(); ++i)
        if (header[i] == name || column_name(header[i]) == name) return int(i);
    FAIL("no column " << name);
    return -1;
}

}  // namespace eomgen_test
