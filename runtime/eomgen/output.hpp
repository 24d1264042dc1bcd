/** @file output.hpp  Samples as CSV at full precision, written to a temporary file and renamed into place. */
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <type_traits>
#include <vector>

namespace eomgen {

/// A CSV field, quoted per RFC 4180 when it holds a comma, a quote or a line break.
inline std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (const char c : text) {
        if (c == '"') quoted += '"';
        quoted += c;
    }
    return quoted + "\"";
}

/**
 * What a program does with the temporary files the runtime writes: `guard(path)` right after one is created,
 * `release(path)` once it is renamed into place or removed. A library installs no signal handler of its own, so
 * by default both do nothing; the eomgen command and eomgen-sim point them at their handler of SIGINT, SIGTERM
 * and SIGHUP (generator/output/atomic_file.hpp), so that an interrupt while a CSV is written leaves no
 * `<path>.tmp` behind. An app that wants the same sets them once, before writing.
 */
struct TemporaryFileHooks {
    void (*guard)(const char* path) = nullptr;
    void (*release)(const char* path) = nullptr;
};

inline TemporaryFileHooks& temporary_file_hooks() {
    static TemporaryFileHooks hooks;
    return hooks;
}

/// A line of CSV: the fields escaped by csv_field(), separated by commas, ended by a newline.
inline std::string csv_row(const std::vector<std::string>& fields) {
    std::string line;
    for (std::size_t i = 0; i < fields.size(); ++i) line += (i ? "," : "") + csv_field(fields[i]);
    return line + "\n";
}

/// A number as the CSV writers write it: max_digits10 significant digits, so that it reads back exactly.
template <class Scalar = double>
std::string csv_number(const Scalar& value) {
    std::ostringstream os;
    os.precision(std::numeric_limits<Scalar>::max_digits10);
    os << value;
    return os.str();
}

/**
 * A text file that appears whole or not at all: written to `<path>.tmp`, which commit() renames over
 * `path` (atomic on POSIX within one directory); if the object goes without commit(), e.g. because the
 * simulation threw, the temporary file is removed and `path` is left as it was (and on an interrupt too,
 * where the program set temporary_file_hooks()). Throws std::runtime_error
 * when the file cannot be opened, written or renamed.
 */
class AtomicOutputFile {
  public:
    explicit AtomicOutputFile(const std::string& path) : path_(path), tmp_path_(path + ".tmp") {
        out_.open(tmp_path_, std::ios::out | std::ios::trunc);
        if (!out_) throw std::runtime_error("cannot open '" + tmp_path_ + "' for writing");
        if (temporary_file_hooks().guard) temporary_file_hooks().guard(tmp_path_.c_str());
        guarded_ = true;
    }
    AtomicOutputFile(const AtomicOutputFile&) = delete;
    AtomicOutputFile& operator=(const AtomicOutputFile&) = delete;
    ~AtomicOutputFile() {
        if (committed_) return;
        out_.close();
        std::error_code ignored;
        std::filesystem::remove(tmp_path_, ignored);
        release();
    }

    std::ostream& stream() { return out_; }
    const std::string& path() const { return path_; }

    /// Throws when a write to the stream has failed.
    void check() {
        if (!out_) throw std::runtime_error("error writing '" + tmp_path_ + "'");
    }

    /// Flushes, closes and renames the temporary file over `path`.
    void commit() {
        out_.flush();
        const bool ok = static_cast<bool>(out_);
        out_.close();
        if (!ok || out_.fail()) throw std::runtime_error("error writing '" + tmp_path_ + "'");
        std::error_code ec;
        std::filesystem::rename(tmp_path_, path_, ec);
        if (ec)
            throw std::runtime_error("cannot rename '" + tmp_path_ + "' to '" + path_ + "': " + ec.message());
        committed_ = true;
        release();
    }

  private:
    void release() {
        if (guarded_ && temporary_file_hooks().release) temporary_file_hooks().release(tmp_path_.c_str());
        guarded_ = false;
    }

    std::string path_, tmp_path_;
    std::ofstream out_;
    bool committed_ = false, guarded_ = false;
};

/**
 * Writes `t,<state names...>,<extra names...>` (the first column `time_name`, "t" or "t [s]") and then one row
 * per call of write_row, every number at
 * std::numeric_limits<Scalar>::max_digits10 significant digits (so each value reads back exactly).
 * Atomic as AtomicOutputFile: rows go to `<path>.tmp`, commit() renames it over `path`.
 */
template <class Scalar>
class CsvWriter {
  public:
    CsvWriter(const std::string& path, const std::vector<std::string>& state_names,
              const std::vector<std::string>& extra_names = {}, const std::string& time_name = "t")
        : file_(path), columns_(state_names.size() + extra_names.size()), n_state_(state_names.size()) {
        std::ostream& out = file_.stream();
        out.precision(std::numeric_limits<Scalar>::max_digits10);
        out << csv_field(time_name);
        for (const auto& name : state_names) out << ',' << csv_field(name);
        for (const auto& name : extra_names) out << ',' << csv_field(name);
        out << '\n';
    }

    /// One row: t, the state x (size = number of state names) and the extras (any indexable, e.g. an
    /// Eigen vector or std::array, size = number of extra names).
    template <class Derived, class Extra>
    void write_row(const Scalar& t, const Eigen::MatrixBase<Derived>& x, const Extra& extra) {
        const std::size_t n_extra = static_cast<std::size_t>(extra.size());
        if (static_cast<std::size_t>(x.size()) != n_state_ || n_state_ + n_extra != columns_)
            throw std::invalid_argument("CsvWriter: row does not match the header of '" + file_.path() + "'");
        std::ostream& out = file_.stream();
        out << t;
        for (Eigen::Index i = 0; i < x.size(); ++i) out << ',' << Scalar(x(i));
        for (std::size_t i = 0; i < n_extra; ++i) out << ',' << Scalar(extra[i]);
        out << '\n';
        file_.check();
    }

    /// A row without extra columns.
    template <class Derived>
    void write_row(const Scalar& t, const Eigen::MatrixBase<Derived>& x) {
        write_row(t, x, std::vector<Scalar>{});
    }

    /// Flushes, closes and renames the temporary file over `path`.
    void commit() { file_.commit(); }

  private:
    AtomicOutputFile file_;
    std::size_t columns_, n_state_;
};

/**
 * Writes `samples` (a range of objects with members t and x, e.g. IntegrationResult::samples) to `path`
 * as CSV, with extra columns from extra(t, x), which returns something indexable of extra_names.size()
 * values (e.g. std::array{energy}). Atomic as CsvWriter: on any error `path` is untouched.
 */
template <class Samples, class Extra>
void write_csv(const std::string& path, const std::vector<std::string>& state_names,
               const std::vector<std::string>& extra_names, const Samples& samples, Extra&& extra,
               const std::string& time_name = "t") {
    using Scalar = std::decay_t<decltype(std::begin(samples)->t)>;
    CsvWriter<Scalar> writer(path, state_names, extra_names, time_name);
    for (const auto& sample : samples) writer.write_row(sample.t, sample.x, extra(sample.t, sample.x));
    writer.commit();
}

/// write_csv with the state columns only.
template <class Samples>
void write_csv(const std::string& path, const std::vector<std::string>& state_names, const Samples& samples) {
    using Scalar = std::decay_t<decltype(std::begin(samples)->t)>;
    CsvWriter<Scalar> writer(path, state_names);
    for (const auto& sample : samples) writer.write_row(sample.t, sample.x);
    writer.commit();
}

}  // namespace eomgen
