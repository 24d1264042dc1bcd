/** @file checker_internals.hpp  The checker's comparisons (class Checker; its sample points in sample_points.hpp),
 * shared by the files that define its parts: checker.cpp (setup, the text's definitions and parts, the driver), evaluation.cpp (prepared sides,
 * equality, the Euler–Lagrange tests), compare_link.cpp (one link a = b judged), diagnosis.cpp (what is wrong
 * and the correction). Private to generator/checker: the public face is checker.hpp. */
#pragma once

#include "checker/checker.hpp"
#include "checker/conditions.hpp"
#include "checker/constrained_motion.hpp"
#include "checker/coverage.hpp"

#include "checker/additive_constant.hpp"
#include "checker/amplitude_equations.hpp"
#include "checker/claimed_solution.hpp"
#include "checker/equivalent_lagrangian.hpp"
#include "checker/approximation.hpp"
#include "checker/budget.hpp"
#include "checker/correction_check.hpp"
#include "checker/definitions.hpp"
#include "checker/discourse.hpp"
#include "checker/hamiltonian_check.hpp"
#include "checker/kinks.hpp"
#include "checker/labels.hpp"
#include "checker/meanings.hpp"
#include "checker/prose.hpp"
#include "checker/latex_normalize.hpp"
#include "checker/motions.hpp"
#include "checker/latex_parser.hpp"
#include "checker/linear_algebra.hpp"
#include "checker/normal_modes_check.hpp"
#include "checker/point_positions.hpp"
#include "checker/printed_numbers.hpp"
#include "checker/sample_points.hpp"
#include "checker/shadowed_labels.hpp"
#include "codegen/cpp_emitter.hpp"
#include "codegen/math_printer.hpp"
#include "mechanics/pole_free_subs.hpp"
#include "mechanics/results.hpp"
#include "mechanics/trig_rewrite.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <functional>
#include <iomanip>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <tuple>

namespace eomgen::checker::detail {

/// `latex` as inline math in a report: `$…$`, a side broken over lines (a display's rows) on one line.
inline std::string m(const std::string& latex) {
    std::string one_line;
    one_line.reserve(latex.size());
    for (std::size_t k = 0; k < latex.size(); ++k) {
        if (latex[k] != '\n') {
            one_line += latex[k];
            continue;
        }
        while (!one_line.empty() && (one_line.back() == ' ' || one_line.back() == '\t' || one_line.back() == '\r'))
            one_line.pop_back();
        while (k + 1 < latex.size() && (latex[k + 1] == ' ' || latex[k + 1] == '\t')) ++k;
        one_line += ' ';
    }
    return "$" + one_line + "$";
}

enum class Tri { No, Yes, Unknown };

/// A side of a link with where its row starts in the file.
/// A side the parser refused for its `\pm` or `\mp` (both_signs.cpp).
bool two_equations_in_one(const Side& s);

struct PSide {
    const Side* side = nullptr;
    std::size_t base = 0;
};

/// A chain a = b = c, continued across rows that start with "=".
struct FullChain {
    std::vector<PSide> sides;
    std::vector<Relation> relations;
    std::vector<std::size_t> relation_offsets;  ///< file offsets
    int section = -1;
    bool display = false;
};

/// A side made ready for comparison: labels replaced, d/dt and ∂ evaluated, free names listed.
struct Prepared {
    bool ok = false;
    std::string problem;  ///< when !ok
    GiNaC::ex value;
    std::vector<const FreeName*> unknown, vectors, units;
    std::vector<GiNaC::ex> constants;  ///< `\text{const}`: an arbitrary additive constant
    bool has_truth_label = false;  ///< refers to eomgen's T, V, L, ...
    bool has_part = false;         ///< uses a part T_{x} whose value came from the text
    bool from_definition = false;  ///< differentiates a quantity the text defines (the step's reference)
    bool has_momenta = false;      ///< written in the momenta p_q (or ∂H/∂·): `value_p` is in them
    GiNaC::ex value_p;             ///< the value before p_q → p(q, q̇) (hamiltonian_check.hpp)
    std::vector<std::string> notes;
    bool comparable() const { return ok && unknown.empty() && vectors.empty(); }
};

/// Terms grouped by their monomial in the velocities and accelerations (the shape of a mechanics equation).
struct Group {
    GiNaC::ex monomial;
    std::vector<GiNaC::ex> terms;  ///< whole terms, monomial included
    GiNaC::ex coefficient = 0;     ///< Σ terms / monomial
};

struct Diagnosis {
    std::string difference;
    std::vector<std::string> lines;
};

class Checker : public Comparisons {
  public:
    // Comparisons, for the files of one capability (approximation, additive_constant).
    bool same(const GiNaC::ex& a, const GiNaC::ex& b, double tol) override { return equal(a, b, tol) == Tri::Yes; }
    bool equation_of_motion(const GiNaC::ex& r, double tol) override {
        int only = -1;
        std::string factor;
        return has_acceleration(r) && euler_lagrange_combination(r, tol, &only, &factor) == Tri::Yes;
    }
    std::vector<bool> euler_lagrange_terms(const GiNaC::ex& r, double tol) override {
        int only = -1;
        std::string factor;
        std::vector<bool> used;
        if (!has_acceleration(r) || euler_lagrange_combination(r, tol, &only, &factor, nullptr, &used) != Tri::Yes)
            return {};
        return used;
    }
    int closest_euler_lagrange(const GiNaC::ex& r, double tol) override {
        GiNaC::ex factor = 1;
        int groups = 0;
        const int i = has_acceleration(r) ? closest_euler_lagrange(r, tol, &factor, &groups) : -1;
        return groups >= 1 ? i : -1;
    }
    bool vanishes_on_constrained_motion(const GiNaC::ex& r, double tol) override {
        if (model_.constraints.empty()) return false;
        const std::optional<bool> h = holds_on_constrained_motion(r, model_, eq_, tol, {}, 1, numbers_.pinned());
        return h && *h;
    }
    std::string latex(const GiNaC::ex& e) override;
    std::vector<std::string> wrong_terms(const GiNaC::ex& text, const GiNaC::ex& truth, double tol) override {
        return compare_to(text, truth, tol).lines;
    }

    Checker(const Model& model, const Equations& eq, const Derivation& d, const CheckOptions& options)
        : model_(model),
          eq_(eq),
          d_(d),
          options_(options),
          numbers_(model, ctx_),
          printer_table_(codegen::symbol_table(model)),
          hamilton_(model, eq),
          modes_(model, eq, d),
          parameter_values_(model, options.set),
          algebra_(model, d, ctx_, [this](const Side& s, std::size_t base) {
              const Prepared p = prepare(PSide{&s, base});
              return ScalarReading{p.ok, p.value, p.problem, p.has_truth_label};
          }) {
        algebra_.set_model_matrices(
            [this](const std::string& key, const GiNaC::matrix* text) { return model_matrix(key, text); });
        algebra_.set_scalar_judge([this](const GiNaC::ex& a, const Side& ls, const GiNaC::ex& b, const Side& rs,
                                         EquationCheck& r) {
            Side left = ls, right = rs;
            left.ok = right.ok = true;
            left.value = a;
            right.value = b;
            return modes_.check(left, right, ctx_, *this, r);
        });
        algebra_.set_vector_judge([this](const std::vector<GiNaC::ex>& v, const std::string& name, std::size_t at,
                                         EquationCheck& r) {
            const TrialSolution* trial = discourse_ ? discourse_->trial_at(at) : nullptr;
            return trial && amplitudes_.check_shape(v, name, *trial, discourse_->stated_frequency(at), *this, r);
        });
        algebra_.set_row_judge([this](const GiNaC::ex& a, const GiNaC::ex& b, std::size_t at, EquationCheck& r) {
            const TrialSolution* trial = discourse_ ? discourse_->trial_at(at) : nullptr;
            return trial &&
                   amplitudes_.check(a, b, "", "", {}, *trial, discourse_->stated_frequency(at), ctx_, *this, r);
        });
        hints_.other_angles = false;  // only the sines and cosines the author or the model wrote
        for (const Parameter& p : model.parameters) hints_.constants.insert(p.symbol);
    }

    CheckReport run();

  private:
    // ----- setup
    void add_name(const std::string& latex, const GiNaC::ex& value) {
        std::string c = canonical_name(latex);
        if (c.empty()) c = latex;
        ctx_.names.emplace(c, value);
    }
    /// `name` stands for eomgen's `truth` unless the model uses the letter (a parameter L is shadowed_labels_).
    void add_label(const std::string& name, const GiNaC::ex& truth, const std::string& what);
    void setup_names();
    /// The map's entries for every line (line 0), or those scoped to the text's `line`.
    void apply_map(int line = 0);

    // ----- evaluation
    GiNaC::ex resolve_operators(const GiNaC::ex& e) const;
    GiNaC::ex with_dotted_definitions(const GiNaC::ex& e) const;  ///< ẋ of the text's x = A cos ωt: its derivative
    Prepared prepare(const PSide& s, const GiNaC::ex* exclude_part = nullptr);
    std::string where(std::size_t file_offset) const {
        const SourcePos p = d_.position(file_offset);
        return std::to_string(p.line) + ":" + std::to_string(p.column);
    }
    bool is_part(const GiNaC::ex& e, std::string* name = nullptr, GiNaC::ex* whole = nullptr) const;

    Tri equal(const GiNaC::ex& a, const GiNaC::ex& b, double tol);
    std::vector<Complex> signature(const GiNaC::ex& e);
    bool same_signature(const std::vector<Complex>& a, const std::vector<Complex>& b, double tol) const;

    // ----- what an equation can be
    bool has_acceleration(const GiNaC::ex& e) const {
        for (const Coordinate& c : model_.coordinates)
            if (e.has(c.qdd)) return true;
        return false;
    }
    bool has_velocity(const GiNaC::ex& e) const {
        for (const Coordinate& c : model_.coordinates)
            if (e.has(c.qd)) return true;
        return false;
    }
    bool depends_on_state(const GiNaC::ex& e) const {
        for (const Coordinate& c : model_.coordinates)
            if (e.has(c.q) || e.has(c.qd)) return true;
        return false;
    }
    /// "the left side is k times the right side", from the factors the two sides do not share.
    std::vector<std::string> factor_analysis(const GiNaC::ex& a, const GiNaC::ex& b, double tol,
                                             std::string* ratio);
    /// r = Σ c_i EL_i with c from the acceleration coefficients: a consequence of the equations of motion.
    /// With `multipliers` (+1 or −1: the text's λ with eomgen's sign or the other), EL_i holds the constraint
    /// forces ± Σ_k A_ki λ_k, the text's λ being the constraints' multipliers.
    Tri euler_lagrange_combination(const GiNaC::ex& r, double tol, int* only, std::string* factor,
                                   std::vector<std::string>* acting = nullptr, std::vector<bool>* terms = nullptr,
                                   int multipliers = 0);
    /// The constraints solved for some coordinates and velocities (those `keep` does not use first), with
    /// the substitutions in LaTeX.
    ConstraintReduction reduction(const GiNaC::ex& keep, std::string* shown);
    /// r = k(q, t)·c with c the velocity form of constraint `index`, k ≠ 0 free of the velocities.
    bool proportional_to_constraint(const GiNaC::ex& r, std::size_t index, double tol);
    /// r is linear in the velocities (no products or powers of them) and has at least one.
    bool linear_in_velocities(const GiNaC::ex& r) const;
    /// r = c·target with c free of the state: the integral of motion written with the model's initial state.
    bool proportional_in_state(const GiNaC::ex& r, const GiNaC::ex& target, double tol, GiNaC::ex* c);

    // ----- diagnosis
    std::vector<Group> groups(const GiNaC::ex& e) const;
    std::string group_name(const GiNaC::ex& monomial) const;
    Diagnosis compare_to(const GiNaC::ex& text, const GiNaC::ex& truth, double tol);
    std::string pair_kind(const GiNaC::ex& t, const GiNaC::ex& u, double tol, int* score);
    /// The factor c making c·truth closest to text group by group; the number of groups that then agree.
    int best_factor(const GiNaC::ex& text, const GiNaC::ex& truth, double tol, GiNaC::ex* c);

    // ----- checking
    void collect_parts(const std::vector<FullChain>& chains);
    /// The text's coordinates of its points (`x_2 = x + l\sin\theta`) matched with the model's (point_positions.cpp);
    /// check_position gives a matched row (a coordinate, or with `vector` a position vector) its verdict, an unmatched
    /// one its note.
    void collect_positions(const std::vector<FullChain>& chains);
    /// (section, point, paragraph end, the conditions in force) → the rows that give its coordinates there.
    using PointRows = std::map<std::tuple<int, std::string, std::size_t, std::string>, std::vector<PositionRow>>;
    void collect_positions_at_points(
        const PointRows& at_points,
        const std::map<std::pair<int, std::string>, const ModelPoint*>& matched_points,
        const std::vector<ModelPoint>& points);
    bool check_position(const FullChain& c, std::size_t j, bool vector, EquationCheck& r);
    /// A vector in the axes' unit vectors (`(x + l\sin\theta)\hat{x} - l\cos\theta\,\hat{y}`): its (axis, component)s.
    std::optional<std::vector<std::pair<int, GiNaC::ex>>> unit_components(const Prepared& v) const;
    std::map<std::size_t, PositionMatch> positions_;  ///< by the relation's file offset
    /// Where a definition whose name stands at file offset `head` (its value at `at`) is in force from: `at`, or the
    /// start of the formula it explains ("…, where ω² = k/m": prose.hpp, explains_formula_before).
    std::size_t in_force_from(std::size_t head, std::size_t at) const;
    /// A definition's value that is a constant of the motion (its time derivative vanishes on the equations of
    /// motion): J = m l^2 \sin^2\theta\,\dot\phi. Held fixed where the text differentiates by a coordinate.
    bool conserved_on_motion(const GiNaC::ex& value);
    void check_chain(const FullChain& c, std::vector<EquationCheck>& out);
    EquationCheck check_link(const FullChain& c, std::size_t i, std::size_t j, bool bridge);
    /// A link not comparable for the text's undefined x, y in a model of polar coordinates: x = r cos φ, y = r sin φ,
    /// taken only where the link then agrees (cartesian_reading.cpp).
    void check_cartesian_reading(const FullChain& c, std::size_t i, std::size_t j, bool bridge, EquationCheck& r);
    /// `a \neq b` between expressions (not_equal.cpp): agrees where they are not identically equal.
    void check_not_equal(const PSide& L, const PSide& R, EquationCheck& r);
    /// How many different quantities (T, V, L, a momentum p_q, …) the rows of the display holding offset `at` name
    /// on their left (compare_link.cpp).
    int display_heads(std::size_t at) const;
    /// check_link, with anything GiNaC throws on a strange input turned into a "not comparable" verdict.
    EquationCheck safe_check_link(const FullChain& c, std::size_t i, std::size_t j, bool bridge);
    /// A side that is one free name the text defined (`\ddot{\tilde\phi}` after `\phi = \phi_0 + \tilde\phi`): its
    /// quantity, not a name a condition gives a value.
    bool defined_quantity(const PSide& s) {
        if (!s.side->ok || !ctx_.free_name_of(s.side->value)) return false;
        const Prepared p = prepare(s);
        return p.ok && !p.value.is_equal(s.side->value);
    }
    /// A line that disagrees only through a name the text defined (`V = m g y` with the text's y of line 23), its
    /// other side eomgen's value: what the name would have to be for it to hold (apply_blames decides).
    struct Blame {
        std::string name;     ///< the defined name, canonical LaTeX
        GiNaC::ex needed;     ///< what the line needs it to be
        int definition_line;  ///< where the text defines it
        SourcePos where;      ///< the line's verdict
        std::string equation;
        bool forward = false;  ///< the definition comes later in the section: the line's own verdict is "not comparable"
        bool squared = false;  ///< the name is a speed the text defines by its square (`v^2 = …`): `needed` is the root
    };
    std::vector<Blame> blames_;
    void blame_definition(const FullChain& c, std::size_t i, std::size_t j, const EquationCheck& r);
    /// A disagreeing link that uses a defined name in any way (inside ∂/∂q too): with what one bare use needs the
    /// name to be, it may agree, and then it confirms that use's blame (apply_blames).
    struct DisagreeingUse {
        std::string name;
        GiNaC::ex symbol;
        FullChain chain;
        std::size_t i = 0, j = 0;
        SourcePos where;
        std::string equation;
        bool forward = false;  ///< as Blame::forward
    };
    std::vector<DisagreeingUse> disagreeing_uses_;
    void note_disagreeing_uses(const FullChain& c, std::size_t i, std::size_t j, const EquationCheck& r);
    /// A definition that two or more lines blame alike is the slip: it disagrees (corrected to what they need), and
    /// they are not comparable, pointing to it.
    void apply_blames(std::vector<EquationCheck>& equations);

    /// `\frac{d}{dt}\frac{\partial L}{\partial \dot q} - \frac{\partial L}{\partial q} = 0` with q none of the model's
    /// coordinates: judged with q as each of them in turn (generic_coordinate.cpp). False when it is no such link.
    bool check_generic_coordinate(const FullChain& c, std::size_t i, std::size_t j, bool bridge, EquationCheck& r);
    /// `\dot{x_p} = …` after `x_p = …`: compared with the derivative of that definition (definition_uses.cpp).
    bool check_derivative_of_definition(const FullChain& c, std::size_t i, std::size_t j, EquationCheck& r);
    /// Side k of c, not comparable for one name the text writes only there, agrees with the nearest comparable side
    /// of its chain once exactly one like-named parameter the text uses elsewhere stands in its place (`m` for
    /// M_2): that link, disagreeing, with the parameter written in (misspelled_names.cpp).
    std::optional<EquationCheck> misspelled_name(const FullChain& c, std::size_t k, const std::vector<bool>& comparable);
    /// The slips misspelled_name() finds in chain `c`, put into `out` (whose entries from `first` are c's links).
    void add_misspelled_names(const FullChain& c, const std::vector<bool>& comparable, std::size_t first,
                              std::vector<EquationCheck>& out);
    /// Every chain of the text while run() checks them.
    const std::vector<FullChain>* all_chains_ = nullptr;

    /// A definition (name = value, side i = 0 of c) written after "⇒" and the relation it follows from: agrees or
    /// disagrees with that relation solved for the name (implication.cpp); false when it follows no such relation.
    bool check_implied_definition(const FullChain& c, std::size_t i, std::size_t j, const GiNaC::ex& name,
                                  const std::string& name_latex, const GiNaC::ex& value, EquationCheck& r);
    /// Whether the chain follows the one before it with only an implication sign between (`\Rightarrow`): a
    /// consequence, not a value the text sets.
    bool after_implication(const FullChain& c) const;
    /// The text's chain just before c, or nullptr (the first, or a chain built for a verification).
    const FullChain* chain_before(const FullChain& c) const;
    /// Where a correction is the relation before solved (implication.cpp): it names a new symbol, so it cannot be
    /// parsed back and checked alone (verify_correction), and needs not be.
    std::set<std::pair<int, int>> solved_corrections_;

    // ----- changes of variable (change_of_variable.cpp)
    /// `r = r_{eq} + \rho`: from `from` to `until` (file offsets) the text's `deviation` is q − point.
    struct VariableChange {
        std::size_t from = 0, until = 0;
        std::size_t coordinate = 0;
        GiNaC::ex point;
        bool own = false;         ///< the point is a constant of the text's own, with no value given
        std::string point_latex;  ///< as the text writes it
        std::string deviation;    ///< the new name, canonical LaTeX
        GiNaC::ex sign;           ///< ±1: the deviation is sign·(q − point)
    };
    std::vector<VariableChange> variable_changes_;
    /// The rows that make a change of variable (the file offset of their relation), with what the report says.
    std::map<std::size_t, std::string> variable_change_rows_;
    /// Reads the changes of variable of the text and defines their names (after collect_definitions).
    void collect_changes_of_variable(const std::vector<FullChain>& chains);
    /// The value the text gives `name` (a constant) in the last chain `name = …` before file offset `before`.
    std::optional<GiNaC::ex> earlier_value(const std::vector<FullChain>& chains, const GiNaC::ex& name,
                                           std::size_t before, int* line);
    /// Where the approximations at file offset `at` are expanded.
    ExpansionPoints expansion_points(std::size_t at) const;

    // ----- definitions confirmed by their uses (definition_uses.cpp)
    /// The rows of the text's definitions (`x_1 = l_1 \sin\theta_1`), by the file offset of the defined name.
    std::map<std::size_t, SourcePos> definition_rows_;
    /// The lines on which a comparison with one of eomgen's quantities agreed after putting a definition in.
    std::map<std::size_t, std::set<int>> confirmed_by_;
    /// A definition whose own row holds as an identity once earlier ones are put in (`\dot{x} = ...` after
    /// `x = ...`): confirming it confirms them. By the file offset of its name, the offsets of theirs.
    std::map<std::size_t, std::set<std::size_t>> derived_from_;
    /// safe_check_link, noting the definitions that a link agreeing with eomgen's quantity used.
    EquationCheck check_link_noting_uses(const FullChain& c, std::size_t i, std::size_t j, bool bridge);
    /// A definition of a quantity of the motion (it depends on the coordinates or on time) that rows agreeing with
    /// eomgen used is consistent with the model: it agrees, through those rows.
    void apply_confirmations(std::vector<EquationCheck>& equations) const;
    /// The link compared with what the sentence before its display calls it (labels.hpp).
    void check_prose_label(const FullChain& c, std::size_t i, std::size_t j, EquationCheck& r);
    /// `K = …` under "the kinetic energy is": a letter introduced for the labelled quantity, compared with it.
    bool introduces_labelled_quantity(const FullChain& c, std::size_t i, std::size_t j, const ProseLabel& label,
                                      EquationCheck& r);
    /// Parses r.corrected back with the names of its line and checks it (correction_check.hpp); a correction
    /// that does not agree is withheld, with a note.
    void verify_correction(const FullChain& c, std::size_t j, EquationCheck& r);
    /// Link a–b of `ch` (a correction parsed back) checked as if it stood at file offset `at` of `like`'s section.
    EquationCheck check_parsed_link(const FullChain& like, std::size_t at, const Chain& ch, std::size_t a,
                                    std::size_t b);
    /// A link that disagrees and agrees once one term the text wrote has its sign flipped or is left out: that edit
    /// of the text becomes r.corrected, in the author's form (authors_form.cpp). False when no single edit does.
    bool correct_in_authors_form(const FullChain& c, std::size_t i, std::size_t j, EquationCheck& r);
    /// a ≈ b compared with the Taylor expansion about q = 0 of the coordinates the text calls small (or, when
    /// `implied`, every coordinate it holds), to the order it keeps (approximation.hpp). False when it does
    /// not apply (no side is a polynomial in them).
    bool approximation(std::size_t at, const std::string& left, const std::string& right, const Prepared& a,
                       const Prepared& b, bool implied, EquationCheck& r);
    /// Whether the text says the link c[i] = c[j] approximates: the prose calls coordinates small, or the link writes
    /// a deviation from the point of a change of variable.
    bool approximation_stated(const FullChain& c, std::size_t i, std::size_t j) const;
    // ----- rows that give rather than claim (given_rows.cpp)
    /// `t = 0`, `t = t_c` (an instant), `x_0 = 1` (an initial value): not judged, with the role.
    bool given_value(const Prepared& a, const Prepared& b, EquationCheck& r);
    /// `T = T_C + T_P` with a part never given a value (or, `valued`, parts whose sum disagrees): naming the parts.
    bool names_parts(const PSide& L, const PSide& R, EquationCheck& r, bool valued = false);
    bool is_share_of(const GiNaC::ex& value, const GiNaC::ex& whole, double tol);  ///< its terms are terms of whole
    bool a_part_is_wrong(const PSide& s, double tol);  ///< s a sum of parts, one of whose values is no share of its whole

    // ----- names stated outside the text's definitions (stated_names.cpp)
    /// The user's symbol-map entry for the name a side is, alone (`I` with `--map I='m k^2'`), in force on its line.
    const MapEntry* map_entry_for(const PSide& s) const;
    /// L = R where one side is a map entry's name and the other a constant: disagrees when it is not the map's value.
    bool check_against_map(const PSide& L, const PSide& R, const Prepared& a, const Prepared& b, double tol,
                           EquationCheck& r);
    /// The link ending at side j of c is `m_2 = m` in the assumption `m_1 = m_2 = m`: it names the common value.
    bool names_common_value(const FullChain& c, std::size_t j) const;
    /// The common value an assumption of the setting names (`m` in "take $m_1 = m_2 = m$") stands for the parameter it
    /// equals to the end of the section (stated_names.cpp): then every comparison reads it, not only the pinned numbers.
    void collect_common_values(const std::vector<FullChain>& chains);
    struct CommonValue {
        GiNaC::ex name, parameter;
        std::size_t from, until;
    };
    std::vector<CommonValue> common_values_;
    /// `side` with the common values in force at file offset `at` put in (`l` → l₂ after "take $l_1 = l_2 = l$").
    Side with_common_values(const Side& side, std::size_t at) const;
    /// The text's assumptions on the model's parameters in force at file offset `at`, parameter → value (`m_1` →
    /// m_2 and `m_2` → m after "take $m_1 = m_2 = m$"): each as the condition states it.
    GiNaC::exmap parameter_assumptions(std::size_t at) const;
    bool verifying_ = false;
    void check_part(const GiNaC::ex& part, const std::string& part_source, const Prepared& other, double tol,
                    EquationCheck& r);
    /// T (or V) minus the text's other parts of it, when the text defines other parts.
    std::optional<GiNaC::ex> expected_part(const GiNaC::ex& part) const;
    /// `V = -m g l \cos\theta + \text{const}`: agrees (true) when the sides differ by a constant; else
    /// the constants are dropped from a and b for the other comparisons (false).
    bool up_to_constant(Prepared& a, Prepared& b, double tol, EquationCheck& r);
    void check_values(const FullChain& c, std::size_t i, std::size_t j, const Prepared& a, const Prepared& b,
                      double tol, EquationCheck& r);
    /// A link a = b (r_ex = a − b) that writes the multipliers: true when decided (compare_multipliers.cpp).
    bool check_multipliers(const PSide& L, const PSide& R, const GiNaC::ex& a, const GiNaC::ex& b,
                           const GiNaC::ex& r_ex, double tol, const std::string& within, EquationCheck& r);
    bool diagnose_solved_acceleration(const PSide& left, const PSide& right, const GiNaC::ex& r, double tol,
                                      EquationCheck& out);
    void diagnose_euler_lagrange(const PSide& left, const PSide& right, const GiNaC::ex& r, double tol,
                                 EquationCheck& out);
    /// The coordinate whose Euler–Lagrange equation r matches best (the most groups of terms equal after the
    /// best factor, `factor`; `groups` of them).
    int closest_euler_lagrange(const GiNaC::ex& r, double tol, GiNaC::ex* factor, int* groups);

    const Model& model_;
    const Equations& eq_;
    const Derivation& d_;
    const CheckOptions& options_;
    /// The text's own meanings of label letters (meanings.hpp), as map entries scoped to the lines after their
    /// definition, and the rows that define them.
    std::vector<MapEntry> meaning_map_;
    std::vector<TextMeaning> meanings_;
    LatexContext ctx_;
    Numbers numbers_;
    codegen::SymbolTable printer_table_;
    trig::Hints hints_;  ///< what is printed is rewritten towards: the author's angle sums (set per link)
    ExMap<GiNaC::ex> truth_;          ///< label symbol → eomgen's value
    ExMap<std::string> label_what_;   ///< label symbol → what it is, for the report
    ExMap<ShadowedLabel> shadowed_labels_;  ///< a parameter written with a label's letter (a length L) → the label
    ExSet bare_only_;                 ///< labels that count only as a whole side (h, H)
    ExSet result_labels_;             ///< labels of the model's declared results
    ExMap<GiNaC::ex> part_value_;     ///< part symbol → its value in the text
    ExMap<std::string> part_origin_;  ///< part symbol → "line N"
    std::vector<GiNaC::ex> motion_;   ///< the equations of motion, = 0
    std::vector<GiNaC::symbol> multipliers_;  ///< λ_k per constraint, as a text names them (\lambda, \lambda_{1})
    /// The text's sign of λ (+1 eomgen's, M q̈ = f + Aᵀλ; −1 the other), set by the first link that holds with one
    /// sign only, and the line of that link: a later link that holds with the other sign only disagrees.
    int multiplier_sign_ = 0;
    int multiplier_sign_line_ = 0;
    std::string multiplier_sign_section_;
    /// False (r set to disagree) when a link that holds with eomgen's sign of λ only, or with the opposite only,
    /// goes against the sign the text took before; true otherwise (and the first such link sets it).
    bool keeps_multiplier_sign(bool with_eomgens, bool with_opposite, EquationCheck& r);
    std::vector<std::pair<GiNaC::ex, std::string>> integrals_of_motion_;
    ExMap<std::vector<Complex>> signatures_;
    TextDefinitions definitions_;   ///< K = ..., used where the text differentiates K
    std::size_t current_offset_ = 0;  ///< file offset of the side being prepared (definitions before it apply)
    /// Derivatives the side takes that do not exist on a switching surface (kinks.hpp): (surface, variable), found
    /// while its operators are resolved and said in its notes.
    mutable std::vector<std::pair<Kink, GiNaC::ex>> kinks_;
    /// Notes the operators add while resolved (d/dτ by a new time: the definitions it used), for prepare().
    mutable std::vector<std::string> operator_notes_;
    void collect_definitions(const std::vector<FullChain>& chains);
    /// `\rho^2\dot\varphi = c_0`: the name c_0, introduced by a chain's last side, defined as the quantity before
    /// it (named_constants.cpp); its file offset → its name.
    void collect_named_constants(const std::vector<FullChain>& chains);
    /// The name a chain's side introduces: the name alone (`c_0`), or times a factor the checker can evaluate
    /// (`I_3\omega_3`, factor I₃), the side's only unknown name.
    struct IntroducedName {
        GiNaC::ex symbol;
        const FreeName* name;
        GiNaC::ex factor;
    };
    std::optional<IntroducedName> introduced_name(const PSide& side);
    std::map<std::size_t, std::string> named_constants_;
    /// A link with `\pm` (or `\mp`) judged with each sign (both_signs.cpp).
    EquationCheck check_both_signs(const FullChain& c, std::size_t i, std::size_t j, bool bridge);
    bool both_signs_ = false;  ///< inside check_both_signs: a side still refused for its ± is not split again
    /// `M`, `K` (`\mathbf{T}`, `\mathbf{V}`): the model's mass and stiffness matrices by name (model_matrices.cpp).
    std::optional<LinearAlgebra::NamedMatrix> model_matrix(const std::string& key, const GiNaC::matrix* text);
    /// `r_{eq} = l_0 + mg/k` under the conditions of an equilibrium: the equations of motion hold at that value
    /// (equilibrium_values.cpp). False (r untouched) when the link is no such value or the point is not set.
    bool check_value_at_point(const PSide& L, const PSide& R, const Prepared& a, const Prepared& b, double tol,
                              std::size_t at, EquationCheck& r);
    /// Judges `quantity = name` when `name` is such a side: a constant of the motion, or the text's definition.
    bool check_named_constant(const PSide& quantity, const PSide& name, const Prepared& value, double tol,
                              EquationCheck& r);
    HamiltonianReading hamilton_;  ///< p_q as variables, H(q, p, t) inside ∂
    ParticularMotions motions_{model_, eq_, ctx_};  ///< [[motions]]: lines that hold on one motion
    /// a = b (link j of c) on the model's particular motion for its section (motions.hpp).
    bool on_motion(const FullChain& c, std::size_t i, std::size_t j, const GiNaC::ex& a, const GiNaC::ex& b,
                   double tol, EquationCheck& r) {
        if (motions_.empty()) return false;
        std::vector<std::string> titles;
        const std::size_t at = c.relation_offsets[j - 1];
        for (const Section& s : d_.sections)
            if (s.begin <= at && at < s.end) titles.push_back(s.title);
        return motions_.check(a, b, c.sides[i].side->source, titles, *this, tol, r);
    }
    std::vector<ClaimedMotion> claimed_motions_;  ///< the solutions the text claimed, judged (claimed_solution.hpp)
    NormalModesCheck modes_;       ///< ω² and secular equations against the model's normal modes
    AmplitudeEquations amplitudes_{model_, motion_};  ///< rows of (K − ω² M) A = 0 for a trial solution
    /// The rows' roles besides claims (discourse.hpp), read from all rows before any is compared.
    std::optional<Discourse> discourse_;
    ParameterValues parameter_values_;  ///< for the numbers the text works out
    static std::vector<std::string> written_names(const PSide& a, const PSide& b) {
        std::vector<std::string> out;
        for (const PSide* s : {&a, &b})
            for (const NameUse& u : s->side->uses) out.push_back(u.name);
        return out;
    }
    std::vector<std::string> chosen_notes_;  ///< "with $m_1 = 0$, the value the text chose on line 31" (check_link)
    std::set<std::string> not_parts_;  ///< T_… the text sets to a nonzero constant: a period, not a part of T
    std::set<std::size_t> at_a_point_;  ///< heads of definitions that hold at a point the text considers
    LinearAlgebra algebra_;             ///< arrays, tuples, eigen-equations: entry by entry
    int velocity_h_line_ = 0;       ///< the first line where the text writes H in velocities (0: none)
    std::size_t velocity_h_at_ = 0;  ///< its file offset
    /// The reference's value as a correction prints it: in the momenta when the text's side is written in them.
    std::string printed_value(const Prepared& ref, const PSide& ref_side, const Prepared& text);
};

/// Whether e holds abs, sign, heaviside, max or min (the model's, or GiNaC's abs and csgn from the text's |x|).
inline bool has_nonsmooth(const GiNaC::ex& e) {
    if (GiNaC::is_a<GiNaC::function>(e)) {
        static const char* const names[] = {"abs", "sign", "heaviside", "max", "min", "csgn", "step"};
        const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
        for (const char* n : names)
            if (name == n) return true;
    }
    for (const GiNaC::ex& op : e)
        if (has_nonsmooth(op)) return true;
    return false;
}

/// Signs the sample states while it lives, where the expressions compared are not smooth.
class SignedStates {
  public:
    template <class Numbers>
    SignedStates(Numbers& numbers, bool needed) : restore_([&numbers, was = numbers.state_signed()] { numbers.sign_state(was); }) {
        if (needed) numbers.sign_state(true);
    }
    ~SignedStates() { restore_(); }
    SignedStates(const SignedStates&) = delete;
    SignedStates& operator=(const SignedStates&) = delete;

  private:
    std::function<void()> restore_;
};

}  // namespace eomgen::checker::detail
