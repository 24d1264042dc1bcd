/**
 * @file sample_csv.hpp  The CSV of a run's samples (`--csv`): t and the state, then energy, the work of the
 * forces, conserved quantities, constraint residuals and multipliers, declared outputs, and any further columns
 * the caller computes (sensitivity_run.hpp's ∂x/∂p), each header with its unit.
 */
#pragma once

#include "eomgen/column_units.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/model_traits.hpp"
#include "eomgen/output.hpp"
#include "eomgen/simulation_options.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace eomgen::sim {


/// The columns a run's samples have after t and the state, each with its unit ("" where none): energy; the work of
/// the forces W = ∫ P dt where h is not conserved (`with_work`), so that energy − energy(0) − work is the balance;
/// the conserved quantities other than h; for constrained models each constraint's residual max(|g|, |c|) (of two
/// levels, so no one unit) and multiplier; the model's declared outputs ([outputs]). The CSV of `--csv` and the
/// Python module's results (python/) have these columns in this order.
template <class M>
std::vector<std::pair<std::string, std::string>> derived_columns(bool with_work) {
    std::vector<std::pair<std::string, std::string>> columns{{"energy", energy_unit<M>()}};
    if (with_work) columns.push_back({"work", energy_unit<M>()});
    for (std::size_t k = 0; k < M::conserved_names.size(); ++k)
        if (std::string(M::conserved_names[k]) != "h") columns.push_back({M::conserved_names[k], conserved_unit<M>(k)});
    if constexpr (is_constrained<M>::value)
        for (std::size_t k = 0; k < M::constraint_names.size(); ++k) {
            const std::string c = M::constraint_names[k];
            columns.push_back({"residual_" + c, ""});
            columns.push_back({"lambda_" + c, multiplier_unit<M>(k)});
        }
    for (std::size_t k = 0; k < M::output_names.size(); ++k) columns.push_back({M::output_names[k], output_unit<M>(k)});
    return columns;
}

/// The values of derived_columns<M>(with_work) at (t, x); `work` is W(t), written where with_work.
template <class M>
std::vector<double> derived_values(const typename M::Params& params, double t, const typename M::State& x,
                                   bool with_work, double work) {
    using Config = typename M::Config;
    const Config q = positions<M::nq>(x), qd = velocities<M::nq>(x);
    typename M::Conserved c;
    M::conserved(t, q, qd, params, c);
    std::vector<double> row{M::energy(t, q, qd, params)};
    if (with_work) row.push_back(work);
    for (int k = 0; k < M::n_conserved; ++k)
        if (std::string(M::conserved_names[std::size_t(k)]) != "h") row.push_back(c(k));
    if constexpr (is_constrained<M>::value) {
        typename M::ConstraintVector g, v, lambda;
        M::constraint_residuals(t, q, qd, params, g, v);
        M::multipliers(t, x, params, lambda);
        for (int k = 0; k < M::n_constraints; ++k) {
            row.push_back(std::max(std::abs(g(k)), std::abs(v(k))));
            row.push_back(lambda(k));
        }
    }
    typename M::Outputs out;
    M::outputs(t, q, qd, params, out);
    for (int k = 0; k < M::n_outputs; ++k) row.push_back(out(k));
    return row;
}

/// Writes the samples with derived_columns<M> (the work where `work` has one value per sample), then the
/// columns `more_names` (headers as written), row k from more_rows[k] (one row per sample); headers with units.
template <class M>
void write_samples(const Options& o, const typename M::Params& params,
                   const std::vector<eomgen::Sample<typename M::State>>& samples, const std::vector<double>& work = {},
                   const std::vector<std::string>& more_names = {},
                   const std::vector<std::vector<double>>& more_rows = {}) {
    using State = typename M::State;
    if (o.csv.empty()) return;
    // Each column's header with its unit where the model declares one: "psi [rad]", "energy [J]".
    std::vector<std::string> names;
    for (std::size_t i = 0; i < M::state_names.size(); ++i) names.push_back(with_unit(M::state_names[i], state_unit<M>(i)));
    const bool with_work = !work.empty() && work.size() == samples.size();
    std::vector<std::string> extra;
    for (const auto& [name, unit] : derived_columns<M>(with_work)) extra.push_back(with_unit(name, unit));
    if (!more_names.empty() && more_rows.size() != samples.size())
        throw std::logic_error("write_samples: one row of further columns per sample");
    extra.insert(extra.end(), more_names.begin(), more_names.end());
    std::size_t row_index = 0;
    eomgen::write_csv(o.csv, names, extra, samples, [&](double t, const State& x) {
        const std::size_t this_row = row_index++;
        std::vector<double> row = derived_values<M>(params, t, x, with_work, with_work ? work[this_row] : 0.0);
        if (!more_names.empty()) row.insert(row.end(), more_rows[this_row].begin(), more_rows[this_row].end());
        return row;
    }, with_unit("t", time_unit<M>()));
    if (o.report_csv) std::cout << "csv:     " << o.csv << " (" << samples.size() << " rows)\n";
}

}  // namespace eomgen::sim
