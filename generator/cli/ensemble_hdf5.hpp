/**
 * @file ensemble_hdf5.hpp  An ensemble's table as HDF5 (`eomgen run ... --out FILE.h5`), built only where
 * CMake finds the HDF5 library (Debian: libhdf5-dev; EOMGEN_HAVE_HDF5).
 *
 * The file holds a group /ensemble with one 1-D dataset per column of the CSV table, in the same order and
 * with the same names (numbers as 64-bit IEEE doubles, NaN where the CSV has an empty field; status,
 * stopped and message as variable-length UTF-8 strings; a number's unit, where the model declares one, as the
 * dataset's attribute `unit`), an attribute `columns` listing them in order, and
 * the run's metadata as string attributes of /ensemble (eomgen's version, the model's name and the hash of
 * its file, the options every member ran with, the design). Like the CSV, it is written to a temporary
 * file beside FILE.h5 and renamed over it, so a reader sees the old file or the whole new one.
 */
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace eomgen::cli {

class Hdf5Table {
  public:
    /// `numeric[k]`: column k holds numbers (as csv_number writes them, or "" for none), else text; `units[k]` its
    /// unit ("rad", "J"; "" for none), written as the dataset's attribute `unit`.
    Hdf5Table(std::string path, std::vector<std::string> columns, std::vector<bool> numeric,
              std::vector<std::string> units, std::vector<std::pair<std::string, std::string>> attributes);

    /// One row, the fields as the CSV has them.
    void add(const std::vector<std::string>& fields);

    /// Writes the file; throws output::WriteError (with HDF5's reason where it gives one) and leaves no
    /// temporary file behind.
    void commit();

  private:
    std::string path_;
    std::vector<std::string> columns_;
    std::vector<bool> numeric_;
    std::vector<std::string> units_;
    std::vector<std::pair<std::string, std::string>> attributes_;
    std::vector<std::vector<double>> numbers_;      ///< per numeric column
    std::vector<std::vector<std::string>> texts_;   ///< per text column
};

}  // namespace eomgen::cli
