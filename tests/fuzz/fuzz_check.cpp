// Fuzz property of `eomgen check` end to end against a fixed model (the 5-20 pendulum, two coordinates):
// any derivation text gets a report without an exception, with every verdict placed inside the text, and
// its JSON rendering is valid UTF-8 (the escaping's job).
#include "checker/checker.hpp"
#include "checker/report.hpp"
#include "harness.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model_file.hpp"
#include "text/escape.hpp"

#ifndef EOMGEN_FUZZ_CHECK_MODEL
#error "EOMGEN_FUZZ_CHECK_MODEL: the model file the derivations are checked against"
#endif

namespace {

struct Fixed {
    eomgen::Model model = eomgen::load_model(EOMGEN_FUZZ_CHECK_MODEL);
    eomgen::Equations eq = eomgen::derive_equations(model);
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using eomgen::fuzz::fail;
    static const Fixed fixed;
    const std::string text = eomgen::fuzz::input_text(data, size);
    const eomgen::checker::Derivation d = eomgen::checker::parse_derivation(text, "fuzzed.md");
    eomgen::checker::CheckReport report;
    try {
        report = eomgen::checker::check_derivation(fixed.model, fixed.eq, d, {});
    } catch (const std::exception& e) {
        fail("fuzz_check", "check_derivation threw", text, e.what());
    }
    const int lines = int(d.line_starts.size());
    for (const auto& e : report.equations)
        if (e.where.line < 1 || e.where.line > lines || e.where.column < 1)
            fail("fuzz_check", "a verdict placed outside the text", text, e.equation);
    const std::string json = eomgen::checker::format_json(report);
    if (eomgen::text::valid_utf8(json) != json) fail("fuzz_check", "JSON that is not valid UTF-8", text, json);
    return 0;
}
