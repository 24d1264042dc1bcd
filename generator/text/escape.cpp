/** @file escape.cpp  Escaping for C++, LaTeX, Markdown, JSON and CSV (see escape.hpp). */
#include "text/escape.hpp"

#include "eomgen/output.hpp"

#include <cstdio>

namespace eomgen::text {
namespace {

std::string hex_byte(unsigned char c, const char* format) {
    char buf[16];
    std::snprintf(buf, sizeof buf, format, static_cast<unsigned>(c));
    return buf;
}

constexpr const char* kReplacement = "\xEF\xBF\xBD";  // U+FFFD

/**
 * `raw` as valid UTF-8 on one line, for the text formats: line breaks and tabs become a space, other control
 * characters are dropped, and each remaining ASCII character goes to `escape(ch, out)`, which appends its
 * escape and returns true, or returns false to have it copied as it is. Non-ASCII characters are copied.
 */
template <class Escape>
std::string one_line(std::string_view raw, Escape&& escape) {
    const std::string s = valid_utf8(raw);
    std::string out;
    for (std::size_t i = 0; i < s.size();) {
        const CodePoint c = decode_utf8(s, i);
        const std::string_view piece(s.data() + i, c.length);
        i += c.length;
        if (is_line_break(c.value) || c.value == '\t')
            out += ' ';
        else if (is_control(c.value))
            continue;
        else if (c.value >= 0x80 || !escape(static_cast<char>(c.value), out))
            out += piece;
    }
    return out;
}

}  // namespace

void append_utf8(std::string& out, long cp) {
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xc0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3f));
    } else if (cp < 0x10000) {
        out += static_cast<char>(0xe0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
        out += static_cast<char>(0x80 | (cp & 0x3f));
    } else {
        out += static_cast<char>(0xf0 | (cp >> 18));
        out += static_cast<char>(0x80 | ((cp >> 12) & 0x3f));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
        out += static_cast<char>(0x80 | (cp & 0x3f));
    }
}

CodePoint decode_utf8(std::string_view s, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char c = byte(i);
    if (c < 0x80) return {c, 1};
    std::size_t n = 0;
    long cp = 0, least = 0;
    if ((c & 0xe0) == 0xc0) {
        n = 2, cp = c & 0x1f, least = 0x80;
    } else if ((c & 0xf0) == 0xe0) {
        n = 3, cp = c & 0x0f, least = 0x800;
    } else if ((c & 0xf8) == 0xf0) {
        n = 4, cp = c & 0x07, least = 0x10000;
    } else {
        return {-1, 1};
    }
    if (i + n > s.size()) return {-1, 1};
    for (std::size_t k = 1; k < n; ++k) {
        if ((byte(i + k) & 0xc0) != 0x80) return {-1, 1};
        cp = (cp << 6) | (byte(i + k) & 0x3f);
    }
    if (cp < least || cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff)) return {-1, 1};
    return {cp, n};
}

bool is_control(long cp) { return (cp >= 0 && cp < 0x20) || (cp >= 0x7f && cp < 0xa0); }

bool is_line_break(long cp) {
    return cp == '\n' || cp == '\r' || cp == '\v' || cp == '\f' || cp == 0x85 || cp == 0x2028 || cp == 0x2029;
}

std::string valid_utf8(std::string_view s) {
    std::string out;
    out.reserve(s.size());
    for (std::size_t i = 0; i < s.size();) {
        const CodePoint c = decode_utf8(s, i);
        if (c.value < 0) {
            out += kReplacement;
            ++i;
            // the continuation bytes of the broken sequence belong to the same replacement
            while (i < s.size() && (static_cast<unsigned char>(s[i]) & 0xc0) == 0x80) ++i;
            continue;
        }
        out.append(s.substr(i, c.length));
        i += c.length;
    }
    return out;
}

std::string cpp_comment(std::string_view raw) {
    // Decoded as UTF-8 so that U+0085/U+2028/U+2029 are seen as the line breaks some tools take them for.
    const std::string s = valid_utf8(raw);
    std::string out;
    for (std::size_t i = 0; i < s.size();) {
        const CodePoint c = decode_utf8(s, i);
        const char ch = s[i];
        if (is_line_break(c.value)) {
            out += c.value == '\n' ? "\\n" : c.value == '\r' ? "\\r" : c.value < 0x80 ? hex_byte(s[i], "\\x%02x")
                                                                                      : " ";
        } else if (is_control(c.value)) {
            out += c.value < 0x80 ? hex_byte(static_cast<unsigned char>(ch), "\\x%02x") : "?";
        } else if ((ch == '*' && i + 1 < s.size() && s[i + 1] == '/') ||
                   (ch == '/' && i + 1 < s.size() && s[i + 1] == '*')) {
            out += ch;
            out += ' ';  // "*/" would close a block comment, "/*" warns (-Wcomment)
        } else if (ch == '?' && !out.empty() && out.back() == '?') {
            out += " ?";  // no trigraph (??/ is a backslash before C++17)
        } else {
            out.append(s, i, c.length);
        }
        i += c.length;
    }
    // A backslash (maybe followed by blanks) at the end would continue the comment onto the next line.
    std::size_t end = out.size();
    while (end > 0 && (out[end - 1] == ' ' || out[end - 1] == '\t')) --end;
    out.resize(end);
    if (!out.empty() && out.back() == '\\') out += '.';
    return out;
}

std::string cpp_string(std::string_view s) {
    std::string out = "\"";
    for (const char ch : s) {
        const unsigned char c = static_cast<unsigned char>(ch);
        if (ch == '"' || ch == '\\' || ch == '?') {
            out += '\\';
            out += ch;
        } else if (c >= 0x20 && c < 0x7f) {
            out += ch;
        } else if (ch == '\n') {
            out += "\\n";
        } else if (ch == '\t') {
            out += "\\t";
        } else {
            out += hex_byte(c, "\\%03o");  // octal: at most three digits, so a following digit is safe
        }
    }
    return out + "\"";
}

std::string latex_text(std::string_view raw) {
    return one_line(raw, [](char ch, std::string& out) {
        switch (ch) {
            case '\\': out += "\\textbackslash{}"; return true;
            case '{': out += "\\{"; return true;
            case '}': out += "\\}"; return true;
            case '$': out += "\\$"; return true;
            case '&': out += "\\&"; return true;
            case '#': out += "\\#"; return true;
            case '%': out += "\\%"; return true;
            case '_': out += "\\_"; return true;
            case '^': out += "\\textasciicircum{}"; return true;
            case '~': out += "\\textasciitilde{}"; return true;
            default: return false;
        }
    });
}

std::string markdown_text(std::string_view raw) {
    return one_line(raw, [](char ch, std::string& out) {
        switch (ch) {
            case '<': out += "&lt;"; return true;
            case '>': out += "&gt;"; return true;
            case '&': out += "&amp;"; return true;
            // Text is always written after a prefix ("- ", "| ", "### "), so line-start syntax cannot form;
            // inline syntax (emphasis, code, links, math, table cells) can, and is escaped.
            case '\\': case '`': case '*': case '_': case '[': case ']': case '|': case '$': case '~':
                out += '\\';
                out += ch;
                return true;
            default: return false;
        }
    });
}

std::string markdown_math(std::string_view raw) {
    // Whether the end of `out` is a backslash that escapes what follows (not the second of "\\").
    const auto escaping = [](const std::string& out) {
        return !out.empty() && out.back() == '\\' && (out.size() < 2 || out[out.size() - 2] != '\\');
    };
    std::string out = one_line(raw, [&](char ch, std::string& o) {
        switch (ch) {
            case '<': o += "\\lt "; return true;
            case '>': o += "\\gt "; return true;
            case '|':
                if (escaping(o)) o.back() = ' ', o += "\\Vert ";  // \| is the norm bar
                else o += "\\vert ";
                return true;
            case '$': o += escaping(o) ? "$" : "\\$"; return true;
            case '`': o += "\\grave{}"; return true;
            default: return false;
        }
    });
    if (escaping(out)) out += ' ';  // a backslash at the very end would escape the closing delimiter
    return out;
}

std::string markdown_mixed(std::string_view raw) {
    const std::string s = valid_utf8(raw);
    std::string out, piece;
    bool math = false;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const bool delimiter = s[i] == '$' && (i == 0 || s[i - 1] != '\\');
        if (!delimiter) {
            piece += s[i];
            continue;
        }
        out += math ? "$" + markdown_math(piece) + "$" : markdown_text(piece);
        piece.clear();
        math = !math;
    }
    out += math ? markdown_text("$" + piece) : markdown_text(piece);  // an unclosed $ is text
    return out;
}

std::string json_string(std::string_view raw) {
    const std::string s = valid_utf8(raw);
    std::string out = "\"";
    for (std::size_t i = 0; i < s.size();) {
        const CodePoint c = decode_utf8(s, i);
        const char ch = s[i];
        i += c.length;
        switch (ch) {
            case '"': out += "\\\""; continue;
            case '\\': out += "\\\\"; continue;
            case '\n': out += "\\n"; continue;
            case '\r': out += "\\r"; continue;
            case '\t': out += "\\t"; continue;
            default: break;
        }
        if (is_control(c.value) || c.value == 0x2028 || c.value == 0x2029) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04lx", c.value);
            out += buf;
        } else {
            append_utf8(out, c.value);
        }
    }
    return out + "\"";
}

std::string csv_field(std::string_view s) { return eomgen::csv_field(valid_utf8(s)); }

}  // namespace eomgen::text
