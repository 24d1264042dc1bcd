/** @file families.hpp  Parameterised model families (n-link chains) written as model-file text. */
#pragma once

#include <string>
#include <vector>

namespace eomgen {

/// A member of a family: which family and how many links.
struct FamilySpec {
    std::string family;  ///< "pendulum" or "rods"
    int n = 0;           ///< number of links, 1 … kMaxFamilyLinks
};

constexpr int kMaxFamilyLinks = 200;

/// The families `family_model_text` knows, for messages and `--help`.
std::vector<std::string> family_names();

/**
 * Parses a family option such as "pendulum:n=20" or "rods:n=8" (the form `eomgen generate --family` takes).
 * Throws std::invalid_argument with a message naming what is wrong (unknown family, missing or bad n).
 */
FamilySpec parse_family_spec(const std::string& spec);

/// The model's name, e.g. "pendulum_20": the generated namespace and file name.
std::string family_model_name(const FamilySpec& spec);

/**
 * The model file (docs/model_files.md) of an n-link planar chain hanging from a fixed pivot, with absolute
 * angles theta1 … thetan from the downward vertical, parameters m1 … mn, l1 … ln and g, readable by
 * parse_model(). T is written the way a user would write it, Σ_i m_i/2 (ẋ_i² + ẏ_i²) with x_i, y_i the
 * sums of l_k sin θ_k and −l_k cos θ_k, so the generator does the differentiating and the simplifying.
 *
 *  - "pendulum": a point mass m_i at the end of each massless link of length l_i.
 *  - "rods": uniform rods of mass m_i and length l_i; the centre of rod i sits halfway along it, and each
 *    rod adds its spin energy (1/2)(m_i l_i²/12) θ̇_i² (Goldstein §5.3).
 */
std::string family_model_text(const FamilySpec& spec);

}  // namespace eomgen
