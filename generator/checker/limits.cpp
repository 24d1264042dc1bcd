/** @file limits.cpp  The limits a text takes in its prose: "as $c \to 0$ it becomes", "in the limit $l \to 0$".
 * A model's parameter sent to a number is that value for the formula the sentence leads into (the first display
 * after it): the equations there are compared with the model's at that value, as for a value the text chooses
 * (`m_1 = 0`). Only where the model's mass matrix stays regular there (det M not identically 0 at the value): a
 * limit in which the equations degenerate (a mass to 0) is not a value to put in, and is left alone. */
#include "checker/discourse.hpp"

#include <cctype>
#include <string>

namespace eomgen::checker {

namespace {

/// `NAME \to VALUE` (or \rightarrow, \longrightarrow), the whole of an inline formula: its two sides, else false.
bool split_limit(const std::string& text, std::string& name, std::string& value) {
    for (const char* arrow : {"\\longrightarrow", "\\rightarrow", "\\to"}) {
        const std::size_t at = text.find(arrow);
        if (at == std::string::npos) continue;
        const std::size_t after = at + std::string(arrow).size();
        if (after < text.size() && std::isalpha(static_cast<unsigned char>(text[after]))) continue;  // \top, \toto
        name = text.substr(0, at);
        value = text.substr(after);
        return name.find_first_not_of(" \t\n") != std::string::npos && value.find_first_not_of(" \t\n") != std::string::npos;
    }
    return false;
}

}  // namespace

void Discourse::read_limits(const Derivation& d, const Model& model, LatexContext& ctx, const GiNaC::matrix& mass) {
    for (std::size_t k = 0; k < d.rows.size(); ++k) {
        const MathRow& row = d.rows[k];
        std::string name, value;
        if (row.display || !split_limit(row.text, name, value)) continue;
        LatexContext scratch = ctx;
        const Side n = parse_expression(name, scratch), v = parse_expression(value, scratch);
        if (!n.ok || !v.ok || !GiNaC::is_a<GiNaC::numeric>(GiNaC::evalf(v.value))) continue;
        const Parameter* parameter = nullptr;
        for (const Parameter& p : model.parameters)
            if (n.value.is_equal(p.symbol)) parameter = &p;
        if (!parameter) continue;
        // The formula the sentence leads into: the first display after the limit, in the same section, with no end
        // of a sentence between them ("… as $c \to 0$. Next, …" is about what came before).
        std::size_t until = 0;
        for (std::size_t j = k + 1; j < d.rows.size(); ++j) {
            const MathRow& next = d.rows[j];
            if (next.section != row.section) break;
            if (!next.display) continue;
            const std::size_t from = row.offset + row.text.size();
            const std::string between = next.offset > from ? d.text.substr(from, next.offset - from) : "";
            bool sentence_ends = false;
            for (std::size_t q = 0; q + 1 < between.size(); ++q)
                sentence_ends = sentence_ends || (between[q] == '.' && std::isspace(static_cast<unsigned char>(between[q + 1])));
            if (sentence_ends) break;
            until = next.offset + next.text.size();
            for (std::size_t b = j + 1; b < d.rows.size() && d.rows[b].display && d.rows[b].block == next.block; ++b)
                until = d.rows[b].offset + d.rows[b].text.size();
            break;
        }
        if (until == 0) continue;
        // Degenerate at the value (a mass or a length to 0 that makes M singular): not a value to put in.
        try {
            if (GiNaC::normal(mass.determinant().subs(parameter->symbol == v.value)).is_zero()) continue;
        } catch (const std::exception&) {  // a pole at the value
            continue;
        }
        Condition c{parameter->symbol, v.value, row.offset, until, d.position(row.offset).line, false};
        c.limit = true;
        conditions_.push_back(c);
    }
}

}  // namespace eomgen::checker
