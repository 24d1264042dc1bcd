/**
 * @file interpreted_table.hpp  An InterpretedModel behind a ModelTable (eomgen/model_table.hpp): the table's plain
 * functions run the model's tapes, so that TableModel, the simulation driver and the ensembles integrate it as they
 * do a compiled model's shared object, and report its errors the same way (singular M, non-finite state).
 *
 * A table's functions carry no context but the parameter block, so the block begins with a pointer to its model;
 * the two functions without a block (init_params, default_state) are one of kSlots instances each, so that up to
 * kSlots interpreted tables live at once in a process (a Python session's models). The Jacobians are null.
 */
#pragma once

#include "eomgen/model_table.hpp"
#include "interpreter/interpreted_model.hpp"

#include <memory>
#include <vector>

namespace eomgen::interpreter {

class InterpretedTable {
  public:
    static constexpr int kSlots = 64;

    /// Takes one of the kSlots slots; throws std::runtime_error when all are in use.
    explicit InterpretedTable(InterpretedModel model);
    ~InterpretedTable();
    InterpretedTable(const InterpretedTable&) = delete;
    InterpretedTable& operator=(const InterpretedTable&) = delete;

    const ModelTable& table() const { return table_; }
    const InterpretedModel& model() const { return *model_; }

  private:
    std::unique_ptr<InterpretedModel> model_;
    int slot_ = -1;
    std::vector<std::vector<const char*>> names_;  ///< the c_str() arrays the table points into
    std::unique_ptr<bool[]> holonomic_;
    ModelTable table_{};
};

}  // namespace eomgen::interpreter
