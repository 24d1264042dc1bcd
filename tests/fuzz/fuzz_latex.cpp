// Fuzz property of the derivation reader (checker/derivation.hpp) and the LaTeX reader
// (checker/latex_parser.hpp): any text splits into sections and math rows without throwing, every row and
// every reported problem lies inside the text, each row's text is the file's bytes at its offset (blanked
// marks aside), and each row parses to chains whose failures are located inside the row.
#include "checker/derivation.hpp"
#include "checker/latex_parser.hpp"
#include "harness.hpp"

namespace {

eomgen::checker::LatexContext context() {
    static const GiNaC::symbol th("theta", "\\theta"), thd("theta_dot", "\\dot{\\theta}"),
        thdd("theta_ddot", "\\ddot{\\theta}"), m("m"), l("l"), g("g"), t("t");
    eomgen::checker::LatexContext c;
    c.names = {{"\\theta", th}, {"\\dot{\\theta}", thd}, {"\\ddot{\\theta}", thdd}, {"m", m},
               {"l", l},        {"g", g},                {"t", t}};
    c.time = t;
    return c;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using eomgen::fuzz::fail;
    const std::string text = eomgen::fuzz::input_text(data, size);
    eomgen::checker::Derivation d;
    try {
        d = eomgen::checker::parse_derivation(text, "fuzzed.md");
    } catch (const std::exception& e) {
        fail("fuzz_latex", "parse_derivation threw", text, e.what());
    }
    for (const auto& p : d.problems)
        if (p.offset >= text.size()) fail("fuzz_latex", "a problem placed past the text", text, p.message);
    eomgen::checker::LatexContext ctx = context();
    for (const auto& row : d.rows) {
        if (row.offset + row.text.size() > text.size()) fail("fuzz_latex", "a row past the text", text, row.text);
        for (std::size_t i = 0; i < row.text.size(); ++i)
            if (row.text[i] != text[row.offset + i] && row.text[i] != ' ')
                fail("fuzz_latex", "a row whose bytes are not the file's", text, row.text);
        std::vector<eomgen::checker::Chain> chains;
        try {
            chains = eomgen::checker::parse_math(row.text, ctx);
        } catch (const std::exception& e) {
            fail("fuzz_latex", "parse_math threw", row.text, e.what());
        }
        for (const auto& c : chains)
            for (const auto& s : c.sides)
                if (s.begin > s.end || s.end > row.text.size() || (!s.ok && s.error_offset > row.text.size()))
                    fail("fuzz_latex", "a side placed outside its row", row.text, s.source + ": " + s.error);
    }
    return 0;
}
