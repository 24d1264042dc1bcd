// Fuzz property of issue 19: whatever text a model file puts in its free-text fields (title, source,
// description, each parameter's, a coordinate's and an output's description), the generated header's tokens outside
// comments and string literals are exactly those of the same model with empty text fields; a field
// the loader refuses is refused with its file:line:col. libFuzzer entry point; tests/fuzz/standalone.cpp
// drives it without libFuzzer (ctest's bounded run).
#include "codegen/cpp_emitter.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model_file.hpp"
#include "text/escape.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace {

/// A TOML basic string holding `bytes`: quotes and backslashes escaped, other ASCII controls as \uXXXX,
/// bytes from 0x80 copied when `raw` (invalid UTF-8 makes the file invalid TOML, which the loader must
/// report), else as valid UTF-8 (broken sequences as U+FFFD), so that non-ASCII text reaches the escaping.
std::string toml_string(const std::string& input, bool raw) {
    const std::string bytes = raw ? input : eomgen::text::valid_utf8(input);
    std::string out = "\"";
    for (const char ch : bytes) {
        const unsigned char c = static_cast<unsigned char>(ch);
        if (ch == '"' || ch == '\\') {
            out += '\\';
            out += ch;
        } else if (c < 0x20 || c == 0x7f) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out += buf;
        } else {
            out += ch;
        }
    }
    return out + "\"";
}

std::string model_text(const std::vector<std::string>& f, bool raw = false) {
    const auto toml_string = [raw](const std::string& b) { return ::toml_string(b, raw); };
    return "name = \"fuzzed\"\ntitle = " + toml_string(f[0]) + "\nsource = " + toml_string(f[1]) +
           "\ndescription = " + toml_string(f[2]) +
           // Units are read by UDUNITS-2 and refused unless they are units (tests/cli/bad/unit_code.toml): the
           // fields that were units are a coordinate's and an output's descriptions, free text like the others.
           "\n\n[[coordinates]]\nname = \"x\"\ninitial = 0.5\ndescription = " + toml_string(f[3]) + "\n\n"
           "[[parameters]]\nname = \"m\"\nvalue = 1\nunit = \"kg\"\ndescription = " +
           toml_string(f[4]) + "\n\n[[parameters]]\nname = \"k\"\nvalue = 4\nunit = \"N/m\"" +
           "\ndescription = " + toml_string(f[6]) + "\n\n[lagrangian]\nT = \"m/2*x'^2\"\nV = \"k/2*x^2\"\n" +
           "\n[outputs]\ny = { expr = \"2*x\", description = " + toml_string(f[5]) + " }\n";
}

/// The header's text outside comments and string and character literals, after line splicing (phase 2
/// of translation, which runs before comments are recognised), with runs of white space as one space.
std::string code_tokens(const std::string& header) {
    std::string src;
    for (std::size_t i = 0; i < header.size(); ++i) {
        if (header[i] == '\\' && i + 1 < header.size() && header[i + 1] == '\n') {
            ++i;
            continue;
        }
        src += header[i];
    }
    std::string out;
    auto space = [&out] {
        if (!out.empty() && out.back() != ' ') out += ' ';
    };
    for (std::size_t i = 0; i < src.size();) {
        if (src.compare(i, 2, "//") == 0) {
            while (i < src.size() && src[i] != '\n') ++i;
            space();
        } else if (src.compare(i, 2, "/*") == 0) {
            const std::size_t end = src.find("*/", i + 2);
            i = end == std::string::npos ? src.size() : end + 2;
            space();
        } else if (src[i] == '"' || src[i] == '\'') {
            const char q = src[i++];
            while (i < src.size() && src[i] != q && src[i] != '\n') i += src[i] == '\\' ? 2 : 1;
            ++i;
            out += q;  // the literal itself, not its contents
            out += q;
        } else if (src[i] == ' ' || src[i] == '\n' || src[i] == '\t') {
            space();
            ++i;
        } else {
            out += src[i++];
        }
    }
    return out;
}

const std::string& baseline() {
    static const std::string tokens = [] {
        const eomgen::Model m = eomgen::parse_model(model_text(std::vector<std::string>(7)), "fuzzed.toml");
        return code_tokens(eomgen::codegen::emit_model_header(m, eomgen::derive_equations(m), "fuzzed.toml"));
    }();
    return tokens;
}

[[noreturn]] void fail(const char* what, const std::string& text, const std::string& detail) {
    std::fprintf(stderr, "fuzz_text_fields: %s\n--- model file ---\n%s\n--- detail ---\n%s\n", what, text.c_str(),
                 detail.c_str());
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // Seven fields, each a length byte (mod 48) and that many bytes.
    std::vector<std::string> fields(7);
    std::size_t pos = 0;
    for (std::string& f : fields) {
        if (pos >= size) break;
        const std::size_t n = std::min<std::size_t>(data[pos++] % 48, size - pos);
        f.assign(reinterpret_cast<const char*>(data + pos), n);
        pos += n;
    }
    const std::string text = model_text(fields, size > 0 && data[0] % 4 == 0);  // a quarter with raw bytes
    eomgen::Model model;
    try {
        model = eomgen::parse_model(text, "fuzzed.toml");
    } catch (const eomgen::ModelError& e) {
        if (e.where().line <= 0 || e.where().column <= 0) fail("an error without its line and column", text, e.what());
        return 0;
    }
    const std::string header = eomgen::codegen::emit_model_header(model, eomgen::derive_equations(model), "fuzzed.toml");
    if (header.find('\0') != std::string::npos) fail("a NUL byte in the header", text, header);
    const std::string tokens = code_tokens(header);
    if (tokens != baseline()) fail("text from a field changed the header's code", text, header);
    // With EOMGEN_FUZZ_HEADERS=DIR, the first few accepted headers whose fields hold text are kept there,
    // for tests/fuzz/compile_headers.cmake to compile (the token property says their code is the empty
    // fields' code; compiling them checks that the comments and literals around it are well formed too).
    static int kept = 0;
    const char* dir = std::getenv("EOMGEN_FUZZ_HEADERS");
    if (dir && kept < 8 && size > 16) {
        std::ofstream(std::string(dir) + "/fuzzed_" + std::to_string(kept++) + ".hpp", std::ios::binary) << header;
    }
    return 0;
}
