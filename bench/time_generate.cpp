/** @file time_generate.cpp  Times eomgen's generation phases for the n-link families; counts the ops it
 * emits. */
// Usage: time_generate FAMILY N... (FAMILY pendulum or rods). One JSON object per line and n:
//   {"family", "n", "parse_s", "derive_s", "emit_s" (the whole header), "total_s", "derive_cpu_s",
//    "emit_cpu_s", "dynamics_emit_s",
//    "comment_s", "comment_chars", "header_bytes", "dynamics_ops": {"add", "mul", "div", "call", "total"}}
// comment_s: expanding and printing the Euler-Lagrange equations as the header's opening comment does (it
// stops once they pass 4000 characters; comment_chars is what it printed). derive_cpu_s, emit_cpu_s: the
// process's CPU time in derive and in the whole header's emit (wall times carry the machine's load).
// dynamics_emit_s and dynamics_ops: CSE and emission of M and f alone (the `dynamics` function, what SymPy's
// side produces), and the BodyEmitter's OpCount for it, which bench/op_count.py re-counts from the header.
#include "codegen/cpp_emitter.hpp"
#include "codegen/math_printer.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/families.hpp"
#include "model/model_file.hpp"

#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: time_generate pendulum|rods N...\n");
        return 2;
    }
    const std::string family = argv[1];
    for (int a = 2; a < argc; ++a) {
        const eomgen::FamilySpec spec = eomgen::parse_family_spec(family + ":n=" + argv[a]);
        const auto t0 = std::chrono::steady_clock::now();
        const eomgen::Model model = eomgen::parse_model(eomgen::family_model_text(spec), family);
        const double parse_s = seconds_since(t0);
        const auto t1 = std::chrono::steady_clock::now();
        const double c1 = cpu_seconds();
        const eomgen::Equations eq = eomgen::derive_equations(model);
        const double derive_s = seconds_since(t1), derive_cpu_s = cpu_seconds() - c1;
        const auto t2 = std::chrono::steady_clock::now();
        const double c2 = cpu_seconds();
        const std::string header = eomgen::codegen::emit_model_header(model, eq, family);
        const double emit_s = seconds_since(t2), emit_cpu_s = cpu_seconds() - c2;
        const double total_s = seconds_since(t0);

        // The dynamics body (M and f) alone, as SymPy's side makes only those: its time and OpCount.
        const auto t3 = std::chrono::steady_clock::now();
        const eomgen::codegen::SymbolTable table = eomgen::codegen::symbol_table(model);
        eomgen::codegen::ExprDag dag(table.info, table.exprs, true);
        std::vector<eomgen::codegen::Output> outputs;
        const unsigned n = static_cast<unsigned>(model.dof());
        for (unsigned i = 0; i < n; ++i)
            for (unsigned j = 0; j < n; ++j) outputs.push_back({"M", eq.M(i, j)});
        for (unsigned i = 0; i < n; ++i) outputs.push_back({"f", eq.f[i]});
        const eomgen::codegen::OpCount ops = eomgen::codegen::emit_body(dag, outputs).ops;
        const double dynamics_emit_s = seconds_since(t3);

        // What the header's opening comment costs: the Euler-Lagrange equations expanded and printed (the
        // header keeps them only when they are short).
        const auto t4 = std::chrono::steady_clock::now();
        eomgen::codegen::MathPrinter printer(table);
        std::size_t comment_chars = 0;
        for (const GiNaC::ex& e : eq.euler_lagrange) {
            if (comment_chars > 4000) break;
            comment_chars += printer.print(e.expand(), eomgen::codegen::MathStyle::Text).size();
        }
        const double comment_s = seconds_since(t4);
        std::printf(
            "{\"family\": \"%s\", \"n\": %d, \"parse_s\": %.6f, \"derive_s\": %.6f, \"emit_s\": %.6f, "
            "\"total_s\": %.6f, \"derive_cpu_s\": %.6f, \"emit_cpu_s\": %.6f, \"dynamics_emit_s\": %.6f, "
            "\"comment_s\": %.6f, \"comment_chars\": %zu, "
            "\"header_bytes\": %zu, \"dynamics_ops\": "
            "{\"add\": %ld, \"mul\": %ld, \"div\": %ld, \"call\": %ld, \"total\": %ld}}\n",
            family.c_str(), spec.n, parse_s, derive_s, emit_s, total_s, derive_cpu_s, emit_cpu_s, dynamics_emit_s, comment_s,
            comment_chars, header.size(), ops.additions, ops.multiplications, ops.divisions,
            ops.function_calls, ops.total());
        std::fflush(stdout);
    }
    return 0;
}
