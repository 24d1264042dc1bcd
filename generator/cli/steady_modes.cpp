/** @file steady_modes.cpp  `eomgen modes --steady`: the linear equations about a steady motion, as text or JSON. */
#include "cli/steady_modes.hpp"

#include "cli/plot.hpp"

#include "mechanics/small_oscillations.hpp"
#include "mechanics/steady_motion.hpp"
#include "mechanics/steady_sweep.hpp"
#include "model/expression_parser.hpp"
#include "text/escape.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

namespace eomgen::cli {

namespace {

using Eigen::MatrixXd;
using text::json_string;

std::string num(double v, int digits) {
    if (v == 0) return "0";
    if (!std::isfinite(v)) return "null";
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}

/// Text: round-off next to the scale shown as 0.
double clean(double v, double scale) { return std::abs(v) < 1e-13 * (1 + scale) ? 0.0 : v; }

MatrixXd clean(const MatrixXd& m) {
    MatrixXd out = m;
    const double scale = m.size() ? m.cwiseAbs().maxCoeff() : 0.0;
    for (Eigen::Index i = 0; i < m.size(); ++i) out(i) = std::abs(m(i)) < 1e-13 * scale ? 0.0 : m(i);
    return out;
}

std::string names(const Model& model, const std::vector<std::size_t>& idx, const char* suffix = "") {
    std::string s;
    for (std::size_t k = 0; k < idx.size(); ++k) s += (k ? ", " : "") + model.coordinates[idx[k]].name + suffix;
    return idx.empty() ? "none" : s;
}

std::string json_names(const Model& model, const std::vector<std::size_t>& idx, const char* suffix = "") {
    std::string s = "[";
    for (std::size_t k = 0; k < idx.size(); ++k) s += (k ? ", " : "") + json_string(model.coordinates[idx[k]].name + suffix);
    return s + "]";
}

std::string matrix(const MatrixXd& m, int digits, bool json) {
    std::string s = "[";
    for (Eigen::Index i = 0; i < m.rows(); ++i) {
        s += i ? (json ? ", [" : "; ") : (json ? "[" : "");
        for (Eigen::Index j = 0; j < m.cols(); ++j) s += (j ? ", " : "") + num(m(i, j), digits);
        if (json) s += "]";
    }
    return s + "]";
}

std::string complex_text(std::complex<double> z) {
    if (z.imag() == 0) return num(z.real(), 12);
    return num(z.real(), 12) + (z.imag() < 0 ? " - " : " + ") + num(std::abs(z.imag()), 12) + "i";
}

std::string complex_json(std::complex<double> z) {
    return "{\"re\": " + num(z.real(), 17) + ", \"im\": " + num(z.imag(), 17) + "}";
}

/// The root locus of a sweep: each eigenvalue's real part (points) and imaginary part (small points) against the
/// parameter, as the benchmark's figure draws it, with the stability changes marked.
void plot_sweep(const Model& model, const SteadySweep& sw, const std::string& output) {
    std::string data = "$locus << EOD\n";
    std::size_t width = 0;
    for (const Eigen::VectorXcd& e : sw.eigenvalues) width = std::max(width, std::size_t(e.size()));
    for (std::size_t k = 0; k < sw.values.size(); ++k) {
        data += num(sw.values[k], 17);
        for (std::size_t j = 0; j < width; ++j) {
            const bool has = Eigen::Index(j) < sw.eigenvalues[k].size();
            data += has ? " " + num(sw.eigenvalues[k](Eigen::Index(j)).real(), 17) + " " +
                              num(std::abs(sw.eigenvalues[k](Eigen::Index(j)).imag()), 17)
                        : " NaN NaN";
        }
        data += "\n";
    }
    data += "EOD\n";
    const bool png = output.size() >= 4 && output.compare(output.size() - 4, 4, ".png") == 0;
    std::string script = data + (png ? "set terminal pngcairo size 1000,600" : "set terminal svg size 1000,600");
    script += " noenhanced\nset output " + gnuplot_string(output) + "\n";
    script += "set title " + gnuplot_string(model.title + ": eigenvalues against " + sw.name) + "\n";
    std::string unit;
    for (const Parameter& p : model.parameters)
        if (p.name == sw.name && !p.unit.empty()) unit = " (" + p.unit + ")";
    script += "set xlabel " + gnuplot_string(sw.name + unit) + "\nset ylabel 'eigenvalue (1/s)'\nset grid\nset key outside right\n";
    script += "set xzeroaxis lt -1\n";
    for (const SteadySweep::Change& c : sw.changes)
        script += "set arrow from " + num(c.value, 17) + ", graph 0 to " + num(c.value, 17) + ", graph 1 nohead dt 2\n";
    script += "plot ";
    for (std::size_t j = 0; j < width; ++j) {
        script += (j ? ", " : "") + std::string("$locus using 1:") + std::to_string(2 + 2 * j) + " with points pt 7 ps 0.5 lc rgb '#1f77b4' " +
                  (j == 0 ? "title 'real part'" : "notitle");
        script += ", $locus using 1:" + std::to_string(3 + 2 * j) + " with points pt 6 ps 0.4 lc rgb '#d62728' " +
                  (j == 0 ? "title '|imaginary part|'" : "notitle");
    }
    script += "\n";
    run_gnuplot(script, output);
}

/// The names of an eigenvector's components: [q, q'] of the second-order coordinates where they decouple, else z.
std::vector<std::string> vector_names(const Model& model, const SteadyMotion& s) {
    std::vector<std::string> out;
    if (s.decoupled) {
        for (std::size_t j : s.second_order) out.push_back(model.coordinates[j].name);
        for (std::size_t j : s.second_order) out.push_back(model.coordinates[j].name + "_dot");
    } else {
        for (std::size_t j : s.coordinates) out.push_back(model.coordinates[j].name);
        for (std::size_t j : s.speeds) out.push_back(model.coordinates[j].name + "_dot");
    }
    return out;
}

/// Eigenvector k scaled so that its largest component is 1 (real).
Eigen::VectorXcd shape(const SteadyMotion& s, Eigen::Index k) {
    Eigen::VectorXcd v = s.eigenvectors.col(k);
    Eigen::Index at = 0;
    v.cwiseAbs().maxCoeff(&at);
    if (std::abs(v(at)) > 0) v /= v(at);
    return v;
}

}  // namespace

std::string steady_modes(const Model& model, const Equations& eq, const SteadyRequest& request) {
    SymbolTable parameters;
    for (const Parameter& p : model.parameters) parameters.symbols[p.name] = p.symbol;
    SteadyMotionOptions options;
    options.set = request.set;
    options.at = request.at;
    std::vector<std::string> in_rates;
    for (const std::string& text : request.steady) {
        const std::size_t eq_sign = text.find('=');
        std::string name = text.substr(0, eq_sign);
        while (!name.empty() && name.back() == ' ') name.pop_back();
        std::string base;
        if (name.size() > 4 && name.compare(name.size() - 4, 4, "_dot") == 0) base = name.substr(0, name.size() - 4);
        else if (!name.empty() && name.back() == '\'') base = name.substr(0, name.size() - 1);
        std::size_t index = 0;
        while (index < model.dof() && model.coordinates[index].name != base) ++index;
        if (eq_sign == std::string::npos || index == model.dof())
            throw ModesError("--steady " + text + ": give NAME_dot=EXPR with NAME a coordinate (e.g. thetaR_dot=-v/rR)");
        SteadyRate r;
        r.coordinate = index;
        r.text = text;
        try {
            r.value = parse_expression(text.substr(eq_sign + 1), parameters, {"", false});
        } catch (const ExpressionError& e) {
            throw ModesError("--steady " + text + ": " + e.message() + " (in the parameters only)");
        }
        for (const Parameter& p : model.parameters)
            if (r.value.has(p.symbol) && std::find(in_rates.begin(), in_rates.end(), p.name) == in_rates.end())
                in_rates.push_back(p.name);
        options.rates.push_back(r);
    }
    // The speed: the one parameter of --steady that the equations do not hold (v in thetaR_dot = -v/rR).
    std::string speed = request.speed;
    if (speed.empty()) {
        std::vector<std::string> free;
        for (const std::string& name : in_rates) {
            const auto p = std::find_if(model.parameters.begin(), model.parameters.end(),
                                        [&](const Parameter& x) { return x.name == name; });
            bool used = false;
            for (std::size_t i = 0; i < model.dof() && !used; ++i) {
                used = eq.f[i].has(p->symbol);
                for (std::size_t j = 0; j < model.dof() && !used; ++j) used = eq.M(unsigned(i), unsigned(j)).has(p->symbol);
            }
            for (const ConstraintEquations& c : eq.constraints) used = used || c.velocity.has(p->symbol);
            if (!used) free.push_back(name);
        }
        if (free.size() == 1) speed = free[0];
    }

    SteadyMotionSolver solver(model, eq);
    const SteadyMotion s = solver.solve(options);
    const std::optional<SpeedSplit> split = split_by_speed(model, solver, options, s, speed);
    std::optional<SteadySweep> sw;
    if (!request.sweep.empty()) {
        const std::string& spec = request.sweep;
        const std::size_t eq_at = spec.find('='), c1 = spec.find(':', eq_at);
        const std::size_t c2 = c1 == std::string::npos ? c1 : spec.find(':', c1 + 1);
        if (eq_at == std::string::npos || c2 == std::string::npos)
            throw ModesError("--sweep " + spec + ": give NAME=START:STOP:COUNT, e.g. v=0:10:201");
        double a = 0, b = 0;
        long count = 0;
        try {
            a = evaluate_constant(spec.substr(eq_at + 1, c1 - eq_at - 1));
            b = evaluate_constant(spec.substr(c1 + 1, c2 - c1 - 1));
            std::size_t used = 0;
            count = std::stol(spec.substr(c2 + 1), &used);
            if (used != spec.size() - c2 - 1) throw std::invalid_argument("count");
        } catch (const std::exception&) {
            throw ModesError("--sweep " + spec + ": START and STOP are numbers, COUNT a whole number");
        }
        sw = sweep_steady_motion(model, solver, options, s, spec.substr(0, eq_at), a, b, count);
        if (!request.plot.empty()) {
            try {
                plot_sweep(model, *sw, request.plot);
            } catch (const std::runtime_error& e) {
                throw ModesError(std::string("--plot: ") + e.what());
            }
        }
    } else if (!request.plot.empty()) {
        throw ModesError("--plot goes with --sweep (the eigenvalues against a parameter)");
    }

    const bool json = request.format == "json";
    std::ostringstream os;
    if (json) {
        auto named = [&](const std::vector<double>& v, const char* suffix) {
            std::string out = "{";
            for (std::size_t i = 0; i < v.size(); ++i)
                out += (i ? ", " : "") + json_string(model.coordinates[i].name + suffix) + ": " + num(v[i], 17);
            return out + "}";
        };
        os << "{\"model\": " << json_string(model.name) << ", \"steady\": [";
        for (std::size_t k = 0; k < request.steady.size(); ++k) os << (k ? ", " : "") << json_string(request.steady[k]);
        os << "], \"motion\": " << json_string(request.motion) << ", \"parameters\": {";
        for (std::size_t i = 0; i < model.parameters.size(); ++i)
            os << (i ? ", " : "") << json_string(model.parameters[i].name) << ": " << num(s.parameters[i], 17);
        os << "}, \"q\": " << named(s.q, "") << ", \"qd\": " << named(s.qd, "_dot") << ", \"multipliers\": {";
        for (std::size_t k = 0; k < s.lambda.size(); ++k)
            os << (k ? ", " : "") << json_string(eq.constraints[k].name) << ": " << num(s.lambda[k], 17);
        os << "}, \"residual\": " << num(s.residual, 6) << ", \"cyclic\": " << json_names(model, s.cyclic)
           << ", \"dependent\": " << json_names(model, s.dependent) << ", \"coordinates\": " << json_names(model, s.coordinates)
           << ", \"speeds\": " << json_names(model, s.speeds, "_dot") << ", \"ignorable\": " << json_names(model, s.ignorable)
           << ", \"second_order\": " << json_names(model, s.second_order) << ", \"A\": " << matrix(s.A, 17, true)
           << ", \"Mr\": " << matrix(s.Mr, 17, true) << ", \"Cr\": " << matrix(s.Cr, 17, true) << ", \"Kr\": " << matrix(s.Kr, 17, true)
           << ", \"decoupled\": " << (s.decoupled ? "true" : "false");
        if (s.decoupled)
            os << ", \"M\": " << matrix(s.M, 17, true) << ", \"C\": " << matrix(s.C, 17, true) << ", \"K\": " << matrix(s.K, 17, true);
        else
            os << ", \"coupling\": " << json_string(s.coupling);
        if (split) {
            os << ", \"split\": {\"speed\": " << json_string(split->speed) << ", \"value\": " << num(split->v, 17);
            if (split->C1.size()) os << ", \"C1\": " << matrix(split->C1, 17, true) << ", \"K2\": " << matrix(split->K2, 17, true)
                                     << ", \"K_rest\": " << matrix(split->K_rest, 17, true);
            if (split->K0.size()) os << ", \"gravity\": " << json_string(split->gravity) << ", \"K0\": " << matrix(split->K0, 17, true);
            os << ", \"notes\": [";
            for (std::size_t k = 0; k < split->notes.size(); ++k) os << (k ? ", " : "") << json_string(split->notes[k]);
            os << "]}";
        }
        os << ", \"eigenvalues\": [";
        for (Eigen::Index k = 0; k < s.eigenvalues.size(); ++k) os << (k ? ", " : "") << complex_json(s.eigenvalues(k));
        os << "], \"eigenvector_components\": [";
        const std::vector<std::string> comps = vector_names(model, s);
        for (std::size_t i = 0; i < comps.size(); ++i) os << (i ? ", " : "") << json_string(comps[i]);
        os << "], \"eigenvectors\": [";
        for (Eigen::Index k = 0; k < s.eigenvalues.size(); ++k) {
            const Eigen::VectorXcd v = shape(s, k);
            os << (k ? ", [" : "[");
            for (Eigen::Index i = 0; i < v.size(); ++i) os << (i ? ", " : "") << complex_json(v(i));
            os << "]";
        }
        os << "], \"stability\": " << json_string(s.stability) << ", \"growth_rate\": " << num(s.growth_rate, 17);
        if (sw) {
            os << ", \"sweep\": {\"parameter\": " << json_string(sw->name) << ", \"values\": [";
            for (std::size_t k = 0; k < sw->values.size(); ++k) os << (k ? ", " : "") << num(sw->values[k], 17);
            os << "], \"eigenvalues\": [";
            for (std::size_t k = 0; k < sw->eigenvalues.size(); ++k) {
                os << (k ? ", [" : "[");
                for (Eigen::Index j = 0; j < sw->eigenvalues[k].size(); ++j) os << (j ? ", " : "") << complex_json(sw->eigenvalues[k](j));
                os << "]";
            }
            os << "], \"changes\": [";
            for (std::size_t k = 0; k < sw->changes.size(); ++k)
                os << (k ? ", " : "") << "{\"value\": " << num(sw->changes[k].value, 17) << ", \"from\": "
                   << json_string(sw->changes[k].from) << ", \"to\": " << json_string(sw->changes[k].to) << "}";
            os << "]}";
        }
        os << "}\n";
        return os.str();
    }
    os << model.name << (model.title.empty() ? "" : ": " + model.title) << "\n";
    os << "steady motion:";
    for (const std::string& r : request.steady) os << " " << r << ";";
    if (!request.motion.empty()) os << " (the model's motion '" << request.motion << "')";
    os << " residual " << num(s.residual, 3) << "\n ";
    for (std::size_t i = 0; i < model.dof(); ++i)
        os << " " << model.coordinates[i].name
           << (std::find(s.cyclic.begin(), s.cyclic.end(), i) != s.cyclic.end() ? "_dot = " + num(clean(s.qd[i], 1), 12)
                                                                                 : " = " + num(clean(s.q[i], 1), 12))
           << ";";
    os << "\n";
    for (std::size_t k = 0; k < s.lambda.size(); ++k)
        os << "  multiplier lambda_" << eq.constraints[k].name << " = " << num(clean(s.lambda[k], 1), 12) << "\n";
    os << "cyclic (turning at constant rates, left out): " << names(model, s.cyclic) << "\n";
    os << "fixed by the holonomic constraints: " << names(model, s.dependent) << "\n";
    os << "minimal coordinates: " << names(model, s.coordinates) << "; independent speeds: " << names(model, s.speeds, "_dot") << "\n";
    if (!s.ignorable.empty()) os << "ignorable (the linear equations do not depend on them): " << names(model, s.ignorable) << "\n";
    os << "A = " << matrix(clean(s.A), 10, false) << "  (z = [" << names(model, s.coordinates) << ", " << names(model, s.speeds, "_dot") << "])\n";
    if (s.decoupled) {
        os << "\nM q'' + C q' + K q = 0, q = [" << names(model, s.second_order) << "]:\n";
        os << "  M = " << matrix(clean(s.M), 14, false) << "\n  C = " << matrix(clean(s.C), 14, false) << "\n  K = " << matrix(clean(s.K), 14, false) << "\n";
        if (!s.extra_speeds.empty())
            os << "  (" << names(model, s.extra_speeds, "_dot") << ": decoupled from them, a neutral mode)\n";
    } else if (!s.second_order.empty()) {
        os << "\nno second-order form in " << names(model, s.second_order) << ": " << s.coupling << "\n";
        os << "  Kane's form over the speeds: M_r = " << matrix(clean(s.Mr), 10, false) << "\n";
    }
    if (split) {
        if (split->C1.size()) {
            os << "\nsplit by " << split->speed << " = " << num(split->v, 12) << ": C = " << split->speed << " C1, K = "
               << (split->K0.size() ? split->gravity + " K0" : std::string("K(0)")) << " + " << split->speed << "^2 K2\n";
            os << "  C1 = " << matrix(clean(split->C1), 14, false) << "\n";
            if (split->K0.size()) os << "  K0 = " << matrix(clean(split->K0), 14, false) << "\n";
            else os << "  K(0) = " << matrix(clean(split->K_rest), 14, false) << "\n";
            os << "  K2 = " << matrix(clean(split->K2), 14, false) << "\n";
        }
        for (const std::string& note : split->notes) os << "  note: " << note << "\n";
    }
    os << "\neigenvalues:";
    for (Eigen::Index k = 0; k < s.eigenvalues.size(); ++k) os << (k ? ", " : " ") << complex_text(s.eigenvalues(k));
    const std::vector<std::string> comps = vector_names(model, s);
    for (Eigen::Index k = 0; k < s.eigenvalues.size(); ++k) {
        if (s.eigenvalues(k).imag() < 0) continue;  // its conjugate's shape is the conjugate
        const Eigen::VectorXcd v = shape(s, k);
        os << "\n  mode " << complex_text(s.eigenvalues(k)) << ": (";
        for (Eigen::Index i = 0; i < v.size() && std::size_t(i) < comps.size(); ++i)
            os << (i ? ", " : "") << comps[std::size_t(i)] << ": " << complex_text(v(i));
        os << ")";
    }
    os << "\n" << s.stability;
    if (s.stability == "unstable") os << ": perturbations grow as exp(" << num(s.growth_rate, 10) << " t)";
    os << "\n";
    if (sw) {
        os << "\nsweep of " << sw->name << ": eigenvalues (stability)\n";
        for (std::size_t k = 0; k < sw->values.size(); ++k) {
            os << "  " << sw->name << " = " << num(sw->values[k], 10) << ":";
            for (Eigen::Index j = 0; j < sw->eigenvalues[k].size(); ++j) os << (j ? ", " : " ") << complex_text(sw->eigenvalues[k](j));
            os << "  (" << sw->stability[k] << ")\n";
        }
        if (sw->changes.empty()) os << "no change of stability on the sweep\n";
        for (const SteadySweep::Change& c : sw->changes)
            os << "stability changes at " << sw->name << " = " << num(c.value, 16) << ": " << c.from << " -> " << c.to << "\n";
    }
    return os.str();
}

}  // namespace eomgen::cli
