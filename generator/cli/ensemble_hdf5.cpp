/** @file ensemble_hdf5.cpp  The ensemble's columns as HDF5 datasets, with the run's metadata as attributes. */
#include "cli/ensemble_hdf5.hpp"

#include "output/atomic_file.hpp"

#include <hdf5.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <limits>
#include <system_error>
#include <unistd.h>

namespace eomgen::cli {

namespace {

/// Closes an HDF5 handle when it goes out of scope.
class Handle {
  public:
    Handle(hid_t id, herr_t (*close)(hid_t), const std::string& what) : id_(id), close_(close) {
        if (id_ < 0) throw eomgen::output::WriteError("HDF5: cannot " + what);
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    ~Handle() { close_(id_); }
    operator hid_t() const { return id_; }

  private:
    hid_t id_;
    herr_t (*close_)(hid_t);
};

void check(herr_t status, const std::string& what) {
    if (status < 0) throw eomgen::output::WriteError("HDF5: cannot " + what);
}

/// A variable-length UTF-8 string type.
hid_t string_type() {
    const hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, H5T_VARIABLE);
    H5Tset_cset(t, H5T_CSET_UTF8);
    return t;
}

void write_strings(hid_t parent, const std::string& name, const std::vector<std::string>& values, bool attribute) {
    const hsize_t n = values.size();
    Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose, "make a dataspace for " + name);
    Handle type(string_type(), H5Tclose, "make a string type");
    std::vector<const char*> pointers;
    for (const std::string& v : values) pointers.push_back(v.c_str());
    if (attribute) {
        Handle a(H5Acreate2(parent, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, "create " + name);
        check(H5Awrite(a, type, pointers.data()), "write " + name);
    } else {
        Handle d(H5Dcreate2(parent, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
                 "create " + name);
        check(H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()), "write " + name);
    }
}

void write_attribute(hid_t parent, const std::string& name, const std::string& value) {
    Handle space(H5Screate(H5S_SCALAR), H5Sclose, "make a dataspace for " + name);
    Handle type(string_type(), H5Tclose, "make a string type");
    Handle a(H5Acreate2(parent, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, "create " + name);
    const char* p = value.c_str();
    check(H5Awrite(a, type, &p), "write " + name);
}

}  // namespace

Hdf5Table::Hdf5Table(std::string path, std::vector<std::string> columns, std::vector<bool> numeric,
                     std::vector<std::string> units, std::vector<std::pair<std::string, std::string>> attributes)
    : path_(std::move(path)), columns_(std::move(columns)), numeric_(std::move(numeric)), units_(std::move(units)),
      attributes_(std::move(attributes)), numbers_(columns_.size()), texts_(columns_.size()) {
    units_.resize(columns_.size());
}

void Hdf5Table::add(const std::vector<std::string>& fields) {
    for (std::size_t k = 0; k < columns_.size(); ++k) {
        if (!numeric_[k]) {
            texts_[k].push_back(fields[k]);
            continue;
        }
        // The CSV's digits read back exactly (max_digits10); "" is a value the member does not have.
        numbers_[k].push_back(fields[k].empty() ? std::numeric_limits<double>::quiet_NaN()
                                                : std::strtod(fields[k].c_str(), nullptr));
    }
}

void Hdf5Table::commit() {
    namespace fs = std::filesystem;
    const std::string tmp = path_ + ".tmp." + std::to_string(::getpid());
    struct Remove {
        const std::string& path;
        bool keep = false;
        ~Remove() {
            std::error_code ignored;
            if (!keep) fs::remove(path, ignored);
        }
    } remove{tmp};
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors come back as statuses, said here, not printed by HDF5
    {
        Handle file(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, "create " + tmp);
        Handle group(H5Gcreate2(file, "ensemble", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                     "create the group /ensemble");
        for (const auto& [name, value] : attributes_) write_attribute(group, name, value);
        write_strings(group, "columns", columns_, true);
        for (std::size_t k = 0; k < columns_.size(); ++k) {
            if (!numeric_[k]) {
                write_strings(group, columns_[k], texts_[k], false);
                continue;
            }
            const hsize_t n = numbers_[k].size();
            Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose, "make a dataspace for " + columns_[k]);
            Handle d(H5Dcreate2(group, columns_[k].c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                     H5Dclose, "create the dataset " + columns_[k]);
            check(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, numbers_[k].data()),
                  "write the dataset " + columns_[k]);
            if (!units_[k].empty()) write_attribute(d, "unit", units_[k]);
        }
        check(H5Fflush(file, H5F_SCOPE_GLOBAL), "write " + tmp);
    }
    std::error_code ec;
    fs::rename(tmp, path_, ec);
    if (ec) throw eomgen::output::WriteError("cannot rename '" + tmp + "' to '" + path_ + "': " + ec.message());
    remove.keep = true;
}

}  // namespace eomgen::cli
