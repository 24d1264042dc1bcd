/** @file labels.cpp  The sentence before a display, read for the name of its equation (label_check.cpp compares
 * the equation with what the name says). */
#include "checker/labels.hpp"

#include "checker/latex_normalize.hpp"
#include "checker/latex_parser.hpp"

#include <algorithm>
#include <cctype>
#include <initializer_list>
#include <utility>

namespace eomgen::checker {
namespace {

std::string m(const std::string& latex) { return "$" + latex + "$"; }

struct Token {
    enum Kind { Word, Math, Punct } kind = Word;
    std::string text;  ///< Word: lower case; Math: the LaTeX; Punct: the character
    std::string raw;   ///< Word: as written
    std::size_t begin = 0, end = 0;  ///< file offsets
};

/// The most prose read on either side of a display (a sentence is shorter): bounded time on any input.
constexpr std::size_t kWindow = 2000;

bool space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }
bool letter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }

/// The prose before the display whose first row starts at `first`: from the previous display or blank line
/// to the display's opening delimiter (`$$`, `\[`, `\begin{…}` with its column specification).
std::pair<std::size_t, std::size_t> prose_window(const std::string& s, std::size_t first) {
    std::size_t end = std::min(first, s.size());
    for (bool more = true; more;) {
        more = false;
        while (end > 0 && space(s[end - 1])) --end;
        if (end >= 2 && (s.compare(end - 2, 2, "$$") == 0 || s.compare(end - 2, 2, "\\[") == 0)) {
            end -= 2;
            more = true;
        } else if (end > 0 && s[end - 1] == '}') {
            // \begin{name} or \begin{array}{ccc}
            for (int groups = 0; groups < 2 && !more; ++groups) {
                std::size_t open = s.rfind('{', end - 1);
                for (int g = 0; g < groups && open != std::string::npos && open > 0; ++g)
                    open = s[open - 1] == '}' ? s.rfind('{', open - 2) : std::string::npos;
                if (open != std::string::npos && open >= 6 && s.compare(open - 6, 6, "\\begin") == 0) {
                    end = open - 6;
                    more = true;
                }
            }
        }
    }
    std::size_t begin = 0;
    // The last blank line before `end`.
    for (std::size_t k = end; k > 0; --k) {
        if (s[k - 1] != '\n') continue;
        std::size_t j = k;
        while (j < end && (s[j] == ' ' || s[j] == '\t' || s[j] == '\r')) ++j;
        if (j < end && s[j] == '\n') {
            begin = j + 1;
            break;
        }
    }
    // The previous display's closing delimiter.
    for (const char* close : {"$$", "\\]", "\\end{"}) {
        const std::size_t at = s.rfind(close, end == 0 ? 0 : end - 1);
        if (at != std::string::npos && at >= begin && at < end) {
            std::size_t after = at + std::string(close).size();
            if (close[1] == 'e') after = s.find('}', at) == std::string::npos ? end : s.find('}', at) + 1;
            begin = std::max(begin, std::min(after, end));
        }
    }
    return {std::max(begin, end > kWindow ? end - kWindow : 0), end};
}

/// Words, inline math (`$…$`, `\(…\)`, a Unicode letter such as θ) and punctuation of s[begin, end).
std::vector<Token> tokenize(const std::string& s, std::size_t begin, std::size_t end) {
    std::vector<Token> out;
    std::size_t i = begin;
    while (i < end) {
        const char c = s[i];
        if (c == '$' || s.compare(i, 2, "\\(") == 0) {
            const bool dollar = c == '$';
            const std::size_t from = i + (dollar ? 1 : 2);
            const std::size_t close = dollar ? s.find('$', from) : s.find("\\)", from);
            if (close != std::string::npos && close < end) {
                out.push_back({Token::Math, s.substr(from, close - from), "", i, close + (dollar ? 1 : 2)});
                i = close + (dollar ? 1 : 2);
                continue;
            }
            ++i;
            continue;
        }
        if (std::isalnum(static_cast<unsigned char>(c))) {
            Token w{Token::Word, "", "", i, i};
            while (i < end) {
                if (std::isalnum(static_cast<unsigned char>(s[i]))) {
                    w.raw += s[i++];
                } else if ((s[i] == '\'' || s[i] == '-') && i + 1 < end && letter(s[i + 1])) {
                    w.raw += s[i++];
                } else if (s.compare(i, 3, "\xE2\x80\x99") == 0 || s.compare(i, 3, "\xE2\x80\x93") == 0) {
                    // ’ (Lagrange’s) and – (Euler–Lagrange) inside a word
                    if (i + 3 >= end || !letter(s[i + 3])) break;
                    w.raw += s[i + 2] == '\x99' ? '\'' : '-';
                    i += 3;
                } else {
                    break;
                }
            }
            w.end = i;
            for (char ch : w.raw) w.text += char(std::tolower(static_cast<unsigned char>(ch)));
            out.push_back(std::move(w));
            continue;
        }
        if (static_cast<unsigned char>(c) >= 0x80) {
            if (const auto sp = spelled_as_latex(s, i); sp && !sp->tokens.empty() && sp->tokens[0].size() > 1 &&
                                                         sp->tokens[0][0] == '\\') {
                std::string latex;
                for (const std::string& t : sp->tokens) latex += (latex.empty() ? "" : " ") + t;
                const std::size_t at = i;
                i += std::max<std::size_t>(1, sp->length);
                // Subscript digits ₀ … ₉ (U+2080 … U+2089): θ₁ is \theta_{1}.
                std::string sub;
                for (; i + 2 < end && s.compare(i, 2, "\xE2\x82") == 0 && static_cast<unsigned char>(s[i + 2]) >= 0x80 &&
                       static_cast<unsigned char>(s[i + 2]) <= 0x89;
                     i += 3)
                    sub += char('0' + (static_cast<unsigned char>(s[i + 2]) - 0x80));
                if (!sub.empty()) latex += "_{" + sub + "}";
                out.push_back({Token::Math, latex, "", at, i});
                continue;
            }
            if (s.compare(i, 3, "\xE2\x80\x94") == 0) out.push_back({Token::Punct, "-", "", i, i + 3});  // —
            ++i;
            while (i < end && (static_cast<unsigned char>(s[i]) & 0xC0) == 0x80) ++i;
            continue;
        }
        if (std::string(".,;:!?()-").find(c) != std::string::npos)
            out.push_back({Token::Punct, std::string(1, c), "", i, i + 1});
        ++i;
    }
    return out;
}

/// The last sentence of the tokens (a sentence that ends the window counts), without what is in parentheses.
std::vector<Token> last_sentence(const std::vector<Token>& t) {
    std::size_t n = t.size();
    while (n > 0 && t[n - 1].kind == Token::Punct && t[n - 1].text != ")") --n;
    std::size_t from = 0;
    for (std::size_t k = n; k > 0; --k)
        if (t[k - 1].kind == Token::Punct && std::string(".!?").find(t[k - 1].text) != std::string::npos) {
            from = k;
            break;
        }
    std::vector<Token> out;
    int depth = 0;
    for (std::size_t k = from; k < n; ++k) {
        if (t[k].kind == Token::Punct && t[k].text == "(") ++depth;
        if (depth == 0) out.push_back(t[k]);
        if (t[k].kind == Token::Punct && t[k].text == ")" && depth > 0) --depth;
    }
    return out;
}

bool is_any(const std::string& w, std::initializer_list<const char*> words) {
    for (const char* x : words)
        if (w == x) return true;
    return false;
}

const char* const kGreek[] = {"alpha", "beta",  "gamma", "delta", "epsilon", "zeta",  "eta",   "theta",
                              "iota",  "kappa", "lambda", "mu",   "nu",      "xi",    "rho",   "sigma",
                              "tau",   "phi",   "chi",   "psi",   "omega",   "varphi", "vartheta"};

/// A candidate: what the label says, and its tokens [start, end].
struct Candidate {
    ProseLabel label;
    std::size_t start = 0, end = 0;
};

class Reader {
  public:
    Reader(const std::vector<Token>& t, const std::function<int(const std::string&)>& coordinate, const Model& model)
        : t_(t), coordinate_(coordinate), model_(model) {}

    std::optional<Candidate> last() {
        std::optional<Candidate> best;
        for (std::size_t k = 0; k < t_.size(); ++k)
            if (auto c = at(k); c && (!best || c->end >= best->end)) best = c;
        return best;
    }

  private:
    bool word(std::size_t k, std::initializer_list<const char*> words) const {
        return k < t_.size() && t_[k].kind == Token::Word && is_any(t_[k].text, words);
    }
    bool punct(std::size_t k, const char* p) const {
        return k < t_.size() && t_[k].kind == Token::Punct && t_[k].text == p;
    }

    /// Token k as a coordinate: its index (pushed to `known`) or its LaTeX (pushed to `unknown`); false when it
    /// cannot be a coordinate's name at all.
    bool coordinate(std::size_t k, ProseLabel& l) const {
        if (k >= t_.size()) return false;
        const Token& x = t_[k];
        std::string latex;
        if (x.kind == Token::Math) {
            if (canonical_name(x.text).empty()) return false;
            latex = x.text;
        } else if (x.kind == Token::Word) {
            for (std::size_t i = 0; i < model_.coordinates.size(); ++i)
                if (x.raw == model_.coordinates[i].name) {
                    l.coordinates.push_back(i);
                    return true;
                }
            if (std::find_if(std::begin(kGreek), std::end(kGreek), [&](const char* g) { return x.raw == g; }) !=
                std::end(kGreek))
                latex = "\\" + x.raw;
            else if (x.raw.size() == 1 && letter(x.raw[0]) && !is_any(x.raw, {"a", "A", "I"}))
                latex = x.raw;
            else
                return false;
        } else {
            return false;
        }
        const int i = coordinate_(latex);
        if (i >= 0)
            l.coordinates.push_back(std::size_t(i));
        else
            l.unknown.push_back(latex);
        return true;
    }

    /// "C", "C and D", "C, D and E" from token k; the index of its last token, or k − 1 when there is none.
    std::size_t coordinate_list(std::size_t k, ProseLabel& l) const {
        if (!coordinate(k, l)) return k - 1;
        std::size_t last = k;
        while ((punct(last + 1, ",") || word(last + 1, {"and", "or"})) && coordinate(last + 2, l)) last += 2;
        return last;
    }

    /// Back over the words that belong to the phrase: "the", "Lagrange's", "Euler-Lagrange", ...
    std::size_t phrase_start(std::size_t k, std::initializer_list<const char*> words) const {
        while (k > 0 && word(k - 1, words)) --k;
        return k;
    }

    std::optional<Candidate> at(std::size_t k) const {
        Candidate c;
        ProseLabel& l = c.label;
        const Token& x = t_[k];
        if (x.kind == Token::Math) {  // $p_\phi$ is conserved
            const std::string name = canonical_name(x.text);
            if (name.rfind("p_{", 0) != 0 || !word(k + 1, {"is", "are"})) return std::nullopt;
            ProseLabel probe;
            Token sub = x;
            sub.text = name.substr(3, name.size() - 4);
            const std::vector<Token> one{sub};
            if (!Reader(one, coordinate_, model_).coordinate(0, probe)) return std::nullopt;
            l = probe;
            l.kind = LabelKind::Momentum;
            c.start = c.end = k;
            return c;
        }
        if (x.kind != Token::Word) return std::nullopt;
        const std::string& w = x.text;
        if (w == "equation" || w == "equations") {
            l.kind = LabelKind::EulerLagrange;
            std::size_t j = k + 1;
            if (word(j, {"of"}) && word(j + 1, {"motion"})) j += 2;
            if (word(j, {"for", "of"})) {
                ++j;
                if (word(j, {"the"})) ++j;
                if (word(j, {"coordinate", "coordinates", "angle", "angles", "variable", "variables"})) ++j;
                const std::size_t last = coordinate_list(j, l);
                if (last + 1 > j) {
                    c.start = phrase_start(k, {"the", "lagrange's", "lagrange", "lagranges", "euler-lagrange",
                                               "differential", "a", "an"});
                    c.end = last;
                    return c;
                }
            }
            // "the θ equation", "the ψ-equation"
            std::size_t before = k;
            if (punct(before - 1, "-")) --before;
            if (before > 0 && coordinate(before - 1, l)) {
                c.start = phrase_start(before - 1, {"the"});
                c.end = k;
                return c;
            }
            return std::nullopt;
        }
        if (w == "energy" || w == "energies") {
            const std::string p = k > 0 && t_[k - 1].kind == Token::Word ? t_[k - 1].text : "";
            if (p == "kinetic")
                l.kind = LabelKind::Kinetic;
            else if (p == "potential" || p == "gravitational")
                l.kind = LabelKind::Potential;
            else if (w == "energies")
                return std::nullopt;  // "the energies are T = …, U = …": several, not the total energy
            else if (p.empty() || is_any(p, {"the", "total", "mechanical", "of", "its", "this", "that", "an"}))
                l.kind = LabelKind::Energy;
            else
                return std::nullopt;  // rotational, translational, elastic: a part
            c.start = phrase_start(k, {"the", "total", "kinetic", "potential", "gravitational", "mechanical"});
            c.end = word(k + 1, {"integral", "function", "equation"}) ? k + 1 : k;
            if (l.kind == LabelKind::Energy && word(k + 1, {"function"})) l.kind = LabelKind::Hamiltonian;
            return c;
        }
        if (w == "hamiltonian" || (w == "integral" && k > 0 && word(k - 1, {"jacobi"}))) {
            if (word(k + 1, {"mechanics", "formalism", "formulation", "equations", "approach"})) return std::nullopt;
            l.kind = LabelKind::Hamiltonian;
            c.start = phrase_start(k, {"the", "jacobi"});
            c.end = k;
            return c;
        }
        if (w == "lagrangian") {
            if (word(k + 1, {"mechanics", "formalism", "formulation", "approach", "method", "multiplier",
                             "multipliers", "equations"}))
                return std::nullopt;
            l.kind = LabelKind::Lagrangian;
            c.start = phrase_start(k, {"the"});
            c.end = k;
            return c;
        }
        if (w == "momentum" || w == "momenta") {
            l.kind = LabelKind::Momentum;
            c.start = phrase_start(k, {"the", "angular", "generalized", "generalised", "conjugate", "canonical",
                                       "linear"});
            c.end = k;
            if (word(k + 1, {"conjugate"}) && word(k + 2, {"to", "of"})) {
                const std::size_t last = coordinate_list(k + 3, l);
                if (last + 1 > k + 3) c.end = last;
            } else if (word(k + 1, {"of"})) {  // the momentum of φ
                ProseLabel probe;
                probe.kind = LabelKind::Momentum;
                if (const std::size_t last = coordinate_list(k + 2, probe); last + 1 > k + 2) {
                    l = probe;
                    c.end = last;
                }
            } else if (k + 1 < t_.size() && t_[k + 1].kind == Token::Math) {
                if (auto p = at(k + 1)) {  // the momentum $p_\phi$ is ...
                    l = p->label;
                    c.end = k + 1;
                }
            } else if (k > 0 && c.start == k && coordinate(k - 1, l)) {
                c.start = phrase_start(k - 1, {"the"});  // the φ momentum
            }
            return c;
        }
        return std::nullopt;
    }

    const std::vector<Token>& t_;
    const std::function<int(const std::string&)>& coordinate_;
    const Model& model_;
};

/// The label with its phrase and line, its coordinates sorted.
ProseLabel finished(const Derivation& d, const std::vector<Token>& t, const Candidate& c) {
    ProseLabel l = c.label;
    std::sort(l.coordinates.begin(), l.coordinates.end());
    l.coordinates.erase(std::unique(l.coordinates.begin(), l.coordinates.end()), l.coordinates.end());
    l.phrase = d.text.substr(t[c.start].begin, t[c.end].end - t[c.start].begin);
    for (char& ch : l.phrase)
        if (ch == '\n' || ch == '\r' || ch == '\t') ch = ' ';
    l.line = d.position(t[c.start].begin).line;
    return l;
}

/**
 * "The last equation (Lagrange's equation for ψ) says …" in the prose after the display (up to the next display
 * or heading): the label of the display's last row ("last", "final") or first row ("first"), given in
 * parentheses or between commas right after the words.
 */
std::optional<ProseLabel> label_after(const Derivation& d, const MathRow& row,
                                      const std::function<int(const std::string&)>& coordinate, const Model& model) {
    const MathRow* first = &row;
    const MathRow* last = &row;
    std::size_t next = d.text.size();  // the next display's first row
    for (const MathRow& r : d.rows) {
        if (r.block == row.block) {
            if (r.offset < first->offset) first = &r;
            if (r.offset > last->offset) last = &r;
        } else if (r.display && r.offset > row.offset && r.offset < next) {
            next = r.offset;
        }
    }
    const std::string& s = d.text;
    std::size_t begin = std::min(last->offset + last->text.size(), s.size());
    const std::size_t heading = s.find("\n#", begin);
    const std::size_t end = std::min({next, heading == std::string::npos ? s.size() : heading, begin + kWindow});
    for (bool more = true; more && begin < end;) {  // the display's closing delimiters
        more = false;
        while (begin < end && space(s[begin])) ++begin;
        for (const char* close : {"$$", "\\]", "\\end{"})
            if (s.compare(begin, std::string(close).size(), close) == 0) {
                begin = close[1] != 'e' ? begin + std::string(close).size()
                                        : (s.find('}', begin) < end ? s.find('}', begin) + 1 : end);
                more = true;
            }
    }
    if (begin >= end) return std::nullopt;
    const std::vector<Token> t = tokenize(s, begin, end);
    for (std::size_t k = 1; k + 1 < t.size(); ++k) {
        const bool words = t[k].kind == Token::Word && t[k].text == "equation" && t[k - 1].kind == Token::Word &&
                           is_any(t[k - 1].text, {"last", "final", "first"});
        if (!words || t[k + 1].kind != Token::Punct || (t[k + 1].text != "(" && t[k + 1].text != ",")) continue;
        const MathRow* meant = t[k - 1].text == "first" ? first : last;
        if (meant != &row) continue;
        const std::string close = t[k + 1].text == "(" ? ")" : ",";
        std::vector<Token> inside;
        for (std::size_t j = k + 2; j < t.size() && !(t[j].kind == Token::Punct && t[j].text == close); ++j)
            inside.push_back(t[j]);
        if (auto c = Reader(inside, coordinate, model).last()) return finished(d, inside, *c);
    }
    return std::nullopt;
}

/// The label in the sentence before the display of `row` (label_before's rules), or std::nullopt.
std::optional<ProseLabel> label_in_sentence_before(const Derivation& d, const MathRow* row,
                                                   const std::function<int(const std::string&)>& coordinate,
                                                   const Model& model) {
    std::size_t first = row->offset;
    for (const MathRow& r : d.rows)
        if (r.block == row->block) first = std::min(first, r.offset);
    const auto [begin, end] = prose_window(d.text, first);
    const std::vector<Token> sentence = last_sentence(tokenize(d.text, begin, end));
    auto found = Reader(sentence, coordinate, model).last();
    if (!found) return std::nullopt;
    // What follows the label names the display: nothing, or a naming verb, within 12 words.
    std::size_t words_after = 0;
    bool naming = true;
    for (std::size_t k = found->end + 1; k < sentence.size(); ++k) {
        // "The conjugate momenta are $p_\theta = …$ and $p_\phi = …$, so $$H = …$$": an equation written inline
        // after the label is what it names, and the display that a "so" brings after it follows from them ("The
        // ψ-equation is $\dot p_\psi = 0$: $$…$$" names the display too).
        if (sentence[k].kind == Token::Math && sentence[k].text.find('=') != std::string::npos)
            for (std::size_t n = k + 1; n < sentence.size(); ++n)
                if (sentence[n].kind == Token::Word &&
                    is_any(sentence[n].text, {"so", "hence", "thus", "therefore", "then", "giving", "whence"}))
                    return std::nullopt;
        if (sentence[k].kind == Token::Punct) continue;
        if (words_after++ == 0) naming = false;
        if (sentence[k].kind == Token::Word &&
            is_any(sentence[k].text, {"is", "are", "reads", "read", "becomes", "become", "gives", "give", "yields",
                                      "yield", "takes", "take", "get", "gets", "obtain", "obtains", "find", "have",
                                      "has", "follows", "conserved", "constant", "written", "writes", "write"}))
            naming = true;
    }
    if (!naming || words_after > 12) return std::nullopt;
    // Not an ingredient of the display: "using the energy", "substituting into the θ equation".
    for (std::size_t k = found->start; k > 0; --k) {
        const Token& x = sentence[k - 1];
        if (x.kind == Token::Punct && std::string(",;:").find(x.text) != std::string::npos) break;
        if (x.kind == Token::Word &&
            is_any(x.text, {"using", "use", "substituting", "substitute", "inserting", "insert", "into", "from",
                            "with", "combining", "combine", "by", "in", "eliminating", "differentiating",
                            "integrating", "solving", "to", "than", "like", "unlike", "not", "without", "for", "of",
                            "after", "before"}) &&
            !(x.text == "of" && k >= 2 && sentence[k - 2].kind == Token::Word &&
              sentence[k - 2].text == "conservation"))  // "conservation of energy" names it
            return std::nullopt;
    }
    return finished(d, sentence, *found);
}

}  // namespace

std::optional<ProseLabel> label_before(const Derivation& d, std::size_t at,
                                       const std::function<int(const std::string&)>& coordinate,
                                       const Model& model) {
    const MathRow* row = nullptr;
    for (const MathRow& r : d.rows)
        if (r.offset <= at && at <= r.offset + r.text.size()) row = &r;
    if (!row || !row->display) return std::nullopt;
    if (auto l = label_in_sentence_before(d, row, coordinate, model)) return l;
    return label_after(d, *row, coordinate, model);
}

}  // namespace eomgen::checker
