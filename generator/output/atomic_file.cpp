/** @file atomic_file.cpp  AtomicFile, and the signal handler that removes unfinished temporaries. */
#include "output/atomic_file.hpp"

#include "eomgen/output.hpp"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <unistd.h>

namespace eomgen::output {
namespace {

// Temporaries being written, as C strings a signal handler may read: only unlink() and raise() are
// called there, both async-signal-safe. A slot is claimed before the file is created and freed after the
// rename, so the handler never removes a file that has become the target.
constexpr int kSlots = 16;
constexpr std::size_t kPathMax = 4096;
char pending[kSlots][kPathMax];
volatile std::sig_atomic_t in_use[kSlots];

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
struct sigaction previous[sizeof kSignals / sizeof kSignals[0]];

extern "C" void remove_pending_and_reraise(int sig) {
    for (int i = 0; i < kSlots; ++i)
        if (in_use[i]) ::unlink(pending[i]);
    // Then whatever the signal did before: end the process, or the program's own handler.
    for (std::size_t k = 0; k < sizeof kSignals / sizeof kSignals[0]; ++k)
        if (kSignals[k] == sig) sigaction(sig, &previous[k], nullptr);
    std::raise(sig);
}

/// Puts the handler in front of what each signal does now, unless it is there or the signal is ignored
/// (nohup). Checked at every file: a program may have set its own handlers since.
void install_handlers() {
    for (std::size_t k = 0; k < sizeof kSignals / sizeof kSignals[0]; ++k) {
        struct sigaction current {};
        sigaction(kSignals[k], nullptr, &current);
        if (current.sa_handler == SIG_IGN || current.sa_handler == remove_pending_and_reraise) continue;
        previous[k] = current;
        struct sigaction sa {};
        sa.sa_handler = remove_pending_and_reraise;
        sigemptyset(&sa.sa_mask);
        sigaction(kSignals[k], &sa, nullptr);
    }
}

int claim(const std::filesystem::path& tmp) {
    const std::string s = tmp.string();
    if (s.size() >= kPathMax) return -1;  // still written atomically; only not cleaned up on a signal
    for (int i = 0; i < kSlots; ++i) {
        if (in_use[i]) continue;
        std::memcpy(pending[i], s.c_str(), s.size() + 1);
        in_use[i] = 1;
        return i;
    }
    return -1;
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path path)
    : path_(std::move(path)), tmp_(path_.string() + ".tmp." + std::to_string(::getpid())) {
    install_handlers();
    slot_ = claim(tmp_);
    out_.open(tmp_, std::ios::binary);
    if (!out_) {
        if (slot_ >= 0) in_use[slot_] = 0;
        throw WriteError("cannot write " + tmp_.string() + ": " + std::strerror(errno));
    }
}

AtomicFile::~AtomicFile() {
    if (committed_) return;
    out_.close();
    std::error_code ec;
    std::filesystem::remove(tmp_, ec);
    if (slot_ >= 0) in_use[slot_] = 0;
}

void AtomicFile::write(const std::string& text) {
    out_ << text;
    if (!out_) throw WriteError("cannot write " + tmp_.string());
}

void AtomicFile::commit() {
    out_.flush();
    out_.close();
    if (!out_) throw WriteError("cannot write " + tmp_.string());
    std::error_code ec;
    std::filesystem::rename(tmp_, path_, ec);
    if (ec) throw WriteError("cannot rename " + tmp_.string() + " to " + path_.string() + ": " + ec.message());
    committed_ = true;
    if (slot_ >= 0) in_use[slot_] = 0;
}

void guard_temporary(const char* path) {
    install_handlers();
    claim(path);
}

void release_temporary(const char* path) {
    for (int i = 0; i < kSlots; ++i)
        if (in_use[i] && std::strcmp(pending[i], path) == 0) {
            in_use[i] = 0;
            return;
        }
}

void guard_runtime_temporaries() {
    eomgen::temporary_file_hooks() = {guard_temporary, release_temporary};
}

void write_atomically(const std::filesystem::path& path, const std::string& text) {
    AtomicFile f(path);
    f.write(text);
    f.commit();
}

}  // namespace eomgen::output
