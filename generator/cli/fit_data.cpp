/** @file fit_data.cpp  Reading a measured time series for `eomgen fit` (fit_data.hpp). */
#include "cli/fit_data.hpp"

#include "eomgen/column_units.hpp"
#include "text/escape.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace eomgen::cli {

namespace {

using text::valid_utf8;

/// The cells of one CSV line (no quoting: the data are numbers and plain names) with their 1-based columns.
struct Cell {
    std::string text;
    int col;
};

std::vector<Cell> split(const std::string& line) {
    std::vector<Cell> cells;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        std::string text = line.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        // Spaces around a cell are not part of it.
        const std::size_t first = text.find_first_not_of(" \t");
        const std::size_t last = text.find_last_not_of(" \t\r");
        const int col = int(start) + 1 + int(first == std::string::npos ? 0 : first);
        cells.push_back({first == std::string::npos ? "" : text.substr(first, last - first + 1), col});
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return cells;
}

std::string place(const std::string& path, int line, int col) {
    return path + ":" + std::to_string(line) + ":" + std::to_string(col) + ": ";
}

}  // namespace

MeasuredSeries read_measured(const std::string& path, const Measurable& measurable) {
    const std::vector<std::string>& names = measurable.names;
    std::ifstream in(path);
    if (!in) throw FitDataError(path + ": cannot read the data file");
    MeasuredSeries s;
    s.path = path;
    std::string line;
    int line_no = 0;
    // The header: t first, then states.
    while (std::getline(in, line)) {
        ++line_no;
        if (line.find_first_not_of(" \t\r") != std::string::npos) break;
    }
    if (line_no == 0 || line.find_first_not_of(" \t\r") == std::string::npos)
        throw FitDataError(path + ": the data file is empty (expected a header: t, then the measured states)");
    const std::vector<Cell> header = split(line);
    const std::string shown = valid_utf8(header[0].text);
    if (column_name(header[0].text) != "t")
        throw FitDataError(place(path, line_no, header[0].col) + "the first column must be t, not '" + shown + "'");
    if (header.size() < 2)
        throw FitDataError(place(path, line_no, header[0].col) + "no measured column after t (expected states such as " +
                           names.front() + ")");
    for (std::size_t c = 1; c < header.size(); ++c) {
        const std::string name = column_name(header[c].text);
        int index = -1;
        for (std::size_t i = 0; i < names.size(); ++i)
            if (names[i] == name) index = int(i);
        if (index < 0) {
            std::string states, outputs;
            for (std::size_t i = 0; i < names.size(); ++i)
                (i < measurable.states ? states : outputs) +=
                    ((i < measurable.states ? states : outputs).empty() ? "" : ", ") + names[i];
            throw FitDataError(place(path, line_no, header[c].col) + "'" + valid_utf8(name) +
                               "' is neither a state nor a declared output of the model (states: " + states +
                               (outputs.empty() ? "" : "; outputs: " + outputs) + ")");
        }
        for (const std::string& earlier : s.names)
            if (earlier == name)
                throw FitDataError(place(path, line_no, header[c].col) + "the column " + name + " is given twice");
        const std::string unit = header[c].text.size() > name.size() ? header[c].text.substr(name.size()) : "";
        if (!unit.empty()) {
            const std::string given = unit.size() > 3 ? unit.substr(2, unit.size() - 3) : "";
            const std::string& expected = measurable.units[std::size_t(index)];
            if (given != expected)
                throw FitDataError(place(path, line_no, header[c].col) + name + " is in " +
                                   (expected.empty() ? "no declared unit" : expected) + " (the unit eomgen run writes), not " +
                                   valid_utf8(given));
        }
        s.names.push_back(name);
        s.index.push_back(index);
    }
    std::vector<std::vector<double>> rows;
    while (std::getline(in, line)) {
        ++line_no;
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        const std::vector<Cell> cells = split(line);
        if (cells.size() != header.size())
            throw FitDataError(place(path, line_no, 1) + std::to_string(cells.size()) + " cells where the header has " +
                               std::to_string(header.size()));
        std::vector<double> row;
        for (const Cell& cell : cells) {
            errno = 0;
            char* end = nullptr;
            const double v = std::strtod(cell.text.c_str(), &end);
            if (cell.text.empty() || end != cell.text.c_str() + cell.text.size() || errno == ERANGE || !std::isfinite(v))
                throw FitDataError(place(path, line_no, cell.col) + "'" + valid_utf8(cell.text) +
                                   "' is not a finite number (a missing measurement is a row left out)");
            row.push_back(v);
        }
        if (row[0] < 0) throw FitDataError(place(path, line_no, cells[0].col) + "t < 0: the motion starts at t = 0");
        if (!s.t.empty() && !(row[0] > s.t.back()))
            throw FitDataError(place(path, line_no, cells[0].col) + "t = " + cells[0].text +
                               " does not come after the row before's " + std::to_string(s.t.back()) +
                               " (the times must increase)");
        s.t.push_back(row[0]);
        rows.push_back(std::move(row));
    }
    if (rows.empty()) throw FitDataError(path + ": no data rows after the header");
    s.y.resize(Eigen::Index(rows.size()), Eigen::Index(s.names.size()));
    for (std::size_t j = 0; j < rows.size(); ++j)
        for (std::size_t c = 0; c < s.names.size(); ++c) s.y(Eigen::Index(j), Eigen::Index(c)) = rows[j][c + 1];
    return s;
}

}  // namespace eomgen::cli
