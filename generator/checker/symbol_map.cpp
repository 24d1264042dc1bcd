/** @file symbol_map.cpp  Reading the symbol map from the command line and from TOML map files. */
#include "checker/symbol_map.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace eomgen::checker {
namespace {

std::string trim(const std::string& s) {
    const std::size_t a = s.find_first_not_of(" \t\r\n");
    if (a == std::string::npos) return "";
    const std::size_t b = s.find_last_not_of(" \t\r\n");
    return s.substr(a, b - a + 1);
}

std::string at(const std::string& path, const toml::source_region& r) {
    return path + ":" + std::to_string(r.begin.line) + ":" + std::to_string(r.begin.column);
}

}  // namespace

MapEntry parse_map_option(const std::string& text) {
    int depth = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\\' && i + 1 < text.size()) {
            ++i;
            continue;
        }
        if (c == '{') ++depth;
        if (c == '}') --depth;
        if (c == '=' && depth == 0) {
            MapEntry e{trim(text.substr(0, i)), trim(text.substr(i + 1)), "--map '" + text + "'"};
            if (e.name.empty() || e.value.empty())
                throw CheckError("--map '" + text + "': expected NAME=VALUE, e.g. --map 'I_{0}=M a^2/2'");
            return e;
        }
    }
    throw CheckError("--map '" + text + "': expected NAME=VALUE, e.g. --map 'I_{0}=M a^2/2'");
}

std::vector<MapEntry> load_map_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw CheckError(path + ": cannot read the map file");
    std::stringstream ss;
    ss << in.rdbuf();
    toml::table root;
    try {
        root = toml::parse(ss.str(), std::string_view(path));
    } catch (const toml::parse_error& e) {
        throw CheckError(at(path, e.source()) + ": " + std::string(e.description()));
    }
    std::vector<MapEntry> out;
    for (auto&& [key, node] : root) {
        if (key.str() != "latex")
            throw CheckError(at(path, node.source()) + ": unknown key '" + std::string(key.str()) +
                             "' (a map file has only a [latex] table)");
        const toml::table* t = node.as_table();
        if (!t) throw CheckError(at(path, node.source()) + ": 'latex' must be a table: [latex]");
        // toml++ iterates tables in key order; keep the file's order, which matters when entries use each
        // other.
        std::vector<std::pair<std::size_t, MapEntry>> entries;
        for (auto&& [name, value] : *t) {
            // A string, or { value = '...', lines = 'N-M' }: an entry for the text's lines N to M only.
            const toml::node* v = &value;
            int first = 0, last = 0;
            if (const toml::table* scoped = value.as_table()) {
                for (auto&& [k, x] : *scoped)
                    if (k.str() != "value" && k.str() != "lines")
                        throw CheckError(at(path, x.source()) + ": unknown key '" + std::string(k.str()) +
                                         "' (an entry is a string or { value = '...', lines = 'N-M' })");
                const auto* lines = scoped->get("lines") ? scoped->get("lines")->as_string() : nullptr;
                v = scoped->get("value");
                if (!v || !lines)
                    throw CheckError(at(path, value.source()) + ": '" + std::string(name.str()) +
                                     "' must be { value = '...', lines = 'N-M' }");
                const std::string range = lines->get();
                char dash = 0;
                std::istringstream is(range);
                if (!(is >> first) || !(is >> dash) || dash != '-' || !(is >> last) || first < 1 || last < first)
                    throw CheckError(at(path, lines->source()) + ": lines must be 'N-M' with 1 <= N <= M, not '" +
                                     range + "'");
            }
            const auto* s = v->as_string();
            if (!s)
                throw CheckError(at(path, v->source()) + ": the value of '" + std::string(name.str()) +
                                 "' must be a string of LaTeX");
            const auto& b = value.source().begin;
            MapEntry e{std::string(name.str()), s->get(), path + ":" + std::to_string(b.line)};
            if (first > 0) {
                e.first_line = first;
                e.last_line = last;
                e.origin += " (the text's lines " + std::to_string(first) + "-" + std::to_string(last) + ")";
            }
            entries.push_back({std::size_t(b.line) * 100000 + b.column, e});
        }
        std::stable_sort(entries.begin(), entries.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
        for (auto& [pos, e] : entries) out.push_back(std::move(e));
    }
    return out;
}

std::pair<std::string, double> parse_set_option(const std::string& text) {
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos || eq == 0) throw CheckError("--set " + text + ": expected NAME=VALUE");
    const std::string value = text.substr(eq + 1);
    std::size_t used = 0;
    double v = 0;
    try {
        v = std::stod(value, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != value.size() || !std::isfinite(v))
        throw CheckError("--set " + text + ": '" + value + "' is not a finite number");
    return {text.substr(0, eq), v};
}

}  // namespace eomgen::checker
