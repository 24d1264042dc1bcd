/** @file model_file.cpp  Model files: TOML via toml++, every problem located at file:line:col. */
#include "model/model_file.hpp"
#include "model/drawing_file.hpp"
#include "model/file_reading.hpp"
#include "model/rolling_contacts.hpp"
#include "model/dimensions.hpp"
#include "model/units.hpp"

#include "model/latex_name.hpp"
#include "text/escape.hpp"

#include "model/expression_parser.hpp"
#include "model/names.hpp"

// toml++ 3.3 asserts preconditions that malformed input breaks ("[\n" in a table header; upstream
// marzer/tomlplusplus#301), aborting builds that compile its parser into this file (TOML_HEADER_ONLY=1)
// without NDEBUG. The code after each of those asserts reports a parse_error, which is what we want.
#ifndef TOML_ASSERT
#define TOML_ASSERT(expr) static_assert(true)
#endif
#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <utility>

namespace eomgen {

namespace {

/// The raw file text, to turn toml++ positions (1-based line, column in code points) and byte offsets
/// into SourceLocations (column in bytes).
class SourceText {
  public:
    SourceText(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {
        // toml++ skips a UTF-8 byte order mark without counting it as a column; so do we.
        line_starts_.push_back(text_.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0);
        for (std::size_t i = 0; i < text_.size(); ++i)
            if (text_[i] == '\n') line_starts_.push_back(i + 1);
    }

    std::string_view text() const { return text_; }

    /// Byte offset of a toml++ position, clamped to the text.
    std::size_t offset_of(const toml::source_position& pos) const {
        if (pos.line == 0) return 0;
        if (pos.line > line_starts_.size()) return text_.size();
        std::size_t i = line_starts_[pos.line - 1];
        for (toml::source_index col = 1; col < pos.column && i < text_.size() && text_[i] != '\n'; ++col) {
            ++i;  // over one code point: its lead byte and continuation bytes 10xxxxxx
            while (i < text_.size() && (static_cast<unsigned char>(text_[i]) & 0xc0) == 0x80) ++i;
        }
        return i;
    }

    SourceLocation at_offset(std::size_t offset) const {
        offset = std::min(offset, text_.size());
        const auto line =
            std::upper_bound(line_starts_.begin(), line_starts_.end(), offset) - line_starts_.begin();
        const std::size_t start = line > 0 ? line_starts_[line - 1] : 0;
        return {file_, static_cast<int>(std::max<std::ptrdiff_t>(line, 1)),
                static_cast<int>(offset >= start ? offset - start + 1 : 1)};
    }

    SourceLocation at(const toml::source_position& pos) const { return at_offset(offset_of(pos)); }
    SourceLocation at(const toml::node& node) const { return at(node.source().begin); }
    SourceLocation file_only() const { return {file_, 0, 0}; }
    /// Where something the file lacks would go: just past its last byte.
    SourceLocation end_of_file() const { return at_offset(text_.size()); }

  private:
    std::string_view text_;
    std::string file_;
    std::vector<std::size_t> line_starts_;
};

using text::append_utf8;

/**
 * Decodes the TOML string literal whose opening quote is at byte `quote` of `text`, recording for each
 * byte of the value the byte offset in `text` it came from, plus one entry for the closing delimiter
 * (where errors at the end of the value point). Handles "...", '...', """...""" and '''...''' with
 * the first newline of multi-line strings trimmed, escapes (one value byte → the backslash), CRLF
 * (toml++ gives "\n") and line-ending backslashes. Returns an empty vector when the decoded text is not
 * `value`, so that a case this misses degrades to pointing at the quote rather than at a wrong place.
 */
std::vector<std::size_t> map_string_value(std::string_view text, std::size_t quote,
                                          const std::string& value) {
    std::vector<std::size_t> raw;
    std::string out;
    if (quote >= text.size() || (text[quote] != '"' && text[quote] != '\'')) return {};
    const char delim = text[quote];
    const bool basic = delim == '"';
    const bool multi = text.substr(quote, 3) == std::string(3, delim);
    std::size_t p = quote + (multi ? 3 : 1);
    if (multi) {
        if (text.substr(p, 1) == "\n")
            p += 1;
        else if (text.substr(p, 2) == "\r\n")
            p += 2;
    }
    auto hex = [&](std::size_t from, std::size_t digits, unsigned long& cp) {
        if (from + digits > text.size()) return false;
        cp = 0;
        for (std::size_t k = 0; k < digits; ++k) {
            const char h = text[from + k];
            const int v = h >= '0' && h <= '9'   ? h - '0'
                          : h >= 'a' && h <= 'f' ? h - 'a' + 10
                          : h >= 'A' && h <= 'F' ? h - 'A' + 10
                                                 : -1;
            if (v < 0) return false;
            cp = cp * 16 + static_cast<unsigned long>(v);
        }
        return true;
    };
    while (p < text.size()) {
        const char c = text[p];
        if (c == delim && (!multi || text.substr(p, 3) == std::string(3, delim))) {
            if (multi) {
                // Up to two quotes right before the closing three belong to the value: """a"""" is a".
                std::size_t run = 0;
                while (p + run < text.size() && text[p + run] == delim) ++run;
                for (std::size_t k = 0; k < std::min<std::size_t>(run - 3, 2); ++k) {
                    out += delim;
                    raw.push_back(p + k);
                }
                p += std::min<std::size_t>(run - 3, 2);
            }
            raw.push_back(p);
            return out == value ? raw : std::vector<std::size_t>{};
        }
        if (basic && c == '\\' && p + 1 < text.size()) {
            const char e = text[p + 1];
            std::size_t length = 2;
            unsigned long cp = 0;
            switch (e) {
                case 'b':
                    out += '\b';
                    break;
                case 't':
                    out += '\t';
                    break;
                case 'n':
                    out += '\n';
                    break;
                case 'f':
                    out += '\f';
                    break;
                case 'r':
                    out += '\r';
                    break;
                case 'e':
                    out += '\x1b';
                    break;
                case '"':
                    out += '"';
                    break;
                case '\\':
                    out += '\\';
                    break;
                case 'x':
                    if (!hex(p + 2, 2, cp)) return {};
                    append_utf8(out, cp);
                    length = 4;
                    break;
                case 'u':
                    if (!hex(p + 2, 4, cp)) return {};
                    append_utf8(out, cp);
                    length = 6;
                    break;
                case 'U':
                    if (!hex(p + 2, 8, cp)) return {};
                    append_utf8(out, cp);
                    length = 10;
                    break;
                default: {
                    if (!multi) return {};
                    // Line-ending backslash: drop it, the newline and all whitespace after it.
                    std::size_t q = p + 1;
                    while (q < text.size() && (text[q] == ' ' || text[q] == '\t')) ++q;
                    if (q >= text.size() || (text[q] != '\n' && text[q] != '\r')) return {};
                    while (q < text.size() &&
                           (text[q] == ' ' || text[q] == '\t' || text[q] == '\n' || text[q] == '\r'))
                        ++q;
                    length = q - p;
                }
            }
            raw.resize(out.size(), p);
            p += length;
            continue;
        }
        if (multi && c == '\r' && text.substr(p, 2) == "\r\n") {
            out += '\n';
            raw.push_back(p);
            p += 2;
            continue;
        }
        if (!multi && c == '\n') return {};
        out += c;
        raw.push_back(p);
        ++p;
    }
    return {};
}

std::string type_name(const toml::node& node) {
    switch (node.type()) {
        case toml::node_type::table:
            return "a table";
        case toml::node_type::array:
            return "an array";
        case toml::node_type::string:
            return "a string";
        case toml::node_type::integer:
            return "an integer";
        case toml::node_type::floating_point:
            return "a floating-point number";
        case toml::node_type::boolean:
            return "a boolean";
        case toml::node_type::date:
            return "a date";
        case toml::node_type::time:
            return "a time";
        case toml::node_type::date_time:
            return "a date-time";
        default:
            return "nothing";
    }
}

/// A name declared in the file, for the validity and uniqueness checks.
struct Declaration {
    std::string name;
    std::string kind;  ///< "coordinate", "parameter", "model"
    SourceLocation where;
    std::size_t order;  ///< position in the file, for ordering; 0 for a name taken from the file name
};

/// One `name = ...` of [outputs]: the key's place and its value (a string, or a table with `expr`).
struct OutputEntry {
    std::string name;
    SourceLocation where;
    const toml::node* value = nullptr;
};

/// A coordinate or parameter table, checked for keys and types, values still unevaluated.
struct Entry {
    const toml::table* table = nullptr;
    std::string name;
    SourceLocation where;
};

class Loader : public FileReading {
  public:
    Loader(std::string_view text, const std::string& path, const std::string& default_name)
        : src_(text, path), path_(path), default_name_(default_name) {}

    Model load() {
        toml::table root;
        try {
            root = toml::parse(src_.text(), std::string_view(path_));
        } catch (const toml::parse_error& e) {
            throw ModelError(src_.at(e.source().begin), "invalid TOML: " + toml_problem(e));
        }

        Model model;
        model.path = path_;
        model.t = GiNaC::symbol("t", "t");
        check_keys(root,
                   {"name", "title", "source", "description", "coordinates", "parameters", "lagrangian",
                    "constraints", "forces", "stabilization", "bodies", "gravity", "springs", "contacts", "results",
                    "outputs", "motions", "generate", "draw"},
                   "at the top level");

        std::vector<Declaration> declarations;
        if (const toml::node* name = root.get("name")) {
            model.name = string_value(*name, "name");
            const SourceLocation where = string_start(*name);
            declarations.push_back({model.name, "model", where, order(where)});
        } else {
            model.name = default_name_.empty() ? std::filesystem::path(path_).stem().string() : default_name_;
            declarations.push_back({model.name, "model", src_.file_only(), 0});
        }
        if (const toml::node* n = root.get("title")) model.title = string_value(*n, "title");
        if (const toml::node* n = root.get("source")) model.source = string_value(*n, "source");
        if (const toml::node* n = root.get("description"))
            model.description = string_value(*n, "description");

        const std::vector<Entry> coordinates =
            entries(root, "coordinates", {"name", "latex", "initial", "rate", "unit", "description"}, true);
        const std::vector<Entry> parameters =
            entries(root, "parameters", {"name", "value", "unit", "latex", "description"}, false);
        const std::vector<Entry> constraints = entries(root, "constraints", {"name", "kind", "expr"}, false);
        const std::vector<Entry> results =
            entries(root, "results", {"name", "latex", "expr", "description", "equals", "on_constraints"}, false);
        const std::vector<Entry> motions =
            entries(root, "motions", {"name", "description", "section", "constants", "conditions"}, false);
        const std::vector<Entry> bodies =
            entries(root, "bodies",
                    {"name", "mass", "shape", "dimensions", "inertia", "position", "orientation", "sequence",
                     "force", "torque"},
                    false);
        const std::vector<Entry> springs = entries(root, "springs", {"name", "stiffness", "length", "from", "to"}, false);
        const std::vector<Entry> contacts =
            entries(root, "contacts", {"name", "body", "radius", "tube", "axis", "normal", "height"}, false);
        for (const auto& c : contacts) declarations.push_back({c.name, "contact", c.where, order(c.where)});
        for (const auto& b : bodies) declarations.push_back({b.name, "body", b.where, order(b.where)});
        for (const auto& s : springs) declarations.push_back({s.name, "spring", s.where, order(s.where)});
        for (const auto& c : constraints)
            declarations.push_back({c.name, "constraint", c.where, order(c.where)});
        for (const auto& c : coordinates)
            declarations.push_back({c.name, "coordinate", c.where, order(c.where)});
        for (const auto& p : parameters)
            declarations.push_back({p.name, "parameter", p.where, order(p.where)});
        const std::vector<OutputEntry> outputs = output_entries(root);
        for (const auto& o : outputs) declarations.push_back({o.name, "output", o.where, order(o.where)});
        check_names(declarations, coordinates, constraints);

        SymbolTable symbols;
        symbols.symbols["t"] = model.t;
        for (const auto& c : coordinates) {
            Coordinate coordinate;
            coordinate.name = c.name;
            coordinate.latex = latex_field(*c.table).value_or(default_latex(c.name));
            coordinate.q = GiNaC::symbol(c.name, coordinate.latex);
            coordinate.qd = GiNaC::symbol(c.name + "_dot", "\\dot{" + coordinate.latex + "}");
            coordinate.qdd = GiNaC::symbol(c.name + "_ddot", "\\ddot{" + coordinate.latex + "}");
            coordinate.where = c.where;
            symbols.symbols[c.name] = coordinate.q;
            symbols.velocities[c.name] = coordinate.qd;
            model.coordinates.push_back(std::move(coordinate));
        }
        for (const auto& p : parameters) {
            Parameter parameter;
            parameter.name = p.name;
            parameter.latex = latex_field(*p.table).value_or(default_latex(p.name));
            parameter.unit = optional_string(*p.table, "unit").value_or("");  // its SI form below, with the value
            parameter.description = optional_string(*p.table, "description").value_or("");
            parameter.symbol = GiNaC::symbol(p.name, parameter.latex);
            parameter.where = p.where;
            symbols.symbols[p.name] = parameter.symbol;
            model.parameters.push_back(std::move(parameter));
        }

        // Numbers after all names exist, so that "pi/4" can say "'m' is not a constant" about a name. A number in a
        // declared unit, or a value with its own ("30 deg", "5 cm"), is converted to SI (model/units.hpp).
        for (std::size_t i = 0; i < coordinates.size(); ++i) {
            Coordinate& c = model.coordinates[i];
            c.description = optional_string(*coordinates[i].table, "description").value_or("");
            const std::optional<Unit> unit = unit_field(*coordinates[i].table);
            std::optional<Unit> per_second;
            if (unit) {
                per_second = unit->per_second();
                c.unit = unit->si();
                c.declared_unit = unit;
            }
            c.initial = constant(*coordinates[i].table, "initial", symbols, 0.0, unit ? &*unit : nullptr);
            c.rate = constant(*coordinates[i].table, "rate", symbols, 0.0, per_second ? &*per_second : nullptr);
        }
        for (std::size_t i = 0; i < parameters.size(); ++i) {
            Parameter& p = model.parameters[i];
            const std::optional<Unit> unit = unit_field(*parameters[i].table);
            if (unit) p.unit = unit->to_si == 1.0 ? unit->text : unit->si();
            p.declared_unit = unit;
            std::optional<Unit> own;  // "40 N/m" without a `unit`: the value's own
            p.value = constant(*parameters[i].table, "value", symbols, 0.0, unit ? &*unit : nullptr, &p.given, &own);
            if (!unit && own) {
                p.unit = own->to_si == 1.0 ? own->text : own->si();
                p.value_unit = own;
            }
        }
        dims_ = symbol_dimensions(model);
        for (const Coordinate& c : model.coordinates)
            if (c.declared_unit)
                for (const GiNaC::symbol& x : {c.q, c.qd, c.qdd}) coordinate_dims_.push_back(dims_[x]);

        read_lagrangian(root, symbols, !bodies.empty(), model);
        read_bodies(bodies, symbols, model);
        read_springs(springs, symbols, model);
        read_gravity(root, symbols, model);
        read_constraints(constraints, symbols, model);
        read_contacts(contacts, symbols, model);
        read_forces(root, symbols, model);
        read_stabilization(root, model);
        read_generate(root, model);
        read_results(results, symbols, model);
        read_outputs(outputs, symbols, model);
        read_motions(motions, symbols, model);
        model.drawing = read_drawing(root, *this, symbols, model);
        return model;
    }

  private:
    [[noreturn]] void fail(const SourceLocation& where, const std::string& message) const override {
        throw ModelError(where, message);
    }

    std::size_t offset_of(const toml::node& node) const { return src_.offset_of(node.source().begin); }
    /// A key that sorts locations in file order (a location without a line first).
    static std::size_t order(const SourceLocation& where) {
        return static_cast<std::size_t>(where.line) * 1000000u + static_cast<std::size_t>(where.column);
    }

    /// Where the text of a string value starts (just inside its quotes), else where the node starts.
    SourceLocation at(const toml::node& node) const override { return src_.at(node); }

    SourceLocation string_start(const toml::node& node) const override {
        if (const auto* s = node.as_string()) {
            const auto map = map_string_value(src_.text(), offset_of(node), s->get());
            if (!map.empty()) return src_.at_offset(map.front());
        }
        return src_.at(node);
    }

    /// Where byte `offset` of a string value is in the file.
    SourceLocation inside_string(const toml::node& node, std::size_t offset) const {
        const auto* s = node.as_string();
        if (!s) return src_.at(node);
        const auto map = map_string_value(src_.text(), offset_of(node), s->get());
        if (map.empty()) return src_.at(node);
        return src_.at_offset(map[std::min(offset, map.size() - 1)]);
    }

    /// toml++'s description, or what a person did where it describes the symptom: a string left open at the end
    /// of its line is "unescaped control characters" to toml++ (the line break inside the string).
    std::string toml_problem(const toml::parse_error& e) const {
        const std::string description(e.description());
        const toml::source_position at = e.source().begin;
        if (description.find("control character") != std::string::npos && at.line >= 1) {
            const std::size_t offset = src_.offset_of(at);
            if (offset < src_.text().size() && (src_.text()[offset] == '\n' || src_.text()[offset] == '\r'))
                return "a string is not closed on its line (end it with its quote; text of several lines goes in "
                       "\"\"\"...\"\"\" or '''...''')";
        }
        return description;
    }

    void check_keys(const toml::table& table, std::vector<std::string> allowed,
                    const std::string& context) const override {
        for (auto&& [key, node] : table) {
            const std::string k(key.str());
            if (std::find(allowed.begin(), allowed.end(), k) != allowed.end()) continue;
            const std::string best = closest_name(k, allowed);
            std::string message = "unknown key '" + k + "' " + context;
            // Sections people look for at the top level that are keys of another table.
            static const std::vector<std::pair<std::string, std::string>> elsewhere = {
                {"dissipation", "the Rayleigh dissipation function is R under [lagrangian] (R = \"...\")"},
                {"rayleigh", "the Rayleigh dissipation function is R under [lagrangian] (R = \"...\")"},
                {"R", "the Rayleigh dissipation function goes under [lagrangian]"},
                {"T", "T goes under [lagrangian]"},
                {"V", "V goes under [lagrangian]"},
                {"L", "write T and V under [lagrangian] (L = T - V)"}};
            const auto hint = std::find_if(elsewhere.begin(), elsewhere.end(), [&](const auto& h) { return h.first == k; });
            if (context == "at the top level" && hint != elsewhere.end()) {
                message += ": " + hint->second;
            } else if (!best.empty()) {
                message += "; did you mean '" + best + "'?";
            } else {
                message += " (expected one of:";
                for (const auto& a : allowed) message += " " + a;
                message += ")";
            }
            fail(src_.at(key.source().begin), message);
        }
    }

    /// A string value; NUL and control characters other than newline and tab are refused where they are
    /// (text from a model file ends up in headers, LaTeX, Markdown and JSON: docs/security.md).
    std::string string_value(const toml::node& node, const std::string& key) const override {
        const auto* s = node.as_string();
        if (!s) fail(src_.at(node), "'" + key + "' must be a string, not " + type_name(node));
        const std::string& v = s->get();  // valid UTF-8: toml++ checks it
        for (std::size_t i = 0; i < v.size();) {
            const text::CodePoint c = text::decode_utf8(v, i);
            if (text::is_control(c.value) && c.value != '\n' && c.value != '\t') {
                char code[16];
                std::snprintf(code, sizeof code, "U+%04lX", c.value);
                fail(inside_string(node, i), "'" + key + "' holds the control character " + std::string(code) +
                                                 ": only newline and tab may appear in a text field");
            }
            i += c.length;
        }
        return v;
    }

    /// A `latex` field: within the safe set of latex_name.hpp, else an error at the offending character.
    std::optional<std::string> latex_field(const toml::table& table) const {
        const toml::node* n = table.get("latex");
        if (!n) return std::nullopt;
        std::string latex = string_value(*n, "latex");
        const LatexNameProblem problem = latex_name_problem(latex);
        if (!problem.message.empty()) fail(inside_string(*n, problem.offset), problem.message);
        return latex;
    }

    std::optional<std::string> optional_string(const toml::table& table, const std::string& key) const {
        if (const toml::node* n = table.get(key)) return string_value(*n, key);
        return std::nullopt;
    }

    /// The tables of `[[key]]`, each with its keys checked and a string `name`.
    std::vector<Entry> entries(const toml::table& root, const std::string& key,
                               const std::vector<std::string>& allowed, bool required) const {
        const std::string context = "in [[" + key + "]]";
        std::vector<Entry> result;
        const toml::node* node = root.get(key);
        if (!node) {
            if (required)
                fail(src_.end_of_file(), "missing [[" + key + "]]: a model needs at least one coordinate");
            return result;
        }
        const toml::array* array = node->as_array();
        if (!array)
            fail(src_.at(*node), "'" + key + "' must be an array of tables, written [[" + key + "]], not " +
                                     type_name(*node));
        if (array->empty() && required) fail(src_.at(*node), "a model needs at least one coordinate");
        for (const toml::node& element : *array) {
            const toml::table* table = element.as_table();
            if (!table)
                fail(src_.at(element),
                     "each entry of '" + key + "' must be a table, not " + type_name(element));
            check_keys(*table, allowed, context);
            const toml::node* name = table->get("name");
            if (!name) fail(src_.at(*table), "missing key 'name' " + context);
            result.push_back({table, string_value(*name, "name"), string_start(*name)});
            if (key == "parameters" && !table->get("value"))
                fail(src_.at(*table), "missing key 'value' " + context + " (the parameter's default value)");
        }
        return result;
    }

    /// "a body", "an output".
    static std::string with_article(const std::string& kind) {
        return (kind.find_first_of("aeiou") == 0 ? "an " : "a ") + kind;
    }

    /// Each name valid and not reserved, and no name declared twice; reported in file order. An output is a
    /// CSV column too, so it may not take the name of another column either (output_name_reason).
    void check_names(std::vector<Declaration> declarations, const std::vector<Entry>& coordinates,
                     const std::vector<Entry>& constraints) const {
        std::vector<std::string> coordinate_names, constraint_names;
        for (const auto& c : coordinates) coordinate_names.push_back(c.name);
        for (const auto& c : constraints) constraint_names.push_back(c.name);
        // Names eomgen derives and prints beside the declared ones (eomgen show, the CSV's columns): a
        // declared name equal to one would make them ambiguous.
        std::map<std::string, std::string> derived;
        for (const auto& c : coordinates)
            derived["p_" + c.name] = "the name of the momentum of coordinate '" + c.name + "'";
        for (const auto& c : constraints) {
            derived["lambda_" + c.name] = "the name of the multiplier of constraint '" + c.name + "'";
            derived["residual_" + c.name] = "the name of the residual of constraint '" + c.name + "'";
        }
        std::stable_sort(declarations.begin(), declarations.end(),
                         [](const Declaration& a, const Declaration& b) { return a.order < b.order; });
        std::map<std::string, const Declaration*> seen;
        for (const auto& d : declarations) {
            const auto derived_name = derived.find(d.name);
            if (derived_name != derived.end() && d.kind != "model")
                fail(d.where, "cannot use '" + d.name + "' as " + with_article(d.kind) + " name: it is " +
                                  derived_name->second);
            if (d.kind == "coordinate" && d.name == "energy")
                fail(d.where, "cannot use 'energy' as a coordinate name: it is the name of the energy column");
            std::string problem = name_problem(d.name, coordinate_names);
            if (problem.empty() && d.kind == "output")
                problem = output_name_reason(d.name, coordinate_names, constraint_names);
            if (!problem.empty()) {
                if (d.where.line == 0)
                    fail(d.where, "no 'name' given, and the file name '" + d.name +
                                      "' cannot be the model's name: " + problem + "; add name = \"...\"");
                fail(d.where, "cannot use '" + d.name + "' as " + with_article(d.kind) + " name: " + problem);
            }
            const auto [it, inserted] = seen.emplace(d.name, &d);
            if (inserted) continue;
            const Declaration& first = *it->second;
            const std::string what =
                first.kind == "model" ? "the model's name" : "the name of " + with_article(first.kind);
            const std::string already = first.where.line == 0
                                            ? what + " (taken from the file name, as no name = \"...\" is given: add one "
                                                     "to keep '" + d.name + "' for " + with_article(d.kind) + ")"
                                            : what + " on line " + std::to_string(first.where.line);
            fail(d.where, "duplicate name '" + d.name + "': already " + already);
        }
    }

    /// The `unit` of an entry, read by UDUNITS-2; nothing when absent or "".
    std::optional<Unit> unit_field(const toml::table& table) const {
        const toml::node* node = table.get("unit");
        if (!node) return std::nullopt;
        const std::string text = string_value(*node, "unit");
        if (text.find_first_not_of(' ') == std::string::npos) return std::nullopt;
        try {
            return parse_unit(text);
        } catch (const UnitError& e) {
            fail(src_.at(*node), std::string("unit: ") + e.what());
        }
    }

    /// A number, or a string with a constant expression such as "pi/4", or a value with its unit ("30 deg"). With
    /// `unit` (the entry's declared unit) a bare number is in that unit; the result is in SI either way, and a value
    /// with a unit of another dimension is an error. `given` receives the text of a value that was converted.
    double constant(const toml::table& table, const std::string& key, const SymbolTable& symbols, double fallback,
                    const Unit* unit = nullptr, std::string* given = nullptr, std::optional<Unit>* own_unit = nullptr) const {
        const toml::node* node = table.get(key);
        if (!node) return fallback;
        double value = 0.0;
        const double scale = unit ? unit->to_si : 1.0;
        auto record = [&](const std::string& text) {
            if (given && scale != 1.0) *given = text;
        };
        if (const auto* i = node->as_integer()) {
            value = static_cast<double>(i->get()) * scale;
            record(std::to_string(i->get()) + " " + (unit ? unit->text : ""));
        } else if (const auto* f = node->as_floating_point()) {
            value = f->get() * scale;
            if (!std::isfinite(value)) fail(src_.at(*node), "'" + key + "' must be a finite number");
            record(fmt::format("{} {}", f->get(), unit ? unit->text : ""));
        } else if (const auto* s = node->as_string()) {
            try {
                value = evaluate_constant(s->get(), symbols) * scale;
                record(s->get() + " " + (unit ? unit->text : ""));
            } catch (const ExpressionError& e) {
                // "30 deg", "40 N/m": a constant expression and a unit after it.
                const auto with_unit = split_value_with_unit(
                    s->get(), [&](const std::string& number) { return evaluate_constant(number, symbols); });
                if (!with_unit) {
                    // "40 bananas": a number, then a word that is no unit; say so rather than "write 40*bananas".
                    const std::string& text = s->get();
                    const std::size_t cut = text.find_last_of(' ');
                    if (cut != std::string::npos && cut + 1 < text.size() && std::isalpha(static_cast<unsigned char>(text[cut + 1]))) {
                        bool number = true;
                        try {
                            evaluate_constant(text.substr(0, cut), symbols);
                        } catch (const ExpressionError&) {
                            number = false;
                        }
                        if (number) {
                            try {
                                parse_unit(text.substr(cut + 1));
                            } catch (const UnitError& u) {
                                fail(inside_string(*node, cut + 1), u.what());
                            }
                        }
                    }
                    fail(inside_string(*node, e.offset()), e.message());
                }
                const Unit& own = with_unit->second;
                if (unit && own.dimension != unit->dimension)
                    fail(src_.at(*node), "'" + key + "' is \"" + s->get() + "\", in " + own.dimension.str() +
                                             ", but the unit declared here, " + unit->text + ", is " +
                                             unit->dimension.str());
                value = with_unit->first * own.to_si;
                if (given && own.to_si != 1.0) *given = s->get();
                if (own_unit) *own_unit = own;
            }
            if (!std::isfinite(value)) fail(src_.at(*node), "'" + key + "' must be a finite number");
        } else {
            fail(src_.at(*node), "'" + key +
                                     "' must be a number or a string with a constant expression such as "
                                     "\"pi/4\", not " +
                                     type_name(*node));
        }
        return value;
    }

    /// Dimensional analysis of an expression term by term (model/dimensions.hpp): a problem fails at its term.
    /// With `numbers_in_si`, a term that is a number alone (a body's position "0", "0.5") is not judged: it is
    /// read in the SI unit of what it gives.
    void check_dimensions(const toml::node& node, const SymbolTable& symbols, const ParseOptions& options,
                          const std::optional<Dims>& expected, const std::string& what,
                          bool numbers_in_si = false) const {
        const auto* s = node.as_string();
        if (!s || dims_.size() <= 1) return;  // only t: the file declares no unit
        const auto parse = [&](const std::string& term) {
            GiNaC::ex e = parse_expression(term, symbols, options);
            if (numbers_in_si && GiNaC::is_a<GiNaC::numeric>(e.evalf()))
                throw std::invalid_argument("a number alone");  // skipped, as a term that does not stand alone
            return e;
        };
        if (const auto problem = term_dimension_problem(s->get(), parse, dims_, coordinate_dims_, expected, what))
            fail(inside_string(node, problem->offset), problem->message);
    }

    /// The entries of a [[bodies]] or [[springs]] vector or matrix (an array of strings, or of arrays of them),
    /// each of dimension `expected` (numbers alone read in SI).
    void check_entry_dimensions(const toml::node& node, const SymbolTable& symbols, const ParseOptions& options,
                                const Dims& expected, const std::string& what) const {
        if (const toml::array* a = node.as_array()) {
            for (const toml::node& item : *a) check_entry_dimensions(item, symbols, options, expected, what);
            return;
        }
        check_dimensions(node, symbols, options, expected, what, true);
    }

    GiNaC::ex expression(const toml::node& node, const std::string& key, const SymbolTable& symbols,
                         const ParseOptions& options) const {
        const auto* s = node.as_string();
        if (!s)
            fail(src_.at(node), "'" + key + "' must be a string with an expression, not " + type_name(node));
        try {
            return parse_expression(s->get(), symbols, options);
        } catch (const ExpressionError& e) {
            fail(inside_string(node, e.offset()), e.message());
        }
    }

    /// [lagrangian]: T, V, R. Optional when the model has [[bodies]] (T = V = 0 then, the bodies' added).
    void read_lagrangian(const toml::table& root, const SymbolTable& symbols, bool has_bodies, Model& model) const {
        const toml::node* node = root.get("lagrangian");
        if (!node && has_bodies) {
            for (SourceExpression* e : {&model.T, &model.V, &model.R}) *e = SourceExpression{0, "0", src_.file_only()};
            return;
        }
        if (!node)
            fail(src_.end_of_file(), "missing [lagrangian] with the kinetic energy T (and potential energy V), "
                                   "or [[bodies]]");
        const toml::table* table = node->as_table();
        if (!table)
            fail(src_.at(*node),
                 "'lagrangian' must be a table [lagrangian] with T and V, not " + type_name(*node));
        check_keys(*table, {"T", "V", "R"}, "in [lagrangian]");

        const toml::node* T = table->get("T");
        if (!T && !has_bodies) fail(src_.at(*table), "missing key 'T' in [lagrangian] (the kinetic energy)");
        if (T) {
            model.T.expr = expression(*T, "T", symbols, {});
            check_dimensions(*T, symbols, {}, energy_dims(), "T is an energy");
            model.T.text = T->as_string()->get();
            model.T.where = string_start(*T);
        } else {
            model.T = SourceExpression{0, "0", src_.at(*table)};
        }

        if (const toml::node* V = table->get("V")) {
            ParseOptions options;
            options.forbid_velocities = "the potential energy V(q, t) must not depend on velocities";
            model.V.expr = expression(*V, "V", symbols, options);
            check_dimensions(*V, symbols, options, energy_dims(), "V is an energy");
            model.V.text = V->as_string()->get();
            model.V.where = string_start(*V);
        } else {
            model.V.expr = 0;
            model.V.text = "0";
            model.V.where = src_.at(*table);
        }
        model.R.expr = 0;
        model.R.text = "0";
        model.R.where = src_.at(*table);
        if (const toml::node* R = table->get("R")) {
            model.R.expr = expression(*R, "R", symbols, {});
            check_dimensions(*R, symbols, {}, energy_dims() - Dims{{0, 0, 1, 0, 0, 0, 0}},
                             "R (Rayleigh's dissipation function) is a power");
            model.R.text = R->as_string()->get();
            model.R.where = string_start(*R);
        }
    }

    /// One scalar: an integer or a string with an expression.
    GiNaC::ex scalar(const toml::node& node, const std::string& key, const SymbolTable& symbols,
                     const ParseOptions& options) const override {
        if (const auto* i = node.as_integer()) return GiNaC::ex(GiNaC::numeric(static_cast<long>(i->get())));
        if (!node.as_string())
            fail(src_.at(node), "each entry of '" + key + "' must be a string with an expression or an integer, not " +
                                    type_name(node) + " (write decimals as strings, e.g. \"0.5\")");
        return expression(node, key, symbols, options);
    }

    /// An array of `count` scalars (any number when count is 0).
    std::vector<GiNaC::ex> scalars(const toml::node& node, const std::string& key, std::size_t count,
                                   const SymbolTable& symbols, const ParseOptions& options) const override {
        const toml::array* array = node.as_array();
        if (!array) fail(src_.at(node), "'" + key + "' must be an array, not " + type_name(node));
        if (count != 0 && array->size() != count)
            fail(src_.at(node), "'" + key + "' must have " + std::to_string(count) + " entries, not " +
                                    std::to_string(array->size()));
        std::vector<GiNaC::ex> out;
        for (const toml::node& element : *array) out.push_back(scalar(element, key, symbols, options));
        return out;
    }

    /// [[bodies]]: name, mass, shape + dimensions or inertia, position (3), orientation (3), sequence.
    void read_bodies(const std::vector<Entry>& entries, const SymbolTable& symbols, Model& model) const {
        ParseOptions constant;
        constant.forbid_velocities = "a body's mass, dimensions and inertia must not depend on velocities";
        ParseOptions placement;
        placement.forbid_velocities = "a body's position and orientation are functions of q and t, without velocities";
        for (const Entry& e : entries) {
            Body body;
            body.name = e.name;
            body.where = e.where;
            const toml::table& t = *e.table;
            const toml::node* mass = t.get("mass");
            if (!mass) fail(src_.at(t), "missing key 'mass' in [[bodies]]");
            body.mass = scalar(*mass, "mass", symbols, constant);
            const Dims kg{{1, 0, 0, 0, 0, 0, 0}}, metre{{0, 1, 0, 0, 0, 0, 0}}, second{{0, 0, 1, 0, 0, 0, 0}};
            check_entry_dimensions(*mass, symbols, constant, kg, "a body's mass is a mass");
            const toml::node* shape = t.get("shape");
            const toml::node* inertia = t.get("inertia");
            if (shape && inertia)
                fail(src_.at(*inertia), "give either 'shape' (with 'dimensions') or 'inertia' in [[bodies]], not both");
            if (!shape && !inertia)
                fail(src_.at(t), "missing key 'shape' (with 'dimensions') or 'inertia' in [[bodies]]");
            if (shape) {
                body.shape = string_value(*shape, "shape");
                const toml::node* dims = t.get("dimensions");
                if (!dims) fail(src_.at(*shape), "missing key 'dimensions' for shape '" + body.shape + "' in [[bodies]]");
                body.dimensions = scalars(*dims, "dimensions", 0, symbols, constant);
                check_entry_dimensions(*dims, symbols, constant, metre, "a body's dimensions are lengths");
            } else {
                if (t.get("dimensions")) fail(src_.at(*t.get("dimensions")), "'dimensions' goes with 'shape', not 'inertia'");
                check_entry_dimensions(*inertia, symbols, constant, kg + metre * 2,
                                       "a body's inertia is a moment of inertia");
                const toml::array* rows = inertia->as_array();
                if (rows && rows->size() == 3 && (*rows)[0].as_array()) {
                    for (unsigned i = 0; i < 3; ++i) {
                        const std::vector<GiNaC::ex> row = scalars((*rows)[i], "inertia", 3, symbols, constant);
                        for (unsigned j = 0; j < 3; ++j) body.inertia(i, j) = row[j];
                    }
                    for (unsigned i = 0; i < 3; ++i)
                        for (unsigned j = i + 1; j < 3; ++j)
                            if (!(body.inertia(i, j) - body.inertia(j, i)).expand().is_zero())
                                fail(src_.at(*inertia), "'inertia' must be symmetric");
                } else {
                    const std::vector<GiNaC::ex> d = scalars(*inertia, "inertia", 3, symbols, constant);
                    for (unsigned i = 0; i < 3; ++i) body.inertia(i, i) = d[i];
                }
            }
            const toml::node* position = t.get("position");
            if (!position)
                fail(src_.at(t), "missing key 'position' in [[bodies]] (the centre of mass, 3 expressions, or "
                                 "{ body = \"name\", point = [x, y, z] })");
            const toml::node* orientation = t.get("orientation");
            const toml::node* sequence = t.get("sequence");
            body.angles = {0, 0, 0};
            if (orientation) read_orientation(*orientation, sequence, symbols, placement, model, body);
            if (sequence) {
                body.sequence = string_value(*sequence, "sequence");
                const std::string& q = body.sequence;
                const bool ok = q.size() == 3 && q.find_first_not_of("xyz") == std::string::npos && q[0] != q[1] &&
                                q[1] != q[2];
                if (!ok)
                    fail(string_start(*sequence), "Euler sequence '" + q +
                                                      "' must be three of x, y, z with no axis twice in a row "
                                                      "(e.g. \"zxz\", \"xyz\")");
            }
            read_position(*position, symbols, placement, model, body);
            ParseOptions load;
            load.forbid_velocities.clear();
            if (const toml::node* force = t.get("force")) {
                const std::vector<GiNaC::ex> f = scalars(*force, "force", 3, symbols, load);
                check_entry_dimensions(*force, symbols, load, kg + metre - second * 2, "a body's force is a force");
                body.force = {f[0], f[1], f[2]};
            }
            if (const toml::node* torque = t.get("torque")) {
                const std::vector<GiNaC::ex> n = scalars(*torque, "torque", 3, symbols, load);
                check_entry_dimensions(*torque, symbols, load, kg + metre * 2 - second * 2, "a body's torque is a torque");
                body.torque = {n[0], n[1], n[2]};
            }
            model.bodies.push_back(std::move(body));
        }
    }

    /// The body named by `node` (a string) among those read before `body`, for a relative position or orientation.
    const Body& earlier_body(const toml::node& node, const Model& model, const std::string& what) const {
        const std::string name = string_value(node, "body");
        for (const Body& b : model.bodies)
            if (b.name == name) return b;
        fail(string_start(node), "no body named '" + name + "' before this one in [[bodies]] (a body's " + what +
                                     " may follow a body declared above it)");
    }

    /// A body's rotation chain as the file gives it or, where it gives Euler angles, as three rotations.
    static std::vector<Rotation> chain_of(const Body& b) {
        return b.rotations.empty() ? euler_chain(b.angles, b.sequence) : b.rotations;
    }

    /// `orientation`: Euler angles [phi, theta, psi] (with `sequence`), a chain [["z", "psi"], ["x", "phi"], ...]
    /// of rotations about body axes, or { body = "B", rotations = [...] }: B's chain, then these.
    void read_orientation(const toml::node& node, const toml::node* sequence, const SymbolTable& symbols,
                          const ParseOptions& placement, const Model& model, Body& body) const {
        const toml::array* array = node.as_array();
        const toml::table* table = node.as_table();
        const bool chain = table || (array && !array->empty() && (*array)[0].as_array());
        if (!chain) {
            const std::vector<GiNaC::ex> a = scalars(node, "orientation", 3, symbols, placement);
            check_entry_dimensions(node, symbols, placement, Dims{}, "a body's orientation is angles");
            body.angles = {a[0], a[1], a[2]};
            return;
        }
        if (sequence) fail(src_.at(*sequence), "'sequence' goes with Euler angles, not with a chain of rotations");
        const toml::node* rotations = &node;
        if (table) {
            check_keys(*table, {"body", "rotations"}, "in a body's 'orientation'");
            const toml::node* parent = table->get("body");
            if (!parent) fail(src_.at(*table), "missing key 'body' in the body's 'orientation'");
            body.rotations = chain_of(earlier_body(*parent, model, "orientation"));
            rotations = table->get("rotations");
            if (!rotations) return;  // oriented as the other body
        }
        const toml::array* list = rotations->as_array();
        if (!list) fail(src_.at(*rotations), "'rotations' must be an array of [\"axis\", \"angle\"] pairs");
        for (const toml::node& pair : *list) {
            const toml::array* p = pair.as_array();
            if (!p || p->size() != 2 || !(*p)[0].is_string())
                fail(src_.at(pair), "a rotation is a pair [\"axis\", \"angle\"], e.g. [\"z\", \"psi\"]");
            const std::string axis = string_value((*p)[0], "axis");
            if (axis != "x" && axis != "y" && axis != "z")
                fail(string_start((*p)[0]), "a rotation's axis is \"x\", \"y\" or \"z\", not '" + axis + "'");
            check_entry_dimensions((*p)[1], symbols, placement, Dims{}, "a rotation's angle is an angle");
            body.rotations.push_back({axis[0], scalar((*p)[1], "orientation", symbols, placement)});
        }
        if (body.rotations.empty()) body.rotations.push_back({'z', 0});
    }

    /// `position`: the centre of mass in space axes, or { body = "B", point = [x, y, z] }: a point of B (B's
    /// axes, from its centre of mass), r_B + A_Bᵀ ρ.
    void read_position(const toml::node& node, const SymbolTable& symbols, const ParseOptions& placement,
                       const Model& model, Body& body) const {
        const Dims metre{{0, 1, 0, 0, 0, 0, 0}};
        if (const toml::table* table = node.as_table()) {
            check_keys(*table, {"body", "point"}, "in a body's 'position'");
            const toml::node* parent = table->get("body");
            if (!parent) fail(src_.at(*table), "missing key 'body' in the body's 'position'");
            const Body& b = earlier_body(*parent, model, "position");
            GiNaC::matrix rho(3, 1);
            if (const toml::node* point = table->get("point")) {
                const std::vector<GiNaC::ex> p = scalars(*point, "point", 3, symbols, placement);
                check_entry_dimensions(*point, symbols, placement, metre, "a body's point is a length");
                for (unsigned i = 0; i < 3; ++i) rho(i, 0) = p[i];
            }
            const GiNaC::matrix r = chain_rotation(chain_of(b)).transpose().mul(rho);
            for (unsigned i = 0; i < 3; ++i) body.centre[i] = (b.centre[i] + r(i, 0)).expand();
            return;
        }
        const std::vector<GiNaC::ex> r = scalars(node, "position", 3, symbols, placement);
        check_entry_dimensions(node, symbols, placement, metre, "a body's position is a length");
        body.centre = {r[0], r[1], r[2]};
    }

    /// [[contacts]]: name, body, radius, tube (a torus' tube radius, default 0), axis ("x", "y" or "z" of the body), normal ("+z", "-z", ...; default
    /// against gravity, else "+z"), height (default 0); each becomes its constraints (model/rolling_contacts.hpp).
    void read_contacts(const std::vector<Entry>& entries, const SymbolTable& symbols, Model& model) const {
        ParseOptions constant;
        constant.forbid_velocities = "a contact's radius and the plane's height must not depend on velocities";
        const Dims metre{{0, 1, 0, 0, 0, 0, 0}};
        for (const Entry& e : entries) {
            RollingContact c;
            c.name = e.name;
            c.where = e.where;
            const toml::table& t = *e.table;
            const toml::node* body = t.get("body");
            if (!body) fail(src_.at(t), "missing key 'body' in [[contacts]] (the wheel, a body of [[bodies]])");
            c.body = string_value(*body, "body");
            if (std::none_of(model.bodies.begin(), model.bodies.end(), [&](const Body& b) { return b.name == c.body; }))
                fail(string_start(*body), "no body named '" + c.body + "' in [[bodies]]");
            const toml::node* radius = t.get("radius");
            if (!radius) fail(src_.at(t), "missing key 'radius' in [[contacts]] (the wheel's radius)");
            c.radius = scalar(*radius, "radius", symbols, constant);
            check_entry_dimensions(*radius, symbols, constant, metre, "a wheel's radius is a length");
            const toml::node* axis = t.get("axis");
            if (!axis) fail(src_.at(t), "missing key 'axis' in [[contacts]] (the wheel's symmetry axis: \"x\", \"y\" or \"z\" of its body)");
            const std::string a = string_value(*axis, "axis");
            if (a != "x" && a != "y" && a != "z")
                fail(string_start(*axis), "a wheel's axis is \"x\", \"y\" or \"z\" of its body, not '" + a + "'");
            c.axis = a[0];
            // Default: the plane faces against gravity where gravity is along one axis.
            int along = -1, count = 0;
            for (int k = 0; k < 3; ++k)
                if (!model.gravity[k].is_zero()) along = k, ++count;
            if (count == 1) {
                GiNaC::exmap values;
                for (const Parameter& p : model.parameters) values[p.symbol] = p.value;
                const GiNaC::ex g = GiNaC::evalf(model.gravity[along].subs(values));
                if (GiNaC::is_a<GiNaC::numeric>(g) && GiNaC::ex_to<GiNaC::numeric>(g).is_real()) {
                    c.normal = static_cast<char>('x' + along);
                    c.normal_sign = GiNaC::ex_to<GiNaC::numeric>(g).to_double() > 0 ? -1 : 1;
                }
            }
            if (const toml::node* normal = t.get("normal")) {
                const std::string n = string_value(*normal, "normal");
                if (n.size() != 2 || (n[0] != '+' && n[0] != '-') || n.find_first_of("xyz", 1) != 1)
                    fail(string_start(*normal), "a plane's normal is one of \"+x\", \"-x\", \"+y\", \"-y\", "
                                                "\"+z\", \"-z\" (the side the wheel is on), not '" + n + "'");
                c.normal = n[1];
                c.normal_sign = n[0] == '+' ? 1 : -1;
            }
            if (const toml::node* tube = t.get("tube")) {
                c.tube = scalar(*tube, "tube", symbols, constant);
                check_entry_dimensions(*tube, symbols, constant, metre, "a tyre's tube radius is a length");
            }
            if (const toml::node* height = t.get("height")) {
                c.height = scalar(*height, "height", symbols, constant);
                check_entry_dimensions(*height, symbols, constant, metre, "a plane's height is a length");
            }
            std::vector<Constraint> generated = rolling_contact_constraints(model, c);
            for (Constraint& k : generated) model.constraints.push_back(std::move(k));
            model.contacts.push_back(std::move(c));
        }
    }

    /// [[springs]]: name, stiffness, length (rest length, default 0), from, to. An end is three expressions
    /// (a point in space axes, in q and t) or a table { body = "name", point = [x, y, z] } (body axes,
    /// from the body's centre of mass; point defaults to the centre itself).
    void read_springs(const std::vector<Entry>& entries, const SymbolTable& symbols, Model& model) const {
        ParseOptions constant;
        constant.forbid_velocities = "a spring's stiffness and rest length must not depend on velocities";
        ParseOptions placement;
        placement.forbid_velocities = "a spring's ends are functions of q and t, without velocities";
        for (const Entry& e : entries) {
            Spring spring;
            spring.name = e.name;
            spring.where = e.where;
            const toml::table& t = *e.table;
            const toml::node* k = t.get("stiffness");
            if (!k) fail(src_.at(t), "missing key 'stiffness' in [[springs]]");
            spring.stiffness = scalar(*k, "stiffness", symbols, constant);
            const Dims kg{{1, 0, 0, 0, 0, 0, 0}}, metre{{0, 1, 0, 0, 0, 0, 0}}, second{{0, 0, 1, 0, 0, 0, 0}};
            check_entry_dimensions(*k, symbols, constant, kg - second * 2, "a spring's stiffness is a force per length");
            if (const toml::node* l = t.get("length")) {
                spring.rest_length = scalar(*l, "length", symbols, constant);
                check_entry_dimensions(*l, symbols, constant, metre, "a spring's length is a length");
            }
            auto end = [&](const char* key) {
                const toml::node* node = t.get(key);
                if (!node)
                    fail(src_.at(t), std::string("missing key '") + key +
                                         "' in [[springs]]: a point [x, y, z] or { body = \"name\", point = [x, y, z] }");
                SpringEnd out;
                if (const toml::table* table = node->as_table()) {
                    check_keys(*table, {"body", "point"}, std::string("in the spring's '") + key + "'");
                    const toml::node* body = table->get("body");
                    if (!body) fail(src_.at(*table), std::string("missing key 'body' in the spring's '") + key + "'");
                    out.body = string_value(*body, "body");
                    if (std::none_of(model.bodies.begin(), model.bodies.end(),
                                     [&](const Body& b) { return b.name == out.body; }))
                        fail(string_start(*body), "no body named '" + out.body + "' in [[bodies]]");
                    if (const toml::node* point = table->get("point")) {
                        const std::vector<GiNaC::ex> p = scalars(*point, "point", 3, symbols, placement);
                        check_entry_dimensions(*point, symbols, placement, metre, "a spring's end is a point");
                        out.point = {p[0], p[1], p[2]};
                    }
                } else {
                    const std::vector<GiNaC::ex> p = scalars(*node, key, 3, symbols, placement);
                    check_entry_dimensions(*node, symbols, placement, metre, "a spring's end is a point");
                    out.point = {p[0], p[1], p[2]};
                }
                return out;
            };
            spring.from = end("from");
            spring.to = end("to");
            model.springs.push_back(std::move(spring));
        }
    }

    /// [gravity]: vector = [gx, gy, gz], the uniform gravitational acceleration in space axes.
    void read_gravity(const toml::table& root, const SymbolTable& symbols, Model& model) const {
        const toml::node* node = root.get("gravity");
        if (!node) return;
        const toml::table* table = node->as_table();
        if (!table) fail(src_.at(*node), "'gravity' must be a table [gravity] with vector = [gx, gy, gz], not " + type_name(*node));
        check_keys(*table, {"vector"}, "in [gravity]");
        const toml::node* vector = table->get("vector");
        if (!vector) fail(src_.at(*table), "missing key 'vector' in [gravity], e.g. vector = [\"0\", \"0\", \"-g\"]");
        ParseOptions options;
        options.forbid_velocities = "gravity must not depend on velocities";
        const std::vector<GiNaC::ex> g = scalars(*vector, "vector", 3, symbols, options);
        check_entry_dimensions(*vector, symbols, options, Dims{{0, 1, -2, 0, 0, 0, 0}}, "gravity is an acceleration");
        model.gravity = {g[0], g[1], g[2]};
    }

    /// [[constraints]]: name, kind = "holonomic" (g(q,t) = 0) or "nonholonomic" (a·q' + b = 0), expr.
    void read_constraints(const std::vector<Entry>& entries, const SymbolTable& symbols, Model& model) const {
        for (const Entry& e : entries) {
            Constraint c;
            c.name = e.name;
            c.where = e.where;
            const toml::node* kind = e.table->get("kind");
            const std::string k = kind ? string_value(*kind, "kind") : "holonomic";
            if (k == "holonomic") {
                c.kind = ConstraintKind::Holonomic;
            } else if (k == "nonholonomic") {
                c.kind = ConstraintKind::Nonholonomic;
            } else {
                fail(string_start(*kind), "constraint kind '" + k + "' is neither \"holonomic\" (g(q, t) = 0) nor "
                                          "\"nonholonomic\" (a(q, t)·q' + b(q, t) = 0)");
            }
            const toml::node* expr = e.table->get("expr");
            if (!expr) fail(src_.at(*e.table), "missing key 'expr' in [[constraints]] (the constraint, = 0)");
            ParseOptions options;
            if (c.kind == ConstraintKind::Holonomic)
                options.forbid_velocities =
                    "a holonomic constraint g(q, t) = 0 has no velocities (declare kind = \"nonholonomic\")";
            c.expr.expr = expression(*expr, "expr", symbols, options);
            check_dimensions(*expr, symbols, options, std::nullopt, "constraint '" + c.name + "' is homogeneous");
            c.expr.text = expr->as_string()->get();
            c.expr.where = string_start(*expr);
            model.constraints.push_back(std::move(c));
        }
    }

    /// An entry's name, not empty and not one of `seen` (name → line), which it joins; `what`: "result".
    void unique_name(const Entry& e, const std::string& what, std::map<std::string, int>& seen) const {
        if (e.name.empty()) fail(e.where, "a " + what + "'s name may not be empty");
        if (const auto [it, inserted] = seen.emplace(e.name, e.where.line); !inserted)
            fail(e.where, "duplicate " + what + " '" + e.name + "': already on line " + std::to_string(it->second));
    }

    /// [[results]]: name, latex, expr, description, equals, on_constraints. `equals` is checked for its form
    /// and its names here; whether the result holds is checked by the mechanics stage (verify_results).
    void read_results(const std::vector<Entry>& entries, const SymbolTable& symbols, Model& model) const {
        std::map<std::string, int> seen;
        for (const Entry& e : entries) {
            const toml::table& t = *e.table;
            Result r;
            r.name = e.name;
            r.where = e.where;
            unique_name(e, "result", seen);
            r.latex = latex_field(t).value_or(default_latex(e.name));
            r.description = optional_string(t, "description").value_or("");
            const toml::node* expr = t.get("expr");
            if (!expr) fail(src_.at(t), "missing key 'expr' in [[results]] (the closed form)");
            r.expr.expr = expression(*expr, "expr", symbols, {});
            r.expr.text = expr->as_string()->get();
            r.expr.where = string_start(*expr);
            if (const toml::node* on = t.get("on_constraints")) {
                const auto* b = on->as_boolean();
                if (!b) fail(src_.at(*on), "'on_constraints' must be true or false, not " + type_name(*on));
                r.on_constraints = b->get();
                if (r.on_constraints && model.constraints.empty())
                    fail(src_.at(*on), "'on_constraints = true' but the model has no [[constraints]]");
            }
            if (const toml::node* eq = t.get("equals")) {
                r.equals = string_value(*eq, "equals");
                r.equals_where = string_start(*eq);
                const std::string problem = equals_problem(r.equals, model);
                if (!problem.empty()) fail(r.equals_where, problem);
            } else if (t.get("on_constraints")) {
                fail(src_.at(*t.get("on_constraints")), "'on_constraints' goes with 'equals'");
            }
            model.results.push_back(std::move(r));
        }
    }

    /// [[motions]]: name, description, section, constants (names the conditions may use), conditions
    /// ("theta' = 0", "psi' = -Omega": a coordinate or its velocity, each at most once, = an expression in the
    /// constants, parameters, coordinates and t).
    void read_motions(const std::vector<Entry>& entries, const SymbolTable& model_symbols, Model& model) const {
        std::map<std::string, int> seen;
        for (const Entry& e : entries) {
            const toml::table& t = *e.table;
            Motion m;
            m.name = e.name;
            m.where = e.where;
            unique_name(e, "motion", seen);
            m.description = optional_string(t, "description").value_or("");
            m.section = optional_string(t, "section").value_or("");
            SymbolTable symbols = model_symbols;
            if (const toml::node* cs = t.get("constants")) {
                const toml::array* list = cs->as_array();
                if (!list) fail(src_.at(*cs), "'constants' must be an array of names, not " + type_name(*cs));
                for (const toml::node& c : *list) {
                    const std::string name = string_value(c, "constants");
                    if (const std::string why = name_problem(name); !why.empty())
                        fail(string_start(c), "the constant '" + name + "' of motion '" + e.name + "': " + why);
                    if (symbols.symbols.count(name))
                        fail(string_start(c), "the constant '" + name + "' of motion '" + e.name +
                                                  "' is already a name of the model");
                    const std::string latex = default_latex(name);
                    m.constants.push_back({name, latex, GiNaC::symbol(name, latex)});
                    symbols.symbols[name] = m.constants.back().symbol;
                }
            }
            const toml::node* cn = t.get("conditions");
            if (!cn) fail(src_.at(t), "missing key 'conditions' in [[motions]] (such as \"theta' = 0\")");
            const toml::array* list = cn->as_array();
            if (!list || list->empty())
                fail(src_.at(*cn), "'conditions' must be a non-empty array of strings such as \"theta' = 0\"");
            std::map<std::size_t, std::string> given;
            for (const toml::node& c : *list) {
                const std::string text = string_value(c, "conditions");
                const std::size_t eq = text.find('=');
                if (eq == std::string::npos || text.find('=', eq + 1) != std::string::npos)
                    fail(string_start(c), "a condition is one equation 'coordinate = value' or "
                                          "'coordinate' = value', such as \"theta' = 0\"");
                const std::size_t lb = text.find_first_not_of(" \t");
                std::size_t le = text.find_last_not_of(" \t", eq - 1);
                if (lb >= eq || le == std::string::npos) fail(string_start(c), "a condition needs a left side");
                std::string lhs = text.substr(lb, le - lb + 1);
                MotionCondition mc;
                mc.text = text;
                if (!lhs.empty() && lhs.back() == '\'') {
                    mc.velocity = true;
                    lhs.pop_back();
                }
                const auto coord = std::find_if(model.coordinates.begin(), model.coordinates.end(),
                                                [&](const Coordinate& q) { return q.name == lhs; });
                if (coord == model.coordinates.end())
                    fail(inside_string(c, lb), "the left side of a condition is a coordinate or its velocity "
                                               "(such as theta or theta'), not '" + text.substr(lb, le - lb + 1) + "'");
                mc.coordinate = std::size_t(coord - model.coordinates.begin());
                if (const auto [it, inserted] = given.emplace(mc.coordinate, text); !inserted)
                    fail(inside_string(c, lb), "'" + lhs + "' is already given by the condition \"" + it->second +
                                                   "\" of motion '" + e.name + "'");
                ParseOptions options;
                options.forbid_velocities = "a condition's value is in the constants, parameters, coordinates "
                                            "and t (no velocities)";
                try {
                    mc.value.expr = parse_expression(text.substr(eq + 1), symbols, options);
                } catch (const ExpressionError& err) {
                    fail(inside_string(c, eq + 1 + err.offset()), err.message());
                }
                mc.value.text = text.substr(eq + 1);
                mc.value.where = inside_string(c, eq + 1);
                m.conditions.push_back(std::move(mc));
            }
            model.motions.push_back(std::move(m));
        }
    }

    /// The entries of [outputs] in file order (a TOML table keeps its keys sorted).
    std::vector<OutputEntry> output_entries(const toml::table& root) const {
        std::vector<OutputEntry> out;
        const toml::node* node = root.get("outputs");
        if (!node) return out;
        const toml::table* table = node->as_table();
        if (!table)
            fail(src_.at(*node),
                 "'outputs' must be a table [outputs] of name = \"expression\", not " + type_name(*node));
        for (auto&& [key, value] : *table)
            out.push_back({std::string(key.str()), src_.at(key.source().begin), &value});
        std::stable_sort(out.begin(), out.end(), [](const OutputEntry& a, const OutputEntry& b) {
            return order(a.where) < order(b.where);
        });
        return out;
    }

    /// [outputs]: name = "expression", or name = { expr = "...", unit = "m", latex = '...', description =
    /// "..." }; the expression in the parameters, q, q', t (the syntax of T).
    void read_outputs(const std::vector<OutputEntry>& entries, const SymbolTable& symbols,
                      Model& model) const {
        for (const OutputEntry& e : entries) {
            DeclaredOutput o;
            o.name = e.name;
            o.where = e.where;
            const toml::node* expr = e.value;
            if (const toml::table* t = e.value->as_table()) {
                check_keys(*t, {"expr", "unit", "latex", "description"}, "in output '" + e.name + "'");
                expr = t->get("expr");
                if (!expr)
                    fail(src_.at(*t), "missing key 'expr' in output '" + e.name + "' (what to record)");
                o.latex = latex_field(*t).value_or(default_latex(e.name));
                o.unit = optional_string(*t, "unit").value_or("");
                o.description = optional_string(*t, "description").value_or("");
            } else if (!e.value->as_string()) {
                fail(src_.at(*e.value), "output '" + e.name +
                                            "' must be a string with an expression or a table "
                                            "{ expr = \"...\", unit = \"...\" }, not " +
                                            type_name(*e.value));
            } else {
                o.latex = default_latex(e.name);
            }
            o.expr.expr = expression(*expr, "expr", symbols, {});
            o.expr.text = expr->as_string()->get();
            o.expr.where = string_start(*expr);
            // Its unit: read by UDUNITS-2, of the expression's dimension where that is known; the value recorded is
            // in it (an output in cm is the SI value times 100).
            if (const toml::table* t = e.value->as_table(); t && !o.unit.empty()) {
                if (const std::optional<Unit> unit = unit_field(*t)) {
                    std::optional<Dims> d;
                    try {
                        d = dimension_of(o.expr.expr, dims_);
                    } catch (const DimensionError& error) {
                        fail(string_start(*expr), "output '" + o.name + "': " + error.what());
                    }
                    if (d && *d != Dims::of(unit->dimension))
                        fail(string_start(*expr), "output '" + o.name + "' is " + d->str() + ", but its unit " +
                                                      unit->text + " is " + Dims::of(unit->dimension).str());
                    if (unit->to_si != 1.0) {
                        const std::optional<GiNaC::ex> factor = exact_factor(unit->to_si);
                        if (!factor)
                            fail(src_.at(*t->get("unit")), "output '" + o.name + "': the unit " + unit->text +
                                                               " is not a simple fraction (or fraction of π) of its SI unit");
                        o.expr.expr = o.expr.expr / *factor;
                    }
                }
            }
            model.outputs.push_back(std::move(o));
        }
    }

    /// Why `equals` names nothing eomgen derives ("" when it is fine).
    static std::string equals_problem(const std::string& target, const Model& model) {
        static const std::string known =
            "\"T\", \"V\", \"L\", \"energy\", \"p_<coordinate>\", \"inertia.<body>.<xx|yy|zz|xy|xz|yz>\", "
            "\"inertia_origin.<body>.<ij>\", \"principal.<body>\", \"principal_origin.<body>\", "
            "\"omega.<body>.<x|y|z>\" or \"omega_space.<body>.<x|y|z>\"";
        if (target == "T" || target == "V" || target == "L" || target == "energy") return "";
        if (target.rfind("p_", 0) == 0) {
            const std::string q = target.substr(2);
            for (const Coordinate& c : model.coordinates)
                if (c.name == q) return "";
            std::vector<std::string> names;
            for (const Coordinate& c : model.coordinates) names.push_back(c.name);
            const std::string best = closest_name(q, names);
            return "'" + target + "': no coordinate '" + q + "'" + (best.empty() ? "" : "; did you mean 'p_" + best + "'?");
        }
        const std::size_t dot = target.find('.');
        const std::string head = target.substr(0, dot);
        if (dot != std::string::npos &&
            (head == "inertia" || head == "inertia_origin" || head == "principal" || head == "principal_origin" ||
             head == "omega" || head == "omega_space")) {
            const std::string rest = target.substr(dot + 1);
            const bool omega = head == "omega" || head == "omega_space";
            const bool component = head == "inertia" || head == "inertia_origin" || omega;
            const std::size_t dot2 = rest.find('.');
            const std::string body = component ? rest.substr(0, dot2) : rest;
            if (omega) {
                const std::string c = dot2 == std::string::npos ? "" : rest.substr(dot2 + 1);
                if (c != "x" && c != "y" && c != "z")
                    return "'" + target + "': name a component, " + head + "." + body + ".x (or y, z)";
            } else if (component) {
                static const std::vector<std::string> ij = {"xx", "yy", "zz", "xy", "yx", "xz", "zx", "yz", "zy"};
                const std::string c = dot2 == std::string::npos ? "" : rest.substr(dot2 + 1);
                if (std::find(ij.begin(), ij.end(), c) == ij.end())
                    return "'" + target + "': name a component, " + head + "." + body + ".xx (or yy, zz, xy, xz, yz)";
            }
            std::vector<std::string> names;
            for (const Body& b : model.bodies) {
                if (b.name == body) return "";
                names.push_back(b.name);
            }
            const std::string best = closest_name(body, names);
            return "'" + target + "': no body '" + body + "' in [[bodies]]" +
                   (best.empty() ? "" : "; did you mean '" + best + "'?");
        }
        return "'equals = \"" + target + "\"' names nothing eomgen derives; use " + known;
    }

    /// [forces]: coordinate = "Q(q, q', t)", the generalized force on that coordinate.
    void read_forces(const toml::table& root, const SymbolTable& symbols, Model& model) const {
        model.forces.assign(model.coordinates.size(), SourceExpression{0, "0", src_.file_only()});
        const toml::node* node = root.get("forces");
        if (!node) return;
        const toml::table* table = node->as_table();
        if (!table) fail(src_.at(*node), "'forces' must be a table [forces] of coordinate = \"Q\", not " + type_name(*node));
        std::vector<std::string> names;
        for (const Coordinate& c : model.coordinates) names.push_back(c.name);
        check_keys(*table, names, "in [forces] (keys are coordinates)");
        for (std::size_t i = 0; i < names.size(); ++i)
            if (const toml::node* q = table->get(names[i])) {
                model.forces[i].expr = expression(*q, names[i], symbols, {});
                // Q_i does the work Q_i δq_i: an energy per unit of the coordinate.
                if (const auto qd = dims_.find(model.coordinates[i].q); qd != dims_.end())
                    check_dimensions(*q, symbols, {}, energy_dims() - qd->second,
                                     "the force on " + names[i] + " is an energy per unit of " + names[i]);
                model.forces[i].text = q->as_string()->get();
                model.forces[i].where = string_start(*q);
            }
    }

    /// [stabilization]: alpha, beta of Baumgarte's method (defaults 0: none).
    void read_stabilization(const toml::table& root, Model& model) const {
        const toml::node* node = root.get("stabilization");
        if (!node) return;
        const toml::table* table = node->as_table();
        if (!table) fail(src_.at(*node), "'stabilization' must be a table with alpha and beta, not " + type_name(*node));
        check_keys(*table, {"alpha", "beta"}, "in [stabilization]");
        const SymbolTable none;
        model.baumgarte_alpha = constant(*table, "alpha", none, 0.0);
        model.baumgarte_beta = constant(*table, "beta", none, 0.0);
        for (const char* key : {"alpha", "beta"})
            if (const toml::node* n = table->get(key); n && constant(*table, key, none, 0.0) < 0)
                fail(src_.at(*n), std::string("'") + key + "' must not be negative");
    }

    /// [generate]: jacobians, stiffness (true or false, default false): the header's optional functions.
    void read_generate(const toml::table& root, Model& model) const {
        const toml::node* node = root.get("generate");
        if (!node) return;
        const toml::table* table = node->as_table();
        if (!table)
            fail(src_.at(*node), "'generate' must be a table with jacobians and stiffness (true or false), not " +
                                     type_name(*node));
        check_keys(*table, {"jacobians", "stiffness"}, "in [generate]");
        auto flag = [&](const char* key, bool& out) {
            const toml::node* n = table->get(key);
            if (!n) return;
            const auto* b = n->as_boolean();
            if (!b) fail(src_.at(*n), std::string("'") + key + "' must be true or false, not " + type_name(*n));
            out = b->get();
        };
        flag("jacobians", model.generate.jacobians);
        flag("stiffness", model.generate.stiffness);
        if (model.generate.jacobians && !model.constraints.empty())
            fail(src_.at(*table->get("jacobians")),
                 "'jacobians = true' is for unconstrained models: a model with [[constraints]] is differentiated by "
                 "forward AD through its rhs() (eomgen::model_jacobian), which needs no generated Jacobian");
    }

    SourceText src_;
    /// The dimension of each symbol whose entry declares a unit (model/dimensions.hpp), filled in with the values.
    mutable std::map<GiNaC::ex, Dims, GiNaC::ex_is_less> dims_;
    mutable std::vector<Dims> coordinate_dims_;  ///< of q, q̇ and q̈ of each coordinate with a unit
    std::string path_;
    std::string default_name_;  ///< the name when the file gives none ("": the file name's stem)
};

}  // namespace

Model parse_model(std::string_view text, const std::string& path, const std::string& default_name) {
    return Loader(text, path, default_name).load();
}

std::string read_model_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ModelError({path, 0, 0}, "cannot open the model file");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw ModelError({path, 0, 0}, "cannot read the model file");
    return text.str();
}

Model load_model(const std::string& path) { return parse_model(read_model_file(path), path); }

}  // namespace eomgen
