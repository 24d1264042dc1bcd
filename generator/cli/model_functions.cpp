/** @file model_functions.cpp  A model's table, compiled or interpreted (model_functions.hpp). */
#include "cli/model_functions.hpp"

#include "codegen/cpp_emitter.hpp"
#include "mechanics/lagrangian.hpp"

#include <filesystem>
#include <iostream>

namespace eomgen::cli {

std::string header_to_compile(const Model& model, const Equations& eq, const std::string& file_name, bool jacobian) {
    Model with = model;
    with.generate.jacobians = with.generate.jacobians || (jacobian && with.constraints.empty());
    return codegen::emit_model_header(with, eq, file_name);
}

ModelFunctions model_functions(const FunctionsRequest& r) {
    const Model& model = *r.model;
    auto progress = [&r](const std::string& what) {
        if (r.progress) r.progress(what);
    };
    auto derive = [&] {
        progress("deriving " + r.path);
        Equations eq = derive_equations(model);
        for (const std::string& w : eq.warnings) std::cerr << r.path << ": warning: " << w << "\n";
        return eq;
    };
    ModelFunctions f;
    if (r.interpret) {
        const Equations eq = derive();
        f.interpreted = std::make_unique<interpreter::InterpretedTable>(interpreter::interpret(model, eq));
        const interpreter::Tape& rhs = eq.constraints.empty() ? f.interpreted->model().dynamics
                                                              : f.interpreted->model().constrained;
        progress("interpreting (no compiler): the right-hand side's tape has " + std::to_string(rhs.code.size()) +
                 " instructions over " + std::to_string(rhs.registers()) + " registers");
        return f;
    }
    auto header = [&] {
        return header_to_compile(model, derive(), std::filesystem::path(r.path).filename().string(), r.jacobian);
    };
    CompileRequest request{r.text, model.name, header, r.use_cache, r.progress};
    request.jacobian = r.jacobian;
    f.compiled = compile_model(request);
    progress(f.compiled.from_cache ? "loaded from the cache: " + f.compiled.path
                                   : "compiled in " + std::to_string(f.compiled.compile_seconds).substr(0, 4) + " s");
    return f;
}

}  // namespace eomgen::cli
