/** @file tape.cpp  Recording a CSE'd expression DAG as a tape, and running it (tape.hpp). */
#include "interpreter/tape.hpp"

#include "codegen/expr_dag.hpp"

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

/// Walks the DAG from the roots, one instruction per operation, each node's register remembered.
class Recorder {
  public:
    Recorder(const ExprDag& dag, int n_inputs) : dag_(dag), reg_(dag.size(), -1) { tape_.n_inputs = n_inputs; }

    std::int32_t term(const Term& t) {
        if (t.node == kOne) return constant(t.coeff.to_double());
        const std::int32_t r = node(t.node);
        return t.coeff.is_equal(1) ? r : emit(TapeOp::Scale, r, 0, t.coeff.to_double());
    }

    Tape finish() {
        // Constants sit before the temporaries: the temporaries' registers were counted from 0 while recording.
        const std::int32_t shift = tape_.first_temporary();
        auto moved = [&](std::int32_t r) { return r >= kTemporary ? r - kTemporary + shift : r; };
        for (Instruction& i : tape_.code) {
            i.a = moved(i.a);
            i.b = moved(i.b);
        }
        for (std::int32_t& o : tape_.outputs) o = moved(o);
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
        tape_.code.push_back({op, a, b, c});
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
    double* w = r + first_temporary();
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
        *w++ = v;
    }
    for (std::size_t k = 0; k < outputs.size(); ++k) out[k] = r[outputs[k]];
}

}  // namespace eomgen::interpreter
