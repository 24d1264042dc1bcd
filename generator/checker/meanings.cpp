/** @file meanings.cpp  A label letter that the sentence around its definition names as something else. */
#include "checker/meanings.hpp"

#include "checker/prose.hpp"

#include <cctype>
#include <cstring>

namespace eomgen::checker {
namespace {

struct Other {
    const char* label;
    const char* noun;
};

/// Nouns that give a label letter another meaning than eomgen's (L the Lagrangian, T the kinetic energy, h the
/// energy function, H the Hamiltonian).
constexpr Other kOthers[] = {{"L", "angular momentum"}, {"T", "period"},  {"T", "tension"},
                             {"h", "height"},           {"H", "height"},  {"L", "length"},
                             {"E", "electric field"},   {"T", "torque"}};

std::string trim(const std::string& s) {
    const std::size_t a = s.find_first_not_of(" \t\r\n");
    if (a == std::string::npos) return "";
    const std::size_t b = s.find_last_not_of(" \t\r\n.,;");
    return b < a ? "" : s.substr(a, b - a + 1);
}

/// Whether every term of `value` (split at its top-level + and −) holds a velocity (`\dot`).
bool every_term_has_velocity(const std::string& value) {
    int depth = 0;
    std::string term;
    bool any = false;
    const auto done = [&]() {
        const std::string t = trim(term);
        term.clear();
        if (t.empty()) return true;
        any = true;
        return t.find("\\dot") != std::string::npos;
    };
    for (const char c : value) {
        if (c == '{' || c == '(' || c == '[') ++depth;
        if (c == '}' || c == ')' || c == ']') --depth;
        if (depth == 0 && (c == '+' || c == '-')) {
            if (!done()) return false;
            continue;
        }
        term += c;
    }
    return done() && any;
}

}  // namespace

std::vector<TextMeaning> text_meanings(const Derivation& d, const std::vector<const MathRow*>& rows) {
    std::vector<TextMeaning> out;
    for (const MathRow* row : rows) {
        std::string t = trim(row->text);
        for (const char* arrow : {"\\longrightarrow", "\\Longrightarrow", "\\Rightarrow", "\\rightarrow", "\\implies"})
            if (t.rfind(arrow, 0) == 0) t = trim(t.substr(std::strlen(arrow)));
        const std::size_t eq = t.find('=');
        if (eq == std::string::npos) continue;
        const std::string name = trim(t.substr(0, eq));
        std::string value = t.substr(eq + 1);
        if (const std::size_t next = value.find('='); next != std::string::npos) value = value.substr(0, next);
        value = trim(value);
        // A value continued on the next row (ending in an operator) is not all of the definition.
        if (value.empty() || std::strchr("+-*/=", value.back()) || value.size() > 400) continue;
        const std::size_t begin = row->offset, end = row->offset + row->text.size();
        // A text that writes its Lagrangian \mathscr{L} or \mathcal{L} and also defines a bare L means another
        // quantity by it.
        const bool script_lagrangian = name == "L" && (d.text.find("\\mathscr{L}") != std::string::npos ||
                                                        d.text.find("\\mathcal{L}") != std::string::npos ||
                                                        d.text.find("\\mathcal L") != std::string::npos);
        const auto meaning = [&](const std::string& noun) {
            TextMeaning m;
            m.name = name;
            m.value = value;
            m.noun = noun;
            m.begin = begin;
            m.end = end;
            m.line = d.position(begin + std::min(row->text.find('='), row->text.size())).line;
            const std::size_t section_end =
                row->section >= 0 ? d.sections[std::size_t(row->section)].end : d.text.size();
            m.last_line = d.position(section_end > 0 ? section_end - 1 : 0).line;
            out.push_back(std::move(m));
        };
        // `V^2 = \dot{X}^2 + \dot{Y}^2`: a label's square written in the velocities, every term of it, is the square
        // of another quantity of the text's (a speed): no one writes eomgen's V, T or L squared so.
        for (const char* sq : {"^{2}", "^2"}) {
            const std::size_t n = std::strlen(sq);
            if (name.size() <= n || name.compare(name.size() - n, n, sq) != 0) continue;
            const std::string letter = trim(name.substr(0, name.size() - n));
            if (letter.size() != 1 || std::string("VUTLHEh").find(letter) == std::string::npos) break;
            if (!every_term_has_velocity(value)) break;
            TextMeaning m;
            m.name = letter;
            m.value = "\\sqrt{" + value + "}";
            m.noun = letter == "V" || letter == "U" ? "speed (its square is written in the velocities)"
                                                    : "quantity whose square it writes in the velocities";
            m.begin = begin;
            m.end = end;
            m.line = d.position(begin + std::min(row->text.find('='), row->text.size())).line;
            const std::size_t section_end = row->section >= 0 ? d.sections[std::size_t(row->section)].end : d.text.size();
            m.last_line = d.position(section_end > 0 ? section_end - 1 : 0).line;
            out.push_back(std::move(m));
            break;
        }
        if (!out.empty() && out.back().begin == begin) continue;
        // T = 2π/ω, T = 2π√(l/g): a period, whatever the sentence says.
        std::string compact;
        for (char ch : value)
            if (!std::isspace(static_cast<unsigned char>(ch))) compact += ch;
        if (name == "T" && (compact.rfind("\\frac{2\\pi}", 0) == 0 || compact.rfind("2\\pi", 0) == 0)) {
            meaning("period (it is 2π over a frequency)");
            continue;
        }
        // h in "U = mgh": a height, wherever the text writes m g h.
        if (name == "h") {
            std::string text;
            for (char ch : d.text)
                if (!std::isspace(static_cast<unsigned char>(ch))) text += ch;
            if (text.find("mgh") != std::string::npos) {
                meaning("height (the text writes m g h)");
                continue;
            }
        }
        std::string sentence;
        for (const Other& o : kOthers) {
            if (name != o.label) continue;
            if (sentence.empty()) sentence = sentence_around(d.text, begin, end);
            const bool other_noun = sentence.find(o.noun) != std::string::npos;
            if (!other_noun && !script_lagrangian) continue;
            meaning(other_noun ? std::string(o.noun) + " (as its sentence says)"
                               : "quantity it names $L$ (its Lagrangian it writes $\\mathscr{L}$ or $\\mathcal{L}$)");
            break;
        }
    }
    return out;
}

std::vector<TextMeaning> prose_namings(const Derivation& d, const std::vector<const MathRow*>& rows) {
    std::vector<TextMeaning> out;
    static const char* const kCues[] = {"call it", "calling it", "denote it by", "denote it", "denoted by",
                                        "denoted", "which we call", "we call it", "call this", "named", "call"};
    for (std::size_t k = 1; k < rows.size(); ++k) {
        const MathRow& row = *rows[k];
        const MathRow& before = *rows[k - 1];
        const std::string name = trim(row.text);
        if (row.display || name.empty() || name.size() > 24 || name.find_first_of("=+-*/()<>") != std::string::npos)
            continue;
        const std::size_t from = before.offset + before.text.size();
        if (from > row.offset || row.offset - from > 200) continue;
        std::string prose;
        for (char c : d.text.substr(from, row.offset - from))
            if (c != '$' && c != '#') prose += char(std::tolower(static_cast<unsigned char>(c)));
        prose = trim(prose);
        bool cued = false;
        for (const char* cue : kCues) {
            const std::size_t n = std::strlen(cue);
            if (prose.size() >= n && prose.compare(prose.size() - n, n, cue) == 0 &&
                (prose.size() == n || !std::isalpha(static_cast<unsigned char>(prose[prose.size() - n - 1])))) {
                cued = true;
                break;
            }
        }
        if (!cued) continue;
        const std::string head = trim(before.text.substr(0, std::min(before.text.find('='), before.text.size())));
        if (head.empty() || head == name || before.text.find('=') == std::string::npos) continue;
        TextMeaning m;
        m.name = name;
        m.value = head;
        m.noun = "the name the text gives $" + head + "$";
        m.begin = row.offset;
        m.end = row.offset + row.text.size();
        m.line = d.position(row.offset).line;
        const std::size_t section_end = row.section >= 0 ? d.sections[std::size_t(row.section)].end : d.text.size();
        m.last_line = d.position(section_end > 0 ? section_end - 1 : 0).line;
        out.push_back(m);
    }
    return out;
}

}  // namespace eomgen::checker
