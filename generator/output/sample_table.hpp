/** @file sample_table.hpp  The CSV of a run's samples as the runtime writes it (eomgen/sample_csv.hpp): a header
 * of names with their units ("theta [rad]"), then rows of numbers. Read back by eomgen report (the drift of the
 * invariants) and eomgen run --animate (the frames). */
#pragma once

#include <string>
#include <vector>

namespace eomgen::output {

/// The columns and rows of a run's CSV: headers without their units ("theta", not "theta [rad]").
struct SampleTable {
    std::vector<std::string> columns;
    std::vector<std::string> units;  ///< "" where a header has none
    std::vector<std::vector<double>> rows;

    /// The index of column `name`, or -1.
    int column(const std::string& name) const;
};

/// Reads a CSV of samples (RFC 4180 quotes); std::runtime_error naming the file and line where it cannot.
SampleTable read_sample_table(const std::string& path);

}  // namespace eomgen::output
