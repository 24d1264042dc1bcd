// Fuzz property of the simulators' command-line values (runtime/eomgen/simulation.hpp, shared by eomgen-sim
// and `eomgen run`): a value or a NAME=VALUE either reads or is refused with a UsageError; nothing else is
// thrown.
#include "eomgen/simulation.hpp"
#include "harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using eomgen::fuzz::fail;
    const std::string text = eomgen::fuzz::input_text(data, size);
    try {
        (void)eomgen::sim::parse_value(text);
    } catch (const eomgen::sim::UsageError&) {
    } catch (const std::exception& e) {
        fail("fuzz_sim_values", "parse_value threw something other than UsageError", text, e.what());
    }
    try {
        (void)eomgen::sim::parse_assignment(text, "--set");
    } catch (const eomgen::sim::UsageError&) {
    } catch (const std::exception& e) {
        fail("fuzz_sim_values", "parse_assignment threw something other than UsageError", text, e.what());
    }
    return 0;
}
