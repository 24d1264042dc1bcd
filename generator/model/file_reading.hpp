/** @file file_reading.hpp  What a reader of one section of a model file needs from the loader (model_file.cpp):
 * places in the file, checked strings and keys, expressions with their errors at file:line:col. Internal to
 * model/: the sections read in their own files (drawing_file.cpp) take it, so model_file.cpp does not grow with
 * each new section. */
#pragma once

#include "model/expression_parser.hpp"
#include "model/source_location.hpp"

#include <toml++/toml.h>

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace eomgen {

class FileReading {
public:
    virtual ~FileReading() = default;
    /// Throws ModelError at `where`.
    [[noreturn]] virtual void fail(const SourceLocation& where, const std::string& message) const = 0;
    /// Where a node starts.
    virtual SourceLocation at(const toml::node& node) const = 0;
    /// Where the text of a string value starts (just inside its quotes), else where the node starts.
    virtual SourceLocation string_start(const toml::node& node) const = 0;
    /// A string value without NUL or control characters (a ModelError where it is not a string).
    virtual std::string string_value(const toml::node& node, const std::string& key) const = 0;
    /// Each key of `table` is one of `allowed`, else a ModelError at the key ("did you mean ...").
    virtual void check_keys(const toml::table& table, std::vector<std::string> allowed,
                            const std::string& context) const = 0;
    /// An integer or a string with an expression.
    virtual GiNaC::ex scalar(const toml::node& node, const std::string& key, const SymbolTable& symbols,
                             const ParseOptions& options) const = 0;
    /// An array of `count` scalars (any number when count is 0).
    virtual std::vector<GiNaC::ex> scalars(const toml::node& node, const std::string& key, std::size_t count,
                                           const SymbolTable& symbols, const ParseOptions& options) const = 0;
};

}  // namespace eomgen
