/**
 * @file table_driver.hpp  The simulation driver (runtime/eomgen/simulation.hpp, ensemble.hpp) for
 * eomgen::TableModel, compiled once in table_driver.cpp (the library eomgen_table_driver) for every program that
 * runs a model through its table: `eomgen run`, `report`, the ensembles, and eomgen-sim. Including this header
 * instead of instantiating the driver in each translation unit saved about 40 s of compile per unit on 2 cores
 * (docs/benchmarks.md, "Build time").
 */
#pragma once

#include "eomgen/ensemble.hpp"
#include "eomgen/model_table.hpp"
#include "eomgen/sensitivity_run.hpp"
#include "eomgen/simulation.hpp"

#include <cstddef>
#include <ostream>
#include <vector>

namespace eomgen {

extern template MemberResult<TableModel> simulate_member<TableModel>(const sim::Options&,
                                                                     const std::vector<Event<TableModel::State>>&,
                                                                     std::size_t, const Member<TableModel>&);

namespace sim {

extern template int run_reporting<TableModel>(const Options&, const char*);
extern template Trajectory<TableModel> simulate<TableModel>(const Options&, const TableModel::Params&,
                                                            const TableModel::State&,
                                                            const std::vector<eomgen::Event<TableModel::State>>&,
                                                            bool, std::ostream*);
extern template SensitivityRun<TableModel> sensitivity_run<TableModel>(const Options&);

}  // namespace sim
}  // namespace eomgen
