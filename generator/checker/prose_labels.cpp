/** @file prose_labels.cpp  A link against what the sentence before its display calls it ("the kinetic energy is",
 * "Lagrange's equation for θ": labels.hpp), and a letter the text introduces there for that quantity. */
#include "checker/checker_internals.hpp"

namespace eomgen::checker::detail {

namespace {

/// The quantity a row names on its left: `L(\theta, \dot{\theta})` → L (the letter as a function), `p_\theta`.
std::string head_letter(const std::string& source) {
    std::string head = trimmed(source);
    if (const std::size_t paren = head.find('('); paren != std::string::npos && !head.empty() && head.back() == ')')
        head = trimmed(head.substr(0, paren));
    return head;
}

/// The letters that name a quantity of the motion, with a word a sentence naming that quantity holds.
constexpr std::pair<const char*, const char*> kSelfLabels[] = {
    {"T", "kinetic"},    {"K", "kinetic"},     {"V", "potential"},  {"U", "potential"},           {"L", "lagrangian"},
    {"H", "hamiltonian"}, {"E", "energy"},     {"\\mathcal{L}", "lagrangian"}, {"\\mathscr{L}", "lagrangian"}};

/// A letter that names a quantity of the motion (T, V, L, H, E, a momentum p_q).
bool is_quantity_letter(const std::string& head) {
    if (head.rfind("p_", 0) == 0 && head.size() <= 12 && head.find_first_of("=+-*/ ") == std::string::npos) return true;
    return std::any_of(std::begin(kSelfLabels), std::end(kSelfLabels), [&](const auto& l) { return head == l.first; });
}

}  // namespace

int Checker::display_heads(std::size_t at) const {
    int block = -1;
    for (const MathRow& row : d_.rows)
        if (row.display && row.offset <= at && at <= row.offset + row.text.size()) block = row.block;
    if (block < 0) return 0;
    std::set<std::string> heads;
    for (const MathRow& row : d_.rows) {
        if (!row.display || row.block != block) continue;
        const std::size_t eq = row.text.find('=');
        if (eq == std::string::npos) continue;
        std::string head = head_letter(row.text.substr(0, eq));
        if (!head.empty() && head.front() == '&') head = trimmed(head.substr(1));
        if (is_quantity_letter(head)) heads.insert(head);
    }
    return int(heads.size());
}

bool Checker::introduces_labelled_quantity(const FullChain& c, std::size_t i, std::size_t j, const ProseLabel& label,
                                           EquationCheck& r) {
    // `K = \frac12 m_1\dot x^2 + …` under "the kinetic energy of the system is": a letter the text gives the
    // quantity its sentence names, defined here; its value is compared with eomgen's, not only adopted.
    if (r.verdict != Verdict::NotJudged || r.role != Role::Definition || i != 0 || j != 1 || !c.sides[0].side->ok ||
        !ctx_.free_name_of(c.sides[0].side->value))
        return false;
    const GiNaC::ex* truth = label.kind == LabelKind::Kinetic     ? &eq_.T
                             : label.kind == LabelKind::Potential ? &eq_.V
                             : label.kind == LabelKind::Lagrangian ? &eq_.L
                                                                   : nullptr;
    if (!truth) return false;
    const Prepared b = prepare(c.sides[j]);
    if (!b.comparable() || !b.units.empty() || !b.constants.empty()) return false;
    const double tol = std::max(1e-9, c.sides[i].side->rounding + c.sides[j].side->rounding);
    const std::string name = label.kind == LabelKind::Kinetic ? "T" : (label.kind == LabelKind::Potential ? "V" : "L");
    EquationCheck judged;
    judged.where = r.where;
    judged.section = r.section;
    judged.equation = r.equation;
    judged.notes = b.notes;
    judged.notes.push_back("the text's $" + c.sides[0].side->source + "$, introduced here for the quantity its sentence "
                           "names (“" + label.phrase + "”, line " + std::to_string(label.line) + ")");
    judged.compared_with = "$" + name + "$";
    if (equal(b.value, *truth, tol) == Tri::Yes) {
        judged.verdict = Verdict::Agrees;
        judged.reason = "equal to eomgen's $" + name + "$";
    } else if (label.kind == LabelKind::Potential && potential_with_another_zero(b.value, *truth, model_, *this, tol, judged)) {
    } else {
        const Diagnosis dg = compare_to(b.value, *truth, tol);
        judged.verdict = Verdict::Disagrees;
        judged.difference = dg.difference;
        judged.wrong_terms = dg.lines;
        judged.corrected = c.sides[0].side->source + " = " + latex(*truth);
    }
    r = std::move(judged);
    return true;
}

void Checker::check_prose_label(const FullChain& c, std::size_t i, std::size_t j, EquationCheck& r) {
    // A row in a letter the text has just given another meaning (`p_\theta = L`) is about that quantity, not
    // about what the sentence before the display names.
    for (const std::string& n : r.notes)
        if (n.find(", as the text names it on line ") != std::string::npos) return;
    const auto coordinate = [this](const std::string& latex) {
        LatexContext ctx = ctx_;
        const Side s = parse_expression(latex, ctx);
        for (std::size_t k = 0; s.ok && k < model_.dof(); ++k)
            if (s.value.is_equal(model_.coordinates[k].q)) return int(k);
        return -1;
    };
    // A chain that names its quantity on the left (`T &= …` under "the kinetic energy T and the potential energy
    // U are") is labelled by its own letter when the sentence names that quantity too, not by the last quantity
    // the sentence names. (A sentence that names only another one still disagrees with it.)
    const std::string head = head_letter(c.sides[0].side->source);
    bool self_labelled = false;
    for (const auto& [letter, noun] : kSelfLabels)
        if (head == letter) {
            self_labelled = lead_in(d_, c.relation_offsets[j - 1], 2).find(noun) != std::string::npos;
            break;
        }
    try {  // what GiNaC throws on a strange input leaves the verdict as it is
        const auto label = label_before(d_, c.relation_offsets[j - 1], coordinate, model_);
        if (!label) return;
        if (introduces_labelled_quantity(c, i, j, *label, r)) return;
        // `L(\theta, \dot\theta) = \frac{1}{2}I_{p}\dot\theta^2 - V` under "the kinetic energy is purely rotational:":
        // the Lagrangian built from the energy the sentence describes. And a display whose rows begin with letters
        // of different quantities (`L = …`, `p_\theta = …`): one label before it cannot name them all, and each row
        // names its own.
        const bool lagrangian = head == "L" || head == "\\mathcal{L}" || head == "\\mathscr{L}";
        if (lagrangian && (label->kind == LabelKind::Kinetic || label->kind == LabelKind::Potential))
            self_labelled = true;
        if (is_quantity_letter(head) && display_heads(c.sides[0].base + c.sides[0].side->begin) > 1)
            self_labelled = true;
        Prepared a = prepare(c.sides[i]), b = prepare(c.sides[j]);
        if (!a.comparable() || !b.comparable()) return;
        GiNaC::exmap zero;  // `= \text{const}`: any constant
        for (const Prepared* p : {&a, &b})
            for (const GiNaC::ex& k : p->constants) zero[k] = 0;
        const double tol = std::max(1e-9, c.sides[i].side->rounding + c.sides[j].side->rounding);
        EquationCheck labelled = r;
        check_label(*label, a.value.subs(zero), b.value.subs(zero), model_, eq_, *this, tol, labelled);
        if (self_labelled && labelled.verdict == Verdict::Disagrees && r.verdict != Verdict::Disagrees) return;
        r = std::move(labelled);
    } catch (const std::exception&) {
    }
}

}  // namespace eomgen::checker::detail
