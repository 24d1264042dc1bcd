/** @file cpp_emitter.cpp  Common-subexpression elimination over the DAG and the header around it. */
#include "codegen/cpp_emitter.hpp"

#include "codegen/jacobian_emitter.hpp"
#include "codegen/tree_emitter.hpp"
#include "codegen/mass_solve_emitter.hpp"
#include "codegen/switching_emitter.hpp"
#include "codegen/units_emitter.hpp"
#include "codegen/math_printer.hpp"
#include "mechanics/rest_linearization.hpp"
#include "text/escape.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <functional>
#include <set>
#include <sstream>

#ifndef EOMGEN_VERSION
#define EOMGEN_VERSION "0.1.0"
#endif

namespace eomgen::codegen {
namespace {

constexpr int kSum = 1, kProduct = 2, kAtom = 4;

std::string scalar_literal(const GiNaC::numeric& integer) {
    // Exact integers within long long print as Scalar(k); larger ones as long double literals.
    if (integer.is_integer() && GiNaC::abs(integer) < GiNaC::numeric(1L << 62))
        return "Scalar(" + numeric_string(integer) + ")";
    return "Scalar(" + fmt::format("{}", integer.to_double()) + "L)";
}

std::string number_literal(const GiNaC::numeric& v) {
    if (v.is_integer()) return scalar_literal(v);
    return scalar_literal(v.numer()) + "/" + scalar_literal(v.denom());
}

class BodyEmitter {
public:
    explicit BodyEmitter(ExprDag& dag) : dag_(dag), uses_(dag.size(), 0), name_(dag.size()) {}

    FunctionBody run(const std::vector<Output>& outputs) {
        std::vector<GiNaC::ex> values;
        for (const Output& o : outputs) values.push_back(o.value);
        std::vector<Term> roots = code_roots(dag_, values);
        uses_.assign(dag_.size(), 0);
        name_.assign(dag_.size(), std::string());
        std::vector<char> seen(dag_.size(), 0);
        std::function<void(NodeId)> count = [&](NodeId id) {
            if (seen[static_cast<std::size_t>(id)]) return;
            seen[static_cast<std::size_t>(id)] = 1;
            const Node& n = dag_.node(id);
            if (n.op == Op::Symbol) used_.insert(n.symbol);
            // x*x reads x twice: a composite base of a power is worth a temporary.
            const int reads = n.op == Op::Pow ? static_cast<int>(n.value.to_int()) : 1;
            for (NodeId a : n.args) {
                uses_[static_cast<std::size_t>(a)] += reads;
                count(a);
            }
        };
        for (const Term& r : roots)
            if (r.node != kOne) {
                uses_[static_cast<std::size_t>(r.node)] += 1;
                count(r.node);
            }
        for (const Term& r : roots)
            if (r.node != kOne) declare(r.node);
        for (std::size_t i = 0; i < outputs.size(); ++i) {
            const std::string value = term(roots[i], kSum);
            if (outputs[i].target == "return")
                body_.lines.push_back("return " + value + ";");
            else
                body_.lines.push_back(outputs[i].target + " = " + value + ";");
        }
        body_.used_symbols.assign(used_.begin(), used_.end());
        body_.functions.assign(functions_.begin(), functions_.end());
        return body_;
    }

private:
    bool wants_temporary(NodeId id) const {
        const Node& n = dag_.node(id);
        if (n.op == Op::Number || n.op == Op::Symbol) return false;
        if (uses_[static_cast<std::size_t>(id)] >= 2) return true;
        // sin/cos of a coordinate get a name of their own even when read once: code that reads like the math.
        return n.op == Op::Func && n.args.size() == 1 && dag_.node(n.args[0]).op == Op::Symbol;
    }

    /// Emits temporaries for id's subtree, children first, in a deterministic order.
    void declare(NodeId id) {
        const std::size_t k = static_cast<std::size_t>(id);
        if (!name_[k].empty() || declared_.count(id)) return;
        declared_.insert(id);
        for (NodeId a : dag_.node(id).args) declare(a);
        if (!wants_temporary(id)) return;
        const Node& n = dag_.node(id);
        std::string name;
        if (n.op == Op::Func && n.args.size() == 1 && dag_.node(n.args[0]).op == Op::Symbol &&
            (n.name == "sin" || n.name == "cos"))
            name = n.name + "_" + dag_.symbol(dag_.node(n.args[0]).symbol).name;
        else
            name = "t" + std::to_string(next_temp_++);
        const std::string value = render(id, kSum);
        body_.lines.push_back("const Scalar " + name + " = " + value + ";");
        name_[k] = name;
    }

    std::string term(const Term& t, int context) {
        if (t.node == kOne) return number_literal(t.coeff);
        if (t.coeff.is_equal(1)) return ref(t.node, context);
        std::string s;
        const GiNaC::numeric a = GiNaC::abs(t.coeff);
        if (a.is_equal(1)) {
            s = "-" + ref(t.node, kProduct + 1);
            ++body_.ops.additions;  // a negation costs like a subtraction
        } else {
            s = (t.coeff.is_negative() ? "-" : "") + number_literal(a) + "*" + ref(t.node, kProduct);
            ++body_.ops.multiplications;
            if (!a.is_integer()) ++body_.ops.divisions;
        }
        return context > kSum ? "(" + s + ")" : s;
    }

    /// A node as an operand: its temporary's name, or its code inline.
    std::string ref(NodeId id, int context) {
        const std::string& n = name_[static_cast<std::size_t>(id)];
        if (!n.empty()) return n;
        return render(id, context);
    }

    std::string render(NodeId id, int context) {
        const Node& n = dag_.node(id);
        std::string out;
        int strength = kAtom;
        switch (n.op) {
            case Op::Number:
                out = number_literal(n.value);
                if (!n.value.is_integer()) strength = kProduct;
                break;
            case Op::Symbol:
                out = dag_.symbol(n.symbol).name;
                break;
            case Op::Func: {
                ++body_.ops.function_calls;
                std::string args;
                for (std::size_t i = 0; i < n.args.size(); ++i) args += (i ? ", " : "") + ref(n.args[i], kSum);
                if (n.name == "sign" || n.name == "heaviside" || n.name == "max" || n.name == "min") {
                    // eomgen/nonsmooth.hpp: one definition for double, long double, AutoDiffScalar and the device.
                    out = "eomgen::" + n.name + "<Scalar>(" + args + ")";
                } else {
                    functions_.insert(n.name);
                    out = n.name + "(" + args + ")";
                }
                break;
            }
            case Op::Pow: {
                const int k = n.value.to_int();
                const std::string b = ref(n.args[0], kAtom);
                out = b;
                for (int i = 1; i < k; ++i) out += "*" + b;
                body_.ops.multiplications += k - 1;
                strength = kProduct;
                break;
            }
            case Op::Mul: {
                std::vector<std::string> num, den;
                for (std::size_t i = 0; i < n.args.size(); ++i)
                    (n.coeffs[i].is_negative() ? den : num).push_back(ref(n.args[i], kProduct + 1));
                auto join = [&](const std::vector<std::string>& v) {
                    std::string s;
                    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? "*" : "") + v[i];
                    return s;
                };
                body_.ops.multiplications += static_cast<long>(std::max<std::size_t>(num.size(), 1) - 1);
                if (den.empty()) {
                    out = join(num);
                } else {
                    body_.ops.multiplications += static_cast<long>(den.size() - 1);
                    ++body_.ops.divisions;
                    out = (num.empty() ? std::string("Scalar(1)") : join(num)) + "/" +
                          (den.size() > 1 ? "(" + join(den) + ")" : den[0]);
                }
                strength = kProduct;
                break;
            }
            case Op::Add: {
                for (std::size_t i = 0; i < n.args.size(); ++i) {
                    const GiNaC::numeric c = n.coeffs[i];
                    std::string t = term(Term{GiNaC::abs(c), n.args[i]}, kSum);
                    if (i == 0)
                        out = c.is_negative() ? "-" + (GiNaC::abs(c).is_equal(1) ? ref(n.args[i], kProduct + 1) : t) : t;
                    else
                        out += (c.is_negative() ? " - " : " + ") + t;
                    if (i > 0 || c.is_negative()) ++body_.ops.additions;
                }
                if (!n.value.is_zero()) {
                    out += (n.value.is_negative() ? " - " : " + ") + number_literal(GiNaC::abs(n.value));
                    ++body_.ops.additions;
                }
                strength = kSum;
                break;
            }
        }
        if (strength < context) return "(" + out + ")";
        return out;
    }

    ExprDag& dag_;
    std::vector<int> uses_;
    std::vector<std::string> name_;
    std::set<NodeId> declared_;
    std::set<int> used_;
    std::set<std::string> functions_;
    int next_temp_ = 0;
    FunctionBody body_;
};

}  // namespace

std::string shortest_decimal(double v) { return fmt::format("{}", v); }

SymbolTable symbol_table(const Model& model) {
    SymbolTable table;
    auto put = [&table](SymbolInfo info, const GiNaC::ex& e) {
        table.info.push_back(std::move(info));
        table.exprs.push_back(e);
    };
    for (std::size_t i = 0; i < model.parameters.size(); ++i) {
        const Parameter& p = model.parameters[i];
        put({SymbolKind::Parameter, int(i), p.name, p.name, p.latex, "p_." + p.name}, p.symbol);
    }
    for (std::size_t i = 0; i < model.coordinates.size(); ++i) {
        const Coordinate& c = model.coordinates[i];
        const std::string k = std::to_string(i);
        put({SymbolKind::Coordinate, int(i), c.name, c.name, c.latex, "q_(" + k + ")"}, c.q);
        put({SymbolKind::Velocity, int(i), c.name + "_dot", c.name + "'", "\\dot{" + c.latex + "}", "qd_(" + k + ")"},
            c.qd);
        put({SymbolKind::Acceleration, int(i), c.name + "_ddot", c.name + "''", "\\ddot{" + c.latex + "}",
             "qdd_(" + k + ")"},
            c.qdd);
    }
    put({SymbolKind::Time, 0, "t", "t", "t", "t"}, model.t);
    put({SymbolKind::Constant, 0, "pi_", "pi", "\\pi", "Scalar(3.141592653589793238462643383279502884L)"}, GiNaC::Pi);
    return table;
}

FunctionBody emit_body(ExprDag& dag, const std::vector<Output>& outputs) {
    BodyEmitter e(dag);
    return e.run(outputs);
}

std::string emit_function(const FunctionSpec& f, const SymbolTable& table) {
    std::ostringstream os;
    os << "    /// " << f.doc << "\n";
    if (!f.template_head.empty()) os << "    " << f.template_head << "\n";
    os << "    EOMGEN_HD static " << f.return_type << " " << f.name << "(";  // device.hpp: host and CUDA device
    std::vector<std::string> params;
    for (const auto& [type, name] : f.inputs) params.push_back("const " + type + "& " + name);
    for (const auto& [type, name] : f.outputs) params.push_back(type + "& " + name);
    for (std::size_t i = 0; i < params.size(); ++i) os << (i ? ", " : "") << params[i];
    os << ") {\n";
    if (!f.delegate.empty()) {
        for (const std::string& l : f.delegate) os << "        " << l << "\n";
        os << "    }\n";
        return os.str();
    }
    ExprDag dag(table.info, table.exprs, true);
    FunctionBody body = emit_body(dag, f.values);
    // Which arguments the body reads, through the locals it declares.
    std::set<std::string> read;
    std::vector<std::string> locals;
    for (int s : body.used_symbols) {
        const SymbolInfo& info = table.info[static_cast<std::size_t>(s)];
        const std::string& src = info.source;
        if (info.kind == SymbolKind::Time) {
            read.insert("t");
            continue;
        }
        if (info.kind == SymbolKind::Constant) {
            locals.push_back("const Scalar " + info.name + " = " + src + ";");
            continue;
        }
        read.insert(src.substr(0, src.find_first_of("(.")));
        locals.push_back("const Scalar " + info.name + " = " + src + ";");
    }
    // A name the lines after the body use is used (momenta()'s M_ * qd_).
    auto used_after = [&f](const std::string& name) {
        auto word_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
        for (const std::string& l : f.after)
            for (std::size_t at = l.find(name); at != std::string::npos; at = l.find(name, at + 1))
                if ((at == 0 || !word_char(l[at - 1])) &&
                    (at + name.size() == l.size() || !word_char(l[at + name.size()])))
                    return true;
        return false;
    };
    for (const auto& [type, name] : f.inputs)
        if (!read.count(name) && !used_after(name)) os << "        static_cast<void>(" << name << ");\n";
    // An output with nothing to hold (e.g. no conserved quantity) is still a parameter.
    for (const auto& output : f.outputs) {
        const std::string& name = output.second;  // not a structured binding: C++17 lambdas cannot capture one
        if (std::none_of(f.values.begin(), f.values.end(),
                         [&](const Output& o) { return o.target.rfind(name + "(", 0) == 0; }) &&
            !used_after(name))
            os << "        static_cast<void>(" << name << ");\n";
    }
    // using-declarations so that overloads for long double (and other scalars, by ADL) are found.
    for (const std::string& fn : body.functions) os << "        using std::" << fn << ";\n";
    for (const std::string& l : locals) os << "        " << l << "\n";
    for (const std::string& l : f.before) os << "        " << l << "\n";
    for (const std::string& l : body.lines) os << "        " << l << "\n";
    for (const std::string& l : f.after) os << "        " << l << "\n";
    os << "    }\n";
    return os.str();
}

namespace {

/// The lines that start with prefix.
std::vector<std::string> only(const std::vector<std::string>& lines, const std::string& prefix) {
    std::vector<std::string> out;
    for (const std::string& l : lines)
        if (l.rfind(prefix, 0) == 0) out.push_back(l);
    return out;
}

std::string string_array(const std::vector<std::string>& names) {
    std::string s = "{";
    for (std::size_t i = 0; i < names.size(); ++i) s += (i ? ", " : "") + text::cpp_string(names[i]);
    return s + "}";
}

std::string double_literal(double v) {
    std::string s = shortest_decimal(v);
    const bool integral = s.find_first_of(".eEn") == std::string::npos;  // n: nan, inf
    return "Scalar(" + s + (integral ? "" : "L") + ")";
}

}  // namespace

std::string emit_model_header(const Model& model, const Equations& eq, const std::string& model_file,
                              GenerationTimings* timings) {
    PhaseClock clock(timings);
    const SymbolTable table = symbol_table(model);
    MathPrinter printer(table);
    const std::size_t n = model.dof();

    std::vector<std::string> coords, states, params, conserved, outputs;
    for (const Coordinate& c : model.coordinates) coords.push_back(c.name);
    states = coords;
    for (const Coordinate& c : model.coordinates) states.push_back(c.name + "_dot");
    for (const Parameter& p : model.parameters) params.push_back(p.name);
    for (const ConservedQuantity& c : eq.conserved) conserved.push_back(c.name);
    for (const DeclaredOutput& o : model.outputs) outputs.push_back(o.name);

    std::ostringstream os;
    // Every comment line goes through text::cpp_comment: a title, source, unit or description is a
    // stranger's text, and no character of it may end the comment (docs/security.md).
    using text::cpp_comment;
    os << "/** @file " << model.name << ".hpp  Equations of motion of \"" << cpp_comment(model.title) << "\". */\n";
    os << "// Generated by eomgen " << EOMGEN_VERSION << " from " << cpp_comment(model_file)
       << ": do not edit, regenerate.\n";
    if (!model.source.empty()) os << "// Source: " << cpp_comment(model.source) << "\n";
    os << "//\n";
    os << "// T = " << cpp_comment(printer.print(eq.T, MathStyle::Text)) << "\n";
    os << "// V = " << cpp_comment(printer.print(eq.V, MathStyle::Text)) << "\n";
    // Large systems' equations are for `eomgen show`, not for a comment nobody reads: printing stops as soon
    // as they pass 4000 characters (expanding and printing all of them took a third of the emit at n = 20).
    constexpr std::size_t kLongestEquations = 4000;
    std::string equations;
    for (std::size_t i = 0; i < n && equations.size() <= kLongestEquations; ++i)
        equations += "//   " + cpp_comment(printer.print(eq.euler_lagrange[i].expand(), MathStyle::Text)) + " = 0\n";
    if (equations.size() <= kLongestEquations)
        os << "//\n// Euler-Lagrange equations, d/dt(dL/dq') - dL/dq = 0:\n" << equations;
    else
        os << "//\n// Euler-Lagrange equations: see `eomgen show " << cpp_comment(model_file) << "`.\n";
    for (const ConstraintEquations& c : eq.constraints)
        os << "// Constraint " << c.name << " (" << (c.kind == ConstraintKind::Holonomic ? "holonomic" : "nonholonomic")
           << "): " << cpp_comment(printer.print(c.kind == ConstraintKind::Holonomic ? c.position : c.velocity, MathStyle::Text))
           << " = 0\n";
    os << "//\n// Conserved: ";
    if (eq.conserved.empty()) os << "nothing found";
    for (std::size_t i = 0; i < eq.conserved.size(); ++i)
        os << (i ? "; " : "") << cpp_comment(eq.conserved[i].name + " (" + eq.conserved[i].reason + ")");
    const SwitchingCode switches = switching_code(model, eq, printer);
    os << switches.comment(printer);
    if (!model.outputs.empty()) os << "\n//\n// Outputs ([outputs]):";
    for (const DeclaredOutput& o : model.outputs)
        os << "\n//   " << cpp_comment(o.name + " = " + printer.print(o.expr.expr, MathStyle::Text) +
                                     (o.unit.empty() ? "" : "  [" + o.unit + "]"));
    os << "\n#pragma once\n\n";
    // A tree of point masses in T gets an O(n) rhs() (codegen/tree_emitter.hpp); every other model solves M.
    clock.lap("comments (T, V, equations)");
    const std::optional<std::string> tree_rhs = emit_tree_rhs(model, eq, table);
    clock.lap(tree_rhs ? "tree of point masses: rhs()" : "tree of point masses: none");
    // The optional functions ([generate], `eomgen generate --with`): analytic Jacobians of unconstrained models
    // (the model file refuses them with constraints), K, C and G about rest.
    const bool jacobians = model.generate.jacobians && eq.constraints.empty();
    const bool rest_matrices = model.generate.stiffness;
    // A tree's Jacobians differentiate its recursion (model_jacobian.hpp); any other model's are symbolic.
    if (jacobians) os << (tree_rhs ? "#include \"eomgen/model_jacobian.hpp\"\n" : "#include \"eomgen/analytic_jacobian.hpp\"\n");
    os << (eq.constraints.empty() ? "#include \"eomgen/linear_solve.hpp\"\n" : "#include \"eomgen/constraints.hpp\"\n");
    if (tree_rhs) os << "#include \"eomgen/particle_tree.hpp\"\n";
    if (switches.include_runtime) os << "#include \"eomgen/nonsmooth.hpp\"\n";
    os << "#include \"eomgen/device.hpp\"\n#include \"eomgen/linearize.hpp\"\n\n";
    os << "#include <Eigen/Core>\n\n#include <array>\n#include <cmath>\n#include <string_view>\n#include <type_traits>\n\n";
    os << "namespace eomgen::models::" << model.name << " {\n\n";
    os << "/// x = [q, q'] with q = " << string_array(coords) << "; M(q,t) q'' = f(q,q',t) solved in rhs().\n";
    os << "template <class Scalar>\nstruct Model {\n";
    os << "    static constexpr const char* name = " << text::cpp_string(model.name) << ";\n";
    os << "    static constexpr const char* title = " << text::cpp_string(model.title) << ";\n";
    os << "    static constexpr const char* source = " << text::cpp_string(model.source) << ";\n";
    os << "    static constexpr int nq = " << n << ";\n";
    os << "    static constexpr int nx = " << 2 * n << ";\n";
    os << "    static constexpr int n_params = " << params.size() << ";\n";
    os << "    static constexpr int n_conserved = " << conserved.size() << ";\n";
    os << "    static constexpr int n_outputs = " << outputs.size() << ";\n";
    os << "    static constexpr bool explicit_time = " << (eq.explicit_time ? "true" : "false") << ";\n";
    const bool forced = std::any_of(eq.generalized_forces.begin(), eq.generalized_forces.end(),
                                    [](const GiNaC::ex& q) { return !q.is_zero(); });
    os << "    /// Generalized forces Q or dissipation R act (the variational integrator does not apply).\n";
    os << "    static constexpr bool has_generalized_forces = " << (forced ? "true" : "false") << ";\n";
    const bool balance = eq.constraints.empty() && (forced || eq.explicit_time);
    if (balance) {
        os << "    /// h is not conserved (forces act, or L depends on t): power() is dh/dt along a motion.\n";
        os << "    static constexpr bool has_power = true;\n";
    }
    os << switches.constants();
    const std::size_t nc = eq.constraints.size();
    std::vector<std::string> constraint_names;
    for (const ConstraintEquations& c : eq.constraints) constraint_names.push_back(c.name);
    if (nc > 0) {
        os << "    static constexpr int n_constraints = " << nc << ";\n";
        os << "    /// Baumgarte stabilisation used by rhs(): A q'' = gamma - 2 alpha (A q' + b) - beta^2 g.\n";
        os << "    static constexpr double baumgarte_alpha = " << shortest_decimal(model.baumgarte_alpha) << ";\n";
        os << "    static constexpr double baumgarte_beta = " << shortest_decimal(model.baumgarte_beta) << ";\n";
    }
    os << "\n";
    os << "    using Config = Eigen::Matrix<Scalar, nq, 1>;\n";
    os << "    using State = Eigen::Matrix<Scalar, nx, 1>;\n";
    os << "    using MassMatrix = Eigen::Matrix<Scalar, nq, nq>;\n";
    os << "    using Conserved = Eigen::Matrix<Scalar, n_conserved, 1>;\n";
    os << "    using Outputs = Eigen::Matrix<Scalar, n_outputs, 1>;\n";
    os << "    using StateJacobian = Eigen::Matrix<Scalar, nx, nx>;\n";
    os << "    using ParameterJacobian = Eigen::Matrix<Scalar, nx, n_params>;\n";
    os << switches.types();
    if (nc > 0) {
        os << "    using ConstraintVector = Eigen::Matrix<Scalar, n_constraints, 1>;\n";
        os << "    using ConstraintJacobian = Eigen::Matrix<Scalar, n_constraints, nq>;\n";
    }
    os << "\n";
    os << "    /// Parameters with the model file's defaults.\n    struct Params {\n";
    for (const Parameter& p : model.parameters) {
        os << "        Scalar " << p.name << " = " << double_literal(p.value) << ";";
        std::string note = p.description;
        if (!p.unit.empty()) note += (note.empty() ? "" : " ") + std::string("[") + p.unit + "]";
        if (!note.empty()) os << "  ///< " << cpp_comment(note);
        os << "\n";
    }
    os << "    };\n\n";
    os << "    static constexpr std::array<const char*, nq> coordinate_names" << string_array(coords) << ";\n";
    os << "    static constexpr std::array<const char*, nx> state_names" << string_array(states) << ";\n";
    os << "    static constexpr std::array<const char*, n_params> param_names" << string_array(params) << ";\n";
    os << "    static constexpr std::array<const char*, n_conserved> conserved_names" << string_array(conserved)
       << ";\n";
    os << "    static constexpr std::array<const char*, n_outputs> output_names" << string_array(outputs) << ";\n";
    os << switches.names_array();
    if (nc > 0) {
        os << "    static constexpr std::array<const char*, n_constraints> constraint_names" << string_array(constraint_names)
           << ";\n";
        os << "    static constexpr std::array<bool, n_constraints> constraint_is_holonomic{";
        for (std::size_t k = 0; k < nc; ++k)
            os << (k ? ", " : "") << (eq.constraints[k].kind == ConstraintKind::Holonomic ? "true" : "false");
        os << "};\n";
    }
    os << emit_unit_arrays(model, eq);
    os << "\n";
    os << "    /// Sets the parameter called `name`; false when there is none.\n";
    os << "    static bool set_param(Params& p_, std::string_view name_, const Scalar& value_) {\n";
    for (const Parameter& p : model.parameters)
        os << "        if (name_ == " << text::cpp_string(p.name) << ") return p_." << p.name << " = value_, true;\n";
    if (model.parameters.empty()) os << "        static_cast<void>(p_);\n        static_cast<void>(name_);\n        static_cast<void>(value_);\n";
    os << "        return false;\n    }\n\n";
    os << "    static std::array<Scalar, n_params> param_values(const Params& p_) {\n";
    os << "        static_cast<void>(p_);\n        return {";
    for (std::size_t i = 0; i < params.size(); ++i) os << (i ? ", " : "") << "p_." << params[i];
    os << "};\n    }\n\n";
    os << "    /// The model file's initial values and rates.\n";
    os << "    static State default_state() {\n        State x_;\n        x_ << ";
    for (std::size_t i = 0; i < n; ++i) os << double_literal(model.coordinates[i].initial) << ", ";
    for (std::size_t i = 0; i < n; ++i) os << (i ? ", " : "") << double_literal(model.coordinates[i].rate);
    os << ";\n        return x_;\n    }\n\n";

    const std::pair<std::string, std::string> t_in{"Scalar", "t"}, q_in{"Config", "q_"}, qd_in{"Config", "qd_"},
        p_in{"Params", "p_"};
    std::vector<Output> mass, force, momenta, grad, cons, recorded;
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < n; ++j)
            mass.push_back({fmt::format("M_({}, {})", i, j), eq.M(static_cast<unsigned>(i), static_cast<unsigned>(j))});
        force.push_back({fmt::format("f_({})", i), eq.f[i]});
        momenta.push_back({fmt::format("out_({})", i), eq.momenta[i]});
        grad.push_back({fmt::format("out_({})", i), eq.dLdq[i]});
    }
    // h = Σ q̇ ∂L/∂q̇ − L is T + V when T is homogeneous quadratic in q̇ and V is free of q̇ (eq.natural).
    // Then energy() returns kinetic_energy() + potential_energy(), lagrangian() their difference and
    // conserved() calls energy() and momenta(), instead of each computing its own copy: the expanded h was the
    // longest function of the n-link pendulum's header (38 kB of 297 kB at n = 20, twice with conserved()), and
    // the header's compile time grows with its code.
    const bool natural = eq.natural;
    // With T homogeneous quadratic in q̇ and V free of q̇, p = M q̇ (Euler's theorem): momenta() from M's entries,
    // whose code is short, instead of the expanded p_i (the n-link pendulum's p_i has O(n²) terms; their CSE was
    // as long as that of M and f at n = 60).
    std::vector<std::string> momenta_before, momenta_after;
    if (natural) {
        momenta.clear();
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j)
                momenta.push_back({fmt::format("M_({}, {})", i, j), eq.M(static_cast<unsigned>(i), static_cast<unsigned>(j))});
        momenta_before = {"MassMatrix M_;"};
        momenta_after = {"out_.noalias() = M_ * qd_;"};
    }
    const std::string args = "t, q_, qd_, p_";
    std::vector<std::string> lagrangian_call, energy_call, conserved_calls;
    if ((eq.L - (eq.T - eq.V)).is_zero())
        lagrangian_call = {"return kinetic_energy(" + args + ") - potential_energy(" + args + ");"};
    if (natural) energy_call = {"return kinetic_energy(" + args + ") + potential_energy(" + args + ");"};
    // Conserved quantities that are h or a momentum: read from energy() and momenta().
    bool momentum_read = false;
    for (std::size_t k = 0; k < eq.conserved.size(); ++k) {
        const GiNaC::ex& v = eq.conserved[k].value;
        std::string line;
        if (v.is_equal(eq.energy)) line = fmt::format("out_({}) = energy({});", k, args);
        for (std::size_t i = 0; i < n && line.empty(); ++i)
            if (v.is_equal(eq.momenta[i])) {
                if (!momentum_read) conserved_calls.push_back("Config momenta_;");
                if (!momentum_read) conserved_calls.push_back("momenta(" + args + ", momenta_);");
                momentum_read = true;
                line = fmt::format("out_({}) = momenta_({});", k, i);
            }
        if (line.empty()) {
            conserved_calls.clear();
            break;
        }
        conserved_calls.push_back(line);
    }
    for (std::size_t i = 0; i < eq.conserved.size(); ++i)
        cons.push_back({fmt::format("out_({})", i), eq.conserved[i].value});
    for (std::size_t i = 0; i < model.outputs.size(); ++i)
        recorded.push_back({fmt::format("out_({})", i), model.outputs[i].expr.expr});
    std::vector<Output> both = mass;
    both.insert(both.end(), force.begin(), force.end());
    // About rest (q' = 0): K = d(dV_eff/dq - Q)/dq, and D's symmetric (damping) and skew (gyroscopic) parts.
    std::vector<Output> stiff, damp, gyro;
    std::vector<std::string> rest_undefined;  // assignments of NaN to the entries that have no value at rest
    std::string rest_undefined_why;
    if (rest_matrices) {
        std::vector<GiNaC::symbol> qs, qds;
        for (const Coordinate& c : model.coordinates) {
            qs.push_back(c.q);
            qds.push_back(c.qd);
        }
        RestLinearization lin;
        try {
            lin = linearize_about_rest(eq.L, eq.generalized_forces, qs, qds);
        } catch (const NoValueAtRest& e) {  // asked for by [generate] stiffness or --with: said where the forces are
            const SourceLocation where = model.forces.empty() ? model.T.where : model.forces.front().where;
            throw ModelError(where, std::string("the stiffness and damping about rest cannot be generated: ") + e.what());
        }
        clock.lap("stiffness: linearize about rest");
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) {
                stiff.push_back({fmt::format("K_({}, {})", i, j), lin.K[i][j]});
                if (lin.D_defined[i][j] && lin.D_defined[j][i]) {
                    damp.push_back({fmt::format("C_({}, {})", i, j), (lin.D[i][j] + lin.D[j][i]) / 2});
                    gyro.push_back({fmt::format("G_({}, {})", i, j), (lin.D[i][j] - lin.D[j][i]) / 2});
                } else {  // dry friction: no value at rest, and the header says so
                    for (const char* m : {"C_", "G_"})
                        rest_undefined.push_back(fmt::format("{}({}, {}) = std::numeric_limits<Scalar>::quiet_NaN();", m, i, j));
                }
            }
        for (const std::string& why : lin.undefined) rest_undefined_why += " NaN where " + cpp_comment(why) + ".";
    }

    std::vector<FunctionSpec> functions = {
        // mass_matrix() and forcing() call dynamics() (M does not depend on q', so at q' = 0) instead of holding
        // second copies of M's and f's code: the header's compile time grows with its code, and neither is on a
        // hot path (rhs() calls dynamics(); the variational integrator's Newton iteration calls momenta() and
        // lagrangian_gradient(), mass_matrix() only in the Legendre transform and the constraint projection).
        {"Mass matrix M = d2L/dq'dq' (symmetric; computed by dynamics() at q' = 0, on which M does not depend).",
         "void", "mass_matrix", {t_in, q_in, p_in}, {{"MassMatrix", "M_"}}, mass,
         {"Config qd_;", "qd_.setZero();", "Config f_;", "dynamics(t, q_, qd_, p_, M_, f_);"}},
        {"Forcing f = dL/dq - (d2L/dq'dq) q' - d2L/dq'dt, the right-hand side of M q'' = f (computed by dynamics()).",
         "void", "forcing", {t_in, q_in, qd_in, p_in}, {{"Config", "f_"}}, force,
         {"MassMatrix M_;", "dynamics(t, q_, qd_, p_, M_, f_);"}},
        {"M and f together, sharing their subexpressions.", "void", "dynamics", {t_in, q_in, qd_in, p_in},
         {{"MassMatrix", "M_"}, {"Config", "f_"}}, both},
        {"Kinetic energy T.", "Scalar", "kinetic_energy", {t_in, q_in, qd_in, p_in}, {}, {{"return", eq.T}}},
        {"Potential energy V.", "Scalar", "potential_energy", {t_in, q_in, qd_in, p_in}, {}, {{"return", eq.V}}},
        {"Lagrangian L = T - V.", "Scalar", "lagrangian", {t_in, q_in, qd_in, p_in}, {}, {{"return", eq.L}},
         lagrangian_call},
        {natural ? "Energy function h = sum q' dL/dq' - L, here T + V (T quadratic in q', V free of q')."
                 : "Energy function h = sum q' dL/dq' - L.",
         "Scalar", "energy", {t_in, q_in, qd_in, p_in}, {}, {{"return", eq.energy}}, energy_call},
        {natural ? "Generalized momenta p = dL/dq', here M q' (T quadratic in q', V free of q')."
                 : "Generalized momenta p = dL/dq'.",
         "void", "momenta", {t_in, q_in, qd_in, p_in}, {{"Config", "out_"}}, momenta, {}, {}, momenta_before,
         momenta_after},
        {"dL/dq.", "void", "lagrangian_gradient", {t_in, q_in, qd_in, p_in}, {{"Config", "out_"}}, grad},
        {"Conserved quantities, in the order of conserved_names.", "void", "conserved", {t_in, q_in, qd_in, p_in},
         {{"Conserved", "out_"}}, cons, conserved_calls},
        {"Declared outputs ([outputs] of the model file), in the order of output_names.", "void", "outputs",
         {t_in, q_in, qd_in, p_in}, {{"Outputs", "out_"}}, recorded},
    };
    if (balance) {
        GiNaC::ex P = -eq.L.diff(model.t);
        for (std::size_t i = 0; i < n; ++i) P += eq.generalized_forces[i] * model.coordinates[i].qd;
        functions.push_back({"Power P = sum Q_i q'_i - dL/dt: dh/dt along a motion, so that h(t) - h(0) - int_0^t P dt stays 0 "
                             "(the energy balance of a damped, driven or rheonomic model).",
                             "Scalar", "power", {t_in, q_in, qd_in, p_in}, {}, {{"return", P}}});
    }
    if (!switches.empty()) functions.push_back(switches.function(t_in, q_in, qd_in, p_in));
    if (rest_matrices) {
        const std::vector<FunctionSpec> rest = {
            {"Stiffness about rest, K = d/dq (dV_eff/dq - Q) at q' = 0 (V_eff = V - T(q' = 0)): M dq'' + (C + G) dq' + K dq "
             "= 0 about an equilibrium.",
             "void", "stiffness", {t_in, q_in, p_in}, {{"MassMatrix", "K_"}}, stiff},
            {"Damping about rest, C: the symmetric part of D = dbeta_i/dq_j - dbeta_j/dq_i - dQ_i/dq'_j at q' = 0 "
             "(beta = dL/dq' at q' = 0)." + rest_undefined_why,
             "void", "damping", {t_in, q_in, p_in}, {{"MassMatrix", "C_"}}, damp, {}, {}, {}, only(rest_undefined, "C_")},
            {"Gyroscopic matrix about rest, G: the skew part of D (does no work)." + rest_undefined_why, "void",
             "gyroscopic", {t_in, q_in, p_in}, {{"MassMatrix", "G_"}}, gyro, {}, {}, {}, only(rest_undefined, "G_")}};
        functions.insert(functions.end(), rest.begin(), rest.end());
    }
    if (nc > 0) {
        std::vector<Output> jac_gamma, residuals, all = both;
        for (std::size_t k = 0; k < nc; ++k) {
            const ConstraintEquations& c = eq.constraints[k];
            for (std::size_t i = 0; i < n; ++i) jac_gamma.push_back({fmt::format("A_({}, {})", k, i), c.jacobian[i]});
            jac_gamma.push_back({fmt::format("gamma_({})", k), c.gamma});
        }
        for (std::size_t k = 0; k < nc; ++k) {
            residuals.push_back({fmt::format("position_({})", k), eq.constraints[k].position});
            residuals.push_back({fmt::format("velocity_({})", k), eq.constraints[k].velocity});
        }
        all.insert(all.end(), jac_gamma.begin(), jac_gamma.end());
        all.insert(all.end(), residuals.begin(), residuals.end());
        const std::pair<std::string, std::string> A_out{"ConstraintJacobian", "A_"}, gamma_out{"ConstraintVector", "gamma_"},
            pos_out{"ConstraintVector", "position_"}, vel_out{"ConstraintVector", "velocity_"};
        functions.push_back({"Constraint Jacobian A (c = A q' + b) and acceleration level A q'' = gamma.", "void",
                             "constraints", {t_in, q_in, qd_in, p_in}, {A_out, gamma_out}, jac_gamma});
        functions.push_back({"Residuals: g(q,t) of holonomic constraints (0 for nonholonomic ones) and c = A q' + b.",
                             "void", "constraint_residuals", {t_in, q_in, qd_in, p_in}, {pos_out, vel_out}, residuals});
        functions.push_back({"M, f, A, gamma and the residuals together, sharing their subexpressions.", "void",
                             "constrained_dynamics", {t_in, q_in, qd_in, p_in},
                             {{"MassMatrix", "M_"}, {"Config", "f_"}, A_out, gamma_out, pos_out, vel_out}, all});
    }
    for (const FunctionSpec& f : functions) {
        os << emit_function(f, table) << "\n";
        clock.lap("function " + f.name + "()");
    }

    if (nc == 0 && tree_rhs) {
        os << *tree_rhs;
        if (jacobians) os << emit_recursion_jacobian();
        clock.lap(jacobians ? "jacobians: through the recursion" : "rhs()");
    } else if (nc == 0) {
        const bool unrolled = n <= kUnrolledSolveMaxN;
        if (unrolled) {
            std::vector<std::vector<bool>> zero(n, std::vector<bool>(n, false));
            for (std::size_t i = 0; i < n; ++i)
                for (std::size_t j = 0; j < n; ++j)
                    zero[i][j] = eq.M(static_cast<unsigned>(i), static_cast<unsigned>(j)).is_zero();
            os << emit_mass_solve(zero) << "\n";
        }
        os << "    /// x' = [q', q''] with M q'' = f solved by L D L^T; a singular M throws eomgen::SingularMassMatrix.\n";
        os << "    static void rhs(const Scalar& t, const State& x_, const Params& p_, State& xdot_) {\n";
        os << "        const Config q_ = x_.template head<nq>();\n";
        os << "        const Config qd_ = x_.template tail<nq>();\n";
        os << "        MassMatrix M_;\n        Config f_;\n        dynamics(t, q_, qd_, p_, M_, f_);\n";
        os << (unrolled ? "        Config qdd_;\n        solve_for_accelerations(t, x_, M_, f_, qdd_);\n"
                        : "        Config qdd_;\n        eomgen::solve_mass_matrix(M_, f_, qdd_, t, x_);\n");
        os << "        xdot_.template head<nq>() = qd_;\n        xdot_.template tail<nq>() = qdd_;\n    }\n\n";
        if (jacobians) os << emit_analytic_jacobian(model, eq, table);
        clock.lap(jacobians ? "jacobians: terms and emission" : "rhs()");
    } else {
        os << "    /// q'' and the multipliers lambda of M q'' = f + A^T lambda, A q'' = gamma - 2 alpha c - beta^2 g,\n"
              "    /// by a Schur complement on M's Cholesky factor (eomgen::solve_constrained). lambda_k is the\n"
              "    /// generalized force of constraint k, its sign that of the constraint as written.\n";
        os << "    static void accelerations(const Scalar& t, const State& x_, const Params& p_, const Scalar& alpha_,\n"
              "                              const Scalar& beta_, Config& qdd_, ConstraintVector& lambda_) {\n";
        os << "        const Config q_ = x_.template head<nq>();\n";
        os << "        const Config qd_ = x_.template tail<nq>();\n";
        os << "        MassMatrix M_;\n        Config f_;\n        ConstraintJacobian A_;\n"
              "        ConstraintVector gamma_, position_, velocity_;\n";
        os << "        constrained_dynamics(t, q_, qd_, p_, M_, f_, A_, gamma_, position_, velocity_);\n";
        os << "        gamma_ -= Scalar(2) * alpha_ * velocity_ + beta_ * beta_ * position_;\n";
        os << "        eomgen::solve_constrained(M_, f_, A_, gamma_, qdd_, lambda_, t, x_);\n    }\n\n";
        os << "    /// x' = [q', q''] with the model's Baumgarte parameters.\n";
        os << "    static void rhs(const Scalar& t, const State& x_, const Params& p_, State& xdot_) {\n";
        os << "        Config qdd_;\n        ConstraintVector lambda_;\n";
        os << "        accelerations(t, x_, p_, Scalar(baumgarte_alpha), Scalar(baumgarte_beta), qdd_, lambda_);\n";
        os << "        xdot_.template head<nq>() = x_.template tail<nq>();\n        xdot_.template tail<nq>() = qdd_;\n    }\n\n";
        os << "    /// The multipliers at state x (with the model's Baumgarte parameters).\n";
        os << "    static void multipliers(const Scalar& t, const State& x_, const Params& p_, ConstraintVector& lambda_) {\n";
        os << "        Config qdd_;\n";
        os << "        accelerations(t, x_, p_, Scalar(baumgarte_alpha), Scalar(baumgarte_beta), qdd_, lambda_);\n    }\n";
    }
    os << "\n    /// A = dx'/dx and B = dx'/dp (columns in param_names order) at (t, x), exact to round-off by forward\n"
          "    /// differentiation through rhs (eomgen/linearize.hpp); for Scalar = double. A member template, so that\n"
          "    /// instantiating the class does not compile the differentiation.\n";
    if (!switches.empty())
        os << "    /// On a switching surface (switch_names) A and B are not defined: the derivative there is the one on the\n"
              "    /// side the code's branch takes (sign(0) = 0).\n";
    os << "    template <class MatA = StateJacobian, class MatB = ParameterJacobian>\n";
    os << "    static void linearization(const Scalar& t, const State& x_, const Params& p_, MatA& A_, MatB& B_) {\n";
    os << "        static_assert(std::is_same_v<Scalar, double>, \"linearization() is for Model<double>\");\n";
    os << "        eomgen::linearize<Model>(t, x_, p_, A_, B_);\n    }\n";
    os << "};\n\n}  // namespace eomgen::models::" << model.name << "\n";
    clock.lap("the rest of the header");
    return os.str();
}

}  // namespace eomgen::codegen
