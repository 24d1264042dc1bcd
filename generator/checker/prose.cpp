/** @file prose.cpp  The sentences around a derivation's math (prose.hpp). */
#include "checker/prose.hpp"

#include "checker/latex_normalize.hpp"

#include <algorithm>
#include <cctype>
#include <iterator>

namespace eomgen::checker {

std::string lead_in(const Derivation& d, std::size_t offset, int sentences) {
    const std::string& s = d.text;
    if (offset > s.size()) return "";
    // The prose from the paragraph start to the math that holds `offset`, inline math left out; a display set
    // off by a blank line takes the paragraph before it (up to two back).
    std::string prose;
    std::size_t end = offset;
    for (int back = 0; back < 3; ++back) {
        const std::size_t para = end == 0 ? std::string::npos : s.rfind("\n\n", end - 1);
        const std::size_t floor = para == std::string::npos ? 0 : para + 2;
        prose.clear();
        bool in_math = false;
        std::size_t last_math_open = std::string::npos;
        for (std::size_t i = floor; i < end; ++i) {
            if (s[i] == '$' && (i == 0 || s[i - 1] != '\\')) {
                in_math = !in_math;
                if (in_math) last_math_open = prose.size();
                if (i + 1 < end && s[i + 1] == '$') ++i;
                continue;
            }
            if (!in_math) prose += s[i];
        }
        if (in_math && last_math_open != std::string::npos) prose.resize(last_math_open);
        for (const char* open : {"\\[", "\\begin{"}) {  // the delimiter that opens the display
            const std::size_t k = prose.rfind(open);
            if (k != std::string::npos) prose.resize(k);
        }
        if (prose.find_first_not_of(" \t\r\n") != std::string::npos || para == std::string::npos) break;
        end = para;
    }
    int seen = 0;
    for (std::size_t k = prose.size(); k-- > 1;)
        if ((prose[k - 1] == '.' || prose[k - 1] == ':' || prose[k - 1] == '?' || prose[k - 1] == '!') &&
            std::isspace(static_cast<unsigned char>(prose[k])) && ++seen == sentences) {
            prose = prose.substr(k);
            break;
        }
    std::string lower;
    for (char c : prose) lower += char(std::tolower(static_cast<unsigned char>(c)));
    return lower;
}

std::string sentence_around(const std::string& s, std::size_t begin, std::size_t end) {
    auto is_end = [&](std::size_t k) {
        return (s[k] == '.' || s[k] == '?' || s[k] == '!') && k + 1 < s.size() &&
               std::isspace(static_cast<unsigned char>(s[k + 1]));
    };
    std::size_t from = begin;
    while (from > 0 && !is_end(from - 1) && !(from >= 2 && s[from - 1] == '\n' && s[from - 2] == '\n')) --from;
    std::size_t to = end;
    while (to < s.size() && !is_end(to) && !(to + 1 < s.size() && s[to] == '\n' && s[to + 1] == '\n')) ++to;
    std::string out = s.substr(from, to - from);
    for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string lead_in_ends_with(const Derivation& d, std::size_t offset, std::initializer_list<const char*> words) {
    std::string before = lead_in(d, offset, 1);
    while (!before.empty() && std::isspace(static_cast<unsigned char>(before.back()))) before.pop_back();
    for (const char* w : words) {
        const std::string word = w;
        if (before.size() < word.size() || before.compare(before.size() - word.size(), word.size(), word) != 0) continue;
        const std::size_t at = before.size() - word.size();
        if (at == 0 || !std::isalpha(static_cast<unsigned char>(before[at - 1]))) return word;
    }
    return "";
}

bool explains_formula_before(const Derivation& d, std::size_t offset) {
    static const char* const kCues[] = {"where", "with", "donde", "wobei", "whereby"};
    const auto cue = [](const std::string& w) {
        return std::any_of(std::begin(kCues), std::end(kCues), [&](const char* c) { return w == c; });
    };
    // The word right before the math, across `$`, braces and spaces (`\text{where } \omega^2`, `\text{donde $`).
    const std::string& s = d.text;
    std::size_t k = std::min(offset, s.size());
    while (k > 0 && (std::isspace(static_cast<unsigned char>(s[k - 1])) || s[k - 1] == '$' || s[k - 1] == '{' || s[k - 1] == '}' ||
                     s[k - 1] == '(' || s[k - 1] == ','))
        --k;
    std::size_t w = k;
    while (w > 0 && std::isalpha(static_cast<unsigned char>(s[w - 1]))) --w;
    std::string word;
    for (std::size_t i = w; i < k; ++i) word += char(std::tolower(static_cast<unsigned char>(s[i])));
    if (cue(word) && (w == 0 || s[w - 1] != '\\')) return true;
    // The sentence leading into it: the unfinished one the math is in, else the one that ends right before it
    // ("where Q is the damper's force:").
    for (int sentences = 1; sentences <= 2; ++sentences) {
        std::string lead = lead_in(d, offset, sentences);
        const std::size_t first = lead.find_first_not_of(" \t\r\n");
        if (first == std::string::npos) continue;
        lead = lead.substr(first);
        // (Or its last line: a display's lines before it and a heading are not part of the sentence.)
        const std::size_t line = lead.find_last_of('\n');
        const std::string last = line == std::string::npos ? lead : trimmed(lead.substr(line + 1));
        const auto starts_where = [](const std::string& x) {
            return x.rfind("where ", 0) == 0 || x.rfind("where,", 0) == 0;
        };
        return starts_where(lead) || starts_where(last);
    }
    return false;
}

bool introduces_name(const Derivation& d, std::size_t offset) {
    const std::string sentence = lead_in(d, offset, 1);
    const auto letter = [](char ch) { return std::isalpha(static_cast<unsigned char>(ch)) != 0; };
    for (const char* cue : {"let", "lets", "letting", "define", "defining", "introduce", "introducing", "denote",
                            "denoting", "call", "write", "writing"}) {
        const std::string w = cue;
        for (std::size_t k = sentence.find(w); k != std::string::npos; k = sentence.find(w, k + 1))
            if ((k == 0 || !letter(sentence[k - 1])) &&
                (k + w.size() == sentence.size() || !letter(sentence[k + w.size()])))
                return true;
    }
    return false;
}

namespace {

bool starts_with_at(const std::string& s, std::size_t at, const char* prefix) {
    return s.compare(at, std::char_traits<char>::length(prefix), prefix) == 0;
}

/// True when s[begin, end) is one display alone: `$$…$$`, `\[…\]` or `\begin{…}…\end{…}`, nothing around it.
bool display_alone(const std::string& s, std::size_t begin, std::size_t end) {
    const std::size_t last = s.find_last_not_of(" \t\r\n", end - 1);
    if (last == std::string::npos || last < begin) return false;
    const std::string tail = s.substr(begin, last + 1 - begin);
    const auto ends_with = [&](const char* x) {
        const std::size_t n = std::char_traits<char>::length(x);
        return tail.size() >= n && tail.compare(tail.size() - n, n, x) == 0;
    };
    if (starts_with_at(s, begin, "$$")) return tail.size() >= 4 && ends_with("$$") && tail.find("$$", 2) == tail.size() - 2;
    if (starts_with_at(s, begin, "\\[")) return ends_with("\\]");
    if (starts_with_at(s, begin, "\\begin{")) return tail.rfind("\\end{") != std::string::npos && ends_with("}");
    return false;
}

/// True when the paragraph that ends at `end` (a blank line) ends a sentence: its last character, inside a
/// display's closing delimiter too, is a full stop, a question or an exclamation mark.
bool ends_sentence(const std::string& s, std::size_t end) {
    std::size_t k = s.find_last_not_of(" \t\r\n", end);
    if (k == std::string::npos) return true;
    std::string tail = s.substr(0, k + 1);
    for (const char* close : {"$$", "\\]"})
        if (tail.size() >= 2 && tail.compare(tail.size() - 2, 2, close) == 0) {
            tail.resize(tail.size() - 2);
            break;
        }
    if (!tail.empty() && tail.back() == '}') {
        const std::size_t env = tail.rfind("\\end{");
        if (env != std::string::npos && tail.find('}', env) == tail.size() - 1) tail.resize(env);
    }
    const std::size_t c = tail.find_last_not_of(" \t\r\n");
    if (c == std::string::npos) return true;
    const char last = tail[c];
    return last == '.' || last == '!' || last == '?';
}

}  // namespace

std::size_t paragraph_end(const Derivation& d, std::size_t at) {
    const std::string& s = d.text;
    std::size_t end = s.find("\n\n", at);
    while (end != std::string::npos && !ends_sentence(s, end)) {
        const std::size_t next = s.find_first_not_of(" \t\r\n", end);
        if (next == std::string::npos) break;
        std::size_t next_end = s.find("\n\n", next);
        if (next_end == std::string::npos) next_end = s.size();
        if (!display_alone(s, next, next_end)) break;
        end = next_end == s.size() ? std::string::npos : next_end;
    }
    return end == std::string::npos ? s.size() : end;
}

}  // namespace eomgen::checker
