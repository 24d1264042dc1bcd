/** @file fit_solve.cpp  The least-squares problem of `eomgen fit` (fit_solve.hpp), solved with Ceres. */
#include "cli/fit_solve.hpp"

#include "eomgen/sensitivity_run.hpp"

#include "eomgen/errors.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/model_jacobian.hpp"
#include "eomgen/radau5.hpp"

#include <Eigen/SVD>
#include <ceres/ceres.h>

#include <cctype>
#include <cmath>
#include <memory>
#include <set>
#include <sstream>
#include <utility>

namespace eomgen::cli {

namespace {

using sim::UsageError;

/// A number of --free, with the option in the message when it cannot be read.
double number(const std::string& text, const std::string& spec) {
    try {
        return sim::parse_value(text);
    } catch (const UsageError& e) {
        throw UsageError("--free " + spec + ": " + e.what());
    }
}

/// The loss of each residual, ½ρ(r²) (Ceres' functions), handed to Ceres as the residual sign(r) sqrt(ρ(r²)), whose
/// half square is that cost, with the Jacobian row d/dθ = ρ'(r²) r / sqrt(ρ(r²)) dr/dθ: Ceres' own loss would apply
/// to the norm of a whole residual block, here a whole experiment.
/// Ceres' loss function of that name at scale a (in r's units), null for another name (squared among them).
std::unique_ptr<ceres::LossFunction> ceres_loss(const std::string& name, double a) {
    if (name == "huber") return std::make_unique<ceres::HuberLoss>(a);
    if (name == "soft_l1") return std::make_unique<ceres::SoftLOneLoss>(a);
    if (name == "cauchy") return std::make_unique<ceres::CauchyLoss>(a);
    if (name == "arctan") return std::make_unique<ceres::ArctanLoss>(a * a);  // its a is in r²'s units
    if (name == "tukey") return std::make_unique<ceres::TukeyLoss>(a);
    return nullptr;
}

class Robust {
  public:
    explicit Robust(const FitLoss& loss) : f_(ceres_loss(loss.name, loss.scale)) {}

    /// ρ, ρ', ρ'' at s = r² (s, 1, 0 for least squares).
    void rho(double s, double out[3]) const {
        if (f_) {
            f_->Evaluate(s, out);
        } else {
            out[0] = s;
            out[1] = 1;
            out[2] = 0;
        }
    }

    /// The residual Ceres sees in place of r, and the factor of r's Jacobian row that gives its row.
    double residual(double r, double& factor) const {
        factor = 1;
        if (!f_) return r;
        double p[3];
        f_->Evaluate(r * r, p);
        if (r == 0 || p[0] <= 0) {
            factor = std::sqrt(std::max(p[1], 0.0));
            return 0;
        }
        const double root = std::sqrt(p[0]);
        factor = p[1] * std::abs(r) / root;
        return r > 0 ? root : -root;
    }

  private:
    std::unique_ptr<ceres::LossFunction> f_;
};

/// The trajectory and its sensitivities at the data's times, by the run's method; false (with the message) when the
/// integration fails at these values (Ceres then tries a shorter step).
bool trajectory(const sim::Options& o, const TableModel::Params& p, const TableModel::State& x0,
                const std::vector<SensitivityColumn>& columns, const std::vector<double>& times, SensitivityResult& r,
                std::string& why) {
    try {
        r = sim::integrate_sensitivities_by<TableModel>(o, p, x0, times.back(), columns, {}, times);
    } catch (const SimulationError& e) {
        why = e.what();
        return false;
    }
    return r.samples.size() == times.size();
}

/// What both costs of one experiment hold: the run's options and fixed values, every unknown and which of them
/// this experiment sees, its data and weights, and the count of integrations.
struct Series {
    const sim::Options& o;
    const TableModel::Params& p;
    const TableModel::State& x0;
    const std::vector<FreeValue>& free;
    const MeasuredSeries& data;
    Eigen::VectorXd w;
    const Robust& loss;
    std::size_t* count;
    std::vector<std::size_t> mine;  ///< indices into `free`: the parameters and this experiment's initial values

    Series(const sim::Options& o, const ExperimentStart& start, const std::vector<FreeValue>& free,
           const MeasuredSeries& data, Eigen::VectorXd w, const Robust& loss, std::size_t* count, int experiment)
        : o(o), p(start.params), x0(start.x0), free(free), data(data), w(std::move(w)), loss(loss), count(count) {
        for (std::size_t i = 0; i < free.size(); ++i)
            if (free[i].experiment < 0 || free[i].experiment == experiment) mine.push_back(i);
    }

    /// The parameters and initial state at the unknowns θ, counting one integration. A constrained model's start is
    /// projected onto its constraints (as --project-initial does: a free initial value or a parameter the
    /// constraints contain moves the consistent start, which is what the sensitivities differentiate); false, with
    /// the message, where the projection fails.
    bool at(const double* theta, TableModel::Params& params, TableModel::State& start, std::string& why) const {
        params = p;
        start = x0;
        for (std::size_t i : mine) {
            const SensitivityColumn& c = free[i].column;
            if (c.kind == SensitivityColumn::Kind::Parameter)
                TableModel::set_param(params, TableModel::param_names[std::size_t(c.index)], theta[i]);
            else
                start(c.index) = theta[i];
        }
        ++*count;
        if (constraint_count<TableModel>() == 0) return true;
        try {
            project_onto_constraints<TableModel>(0.0, start, params);
        } catch (const SimulationError& e) {
            why = e.what();
            return false;
        }
        return true;
    }
};

/// r = w (x(t_j) − y_j) over one experiment's samples and measured columns, J = w S in the columns of its unknowns
/// (0 in the other experiments' initial values): Ceres' cost of one whole series. With a robust loss Ceres gets
/// each r and its row through Robust.
class SeriesCost : public ceres::CostFunction {
  public:
    explicit SeriesCost(Series s) : s_(std::move(s)) {
        for (std::size_t i : s_.mine) columns_.push_back(s_.free[i].column);
        set_num_residuals(int(s_.data.y.size()));
        mutable_parameter_block_sizes()->push_back(int(s_.free.size()));
    }

    bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
        TableModel::Params p;
        TableModel::State x0;
        if (!s_.at(parameters[0], p, x0, last_failure_)) return false;
        const MeasuredSeries& data = s_.data;
        SensitivityResult r;
        if (!trajectory(s_.o, p, x0, columns_, data.t, r, last_failure_)) return false;
        const Eigen::Index m = data.y.cols(), k = Eigen::Index(s_.free.size());
        for (Eigen::Index j = 0; j < data.y.rows(); ++j)
            for (Eigen::Index c = 0; c < m; ++c) {
                // A state's value and row of S, or an output's and its row of Yx S + Yp.
                const SensitivitySample& sample = r.samples[std::size_t(j)];
                const Eigen::Index nx = sample.x.size(), s = data.index[std::size_t(c)];
                const bool state = s < nx;
                const Eigen::Index row = j * m + c;
                double factor = 1;
                const double r = s_.w(c) * ((state ? sample.x(s) : sample.y(s - nx)) - data.y(j, c));
                residuals[row] = s_.loss.residual(r, factor);
                if (jacobians && jacobians[0]) {
                    for (Eigen::Index i = 0; i < k; ++i) jacobians[0][row * k + i] = 0;
                    for (std::size_t i = 0; i < s_.mine.size(); ++i)
                        jacobians[0][row * k + Eigen::Index(s_.mine[i])] =
                            factor * s_.w(c) * (state ? sample.S(s, Eigen::Index(i)) : sample.Y(s - nx, Eigen::Index(i)));
                }
            }
        return true;
    }

    const std::string& last_failure() const { return last_failure_; }

  private:
    Series s_;
    std::vector<SensitivityColumn> columns_;
    mutable std::string last_failure_;
};

/// The residuals alone (the trajectory without sensitivities), for Ceres' central differences.
class SeriesResiduals {
  public:
    explicit SeriesResiduals(Series s) : s_(std::move(s)) {}

    bool operator()(double const* const* parameters, double* residuals) const {
        TableModel::Params p;
        TableModel::State x0;
        std::string why;
        if (!s_.at(parameters[0], p, x0, why)) return false;
        const MeasuredSeries& data = s_.data;
        const auto f = [&p](const double& t, const TableModel::State& x, TableModel::State& xdot) {
            TableModel::rhs(t, x, p, xdot);
        };
        const sim::Options& o = s_.o;
        IntegrationResult<TableModel::State> r;
        try {
            if (o.method == "radau5") {
                Radau5Options<double> opt;
                opt.rtol = o.rtol;
                opt.atol = o.atol;
                opt.max_steps = o.max_steps;
                const auto jac = [&p](const double& t, const TableModel::State& x, Eigen::MatrixXd& J) {
                    model_jacobian<TableModel>(t, x, p, J);
                };
                r = integrate_radau5(f, jac, 0.0, x0, data.t.back(), opt, {}, data.t);
            } else {
                sim::with_adaptive_method(o.method, [&](auto method) {
                    using Method = decltype(method);
                    r = integrate_with<Method::template type>(f, 0.0, x0, data.t.back(),
                                                              Method::template options<TableModel::State>(o), {}, data.t);
                });
            }
        } catch (const SimulationError&) {
            return false;
        }
        if (r.samples.size() != data.t.size()) return false;
        const Eigen::Index m = data.y.cols();
        for (Eigen::Index j = 0; j < data.y.rows(); ++j) {
            const auto& sample = r.samples[std::size_t(j)];
            const Eigen::Index nx = sample.x.size();
            TableModel::Outputs y;
            if (TableModel::n_outputs > 0)
                TableModel::outputs(sample.t, sample.x.head(nx / 2), sample.x.tail(nx / 2), p, y);
            for (Eigen::Index c = 0; c < m; ++c) {
                const Eigen::Index s = data.index[std::size_t(c)];
                double factor;
                residuals[j * m + c] = s_.loss.residual(s_.w(c) * ((s < nx ? sample.x(s) : y(s - nx)) - data.y(j, c)), factor);
            }
        }
        return true;
    }

  private:
    Series s_;
};

}  // namespace

FitLoss parse_loss(const std::string& spec) {
    FitLoss loss;
    const std::size_t colon = spec.find(':');
    loss.name = spec.substr(0, colon);
    if (loss.name == "squared") {
        if (colon != std::string::npos) throw UsageError("--loss " + spec + ": squared (least squares) has no scale");
        return loss;
    }
    if (!ceres_loss(loss.name, 1))
        throw UsageError("--loss " + spec + ": expected squared, or huber, soft_l1, cauchy, arctan or tukey with a scale "
                         "(huber:0.03: residuals larger than 0.03, in the data's units after --weight, count less)");
    if (colon == std::string::npos)
        throw UsageError("--loss " + spec + ": give the scale, " + loss.name +
                         ":S, in the residuals' units after --weight (two or three times the noise)");
    try {
        loss.scale = sim::parse_value(spec.substr(colon + 1));
    } catch (const UsageError& e) {
        throw UsageError("--loss " + spec + ": " + e.what());
    }
    if (!(loss.scale > 0) || !std::isfinite(loss.scale))
        throw UsageError("--loss " + spec + ": the scale must be a positive number");
    return loss;
}

std::string experiment_prefix(const std::string& spec, std::size_t experiments, const std::string& option,
                              int& experiment) {
    experiment = -1;
    std::size_t digits = 0;
    while (digits < spec.size() && std::isdigit(static_cast<unsigned char>(spec[digits]))) ++digits;
    if (digits == 0 || digits >= spec.size() || spec[digits] != ':') return spec;
    const std::string number = spec.substr(0, digits);
    const std::size_t k = number.size() > 6 ? 0 : std::size_t(std::stoul(number));
    if (k < 1 || k > experiments)
        throw UsageError(option + " " + spec + ": there is no experiment " + number + " (K: is the place of a data " +
                         "file, from 1; there " +
                         (experiments == 1 ? "is 1 data file" : "are " + std::to_string(experiments) + " data files") + ")");
    experiment = int(k) - 1;
    return spec.substr(digits + 1);
}

std::vector<FreeValue> parse_free(const std::vector<std::string>& specs, const std::vector<ExperimentStart>& starts) {
    struct Given {
        FreeValue value;
        int own = -1;            ///< K:… — the experiment (from 0) whose own unknown it is; -1: every experiment's
        bool has_start = false;  ///< =start given
    };
    std::vector<Given> given;
    std::set<std::string> seen;
    const std::size_t experiments = starts.size();
    for (const std::string& whole : specs) {
        // [K:]NAME or [K:]x0:NAME, then =start, then :lo:hi.
        Given g;
        const std::string spec = experiment_prefix(whole, experiments, "--free", g.own);
        const ExperimentStart& at = starts.at(g.own < 0 ? 0 : std::size_t(g.own));
        const bool initial = spec.rfind("x0:", 0) == 0;
        const std::size_t from = initial ? 3 : 0;
        const std::size_t end = spec.find_first_of("=:", from);
        FreeValue& f = g.value;
        f.name = spec.substr(0, end);
        const std::string bare = f.name.substr(from);
        if (bare.empty())
            throw UsageError("--free " + whole + ": expected [K:]NAME[=start][:lo:hi] or [K:]x0:STATE[=start][:lo:hi]");
        // One unknown per value: `c` (every experiment's) and `2:c` would be two for experiment 2's c.
        const std::string key = (g.own < 0 ? std::string() : std::to_string(g.own + 1) + ":") + f.name;
        if (!seen.insert(key).second) throw UsageError("--free " + key + ": given twice");
        if (g.own >= 0 && seen.count(f.name))
            throw UsageError("--free " + whole + ": " + f.name + " is already free for every experiment (--free " +
                             f.name + "); free it for each experiment (K:" + f.name + ") or for all, not both");
        if (g.own < 0)
            for (std::size_t e = 1; e <= experiments; ++e)
                if (seen.count(std::to_string(e) + ":" + f.name))
                    throw UsageError("--free " + whole + ": " + f.name + " is already free for experiment " +
                                     std::to_string(e) + " (--free " + std::to_string(e) + ":" + f.name +
                                     "); free it for each experiment (K:" + f.name + ") or for all, not both");
        if (initial) {
            const int i = sim::index_of(TableModel::state_names, bare);
            if (i < 0)
                throw UsageError("--free " + whole + ": no state '" + bare + "'" +
                                 sim::did_you_mean(bare, TableModel::state_names) + " (states: " +
                                 sim::list(TableModel::state_names) + ")");
            f.column = {SensitivityColumn::Kind::InitialValue, i};
            f.start = at.x0(i);
        } else {
            const int i = sim::index_of(TableModel::param_names, bare);
            if (i < 0)
                throw UsageError("--free " + whole + ": " + std::string(TableModel::name) + " has no parameter '" + bare +
                                 "'" + sim::did_you_mean(bare, TableModel::param_names) + " (it has " +
                                 sim::list(TableModel::param_names) + "; an initial value is x0:NAME)");
            f.column = {SensitivityColumn::Kind::Parameter, i};
            f.start = TableModel::param_values(at.params)[std::size_t(i)];
        }
        std::string rest = end == std::string::npos ? "" : spec.substr(end);
        if (!rest.empty() && rest[0] == '=') {
            const std::size_t colon = rest.find(':');
            f.start = number(rest.substr(1, colon == std::string::npos ? std::string::npos : colon - 1), whole);
            rest = colon == std::string::npos ? "" : rest.substr(colon);
            g.has_start = true;
        }
        if (!rest.empty()) {
            const std::size_t second = rest.find(':', 1);
            if (rest[0] != ':' || second == std::string::npos)
                throw UsageError("--free " + whole + ": bounds are :lo:hi, e.g. " + bare + "=1:0.5:2");
            f.lower = number(rest.substr(1, second - 1), whole);
            f.upper = number(rest.substr(second + 1), whole);
            if (!(f.lower < f.upper)) throw UsageError("--free " + whole + ": the lower bound must be below the upper");
            if (f.start < f.lower || f.start > f.upper)
                throw UsageError("--free " + whole + ": the start " + std::to_string(f.start) + " is outside [" +
                                 std::to_string(f.lower) + ", " + std::to_string(f.upper) + "]");
        }
        given.push_back(g);
    }
    if (given.empty()) throw UsageError("give the unknowns with --free NAME (a parameter) or --free x0:STATE");
    // The parameters every experiment shares first; then, experiment by experiment, its own parameters and its
    // initial values (an x0:STATE without K: is one unknown in each experiment, named x0:STATE[e] among several).
    std::vector<FreeValue> unknowns;
    for (const Given& g : given)
        if (g.value.column.kind == SensitivityColumn::Kind::Parameter && g.own < 0) {
            FreeValue f = g.value;
            f.experiment = -1;
            unknowns.push_back(f);
        }
    for (std::size_t e = 0; e < experiments; ++e)
        for (const SensitivityColumn::Kind kind : {SensitivityColumn::Kind::Parameter, SensitivityColumn::Kind::InitialValue})
            for (const Given& g : given) {
                if (g.value.column.kind != kind || (g.own >= 0 && g.own != int(e))) continue;
                if (kind == SensitivityColumn::Kind::Parameter && g.own < 0) continue;  // shared: above
                FreeValue f = g.value;
                if (experiments > 1) f.name += "[" + std::to_string(e + 1) + "]";
                if (kind == SensitivityColumn::Kind::InitialValue && g.own < 0 && !g.has_start) {
                    // No =start: where this experiment's --init puts it.
                    f.start = starts[e].x0(f.column.index);
                    if (f.start < f.lower || f.start > f.upper) {
                        std::ostringstream os;
                        os << "--free " << f.name << ": experiment " << e + 1 << " starts at " << f.start
                           << ", outside [" << f.lower << ", " << f.upper << "] (give its start, or --init " << e + 1
                           << ":" << TableModel::state_names[std::size_t(f.column.index)] << "=...)";
                        throw UsageError(os.str());
                    }
                }
                f.experiment = int(e);
                unknowns.push_back(f);
            }
    return unknowns;
}

FitOutcome fit(const sim::Options& options, const std::vector<ExperimentStart>& starts,
               const std::vector<FreeValue>& free, const std::vector<MeasuredSeries>& data,
               const std::map<std::string, double>& weights, std::size_t max_iterations, const FitLoss& loss,
               FitJacobian jacobian) {
    const std::size_t k = free.size();
    std::size_t n = 0;
    for (const MeasuredSeries& d : data) n += std::size_t(d.y.size());
    if (n <= k)
        throw UsageError("the data give " + std::to_string(n) + " measurements for " + std::to_string(k) +
                         " unknowns: a fit needs more measurements than unknowns");
    if (!sim::is_adaptive_method(options.method) && options.method != "radau5")
        throw UsageError("eomgen fit needs a method with error control (dopri5, dop853, adams or radau5), not " +
                         options.method);
    std::vector<Eigen::VectorXd> w;
    for (const MeasuredSeries& d : data) w.push_back(Eigen::VectorXd::Ones(d.y.cols()));
    for (const auto& [name, value] : weights) {
        if (!(value > 0) || !std::isfinite(value)) throw UsageError("--weight " + name + ": must be a positive number");
        bool found = false;
        for (std::size_t e = 0; e < data.size(); ++e)
            for (std::size_t c = 0; c < data[e].names.size(); ++c)
                if (data[e].names[c] == name) {
                    w[e](Eigen::Index(c)) = value;
                    found = true;
                }
        if (!found) throw UsageError("--weight " + name + ": no measured column '" + name + "' in the data");
    }
    // What integrate_sensitivities refuses is said before Ceres starts.
    for (std::size_t e = 0; e < data.size(); ++e) {
        std::vector<SensitivityColumn> columns;
        for (const FreeValue& f : free)
            if (f.experiment < 0 || f.experiment == int(e)) columns.push_back(f.column);
        try {
            check_sensitivity_columns<TableModel>(0.0, starts[e].x0, starts[e].params, columns);
        } catch (const std::invalid_argument& err) {
            throw UsageError(std::string("--free: ") + err.what());
        }
    }
    // A bounded loss (arctan, tukey) is flat where every residual is beyond its scale, as from a poor start: it
    // starts where Huber's loss of the same scale ends.
    const bool bounded = loss.name == "arctan" || loss.name == "tukey";
    Robust robust(bounded ? FitLoss{"huber", loss.scale} : loss);

    std::vector<double> theta;
    for (const FreeValue& f : free) theta.push_back(f.start);
    // The exact costs also give J at the solution for the statistics, whichever Jacobian the solver used.
    std::size_t integrations = 0;
    std::vector<std::unique_ptr<SeriesCost>> exact;
    std::vector<std::unique_ptr<ceres::CostFunction>> differences;
    ceres::Problem::Options po;
    po.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem problem(po);
    for (std::size_t e = 0; e < data.size(); ++e) {
        const Series series(options, starts[e], free, data[e], w[e], robust, &integrations, int(e));
        exact.push_back(std::make_unique<SeriesCost>(series));
        ceres::CostFunction* cost = exact.back().get();
        if (jacobian == FitJacobian::Differences) {
            auto* numeric =
                new ceres::DynamicNumericDiffCostFunction<SeriesResiduals, ceres::CENTRAL>(new SeriesResiduals(series));
            numeric->AddParameterBlock(int(k));
            numeric->SetNumResiduals(int(data[e].y.size()));
            differences.emplace_back(numeric);
            cost = numeric;
        }
        problem.AddResidualBlock(cost, nullptr, theta.data());
    }
    for (std::size_t i = 0; i < k; ++i) {
        if (std::isfinite(free[i].lower)) problem.SetParameterLowerBound(theta.data(), int(i), free[i].lower);
        if (std::isfinite(free[i].upper)) problem.SetParameterUpperBound(theta.data(), int(i), free[i].upper);
    }
    ceres::Solver::Options so;
    so.minimizer_type = ceres::TRUST_REGION;
    so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
    so.linear_solver_type = ceres::DENSE_QR;
    so.max_num_iterations = int(max_iterations);
    so.function_tolerance = 1e-12;
    so.gradient_tolerance = 1e-12;
    so.parameter_tolerance = 1e-12;
    so.logging_type = ceres::SILENT;
    so.minimizer_progress_to_stdout = false;
    ceres::Solver::Summary summary;
    ceres::Solve(so, &problem, &summary);
    std::size_t iterations = summary.iterations.size() > 0 ? summary.iterations.size() - 1 : 0;
    double seconds = summary.total_time_in_seconds;
    if (bounded) {
        robust = Robust(loss);
        ceres::Solve(so, &problem, &summary);
        iterations += summary.iterations.size() > 0 ? summary.iterations.size() - 1 : 0;
        seconds += summary.total_time_in_seconds;
    }

    FitOutcome out;
    out.estimate = theta;
    out.iterations = iterations;
    out.converged = summary.termination_type == ceres::CONVERGENCE;
    out.termination = summary.message;
    out.residuals = n;
    out.trajectories = integrations;
    out.solve_seconds = seconds;

    // J and r at the solution, the experiments' rows one after another; the fitted trajectories (unweighted). The
    // costs evaluate them as they are (least squares in place of the loss they were solved with).
    robust = Robust(FitLoss{});
    const Robust chosen(loss);
    Eigen::VectorXd r(static_cast<Eigen::Index>(n));
    Eigen::MatrixXd J(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(k));
    Eigen::Index row = 0;
    for (std::size_t e = 0; e < data.size(); ++e) {
        const Eigen::Index rows = data[e].y.size();
        Eigen::VectorXd re(rows);
        Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> Je(rows, Eigen::Index(k));
        const double* blocks[] = {theta.data()};
        double* jac[] = {Je.data()};
        if (!exact[e]->Evaluate(blocks, re.data(), jac))
            throw SimulationError("the model cannot be integrated at the fit's estimates: " + exact[e]->last_failure(), 0);
        r.segment(row, rows) = re;
        J.middleRows(row, rows) = Je;
        row += rows;
        const MeasuredSeries& d = data[e];
        Eigen::MatrixXd model(d.y.rows(), d.y.cols());
        for (Eigen::Index j = 0; j < d.y.rows(); ++j)
            for (Eigen::Index c = 0; c < d.y.cols(); ++c) model(j, c) = re(j * d.y.cols() + c) / w[e](c) + d.y(j, c);
        out.model.push_back(std::move(model));
    }
    const double rss = r.squaredNorm();
    out.rms = std::sqrt(rss / double(n));
    out.residual_sigma = std::sqrt(rss / double(n - k));
    if (loss.name != "squared") {
        // Huber's covariance of an M-estimator (Robust Statistics, 1981, 7.6): K² Σψ²/(n − k) / (mean ψ')² (JᵀJ)⁻¹,
        // ψ(r) = ρ'(r²) r, ψ'(r) = ρ'(r²) + 2 r² ρ''(r²), K = 1 + (k/n) var ψ' / (mean ψ')²; least squares
        // (ψ = r) gives s² (JᵀJ)⁻¹.
        double psi2 = 0, dpsi = 0, dpsi2 = 0;
        for (Eigen::Index i = 0; i < r.size(); ++i) {
            double p[3];
            chosen.rho(r(i) * r(i), p);
            const double psi = p[1] * r(i), d = p[1] + 2 * r(i) * r(i) * p[2];
            psi2 += psi * psi;
            dpsi += d;
            dpsi2 += d * d;
            if (std::abs(r(i)) > loss.scale) ++out.beyond_scale;
        }
        const double mean = dpsi / double(n), var = std::max(dpsi2 / double(n) - mean * mean, 0.0);
        if (mean > 0) {
            const double K = 1 + double(k) / double(n) * var / (mean * mean);
            out.residual_sigma = K * std::sqrt(psi2 / double(n - k)) / mean;
        } else {
            out.residual_sigma = std::numeric_limits<double>::quiet_NaN();
            out.caveat = "no standard errors: the residuals lie where the " + loss.name +
                         " loss bends down (its mean curvature is not positive); a larger scale";
        }
    }

    // Relative sensitivities: J's columns times |θ| (1 where θ = 0), so that the rank test does not depend on units.
    Eigen::VectorXd scale(static_cast<Eigen::Index>(k));
    for (std::size_t i = 0; i < k; ++i) scale(Eigen::Index(i)) = theta[i] != 0 ? std::abs(theta[i]) : 1.0;
    const Eigen::MatrixXd Js = J * scale.asDiagonal();
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Js, Eigen::ComputeThinU | Eigen::ComputeThinV);
    out.singular_values = svd.singularValues();
    const double largest = out.singular_values.size() ? out.singular_values(0) : 0;
    // Below 1e-7 of the largest: what the integration's own error (rtol 1e-10) cannot tell from 0.
    const double cutoff = 1e-7 * largest;
    Eigen::MatrixXd inverse_s = Eigen::MatrixXd::Zero(Eigen::Index(k), Eigen::Index(k));  // (Jsᵀ Js)⁺
    std::vector<bool> determined(k, true);
    for (Eigen::Index i = 0; i < Eigen::Index(k); ++i) {
        const double sigma = out.singular_values(i);
        const Eigen::VectorXd v = svd.matrixV().col(i);
        if (sigma > cutoff && largest > 0) {
            inverse_s += v * v.transpose() / (sigma * sigma);
        } else {
            out.undetermined.push_back(v);
            for (Eigen::Index a = 0; a < Eigen::Index(k); ++a)
                if (std::abs(v(a)) > 1e-3) determined[std::size_t(a)] = false;
        }
    }
    const Eigen::MatrixXd covariance =
        out.residual_sigma * out.residual_sigma * (scale.asDiagonal() * inverse_s * scale.asDiagonal());
    const double nan = std::numeric_limits<double>::quiet_NaN();
    out.standard_error.assign(k, nan);
    out.correlation = Eigen::MatrixXd::Constant(Eigen::Index(k), Eigen::Index(k), nan);
    for (std::size_t a = 0; a < k; ++a) {
        if (!determined[a]) continue;
        out.standard_error[a] = std::sqrt(covariance(Eigen::Index(a), Eigen::Index(a)));
        for (std::size_t b = 0; b < k; ++b)
            if (determined[b])
                out.correlation(Eigen::Index(a), Eigen::Index(b)) =
                    covariance(Eigen::Index(a), Eigen::Index(b)) /
                    std::sqrt(covariance(Eigen::Index(a), Eigen::Index(a)) * covariance(Eigen::Index(b), Eigen::Index(b)));
    }
    return out;
}

}  // namespace eomgen::cli
