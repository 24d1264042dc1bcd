/** @file tape.cpp  Recording a CSE'd expression DAG as a tape, and running it (tape.hpp). */
#include "interpreter/tape.hpp"

#include "codegen/expr_dag.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <unordered_map>

namespace eomgen::interpreter {
namespace {

using codegen::ExprDag;
using codegen::kOne;
using codegen::Node;
using codegen::NodeId;
using codegen::Op;
using codegen::Term;

const std::unordered_map<std::string, TapeOp>& functions() {
    static const std::unordered_map<std::string, TapeOp> f = {
        {"sin", TapeOp::Sin},   {"cos", TapeOp::Cos},   {"tan", TapeOp::Tan},   {"exp", TapeOp::Exp},
        {"log", TapeOp::Log},   {"sqrt", TapeOp::Sqrt}, {"asin", TapeOp::Asin}, {"acos", TapeOp::Acos},
        {"atan", TapeOp::Atan}, {"sinh", TapeOp::Sinh}, {"cosh", TapeOp::Cosh}, {"tanh", TapeOp::Tanh},
        {"abs", TapeOp::Abs},   {"sign", TapeOp::Sign}, {"heaviside", TapeOp::Heaviside},
        {"max", TapeOp::Max},   {"min", TapeOp::Min},   {"atan2", TapeOp::Atan2}, {"pow", TapeOp::Pow}};
    return f;
}

bool binary(TapeOp op) { return op == TapeOp::Max || op == TapeOp::Min || op == TapeOp::Atan2 || op == TapeOp::Pow; }

/// Whether the instruction reads its operand b.
bool uses_b(TapeOp op) {
    return binary(op) || op == TapeOp::Add || op == TapeOp::Sub || op == TapeOp::Mul || op == TapeOp::Div ||
           op == TapeOp::AddScaled;
}

/// Walks the DAG from the roots, one instruction per operation, each node's register remembered.
class Recorder {
  public:
    Recorder(const ExprDag& dag, int n_inputs) : dag_(dag), reg_(dag.size(), -1) { tape_.n_inputs = n_inputs; }

    std::int32_t term(const Term& t) {
        if (t.node == kOne) return constant(t.coeff.to_double());
        const std::int32_t r = node(t.node);
        return t.coeff.is_equal(1) ? r : emit(TapeOp::Scale, r, 0, t.coeff.to_double());
    }

    /// Gives each temporary a register (a linear scan: a register is free again after its value's last read; the
    /// outputs' stay to the end) and places the temporaries after the constants.
    Tape finish() {
        const std::int32_t first = tape_.first_temporary();
        const std::size_t n = tape_.code.size();
        auto temporary = [](std::int32_t r) { return r >= kTemporary; };
        constexpr std::size_t kNever = static_cast<std::size_t>(-1);
        std::vector<std::size_t> last(n, 0);  // by temporary: the instruction that reads it last (0: none)
        std::vector<char> read(n, 0);
        auto note = [&](std::int32_t r, std::size_t at) {
            if (!temporary(r)) return;
            const std::size_t k = static_cast<std::size_t>(r - kTemporary);
            if (last[k] != kNever) last[k] = at;
            read[k] = 1;
        };
        for (std::size_t i = 0; i < n; ++i) {
            note(tape_.code[i].a, i);
            if (uses_b(tape_.code[i].op)) note(tape_.code[i].b, i);
        }
        for (std::int32_t o : tape_.outputs)
            if (temporary(o)) last[static_cast<std::size_t>(o - kTemporary)] = kNever, read[static_cast<std::size_t>(o - kTemporary)] = 1;
        std::vector<std::int32_t> where(n, -1), free;
        std::int32_t next = first;
        auto placed = [&](std::int32_t r) { return temporary(r) ? where[static_cast<std::size_t>(r - kTemporary)] : r; };
        auto release = [&](std::int32_t r, std::size_t at) {
            if (temporary(r) && last[static_cast<std::size_t>(r - kTemporary)] == at) {
                free.push_back(where[static_cast<std::size_t>(r - kTemporary)]);
                last[static_cast<std::size_t>(r - kTemporary)] = kNever - 1;  // released once, also when a == b
            }
        };
        for (std::size_t i = 0; i < n; ++i) {
            Instruction& ins = tape_.code[i];
            const std::int32_t a = ins.a, b = ins.b;
            ins.a = placed(a);
            if (uses_b(ins.op)) ins.b = placed(b);
            release(a, i);
            if (uses_b(ins.op)) release(b, i);
            std::int32_t r;
            if (free.empty()) {
                r = next++;
            } else {
                r = free.back();
                free.pop_back();
            }
            ins.dst = r;
            where[i] = r;
            if (!read[i]) free.push_back(r);  // written and never read (not an output): free again at once
        }
        for (std::int32_t& o : tape_.outputs) o = placed(o);
        tape_.n_registers = next;
        return std::move(tape_);
    }

    void output(std::int32_t r) { tape_.outputs.push_back(r); }

  private:
    /// Temporaries are numbered from here while recording (the count of constants is not known until the end).
    static constexpr std::int32_t kTemporary = 1 << 30;

    std::int32_t constant(double v) {
        auto it = constants_.find(v);
        if (it != constants_.end()) return it->second;
        const std::int32_t r = tape_.n_inputs + static_cast<std::int32_t>(tape_.constants.size());
        tape_.constants.push_back(v);
        constants_.emplace(v, r);
        return r;
    }

    std::int32_t emit(TapeOp op, std::int32_t a, std::int32_t b = 0, double c = 0) {
        tape_.code.push_back({op, 0, a, b, c});
        return kTemporary + static_cast<std::int32_t>(tape_.code.size()) - 1;
    }

    /// base^k for an integer k ≠ 0 by multiplications (as the emitted code writes x*x*x), 1/base^−k below 0.
    std::int32_t power(std::int32_t base, long k) {
        const long m = k < 0 ? -k : k;
        std::int32_t r = base;
        for (long i = 1; i < m; ++i) r = emit(TapeOp::Mul, r, base);
        return k < 0 ? emit(TapeOp::Div, constant(1), r) : r;
    }

    std::int32_t node(NodeId id) {
        std::int32_t& memo = reg_[static_cast<std::size_t>(id)];
        if (memo >= 0) return memo;
        const Node& n = dag_.node(id);
        std::int32_t r = -1;
        switch (n.op) {
            case Op::Number:
                r = constant(n.value.to_double());
                break;
            case Op::Symbol:
                r = n.symbol;
                break;
            case Op::Func: {
                auto f = functions().find(n.name);
                if (f == functions().end() || n.args.size() != (binary(f->second) ? 2u : 1u))
                    throw std::runtime_error("function " + n.name + " cannot be interpreted");
                const std::int32_t a = node(n.args[0]);
                r = emit(f->second, a, n.args.size() > 1 ? node(n.args[1]) : 0);
                break;
            }
            case Op::Pow:
                r = power(node(n.args[0]), n.value.to_long());
                break;
            case Op::Mul: {
                std::int32_t num = -1, den = -1;
                for (std::size_t i = 0; i < n.args.size(); ++i) {
                    const long k = n.coeffs[i].to_long();
                    const std::int32_t f = power(node(n.args[i]), k < 0 ? -k : k);
                    std::int32_t& into = k < 0 ? den : num;
                    into = into < 0 ? f : emit(TapeOp::Mul, into, f);
                }
                if (num < 0) num = constant(1);
                r = den < 0 ? num : emit(TapeOp::Div, num, den);
                break;
            }
            case Op::Add: {
                for (std::size_t i = 0; i < n.args.size(); ++i) {
                    const double c = n.coeffs[i].to_double();
                    const std::int32_t a = node(n.args[i]);
                    if (r < 0)
                        r = c == 1 ? a : c == -1 ? emit(TapeOp::Neg, a) : emit(TapeOp::Scale, a, 0, c);
                    else
                        r = c == 1 ? emit(TapeOp::Add, r, a) : c == -1 ? emit(TapeOp::Sub, r, a)
                                                                : emit(TapeOp::AddScaled, r, a, c);
                }
                if (!n.value.is_zero()) r = r < 0 ? constant(n.value.to_double()) : emit(TapeOp::AddConst, r, 0, n.value.to_double());
                if (r < 0) r = constant(0);
                break;
            }
        }
        memo = r;
        return r;
    }

    const ExprDag& dag_;
    std::vector<std::int32_t> reg_;
    std::map<double, std::int32_t> constants_;
    Tape tape_;
};

}  // namespace

Tape record_tape(const codegen::SymbolTable& table, const std::vector<GiNaC::ex>& values) {
    ExprDag dag(table.info, table.exprs, true);
    const std::vector<Term> roots = codegen::code_roots(dag, values);
    Recorder recorder(dag, static_cast<int>(table.info.size()));
    std::vector<std::int32_t> regs;
    for (const Term& t : roots) regs.push_back(recorder.term(t));
    for (std::int32_t r : regs) recorder.output(r);
    return recorder.finish();
}

void Tape::run(double* r, double* out) const {
    double* c = r + n_inputs;
    for (std::size_t k = 0; k < constants.size(); ++k) c[k] = constants[k];
#if defined(__GNUC__)
    // Threaded dispatch (GCC's labels as values): each operation jumps to the next one's code itself, so that the
    // processor predicts each jump from the operation it follows; one shared switch mispredicted on most of a long
    // tape (the Whipple bicycle's ran at about 10 ns an instruction).
    static void* const kLabels[] = {
        &&op_add, &&op_sub, &&op_mul, &&op_div, &&op_neg, &&op_add_scaled, &&op_scale, &&op_add_const,
        &&op_sin, &&op_cos, &&op_tan, &&op_exp, &&op_log, &&op_sqrt, &&op_asin, &&op_acos, &&op_atan, &&op_sinh,
        &&op_cosh, &&op_tanh, &&op_abs, &&op_sign, &&op_heaviside, &&op_max, &&op_min, &&op_atan2, &&op_pow};
    static_assert(sizeof kLabels / sizeof kLabels[0] == static_cast<std::size_t>(TapeOp::Pow) + 1,
                  "one label per TapeOp, in its order");
    const Instruction* i = code.data();
    const Instruction* const end = i + code.size();
#define EOMGEN_NEXT(value)                                         \
    do {                                                           \
        r[i->dst] = (value);                                       \
        if (++i == end) goto done;                                 \
        goto* kLabels[static_cast<std::size_t>(i->op)];            \
    } while (0)
    if (i == end) goto done;
    goto* kLabels[static_cast<std::size_t>(i->op)];
op_add: EOMGEN_NEXT(r[i->a] + r[i->b]);
op_sub: EOMGEN_NEXT(r[i->a] - r[i->b]);
op_mul: EOMGEN_NEXT(r[i->a] * r[i->b]);
op_div: EOMGEN_NEXT(r[i->a] / r[i->b]);
op_neg: EOMGEN_NEXT(-r[i->a]);
op_add_scaled: EOMGEN_NEXT(r[i->a] + i->c * r[i->b]);
op_scale: EOMGEN_NEXT(i->c * r[i->a]);
op_add_const: EOMGEN_NEXT(r[i->a] + i->c);
op_sin: EOMGEN_NEXT(std::sin(r[i->a]));
op_cos: EOMGEN_NEXT(std::cos(r[i->a]));
op_tan: EOMGEN_NEXT(std::tan(r[i->a]));
op_exp: EOMGEN_NEXT(std::exp(r[i->a]));
op_log: EOMGEN_NEXT(std::log(r[i->a]));
op_sqrt: EOMGEN_NEXT(std::sqrt(r[i->a]));
op_asin: EOMGEN_NEXT(std::asin(r[i->a]));
op_acos: EOMGEN_NEXT(std::acos(r[i->a]));
op_atan: EOMGEN_NEXT(std::atan(r[i->a]));
op_sinh: EOMGEN_NEXT(std::sinh(r[i->a]));
op_cosh: EOMGEN_NEXT(std::cosh(r[i->a]));
op_tanh: EOMGEN_NEXT(std::tanh(r[i->a]));
op_abs: EOMGEN_NEXT(std::abs(r[i->a]));
op_sign: EOMGEN_NEXT(r[i->a] > 0 ? 1.0 : r[i->a] < 0 ? -1.0 : 0.0);
op_heaviside: EOMGEN_NEXT(r[i->a] > 0 ? 1.0 : r[i->a] < 0 ? 0.0 : 0.5);
op_max: EOMGEN_NEXT(r[i->a] < r[i->b] ? r[i->b] : r[i->a]);
op_min: EOMGEN_NEXT(r[i->b] < r[i->a] ? r[i->b] : r[i->a]);
op_atan2: EOMGEN_NEXT(std::atan2(r[i->a], r[i->b]));
op_pow: EOMGEN_NEXT(std::pow(r[i->a], r[i->b]));
#undef EOMGEN_NEXT
done:
#else
    for (const Instruction& i : code) {
        const double a = r[i.a];
        double v;
        switch (i.op) {
            case TapeOp::Add: v = a + r[i.b]; break;
            case TapeOp::Sub: v = a - r[i.b]; break;
            case TapeOp::Mul: v = a * r[i.b]; break;
            case TapeOp::Div: v = a / r[i.b]; break;
            case TapeOp::Neg: v = -a; break;
            case TapeOp::AddScaled: v = a + i.c * r[i.b]; break;
            case TapeOp::Scale: v = i.c * a; break;
            case TapeOp::AddConst: v = a + i.c; break;
            case TapeOp::Sin: v = std::sin(a); break;
            case TapeOp::Cos: v = std::cos(a); break;
            case TapeOp::Tan: v = std::tan(a); break;
            case TapeOp::Exp: v = std::exp(a); break;
            case TapeOp::Log: v = std::log(a); break;
            case TapeOp::Sqrt: v = std::sqrt(a); break;
            case TapeOp::Asin: v = std::asin(a); break;
            case TapeOp::Acos: v = std::acos(a); break;
            case TapeOp::Atan: v = std::atan(a); break;
            case TapeOp::Sinh: v = std::sinh(a); break;
            case TapeOp::Cosh: v = std::cosh(a); break;
            case TapeOp::Tanh: v = std::tanh(a); break;
            case TapeOp::Abs: v = std::abs(a); break;
            case TapeOp::Sign: v = a > 0 ? 1.0 : a < 0 ? -1.0 : 0.0; break;
            case TapeOp::Heaviside: v = a > 0 ? 1.0 : a < 0 ? 0.0 : 0.5; break;
            case TapeOp::Max: v = a < r[i.b] ? r[i.b] : a; break;
            case TapeOp::Min: v = r[i.b] < a ? r[i.b] : a; break;
            case TapeOp::Atan2: v = std::atan2(a, r[i.b]); break;
            case TapeOp::Pow: v = std::pow(a, r[i.b]); break;
            default: v = 0; break;
        }
        r[i.dst] = v;
    }
#endif
    for (std::size_t k = 0; k < outputs.size(); ++k) out[k] = r[outputs[k]];
}

void Tape::run_tangent(double* r, double* dr, int k, double* out, double* dout) const {
    const std::size_t K = static_cast<std::size_t>(k);
    for (std::size_t j = 0; j < constants.size(); ++j) {
        r[static_cast<std::size_t>(n_inputs) + j] = constants[j];
        std::fill_n(dr + (static_cast<std::size_t>(n_inputs) + j) * K, K, 0.0);
    }
    for (const Instruction& i : code) {
        const double a = r[i.a], b = uses_b(i.op) ? r[i.b] : 0.0;
        const double* da = dr + static_cast<std::size_t>(i.a) * K;
        const double* db = dr + static_cast<std::size_t>(i.b) * K;
        double* dv = dr + static_cast<std::size_t>(i.dst) * K;
        // v = value; dv = ca·da + cb·db (cb ignored for one-operand operations)
        double v = 0, ca = 0, cb = 0;
        switch (i.op) {
            case TapeOp::Add: v = a + b, ca = 1, cb = 1; break;
            case TapeOp::Sub: v = a - b, ca = 1, cb = -1; break;
            case TapeOp::Mul: v = a * b, ca = b, cb = a; break;
            case TapeOp::Div: v = a / b, ca = 1 / b, cb = -v / b; break;
            case TapeOp::Neg: v = -a, ca = -1; break;
            case TapeOp::AddScaled: v = a + i.c * b, ca = 1, cb = i.c; break;
            case TapeOp::Scale: v = i.c * a, ca = i.c; break;
            case TapeOp::AddConst: v = a + i.c, ca = 1; break;
            case TapeOp::Sin: v = std::sin(a), ca = std::cos(a); break;
            case TapeOp::Cos: v = std::cos(a), ca = -std::sin(a); break;
            case TapeOp::Tan: v = std::tan(a), ca = 1 + v * v; break;
            case TapeOp::Exp: v = std::exp(a), ca = v; break;
            case TapeOp::Log: v = std::log(a), ca = 1 / a; break;
            case TapeOp::Sqrt: v = std::sqrt(a), ca = 0.5 / v; break;
            case TapeOp::Asin: v = std::asin(a), ca = 1 / std::sqrt(1 - a * a); break;
            case TapeOp::Acos: v = std::acos(a), ca = -1 / std::sqrt(1 - a * a); break;
            case TapeOp::Atan: v = std::atan(a), ca = 1 / (1 + a * a); break;
            case TapeOp::Sinh: v = std::sinh(a), ca = std::cosh(a); break;
            case TapeOp::Cosh: v = std::cosh(a), ca = std::sinh(a); break;
            case TapeOp::Tanh: v = std::tanh(a), ca = 1 - v * v; break;
            case TapeOp::Abs: v = std::abs(a), ca = a > 0 ? 1.0 : a < 0 ? -1.0 : 0.0; break;
            case TapeOp::Sign: v = a > 0 ? 1.0 : a < 0 ? -1.0 : 0.0; break;
            case TapeOp::Heaviside: v = a > 0 ? 1.0 : a < 0 ? 0.0 : 0.5; break;
            case TapeOp::Max:
                if (a < b)
                    v = b, cb = 1;
                else
                    v = a, ca = 1;
                break;
            case TapeOp::Min:
                if (b < a)
                    v = b, cb = 1;
                else
                    v = a, ca = 1;
                break;
            case TapeOp::Atan2: {
                const double q = a * a + b * b;
                v = std::atan2(a, b), ca = b / q, cb = -a / q;
                break;
            }
            case TapeOp::Pow:
                v = std::pow(a, b);
                ca = b * std::pow(a, b - 1);
                cb = a > 0 ? v * std::log(a) : 0.0;  // a ≤ 0: b is an exponent the value allows only as a constant
                break;
        }
        r[i.dst] = v;
        if (uses_b(i.op)) {
            for (std::size_t d = 0; d < K; ++d) dv[d] = ca * da[d] + cb * db[d];
        } else {
            for (std::size_t d = 0; d < K; ++d) dv[d] = ca * da[d];
        }
    }
    for (std::size_t o = 0; o < outputs.size(); ++o) {
        out[o] = r[outputs[o]];
        std::copy_n(dr + static_cast<std::size_t>(outputs[o]) * K, K, dout + o * K);
    }
}

}  // namespace eomgen::interpreter
