/** @file inertia.hpp  Symbolic inertia tensors: shapes, a density integrated over a region, parallel axes,
 * principal axes. */
#pragma once

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace eomgen {

/**
 * Inertia tensors are 3×3 GiNaC::matrix objects I_jk = ∫ (r² δ_jk − x_j x_k) dm (Goldstein (5.7)), in the
 * body's own axes; vectors are 3×1 matrices. Every shape's tensor is about its centre of mass, with the
 * axes stated in its doc line (the symmetry axis, where there is one, is z).
 */

/// Thin rod of length l along z: diag(M l²/12, M l²/12, 0).
GiNaC::matrix thin_rod_inertia(const GiNaC::ex& mass, const GiNaC::ex& length);
/// Thin disk of radius R in the x-y plane: diag(M R²/4, M R²/4, M R²/2).
GiNaC::matrix thin_disk_inertia(const GiNaC::ex& mass, const GiNaC::ex& radius);
/// Thin ring (hoop) of radius R in the x-y plane: diag(M R²/2, M R²/2, M R²).
GiNaC::matrix ring_inertia(const GiNaC::ex& mass, const GiNaC::ex& radius);
/// Solid sphere of radius R: (2/5) M R² 1.
GiNaC::matrix solid_sphere_inertia(const GiNaC::ex& mass, const GiNaC::ex& radius);
/// Thin spherical shell of radius R: (2/3) M R² 1.
GiNaC::matrix hollow_sphere_inertia(const GiNaC::ex& mass, const GiNaC::ex& radius);
/// Solid circular cone, base radius R, height h, axis z; its centre of mass is h/4 above the base:
/// diag(3/20 M R² + 3/80 M h², same, 3/10 M R²).
GiNaC::matrix solid_cone_inertia(const GiNaC::ex& mass, const GiNaC::ex& radius, const GiNaC::ex& height);
/// Solid cylinder, radius R, height h, axis z: diag(M(3R² + h²)/12, same, M R²/2).
GiNaC::matrix cylinder_inertia(const GiNaC::ex& mass, const GiNaC::ex& radius, const GiNaC::ex& height);
/// Solid box with sides a, b, c along x, y, z: diag(M(b² + c²)/12, M(a² + c²)/12, M(a² + b²)/12).
GiNaC::matrix box_inertia(const GiNaC::ex& mass, const GiNaC::ex& a, const GiNaC::ex& b, const GiNaC::ex& c);
/// Thin rectangular plate with sides a along x, b along y: diag(M b²/12, M a²/12, M(a² + b²)/12).
GiNaC::matrix rectangular_plate_inertia(const GiNaC::ex& mass, const GiNaC::ex& a, const GiNaC::ex& b);
/// Thin right-triangle plate, legs a along x and b along y; its centre of mass is (a/3, b/3) from the
/// right angle: [[M b²/18, M a b/36, 0], [M a b/36, M a²/18, 0], [0, 0, M(a² + b²)/18]].
GiNaC::matrix right_triangle_plate_inertia(const GiNaC::ex& mass, const GiNaC::ex& a, const GiNaC::ex& b);

/// The names accepted by shape_inertia and the dimensions each takes, in order (e.g. "solid_cone":
/// {"radius", "height"}). Empty when `shape` is unknown.
std::vector<std::string> shape_dimensions(const std::string& shape);
/// All shape names, for error messages.
std::vector<std::string> shape_names();
/// The tensor of a named shape (see shape_dimensions); throws std::invalid_argument on an unknown name
/// or a wrong number of dimensions.
GiNaC::matrix shape_inertia(const std::string& shape, const GiNaC::ex& mass,
                            const std::vector<GiNaC::ex>& dimensions);

/// One integration: `variable` from `lower` to `upper`; the limits may depend on the variables of the
/// bounds that come after it (integrated later, i.e. further out).
struct Bound {
    GiNaC::symbol variable;
    GiNaC::ex lower, upper;
};

/// Mass, centre of mass and inertia tensor of a body.
struct MassProperties {
    GiNaC::ex mass;
    GiNaC::matrix centre{3, 1};          ///< centre of mass in the integration frame
    GiNaC::matrix inertia_origin{3, 3};  ///< about the integration frame's origin
    GiNaC::matrix inertia_centre{3, 3};  ///< about the centre of mass, same axes
};

/**
 * Integrates a density ρ(x, y, z) over a region: m = ∫ρ, r_c = ∫ρ r / m, I_jk = ∫ρ (r² δ_jk − x_j x_k).
 * `bounds` lists the integrations innermost first (the 5-15 triangle: {x, 0, a − y}, {y, 0, a}). A
 * coordinate among x, y, z without a bound is 0 on the body: two bounds give a plate (ρ per area), one a
 * rod (ρ per length). GiNaC integrates polynomials exactly; throws std::invalid_argument when an
 * integral is left unevaluated.
 */
MassProperties integrate_mass_properties(const GiNaC::ex& density, const GiNaC::symbol& x,
                                         const GiNaC::symbol& y, const GiNaC::symbol& z,
                                         const std::vector<Bound>& bounds);

/**
 * Parallel-axis (Steiner) shift: the tensor about a point P, from the tensor about the centre of mass,
 * \f[ I_P = I_c + M\,(d^2\,\mathbb{1} - d\,d^T), \f] d (3×1) the centre of mass relative to P.
 * The reverse, I_c = I_P − M(d² 1 − d dᵀ), is shift_to_centre.
 */
GiNaC::matrix parallel_axis(const GiNaC::matrix& inertia_centre, const GiNaC::ex& mass,
                            const GiNaC::matrix& d);
GiNaC::matrix shift_to_centre(const GiNaC::matrix& inertia_point, const GiNaC::ex& mass,
                              const GiNaC::matrix& d);

/// Principal moments I_1 ≤ I_2 ≤ I_3 and orthonormal principal axes (3×1 each, axes[i] for moments[i]).
struct PrincipalAxes {
    bool exact = false;  ///< symbolic from a factorization, or numeric
    std::vector<GiNaC::ex> moments;
    std::vector<GiNaC::matrix> axes;
};

/**
 * Principal moments and axes of a symmetric tensor: the roots of det(λ1 − I) = 0 and the null spaces of
 * I − λ1 (Goldstein §5.4). Exact when the characteristic polynomial factors over the rationals into
 * linear factors in λ (GiNaC's factor()); each axis is then scaled so its first non-zero component is
 * positive and normalised. Otherwise `values` is substituted (e.g. parameter defaults) and the tensor
 * diagonalised numerically (Eigen), exact = false; throws std::invalid_argument if it is still not numeric.
 * Moments are ordered by their value with every remaining symbol set to 1 (parameters are positive).
 */
PrincipalAxes principal_axes(const GiNaC::matrix& inertia, const GiNaC::exmap& values = {});

}  // namespace eomgen
