/** @file misspelled_names.cpp  A name the text writes once where it means one of the model's parameters of the
 * same letter: `m g l \cos\theta` in a Lagrangian whose masses the text calls M_1 and M_2 everywhere else. The side
 * is not comparable as it stands (m is neither the model's nor defined by the text); if putting exactly one
 * like-named parameter that the text uses elsewhere in its place makes the side agree with the comparable side of
 * its chain, the line disagrees — a slip of the pen — and the correction writes that parameter. */
#include "checker/checker_internals.hpp"

#include <cctype>

namespace eomgen::checker::detail {

namespace {

/// The letter a canonical name starts with, in lower case: `M_{2}` → "m", `\Phi_{0}` → "\phi"; "" for names with
/// accents or primes (`\dot{x}`, `x'`), which are not misspellings of a parameter.
std::string base_letter(const std::string& canonical) {
    if (canonical.empty() || canonical.find('\'') != std::string::npos) return "";
    if (canonical[0] != '\\') {
        if (!std::isalpha(static_cast<unsigned char>(canonical[0]))) return "";
        const bool subscript_or_end = canonical.size() == 1 || canonical[1] == '_';
        return subscript_or_end ? std::string(1, char(std::tolower(static_cast<unsigned char>(canonical[0])))) : "";
    }
    std::size_t k = 1;
    while (k < canonical.size() && std::isalpha(static_cast<unsigned char>(canonical[k]))) ++k;
    const std::string command = canonical.substr(1, k - 1);
    static const std::set<std::string> greek{
        "alpha", "beta", "gamma", "delta", "epsilon", "varepsilon", "zeta", "eta", "theta", "vartheta",
        "iota", "kappa", "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi", "varphi",
        "chi", "psi", "omega"};
    std::string lower;
    for (char ch : command) lower += char(std::tolower(static_cast<unsigned char>(ch)));
    if (!greek.count(lower) || (k < canonical.size() && canonical[k] != '_')) return "";
    return "\\" + lower;
}

/// The ways a text writes a canonical name: `M_{2}` as itself or as `M_2`.
std::vector<std::string> written_forms(const std::string& canonical) {
    std::vector<std::string> forms{canonical};
    const std::size_t u = canonical.find("_{");
    if (u != std::string::npos && canonical.size() == u + 4 && canonical.back() == '}')
        forms.push_back(canonical.substr(0, u + 1) + canonical[u + 2]);
    return forms;
}

}  // namespace

std::optional<EquationCheck> Checker::misspelled_name(const FullChain& c, std::size_t k,
                                                      const std::vector<bool>& comparable) {
    if (verifying_ || !all_chains_) return std::nullopt;
    const PSide& side = c.sides[k];
    const Prepared p = prepare(side);
    if (!p.ok || p.unknown.size() != 1 || !p.vectors.empty() || !p.units.empty()) return std::nullopt;
    const FreeName& name = *p.unknown.front();
    if (name.kind != NameKind::Unknown) return std::nullopt;
    const std::string letter = base_letter(name.name);
    if (letter.empty()) return std::nullopt;
    // Written in this chain only: a name the text uses on other lines is its own notation (or defined there) —
    // except after a later line that introduces it as a parameter's name (`m_1 = m_2 = m`, the case the text turns
    // to): the uses from there on are that notation, and say nothing of this line.
    const auto uses_name = [&](const Side& s) {
        return std::any_of(s.uses.begin(), s.uses.end(), [&](const NameUse& u) { return u.name == name.name; });
    };
    const auto introduces_name = [&](const FullChain& other) {
        if (std::any_of(other.relations.begin(), other.relations.end(), [](Relation r) { return r != Relation::Equal; }))
            return false;
        bool alone = false, parameter = false;
        for (const PSide& s : other.sides) {
            if (!s.side->ok) continue;
            alone = alone || s.side->value.is_equal(name.symbol);
            parameter = parameter || std::any_of(model_.parameters.begin(), model_.parameters.end(),
                                                 [&](const Parameter& par) { return s.side->value.is_equal(par.symbol); });
        }
        return alone && parameter;
    };
    bool after = false, introduced = false;
    int introduced_line = 0;
    for (const FullChain& other : *all_chains_) {
        if (&other == &c) {
            after = true;
            continue;
        }
        if (introduced || !std::any_of(other.sides.begin(), other.sides.end(),
                                       [&](const PSide& s) { return uses_name(*s.side); }))
            continue;
        if (!after || !introduces_name(other)) return std::nullopt;
        introduced = true;
        introduced_line = d_.position(other.relation_offsets.empty() ? other.sides.front().base
                                                                     : other.relation_offsets.front())
                              .line;
    }
    // The comparable side it is compared with: the nearest before it (else after it), with only `=` between.
    std::size_t anchor = c.sides.size();
    for (std::size_t q = k; q-- > 0;) {
        if (c.relations[q] != Relation::Equal) break;
        if (comparable[q]) {
            anchor = q;
            break;
        }
    }
    if (anchor == c.sides.size())
        for (std::size_t q = k + 1; q < c.sides.size(); ++q) {
            if (c.relations[q - 1] != Relation::Equal) break;
            if (comparable[q]) {
                anchor = q;
                break;
            }
        }
    if (anchor == c.sides.size()) return std::nullopt;
    // The model's parameters of the same letter that the text writes somewhere.
    std::vector<const Parameter*> candidates;
    for (const Parameter& par : model_.parameters) {
        const std::string canonical = canonical_name(par.latex);
        if (canonical == name.name || base_letter(canonical) != letter) continue;
        const bool written = std::any_of(all_chains_->begin(), all_chains_->end(), [&](const FullChain& ch) {
            return std::any_of(ch.sides.begin(), ch.sides.end(),
                               [&](const PSide& s) { return s.side->ok && s.side->value.has(par.symbol); });
        });
        if (written) candidates.push_back(&par);
    }
    if (candidates.empty() || candidates.size() > 8) return std::nullopt;
    const std::size_t lo = std::min(anchor, k), hi = std::max(anchor, k);
    const Parameter* found = nullptr;
    EquationCheck with;
    for (const Parameter* par : candidates) {
        Side replaced = *side.side;
        replaced.value = replaced.value.subs(name.symbol == par->symbol);
        replaced.uses.erase(std::remove_if(replaced.uses.begin(), replaced.uses.end(),
                                           [&](const NameUse& u) { return u.name == name.name; }),
                            replaced.uses.end());
        FullChain f = c;
        f.sides[k].side = &replaced;
        verifying_ = true;
        EquationCheck r;
        try {
            r = check_link(f, lo, hi, hi > lo + 1);
        } catch (const std::exception&) {
            r.verdict = Verdict::NotComparable;
        }
        verifying_ = false;
        if (r.verdict != Verdict::Agrees) continue;
        if (found) return std::nullopt;  // two would do: the text's meaning is not clear
        found = par;
        with = std::move(r);
    }
    if (!found) return std::nullopt;
    EquationCheck r = std::move(with);
    r.where = d_.position(k > anchor ? c.relation_offsets[k - 1] : c.relation_offsets[k]);
    r.verdict = Verdict::Disagrees;
    std::string at;
    for (const NameUse& u : side.side->uses)
        if (u.name == name.name) {
            at = " (" + where(side.base + u.offset) + ")";
            break;
        }
    const std::string cand = canonical_name(found->latex);
    r.reason = "$" + name.name + "$" + at + " is not a symbol of the model, the text does not define it and writes it " +
               (introduced ? "here before it names a parameter so (line " + std::to_string(introduced_line) + ")"
                           : std::string("only here")) +
               "; with $" + cand + "$, which the text writes elsewhere, in its place the line agrees (a slip "
               "for $" + cand + "$?)";
    r.difference.clear();
    r.wrong_terms = {"$" + name.name + "$ where $" + cand + "$ belongs"};
    // The correction: the side as written, the name replaced where it stands.
    std::string source = side.side->source;
    std::vector<std::size_t> at_offsets;
    for (const NameUse& u : side.side->uses)
        if (u.name == name.name && u.offset >= side.side->begin) at_offsets.push_back(u.offset - side.side->begin);
    std::sort(at_offsets.rbegin(), at_offsets.rend());
    bool replaced_all = !at_offsets.empty();
    for (const std::size_t pos : at_offsets) {
        bool done = false;
        for (const std::string& form : written_forms(name.name))
            if (source.compare(pos, form.size(), form) == 0) {
                source.replace(pos, form.size(), cand);
                done = true;
                break;
            }
        replaced_all = replaced_all && done;
    }
    r.corrected.clear();
    if (replaced_all) {
        const std::string& anchor_source = c.sides[anchor].side->source;
        r.corrected = anchor < k ? anchor_source + " = " + source : source + " = " + anchor_source;
        r.equation = anchor < k ? anchor_source + " = " + side.side->source : side.side->source + " = " + anchor_source;
        verify_correction(c, hi, r);
    }
    return r;
}

void Checker::add_misspelled_names(const FullChain& c, const std::vector<bool>& comparable, std::size_t first,
                                   std::vector<EquationCheck>& out) {
    // A slip takes the place of its link's "not comparable" where the side it was compared with is a neighbour; a
    // link read otherwise already (with a value the text gives the name later, say) keeps that reading.
    for (std::size_t k = 0; k < c.sides.size(); ++k) {
        if (comparable[k]) continue;
        std::optional<EquationCheck> slip = misspelled_name(c, k, comparable);
        if (!slip) continue;
        const auto at_slip = [&](const EquationCheck& e) {
            return e.where.line == slip->where.line && e.where.column == slip->where.column;
        };
        if (std::any_of(out.begin() + std::ptrdiff_t(first), out.end(),
                        [&](const EquationCheck& e) { return at_slip(e) && e.verdict != Verdict::NotComparable; }))
            continue;
        const auto it = std::find_if(out.begin() + std::ptrdiff_t(first), out.end(), at_slip);
        if (it != out.end())
            *it = std::move(*slip);
        else
            out.push_back(std::move(*slip));
    }
}

}  // namespace eomgen::checker::detail
