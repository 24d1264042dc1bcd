/** @file tree_emitter.hpp  rhs() of a model whose T is a tree of point masses: O(n), no M formed. */
#pragma once

#include "codegen/cpp_emitter.hpp"
#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <cstddef>
#include <optional>
#include <string>

namespace eomgen::codegen {

/// Below this many coordinates the header's unrolled L D Lᵀ of M is as fast (bench/time_chain, docs/benchmarks.md).
constexpr std::size_t kTreeMinN = 13;

/**
 * For an unconstrained model with at least kTreeMinN coordinates whose T is a tree of point masses
 * (mechanics/particle_tree.hpp): the members `tree_parent` and `tree_order` (the tree's shape),
 * `tree_terms(t, q_, qd_, p_, terms_)` (levers, their accelerations, weights, joint inertias and forces, CSE'd
 * together) and `rhs(t, x_, p_, xdot_)` by eomgen::particle_tree_accelerations; nothing for any other model.
 */
std::optional<std::string> emit_tree_rhs(const Model& model, const Equations& eq, const SymbolTable& table);

}  // namespace eomgen::codegen
