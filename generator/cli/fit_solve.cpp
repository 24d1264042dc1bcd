/** @file fit_solve.cpp  The least-squares problem of `eomgen fit` (fit_solve.hpp), solved with Ceres. */
#include "cli/fit_solve.hpp"

#include "eomgen/sensitivity_run.hpp"

#include "eomgen/errors.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/model_jacobian.hpp"
#include "eomgen/radau5.hpp"

#include <Eigen/SVD>
#include <ceres/ceres.h>

#include <cmath>
#include <memory>
#include <set>
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

/// The unknowns θ applied to the run's parameters and initial state.
void apply(const std::vector<FreeValue>& free, const double* theta, TableModel::Params& p, TableModel::State& x0) {
    for (std::size_t k = 0; k < free.size(); ++k) {
        const SensitivityColumn& c = free[k].column;
        if (c.kind == SensitivityColumn::Kind::Parameter)
            TableModel::set_param(p, TableModel::param_names[std::size_t(c.index)], theta[k]);
        else
            x0(c.index) = theta[k];
    }
}

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

/// What both costs of the series hold: the run's options and fixed values, the unknowns, the data, the weights, and
/// the count of integrations.
struct Series {
    const sim::Options& o;
    const TableModel::Params& p;
    const TableModel::State& x0;
    const std::vector<FreeValue>& free;
    const MeasuredSeries& data;
    Eigen::VectorXd w;
    std::size_t* count;

    /// The parameters and initial state at the unknowns θ, counting one integration.
    void at(const double* theta, TableModel::Params& params, TableModel::State& start) const {
        params = p;
        start = x0;
        apply(free, theta, params, start);
        ++*count;
    }
};

/// r = w (x(t_j) − y_j) over the samples and measured columns, J = w S: Ceres' cost of the whole series.
class SeriesCost : public ceres::CostFunction {
  public:
    explicit SeriesCost(Series s) : s_(std::move(s)) {
        for (const FreeValue& f : s_.free) columns_.push_back(f.column);
        set_num_residuals(int(s_.data.y.size()));
        mutable_parameter_block_sizes()->push_back(int(s_.free.size()));
    }

    bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
        TableModel::Params p;
        TableModel::State x0;
        s_.at(parameters[0], p, x0);
        const sim::Options& o_ = s_.o;
        const MeasuredSeries& data_ = s_.data;
        const Eigen::VectorXd& w_ = s_.w;
        SensitivityResult r;
        if (!trajectory(o_, p, x0, columns_, data_.t, r, last_failure_)) return false;
        const Eigen::Index m = data_.y.cols(), k = Eigen::Index(s_.free.size());
        for (Eigen::Index j = 0; j < data_.y.rows(); ++j)
            for (Eigen::Index c = 0; c < m; ++c) {
                const int s = data_.state_index[std::size_t(c)];
                const Eigen::Index row = j * m + c;
                residuals[row] = w_(c) * (r.samples[std::size_t(j)].x(s) - data_.y(j, c));
                if (jacobians && jacobians[0])
                    for (Eigen::Index i = 0; i < k; ++i)
                        jacobians[0][row * k + i] = w_(c) * r.samples[std::size_t(j)].S(s, i);
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
        s_.at(parameters[0], p, x0);
        const sim::Options& o_ = s_.o;
        const MeasuredSeries& data_ = s_.data;
        const Eigen::VectorXd& w_ = s_.w;
        const auto f = [&p](const double& t, const TableModel::State& x, TableModel::State& xdot) {
            TableModel::rhs(t, x, p, xdot);
        };
        IntegrationResult<TableModel::State> r;
        try {
            if (o_.method == "radau5") {
                Radau5Options<double> opt;
                opt.rtol = o_.rtol;
                opt.atol = o_.atol;
                opt.max_steps = o_.max_steps;
                const auto jac = [&p](const double& t, const TableModel::State& x, Eigen::MatrixXd& J) {
                    model_jacobian<TableModel>(t, x, p, J);
                };
                r = integrate_radau5(f, jac, 0.0, x0, data_.t.back(), opt, {}, data_.t);
            } else {
                sim::with_adaptive_method(o_.method, [&](auto method) {
                    using Method = decltype(method);
                    r = integrate_with<Method::template type>(f, 0.0, x0, data_.t.back(),
                                                              Method::template options<TableModel::State>(o_), {}, data_.t);
                });
            }
        } catch (const SimulationError&) {
            return false;
        }
        if (r.samples.size() != data_.t.size()) return false;
        const Eigen::Index m = data_.y.cols();
        for (Eigen::Index j = 0; j < data_.y.rows(); ++j)
            for (Eigen::Index c = 0; c < m; ++c)
                residuals[j * m + c] =
                    w_(c) * (r.samples[std::size_t(j)].x(data_.state_index[std::size_t(c)]) - data_.y(j, c));
        return true;
    }

  private:
    Series s_;
};

}  // namespace

std::vector<FreeValue> parse_free(const std::vector<std::string>& specs, const TableModel::Params& params,
                                  const TableModel::State& x0) {
    std::vector<FreeValue> free;
    std::set<std::string> seen;
    const auto values = TableModel::param_values(params);
    for (const std::string& spec : specs) {
        // NAME or x0:NAME, then =start, then :lo:hi.
        const bool initial = spec.rfind("x0:", 0) == 0;
        const std::size_t from = initial ? 3 : 0;
        const std::size_t end = spec.find_first_of("=:", from);
        FreeValue f;
        f.name = spec.substr(0, end);
        const std::string bare = f.name.substr(from);
        if (bare.empty()) throw UsageError("--free " + spec + ": expected NAME[=start][:lo:hi] or x0:STATE[=start][:lo:hi]");
        if (!seen.insert(f.name).second) throw UsageError("--free " + f.name + ": given twice");
        if (initial) {
            const int i = sim::index_of(TableModel::state_names, bare);
            if (i < 0)
                throw UsageError("--free " + spec + ": no state '" + bare + "'" +
                                 sim::did_you_mean(bare, TableModel::state_names) + " (states: " +
                                 sim::list(TableModel::state_names) + ")");
            f.column = {SensitivityColumn::Kind::InitialValue, i};
            f.start = x0(i);
        } else {
            const int i = sim::index_of(TableModel::param_names, bare);
            if (i < 0)
                throw UsageError("--free " + spec + ": " + std::string(TableModel::name) + " has no parameter '" + bare +
                                 "'" + sim::did_you_mean(bare, TableModel::param_names) + " (it has " +
                                 sim::list(TableModel::param_names) + "; an initial value is x0:NAME)");
            f.column = {SensitivityColumn::Kind::Parameter, i};
            f.start = values[std::size_t(i)];
        }
        std::string rest = end == std::string::npos ? "" : spec.substr(end);
        if (!rest.empty() && rest[0] == '=') {
            const std::size_t colon = rest.find(':');
            f.start = number(rest.substr(1, colon == std::string::npos ? std::string::npos : colon - 1), spec);
            rest = colon == std::string::npos ? "" : rest.substr(colon);
        }
        if (!rest.empty()) {
            const std::size_t second = rest.find(':', 1);
            if (rest[0] != ':' || second == std::string::npos)
                throw UsageError("--free " + spec + ": bounds are :lo:hi, e.g. " + bare + "=1:0.5:2");
            f.lower = number(rest.substr(1, second - 1), spec);
            f.upper = number(rest.substr(second + 1), spec);
            if (!(f.lower < f.upper)) throw UsageError("--free " + spec + ": the lower bound must be below the upper");
            if (f.start < f.lower || f.start > f.upper)
                throw UsageError("--free " + spec + ": the start " + std::to_string(f.start) + " is outside [" +
                                 std::to_string(f.lower) + ", " + std::to_string(f.upper) + "]");
        }
        free.push_back(f);
    }
    if (free.empty()) throw UsageError("give the unknowns with --free NAME (a parameter) or --free x0:STATE");
    return free;
}

FitOutcome fit(const sim::Options& options, const TableModel::Params& params, const TableModel::State& x0,
               const std::vector<FreeValue>& free, const MeasuredSeries& data,
               const std::map<std::string, double>& weights, std::size_t max_iterations, FitJacobian jacobian) {
    const std::size_t k = free.size(), n = std::size_t(data.y.size());
    if (n <= k)
        throw UsageError("the data give " + std::to_string(n) + " measurements for " + std::to_string(k) +
                         " unknowns: a fit needs more measurements than unknowns");
    if (!sim::is_adaptive_method(options.method) && options.method != "radau5")
        throw UsageError("eomgen fit needs a method with error control (dopri5, dop853, adams or radau5), not " +
                         options.method);
    Eigen::VectorXd w = Eigen::VectorXd::Ones(data.y.cols());
    for (const auto& [name, value] : weights) {
        std::size_t c = 0;
        while (c < data.names.size() && data.names[c] != name) ++c;
        if (c == data.names.size())
            throw UsageError("--weight " + name + ": no measured column '" + name + "' in " + data.path);
        if (!(value > 0) || !std::isfinite(value)) throw UsageError("--weight " + name + ": must be a positive number");
        w(Eigen::Index(c)) = value;
    }
    // What integrate_sensitivities refuses is said before Ceres starts.
    {
        std::vector<SensitivityColumn> columns;
        for (const FreeValue& f : free) columns.push_back(f.column);
        try {
            check_sensitivity_columns<TableModel>(0.0, x0, params, columns);
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("--free: ") + e.what());
        }
    }

    std::vector<double> theta;
    for (const FreeValue& f : free) theta.push_back(f.start);
    // The exact cost also gives J at the solution for the statistics, whichever Jacobian the solver used.
    std::size_t integrations = 0;
    const Series series{options, params, x0, free, data, w, &integrations};
    SeriesCost exact(series);
    ceres::Problem::Options po;
    po.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem problem(po);
    std::unique_ptr<ceres::CostFunction> differences;
    if (jacobian == FitJacobian::Differences) {
        auto* numeric = new ceres::DynamicNumericDiffCostFunction<SeriesResiduals, ceres::CENTRAL>(
            new SeriesResiduals(series));
        numeric->AddParameterBlock(int(k));
        numeric->SetNumResiduals(int(n));
        differences.reset(numeric);
    }
    problem.AddResidualBlock(differences ? differences.get() : &exact, nullptr, theta.data());
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

    FitOutcome out;
    out.estimate = theta;
    out.iterations = summary.iterations.size() > 0 ? summary.iterations.size() - 1 : 0;
    out.converged = summary.termination_type == ceres::CONVERGENCE;
    out.termination = summary.message;
    out.residuals = n;
    out.trajectories = integrations;
    out.solve_seconds = summary.total_time_in_seconds;

    // J and r at the solution.
    Eigen::VectorXd r(static_cast<Eigen::Index>(n));
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> J(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(k));
    const double* blocks[] = {theta.data()};
    double* jac[] = {J.data()};
    if (!exact.Evaluate(blocks, r.data(), jac))
        throw SimulationError("the model cannot be integrated at the fit's estimates: " + exact.last_failure(), 0);
    const double rss = r.squaredNorm();
    out.rms = std::sqrt(rss / double(n));
    out.residual_sigma = std::sqrt(rss / double(n - k));

    // The fitted trajectory at the data's times (unweighted): the residual is model − data.
    out.model.resize(data.y.rows(), data.y.cols());
    for (Eigen::Index j = 0; j < data.y.rows(); ++j)
        for (Eigen::Index c = 0; c < data.y.cols(); ++c) out.model(j, c) = r(j * data.y.cols() + c) / w(c) + data.y(j, c);

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
