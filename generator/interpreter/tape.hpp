/**
 * @file tape.hpp  Straight-line code as data: the values a generated function computes, recorded from the same
 * CSE'd expression DAG the C++ emitter prints (codegen/expr_dag.hpp), and run by a loop over instructions.
 *
 * Why: compiling a model's shared object takes the C++ compiler seconds (1.8 s for a double pendulum, more for
 * constrained models), most of a first `eomgen run` or a first `simulate` from Python. A tape is recorded in
 * milliseconds and evaluates the same operations in the same order as the emitted code, without a compiler; each
 * instruction costs a dispatch more than compiled code (docs/interpreter.md measures how much).
 *
 * Registers: [0, n_inputs) are the inputs, in the order of the symbol table (codegen::symbol_table: each parameter,
 * then q, q̇, q̈ of each coordinate, then t and π); then the constants; then the temporaries. A temporary's register
 * is reused once its value has been read for the last time (a linear scan over the recorded code), so that the
 * registers a run touches stay few and in the cache: the Whipple bicycle's tape of about 15,000 instructions needs
 * a few hundred.
 */
#pragma once

#include "codegen/cpp_emitter.hpp"

#include <cstdint>
#include <vector>

namespace eomgen::interpreter {

enum class TapeOp : std::uint8_t {
    Add,        ///< r = a + b
    Sub,        ///< r = a − b
    Mul,        ///< r = a · b
    Div,        ///< r = a / b
    Neg,        ///< r = −a
    AddScaled,  ///< r = a + c · b
    Scale,      ///< r = c · a
    AddConst,   ///< r = a + c
    Sin, Cos, Tan, Exp, Log, Sqrt, Asin, Acos, Atan, Sinh, Cosh, Tanh, Abs,
    Sign,       ///< 1, −1, or 0 at 0 (eomgen/nonsmooth.hpp)
    Heaviside,  ///< 1, 0, or 1/2 at 0
    Max, Min, Atan2, Pow,
};

struct Instruction {
    TapeOp op;
    std::int32_t dst = 0;       ///< the register written
    std::int32_t a = 0, b = 0;  ///< operand registers (b unused by one-operand operations)
    double c = 0;               ///< the constant of AddScaled, Scale, AddConst
};

struct Tape {
    int n_inputs = 0;
    std::vector<double> constants;
    std::vector<Instruction> code;
    std::vector<std::int32_t> outputs;  ///< the register holding each value, in the order recorded
    int n_registers = 0;                ///< inputs, constants and temporaries

    int first_temporary() const { return n_inputs + static_cast<int>(constants.size()); }
    int registers() const { return n_registers; }

    /// Runs the tape: `registers` holds registers() doubles, the inputs in its first n_inputs (the rest is
    /// overwritten); the values go to out[0 .. outputs.size()).
    void run(double* registers, double* out) const;

    /// Runs the tape with k derivatives of each value (forward differentiation): `tangents` holds registers() × k
    /// doubles, register j's at [j k, (j + 1) k), the inputs' set by the caller (the rest overwritten); the values go to
    /// out as run() writes them, their derivatives to dout[i k + d]. Where a function has no derivative (sign,
    /// heaviside; abs, max, min on their switching surface) it takes the side the value's branch takes.
    void run_tangent(double* registers, double* tangents, int k, double* out, double* dout) const;
};

/// Records `values` (expressions in the symbols of `table`) as one tape, their common subexpressions computed once:
/// the expansion, Horner scheme and sharing of codegen::emit_body, so that the tape does the emitted code's
/// arithmetic. Throws std::runtime_error for what generated code cannot express either.
Tape record_tape(const codegen::SymbolTable& table, const std::vector<GiNaC::ex>& values);

}  // namespace eomgen::interpreter
