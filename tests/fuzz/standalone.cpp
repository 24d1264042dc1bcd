// Drives a libFuzzer entry point without libFuzzer (g++, ctest): every file of the corpus paths given,
// then --random N inputs from --seed S (random bytes, biased towards the characters that break escaping).
// Exit 0 when every input passed; a failing input aborts inside the harness with its report.
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

int run(const std::string& bytes) {
    return LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

}  // namespace

int main(int argc, char** argv) {
    long random = 0;
    unsigned seed = 1;
    std::vector<std::filesystem::path> files;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--random" && i + 1 < argc) {
            random = std::atol(argv[++i]);
        } else if (a == "--seed" && i + 1 < argc) {
            seed = static_cast<unsigned>(std::atol(argv[++i]));
        } else if (std::filesystem::is_directory(a)) {
            for (const auto& e : std::filesystem::directory_iterator(a)) files.push_back(e.path());
        } else {
            files.push_back(a);
        }
    }
    long count = 0;
    for (const auto& f : files) {
        std::ifstream in(f, std::ios::binary);
        run(std::string(std::istreambuf_iterator<char>(in), {}));
        ++count;
    }
    static const std::string specials =
        std::string("*/\\\n\r\"'?$%#&^_~{}<>|`[]\x7f") + "\xc2\x85\xe2\x80\xa8\xff" + std::string(1, '\0');
    std::mt19937 rng(seed);
    for (long k = 0; k < random; ++k) {
        std::string bytes;
        const int n = int(rng() % 160);
        // Half the inputs without control characters, which the loader accepts: they test the escaping;
        // the other half anything, which mostly tests that refusals come with their line and column.
        const bool printable = k % 2 == 0;
        for (int i = 0; i < n; ++i) {
            const unsigned r = rng() % 8;
            if (printable)
                bytes += r < 4 ? std::string(1, "*/\\\"'?$%#&^_~{}<>|`[]"[rng() % 21])
                               : r < 5 ? std::string("\xe2\x80\xa8") : std::string(1, char(' ' + rng() % 95));
            else
                bytes += r < 3 ? specials[rng() % specials.size()] : r < 5 ? char('a' + rng() % 26) : char(rng() % 256);
        }
        run(bytes);
        ++count;
    }
    std::cout << "standalone fuzz driver: " << count << " inputs, none failed\n";
    return 0;
}
