// Property tests of the escaping functions (text/escape.hpp) and of the safe set of LaTeX names: for
// random byte strings (invalid UTF-8, control characters and each language's special characters weighted
// in), the output is inert in its language and, where the language allows, decodes back to the input.
#include "model/latex_name.hpp"
#include "text/escape.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <string>
#include <vector>

using namespace eomgen::text;

namespace {

/// Random strings biased towards what breaks escaping: specials of every language, line breaks of every
/// kind (U+0085, U+2028, U+2029), broken UTF-8, and plain text around them.
std::vector<std::string> hostile_strings(unsigned seed, int count) {
    static const std::vector<std::string> pieces = {
        "*/", "/*", "//", "\\", "\n", "\r", "\v", "\f", "\t", std::string(1, '\0'), "\x7f", "\xc2\x85",
        "\xe2\x80\xa8", "\xe2\x80\xa9", "?\?/", "?\?", "?", "\"", "'", "$", "$$", "%", "#", "&", "^", "_", "~",
        "{", "}", "<", ">", "<script>", "|", "`", "[", "](", ",", "\xff", "\xc3", "\xe2\x82", "\xed\xa0\x80",
        "\xc0\xaf", "\xf4\x90\x80\x80", "é", "θ", "\\input{/etc/passwd}", "\\write18{rm -rf ~}", "#include <x>",
        "PWNED", "a", "b", " ", "1", "\\u0000", "\\n"};
    std::mt19937 rng(seed);
    std::vector<std::string> out = {""};
    for (const std::string& p : pieces) out.push_back(p);
    for (int k = 0; k < count; ++k) {
        std::string s;
        const int n = int(rng() % 12);
        for (int i = 0; i < n; ++i) {
            if (rng() % 4 == 0)
                s += static_cast<char>(rng() % 256);
            else
                s += pieces[rng() % pieces.size()];
        }
        out.push_back(s);
    }
    return out;
}

bool has_line_break_or_control(const std::string& s) {
    for (std::size_t i = 0; i < s.size();) {
        const CodePoint c = decode_utf8(s, i);
        if (c.value < 0) return true;  // not even valid UTF-8
        if (is_line_break(c.value) || c.value < 0x20 || c.value == 0x7f || (c.value >= 0x80 && c.value < 0xa0))
            return true;
        i += c.length;
    }
    return false;
}

/// Reads a C++ string literal back (the escapes cpp_string writes: \" \\ \? \n \t and \ooo).
std::string decode_cpp_string(const std::string& lit) {
    REQUIRE(lit.size() >= 2);
    REQUIRE(lit.front() == '"');
    REQUIRE(lit.back() == '"');
    std::string out;
    for (std::size_t i = 1; i + 1 < lit.size(); ++i) {
        const char c = lit[i];
        REQUIRE(c != '"');
        if (c != '\\') {
            out += c;
            continue;
        }
        const char e = lit[++i];
        if (e == 'n') out += '\n';
        else if (e == 't') out += '\t';
        else if (e >= '0' && e <= '7') {
            out += static_cast<char>((e - '0') * 64 + (lit[i + 1] - '0') * 8 + (lit[i + 2] - '0'));
            i += 2;
        } else out += e;
    }
    return out;
}

/// Reads a JSON string back (the escapes json_string writes).
std::string decode_json_string(const std::string& lit) {
    REQUIRE(lit.front() == '"');
    REQUIRE(lit.back() == '"');
    std::string out;
    for (std::size_t i = 1; i + 1 < lit.size(); ++i) {
        const char c = lit[i];
        REQUIRE(c != '"');
        if (c != '\\') {
            out += c;
            continue;
        }
        const char e = lit[++i];
        if (e == 'n') out += '\n';
        else if (e == 'r') out += '\r';
        else if (e == 't') out += '\t';
        else if (e == 'u') {
            const long cp = std::stol(lit.substr(i + 1, 4), nullptr, 16);
            i += 4;
            if (cp < 0x80) {
                out += static_cast<char>(cp);
            } else if (cp < 0x800) {
                out += static_cast<char>(0xc0 | (cp >> 6));
                out += static_cast<char>(0x80 | (cp & 0x3f));
            } else {
                out += static_cast<char>(0xe0 | (cp >> 12));
                out += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
                out += static_cast<char>(0x80 | (cp & 0x3f));
            }
        } else out += e;
    }
    return out;
}

/// Reads an RFC 4180 field back.
std::string decode_csv_field(const std::string& f) {
    if (f.empty() || f.front() != '"') {
        REQUIRE(f.find_first_of(",\"\r\n") == std::string::npos);
        return f;
    }
    REQUIRE(f.back() == '"');
    std::string out;
    for (std::size_t i = 1; i + 1 < f.size(); ++i) {
        if (f[i] == '"') {
            REQUIRE(f[i + 1] == '"');
            ++i;
        }
        out += f[i];
    }
    return out;
}

}  // namespace

TEST_CASE("cpp_comment: nothing can end the comment or continue it onto the next line", "[escape]") {
    for (const std::string& s : hostile_strings(1, 3000)) {
        const std::string c = cpp_comment(s);
        INFO("input: " << s << "\noutput: " << c);
        CHECK_FALSE(has_line_break_or_control(c));
        CHECK(c.find("*/") == std::string::npos);
        CHECK(c.find("/*") == std::string::npos);
        CHECK(c.find("??") == std::string::npos);
        CHECK((c.empty() || c.back() != '\\'));
    }
    CHECK(cpp_comment("Goldstein ch. 5, Ex. 30") == "Goldstein ch. 5, Ex. 30");  // ordinary text unchanged
    CHECK(cpp_comment("a\nb") == "a\\nb");
}

TEST_CASE("cpp_string: printable ASCII only, and it reads back as the input", "[escape]") {
    for (const std::string& s : hostile_strings(2, 3000)) {
        const std::string lit = cpp_string(s);
        INFO("input: " << s << "\noutput: " << lit);
        for (const char ch : lit) CHECK((ch >= 0x20 && ch < 0x7f));
        CHECK(lit.find("??") == std::string::npos);
        CHECK(decode_cpp_string(lit) == s);
    }
    CHECK(cpp_string("door") == "\"door\"");
}

TEST_CASE("latex_text: no special character of TeX survives unescaped", "[escape]") {
    for (const std::string& s : hostile_strings(3, 3000)) {
        const std::string l = latex_text(s);
        INFO("input: " << s << "\noutput: " << l);
        CHECK_FALSE(has_line_break_or_control(l));
        // Remove the escapes latex_text writes; what is left may hold none of the specials.
        std::string rest = l;
        for (const std::string e : {"\\textbackslash{}", "\\textasciicircum{}", "\\textasciitilde{}", "\\{", "\\}",
                                    "\\$", "\\&", "\\#", "\\%", "\\_"}) {
            for (std::size_t p; (p = rest.find(e)) != std::string::npos;) rest.replace(p, e.size(), " ");
        }
        CHECK(rest.find_first_of("\\{}$&#^_~%") == std::string::npos);
    }
    CHECK(latex_text("Goldstein ch. 5") == "Goldstein ch. 5");
    CHECK(latex_text("m_rod 50% \\input") == "m\\_rod 50\\% \\textbackslash{}input");
}

TEST_CASE("markdown_text and markdown_math: no raw HTML, no live Markdown or math delimiters", "[escape]") {
    for (const std::string& s : hostile_strings(4, 3000)) {
        for (const std::string& m : {markdown_text(s), markdown_math(s), markdown_mixed(s)}) {
            INFO("input: " << s << "\noutput: " << m);
            CHECK_FALSE(has_line_break_or_control(m));
            CHECK(m.find('<') == std::string::npos);
            CHECK(m.find('>') == std::string::npos);
        }
        const std::string t = markdown_text(s);
        for (std::size_t i = 0; i < t.size(); ++i)
            if (std::string("`*_[]|$~").find(t[i]) != std::string::npos) {
                // every such character is preceded by an odd number of backslashes
                std::size_t b = 0;
                while (b < i && t[i - 1 - b] == '\\') ++b;
                CHECK(b % 2 == 1);
            }
        const std::string m = markdown_math(s);
        for (std::size_t i = 0; i < m.size(); ++i)
            if (m[i] == '$' || m[i] == '|') CHECK((i > 0 && m[i - 1] == '\\'));
    }
    CHECK(markdown_mixed("compared with $T_{disk}$, a part of $T$") == "compared with $T_{disk}$, a part of $T$");
}

TEST_CASE("json_string: valid UTF-8 without control characters, reading back as the valid part", "[escape]") {
    for (const std::string& s : hostile_strings(5, 3000)) {
        const std::string j = json_string(s);
        INFO("input: " << s << "\noutput: " << j);
        CHECK_FALSE(has_line_break_or_control(j));
        CHECK(decode_json_string(j) == valid_utf8(s));
    }
    CHECK(json_string("\xff") == "\"\xEF\xBF\xBD\"");
}

TEST_CASE("csv_field: RFC 4180, reading back as the (valid UTF-8) input", "[escape]") {
    for (const std::string& s : hostile_strings(6, 3000)) {
        const std::string f = csv_field(s);
        INFO("input: " << s << "\noutput: " << f);
        CHECK(decode_csv_field(f) == valid_utf8(s));
    }
    CHECK(csv_field("theta") == "theta");
    CHECK(csv_field("a,b") == "\"a,b\"");
}

TEST_CASE("LaTeX names: the documented safe set and nothing else", "[escape][latex]") {
    for (const char* ok : {"\\theta", "I_{3}'", "\\omega_{z}", "\\dot{x}", "\\mathrm{m}_{\\text{rod}}", "\\ell",
                           "x^{2}", "\\hat{\\mathbf{e}}_r", "\\Omega", "I'", "\\,a"})
        CHECK(eomgen::latex_name_problem(ok).message.empty());
    struct Bad {
        const char* text;
        std::size_t offset;
    };
    for (const Bad& b : {Bad{"\\input{/etc/passwd}", 0}, Bad{"x\\write18{ls}", 1}, Bad{"\\catcode", 0},
                         Bad{"a$b", 1}, Bad{"50%", 2}, Bad{"#1", 0}, Bad{"a&b", 1}, Bad{"~", 0}, Bad{"}{", 0},
                         Bad{"{x", 2}, Bad{"\\", 0}, Bad{"x\ny", 1}, Bad{"\xce\xb8", 0}, Bad{"\\def\\x", 0},
                         Bad{"", 0}}) {
        const eomgen::LatexNameProblem p = eomgen::latex_name_problem(b.text);
        INFO(b.text);
        CHECK_FALSE(p.message.empty());
        CHECK(p.offset == b.offset);
    }
    // Random strings: whatever is accepted holds no byte outside the safe alphabet and balanced braces.
    for (const std::string& s : hostile_strings(7, 3000)) {
        if (!eomgen::latex_name_problem(s).message.empty()) continue;
        INFO(s);
        int depth = 0;
        for (std::size_t i = 0; i < s.size(); ++i) {
            const char c = s[i];
            CHECK(std::string("$%#&~\n\r\t").find(c) == std::string::npos);
            CHECK(static_cast<unsigned char>(c) < 0x80);
            if (c == '\\') {
                ++i;  // a control symbol such as \} is no group delimiter
                continue;
            }
            depth += c == '{' ? 1 : c == '}' ? -1 : 0;
            CHECK(depth >= 0);
        }
        CHECK(s.find("\\input") == std::string::npos);
        CHECK(depth == 0);
    }
}
