// Drives a libFuzzer entry point without libFuzzer (g++, ctest): every file of the corpus paths given,
// then --random N inputs of random bytes (biased towards the characters that break escaping) and
// --mutate N mutations of the corpus files (bytes inserted, deleted, replaced with tokens of the --dict
// file, and pieces of two files spliced), all from --seed S. An input that takes longer than --slow
// seconds of processor time (default 10) fails the run: every command must answer in bounded time.
// Exit 0 when every input passed; a failing input aborts inside the harness with its report.
#include <algorithm>
#include <chrono>
#include <ctime>
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

double slow_seconds = 10;
double slowest = 0;

/// Processor time of this process: the limit is on the work an input takes, which a loaded machine does not
/// stretch (a run at nice 19 beside a build waited 26 s of wall time for 3 s of work).
double cpu_seconds() { return double(std::clock()) / CLOCKS_PER_SEC; }

void run(const std::string& bytes) {
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = cpu_seconds();
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    const double s = cpu_seconds() - cpu_start;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    slowest = std::max(slowest, s);
    if (s > slow_seconds) {
        std::cerr << "standalone fuzz driver: an input took " << s << " s of processor time (" << wall
                  << " s of wall time; limit " << slow_seconds << " s):\n--- input ---\n"
                  << bytes << "\n";
        std::exit(1);
    }
}

std::string read(const std::filesystem::path& f) {
    std::ifstream in(f, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

/// The tokens of a libFuzzer dictionary: lines `"token"` or `name="token"`, with \\, \" and \xNN escapes.
std::vector<std::string> read_dict(const std::filesystem::path& f) {
    std::vector<std::string> out;
    std::ifstream in(f);
    for (std::string line; std::getline(in, line);) {
        const auto open = line.find('"');
        if (line.empty() || line[0] == '#' || open == std::string::npos) continue;
        std::string token;
        for (std::size_t i = open + 1; i < line.size() && line[i] != '"'; ++i) {
            if (line[i] == '\\' && i + 1 < line.size()) {
                if (line[i + 1] == 'x' && i + 3 < line.size()) {
                    token += char(std::stoi(line.substr(i + 2, 2), nullptr, 16));
                    i += 3;
                } else {
                    token += line[++i];
                }
            } else {
                token += line[i];
            }
        }
        out.push_back(token);
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    long random = 0, mutate = 0;
    unsigned seed = 1;
    std::vector<std::filesystem::path> files;
    std::vector<std::string> dict;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--random" && i + 1 < argc) {
            random = std::atol(argv[++i]);
        } else if (a == "--mutate" && i + 1 < argc) {
            mutate = std::atol(argv[++i]);
        } else if (a == "--seed" && i + 1 < argc) {
            seed = static_cast<unsigned>(std::atol(argv[++i]));
        } else if (a == "--slow" && i + 1 < argc) {
            slow_seconds = std::atof(argv[++i]);
        } else if (a == "--dict" && i + 1 < argc) {
            dict = read_dict(argv[++i]);
        } else if (std::filesystem::is_directory(a)) {
            for (const auto& e : std::filesystem::directory_iterator(a))
                if (e.is_regular_file()) files.push_back(e.path());
        } else {
            files.push_back(a);
        }
    }
    std::sort(files.begin(), files.end());  // the same inputs in the same order on every file system
    std::vector<std::string> corpus;
    for (const auto& f : files) corpus.push_back(read(f));
    long count = 0;
    for (const std::string& c : corpus) {
        run(c);
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
    for (long k = 0; k < mutate && !corpus.empty(); ++k) {
        std::string bytes = corpus[rng() % corpus.size()];
        const int edits = 1 + int(rng() % 6);
        for (int e = 0; e < edits; ++e) {
            const std::size_t at = bytes.empty() ? 0 : rng() % (bytes.size() + 1);
            const std::string token = !dict.empty() && rng() % 2 ? dict[rng() % dict.size()]
                                                                  : std::string(1, specials[rng() % specials.size()]);
            switch (rng() % 4) {
                case 0:
                    bytes.insert(at, token);
                    break;
                case 1:
                    bytes.erase(at, 1 + rng() % 8);
                    break;
                case 2:
                    bytes.replace(at, token.size(), token);
                    break;
                default: {  // a piece of another corpus file
                    const std::string& other = corpus[rng() % corpus.size()];
                    const std::size_t from = other.empty() ? 0 : rng() % other.size();
                    bytes.insert(at, other.substr(from, 1 + rng() % 200));
                }
            }
        }
        run(bytes);
        ++count;
    }
    std::cout << "standalone fuzz driver: " << count << " inputs, none failed; the slowest took " << slowest
              << " s of processor time\n";
    return 0;
}
