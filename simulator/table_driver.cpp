/** @file table_driver.cpp  The driver's templates for eomgen::TableModel, instantiated once (table_driver.hpp). */
#include "table_driver.hpp"

namespace eomgen {

template MemberResult<TableModel> simulate_member<TableModel>(const sim::Options&,
                                                              const std::vector<Event<TableModel::State>>&,
                                                              std::size_t, const Member<TableModel>&);

namespace sim {

template int run_reporting<TableModel>(const Options&, const char*);
template Trajectory<TableModel> simulate<TableModel>(const Options&, const TableModel::Params&,
                                                     const TableModel::State&,
                                                     const std::vector<eomgen::Event<TableModel::State>>&, bool,
                                                     std::ostream*);
template SensitivityRun<TableModel> sensitivity_run<TableModel>(const Options&);

}  // namespace sim
}  // namespace eomgen
