/** @file sample_table.cpp  Reading a run's CSV of samples. */
#include "output/sample_table.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace eomgen::output {
namespace {

/// The fields of one CSV line (RFC 4180 quotes).
std::vector<std::string> csv_fields(const std::string& line) {
    std::vector<std::string> out(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                out.back() += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                out.back() += c;
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            out.emplace_back();
        } else if (c != '\r') {
            out.back() += c;
        }
    }
    return out;
}

}  // namespace

int SampleTable::column(const std::string& name) const {
    for (std::size_t i = 0; i < columns.size(); ++i)
        if (columns[i] == name) return int(i);
    return -1;
}

SampleTable read_sample_table(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read the samples " + path);
    SampleTable table;
    std::string line;
    if (!std::getline(in, line)) throw std::runtime_error(path + " is empty: no header of samples");
    for (std::string h : csv_fields(line)) {
        std::string unit;
        if (const std::size_t b = h.find(" ["); b != std::string::npos && !h.empty() && h.back() == ']') {
            unit = h.substr(b + 2, h.size() - b - 3);
            h = h.substr(0, b);
        }
        table.columns.push_back(h);
        table.units.push_back(unit);
    }
    for (int number = 2; std::getline(in, line); ++number) {
        if (line.empty()) continue;
        const std::vector<std::string> fields = csv_fields(line);
        if (fields.size() != table.columns.size())
            throw std::runtime_error(path + ":" + std::to_string(number) + ": " + std::to_string(fields.size()) +
                                     " fields where the header has " + std::to_string(table.columns.size()));
        std::vector<double> row;
        for (const std::string& f : fields) {
            char* end = nullptr;
            const double x = std::strtod(f.c_str(), &end);
            row.push_back(end != f.c_str() ? x : std::nan(""));
        }
        table.rows.push_back(std::move(row));
    }
    return table;
}

}  // namespace eomgen::output
