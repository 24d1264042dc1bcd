/** @file rolling_contacts.hpp  A wheel rolling without slipping on a plane, as the constraints it imposes. */
#pragma once

#include "model/model.hpp"

#include <vector>

namespace eomgen {

/**
 * The constraints of a rolling contact (docs/model_files.md, "Rolling contacts"). With the wheel's centre C
 * and axis a = Aᵀ e_axis in space axes, the plane's unit normal n and s = √(1 − (n·a)²), the rim's lowest
 * point is P = C + r d − ρ n, d = −(n − (n·a) a)/s, the unit vector in the wheel's plane most against n, ρ a
 * torus' tube radius (0 for a knife edge: the tube's lowest point lies below its centre circle along −n). Then
 * - touching: n·P − h = n·C − r s − ρ − h = 0 (holonomic), left out where it vanishes identically in the model's
 *   coordinates (probed at random configurations with random parameter values), e.g. when the coordinates
 *   are the contact point's;
 * - rolling: the velocity of the wheel's material point at P, v_C + ω × (P − C), has no component along the
 *   plane (two nonholonomic constraints, one per tangent axis). Its normal component equals the time
 *   derivative of the touching constraint (the rim's tangent at P lies in the plane), so nothing is redundant.
 * s = 0 is the wheel lying flat, where the contact point is undefined. Throws ModelError at the contact when
 * its body is unknown.
 */
std::vector<Constraint> rolling_contact_constraints(const Model& model, const RollingContact& contact);

}  // namespace eomgen
