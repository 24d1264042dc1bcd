// Fuzz property of the model-file loader (every section: coordinates, parameters, constraints, forces,
// bodies, springs, results): a file is either refused with a ModelError located at fuzzed.toml:line:col,
// or loaded; a loaded model is derived and its header emitted as `eomgen generate` does, and the only
// error allowed there is a ModelError (a singular mass matrix, say) with its place.
#include "codegen/cpp_emitter.hpp"
#include "harness.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using eomgen::fuzz::fail;
    const std::string text = eomgen::fuzz::input_text(data, size);
    try {
        const eomgen::Model model = eomgen::parse_model(text, "fuzzed.toml");
        const std::string header =
            eomgen::codegen::emit_model_header(model, eomgen::derive_equations(model), "fuzzed.toml");
        if (header.find('\0') != std::string::npos) fail("fuzz_model_file", "a NUL byte in the header", text, header);
    } catch (const eomgen::ModelError& e) {
        if (!eomgen::fuzz::located(e.what(), "fuzzed.toml"))
            fail("fuzz_model_file", "an error without fuzzed.toml:line:col", text, e.what());
    } catch (const std::exception& e) {
        fail("fuzz_model_file", "an exception other than ModelError", text, e.what());
    }
    return 0;
}
