// Fuzz property of the model files' expression language (model/expression_parser.hpp): any bytes either
// parse to an expression in the table's names or are refused with an ExpressionError whose offset lies in
// the text; nothing else is thrown, and evaluate_constant's value, when it returns, is finite.
#include "harness.hpp"
#include "model/expression_parser.hpp"

#include <cmath>

namespace {

const eomgen::SymbolTable& table() {
    static const eomgen::SymbolTable t = [] {
        static const GiNaC::symbol x("x"), x_dot("x_dot"), y("y"), y_dot("y_dot"), m("m"), g("g"), t("t");
        eomgen::SymbolTable s;
        s.symbols = {{"x", x}, {"y", y}, {"m", m}, {"g", g}, {"t", t}};
        s.velocities = {{"x", x_dot}, {"y", y_dot}};
        return s;
    }();
    return t;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using eomgen::fuzz::fail;
    const std::string text = eomgen::fuzz::input_text(data, size);
    for (const bool no_velocities : {false, true}) {
        eomgen::ParseOptions options;
        if (no_velocities) options.forbid_velocities = "V must not depend on velocities";
        try {
            (void)eomgen::parse_expression(text, table(), options);
        } catch (const eomgen::ExpressionError& e) {
            if (e.offset() > text.size()) fail("fuzz_expression", "an error offset past the text", text, e.what());
        } catch (const std::exception& e) {
            fail("fuzz_expression", "an exception other than ExpressionError", text, e.what());
        }
    }
    try {
        const double v = eomgen::evaluate_constant(text);
        if (!std::isfinite(v)) fail("fuzz_expression", "a constant that is not finite", text, std::to_string(v));
    } catch (const eomgen::ExpressionError& e) {
        if (e.offset() > text.size()) fail("fuzz_expression", "an error offset past the text", text, e.what());
    } catch (const std::exception& e) {
        fail("fuzz_expression", "evaluate_constant threw something else", text, e.what());
    }
    return 0;
}
