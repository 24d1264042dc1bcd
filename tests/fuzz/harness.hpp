// What every fuzz harness of tests/fuzz/ shares: the input as a string, and a failure that prints what
// broke with the input and aborts (libFuzzer then saves the input; the standalone driver stops there).
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace eomgen::fuzz {

inline std::string input_text(const std::uint8_t* data, std::size_t size) {
    return std::string(reinterpret_cast<const char*>(data), size);
}

[[noreturn]] inline void fail(const char* harness, const char* what, const std::string& input,
                              const std::string& detail) {
    std::fprintf(stderr, "%s: %s\n--- input ---\n%s\n--- detail ---\n%s\n", harness, what, input.c_str(),
                 detail.c_str());
    std::abort();
}

/// True when `message` begins with "<file>:<line>:<col>: " with a line and a column of at least 1.
inline bool located(const std::string& message, const std::string& file) {
    if (message.compare(0, file.size() + 1, file + ":") != 0) return false;
    std::size_t i = file.size() + 1;
    for (int field = 0; field < 2; ++field) {
        const std::size_t start = i;
        while (i < message.size() && message[i] >= '0' && message[i] <= '9') ++i;
        if (i == start || i >= message.size() || message[i] != ':' || message[start] == '0') return false;
        ++i;
    }
    return true;
}

}  // namespace eomgen::fuzz
