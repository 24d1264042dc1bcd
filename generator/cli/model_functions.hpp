/**
 * @file model_functions.hpp  A model file's functions for the simulation driver, as `eomgen run` and `eomgen fit`
 * get them: compiled into a cached shared object (compiled_model.hpp), or with `interpret` run on the interpreter's
 * tapes (interpreter/interpreted_table.hpp), nothing compiled. Either way a ModelTable that TableModel binds.
 */
#pragma once

#include "cli/compiled_model.hpp"
#include "interpreter/interpreted_table.hpp"
#include "model/model.hpp"

#include <functional>
#include <memory>
#include <string>

namespace eomgen::cli {

struct FunctionsRequest {
    const Model* model = nullptr;
    std::string text;  ///< the model file's bytes (the cache key)
    std::string path;  ///< the model file's path, for messages and the header's comment
    bool jacobian = false;   ///< the integration needs ∂ẋ/∂x or ∂ẋ/∂p (radau5, sensitivities, fit)
    bool interpret = false;  ///< the interpreter's tapes instead of the compiler
    bool use_cache = true;
    std::function<void(const std::string&)> progress;  ///< may be empty
};

/// The table of one model, holding what it points into.
struct ModelFunctions {
    CompiledModel compiled;                                     ///< when compiled
    std::unique_ptr<interpreter::InterpretedTable> interpreted;  ///< when interpreted
    const ModelTable& table() const { return interpreted ? interpreted->table() : *compiled.table; }
};

/// Derives the model where needed and compiles it (or loads it from the cache), or records its tapes. The model's
/// warnings go to stderr. Throws ModelError, CompileError, CacheError as compile_model does.
ModelFunctions model_functions(const FunctionsRequest& request);

/// The header `eomgen run`, `fit` and `report` compile: the model's, with its analytic Jacobians where the
/// integration needs J (`jacobian`: --method radau5) and the model has no constraints (which have none).
std::string header_to_compile(const Model& model, const Equations& eq, const std::string& file_name, bool jacobian);

}  // namespace eomgen::cli
