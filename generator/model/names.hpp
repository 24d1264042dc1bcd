/** @file names.hpp  Which names models may use for coordinates, parameters and themselves; their LaTeX. */
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace eomgen {

/// True for an identifier of the model language: [A-Za-z][A-Za-z0-9_]*.
bool is_identifier(std::string_view name);

/// True for every C++20 keyword, including the alternative tokens (`and`, `not`, `xor_eq`, ...),
/// because any of them as a variable name would break the generated code.
bool is_cpp_keyword(std::string_view name);

/**
 * Why `name` may not name a coordinate, parameter or model, or "" when it may. Reserved are (see
 * docs/model_files.md): C++ keywords; `t`, `pi`, `dot` and the expression functions; the names the
 * generated code uses (Scalar, Model, Params, Config, State, MassMatrix, Conserved, Eigen, std, eomgen);
 * every macro of the standard headers, glibc and Eigen (M_PI, NAN, errno, ...) and EIGEN_*; t0, t1, ... (temporaries); names ending in `_` or
 * containing `__`; `<coordinate>_dot` and `<coordinate>_ddot`; names starting with `sin_` or `cos_`.
 * Does not check that `name` is an identifier (see name_problem).
 *
 * @param name         the candidate
 * @param coordinates  the model's coordinate names, for the `<coordinate>_dot` rule
 * @return             the reason as a sentence fragment, e.g. "'class' is a C++ keyword"
 */
std::string reserved_name_reason(std::string_view name, const std::vector<std::string>& coordinates = {});

/// Why `name` is not a valid identifier or is reserved, or "" when it can be used. Combines
/// is_identifier and reserved_name_reason.
std::string name_problem(std::string_view name, const std::vector<std::string>& coordinates = {});

/**
 * Why `name` may not name a declared output ([outputs]) although it may name a coordinate or parameter, or ""
 * when it may: an output is a column of the CSV a run writes, beside `energy`, the conserved quantities (`h`,
 * `p_<coordinate>`) and each constraint's `residual_<constraint>` and `lambda_<constraint>` (its multiplier),
 * and a column name must say which quantity it is. Check name_problem first.
 */
std::string output_name_reason(std::string_view name, const std::vector<std::string>& coordinates,
                               const std::vector<std::string>& constraints);

/// Optimal-string-alignment distance: insertions, deletions, substitutions and swaps of neighbours.
std::size_t edit_distance(std::string_view a, std::string_view b);

/**
 * The candidate closest to a misspelt `name` for a "did you mean" hint, or "" when none is close:
 * within edit distance 2 and at most half the length of the longer word (so `x` does not suggest `m`),
 * or equal up to letter case. Ties go to the candidate listed first.
 */
std::string closest_name(std::string_view name, const std::vector<std::string>& candidates);

/**
 * Default LaTeX for a name: Greek letters become their command (`alpha` → `\alpha`, `Omega` → `\Omega`),
 * trailing digits and `_` parts become a subscript (`theta1` → `\theta_{1}`, `m_rod` → `m_{rod}`,
 * `x_1_alpha` → `x_{1,\alpha}`); anything else is the name itself.
 */
std::string default_latex(std::string_view name);

}  // namespace eomgen
