/**
 * @file small_oscillations.hpp  Equilibria, linearization, normal modes and stability (Goldstein ch. 6).
 *
 * With the velocities split out of the Lagrangian, L = ½ q̇ᵀ M(q) q̇ + β(q)ᵀ q̇ − V_eff(q), where
 * V_eff = V − T₀ and T₀ is the part of T free of velocities (a rotating frame, a hoop spun at a fixed rate),
 * a state of rest q̇ = 0 at q₀ is an equilibrium where ∂V_eff/∂q = Q(q₀, 0) (Q: generalized forces,
 * −∂R/∂q̇ of a Rayleigh function included). About it (Goldstein §6.1–6.2; Meirovitch, Methods of Analytical
 * Dynamics, ch. 6 for the gyroscopic and damped cases)
 *
 *     M₀ δq̈ + (C₀ + G₀) δq̇ + K₀ δq = 0,
 *
 * K₀ = ∂²V_eff/∂q² − ∂Q/∂q, G₀ the skew part of ∂β_i/∂q_j − ∂β_j/∂q_i − ∂Q/∂q̇ (gyroscopic), C₀ its
 * symmetric part (damping). Without C₀ and G₀, K₀ a = ω² M₀ a gives the normal modes; otherwise the
 * eigenvalues λ of the quadratic problem (λ² M₀ + λ(C₀ + G₀) + K₀) a = 0 decide stability.
 *
 * Cyclic coordinates with given momenta (a top's spin and precession) are removed first by Routh's
 * procedure: q̇_c from p_c = ∂L/∂q̇_c, and the Routhian L − p_c·q̇_c is the Lagrangian of the rest, its
 * V_eff the amended potential V − T₀ + ½ (p_c − b_c)ᵀ M_cc⁻¹ (p_c − b_c) (Goldstein §8.3). Where that is
 * 0/0 (a sleeping top at θ = 0, where the Euler angles are singular) values and derivatives are taken as
 * limits by series expansion.
 */
#pragma once

#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <ginac/ginac.h>

#include <complex>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace eomgen {

/// What `eomgen modes` asks: parameter values, starting guesses, momenta of cyclic coordinates.
struct ModesOptions {
    std::map<std::string, double> set;                 ///< parameter values instead of the model's
    std::vector<std::map<std::string, double>> at;     ///< starting guesses (coordinates not named: scanned)
    std::map<std::string, double> momentum;            ///< p_<q> = value: q is reduced away (Routh)
    std::vector<std::string> inputs;                   ///< parameters taken as inputs u: B = ∂ẋ/∂u
};

/// A request that cannot be served: an unknown name, a model eomgen cannot linearize (the message says why).
struct ModesError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// One normal mode: K₀ a = ω² M₀ a, a scaled to its largest component = 1.
struct NormalMode {
    double omega2 = 0;                   ///< ω² (negative: the mode grows as e^{√(−ω²) t})
    std::optional<GiNaC::ex> omega2_exact;  ///< ω² in the parameters, where the characteristic polynomial factors
    std::vector<double> shape;           ///< over the coordinates that remain
};

enum class Stability { Stable, Marginal, Unstable, GyroscopicallyStable };

struct Equilibrium {
    std::vector<double> q;                 ///< over the remaining coordinates
    std::vector<std::optional<GiNaC::ex>> exact;  ///< per coordinate, in the parameters (where found)
    std::vector<std::vector<double>> M, K, C, G;  ///< the linearization, numbers
    std::vector<std::vector<double>> A, B;  ///< first-order form δẋ = A δx + B δu, x = [q, q̇] (B: 2n × inputs)
    std::vector<double> multipliers;       ///< λ_k there, per constraint (the force each constraint exerts at rest)
    /// Orthonormal basis of the constraints' tangent space there (n × (n − m), columns): δq = N δs. The modes
    /// and eigenvalues are those of the motion on it; K is K₀ − Σ λ_k ∂²g_k/∂q², and A acts on x = [δq, δq̇]
    /// as T A_s Tᵀ with T = diag(N, N) (zero on directions that leave the manifold). The identity without constraints.
    std::vector<std::vector<double>> tangent;
    std::vector<NormalMode> modes;         ///< K₀ a = ω² M₀ a (always; with C₀ or G₀ they are not the motion)
    /// M₀ and K₀ in the parameters, where the equilibrium is exact (each coordinate they depend on has an exact
    /// value) and there are no constraints, damping or gyroscopic terms; empty otherwise. det(K₀ − ω² M₀) = 0
    /// is the secular equation (the checker compares a text's with it).
    std::vector<std::vector<GiNaC::ex>> M_exact, K_exact;
    std::vector<std::complex<double>> eigenvalues;  ///< λ of the full first-order system ẋ = A x
    Stability stability = Stability::Stable;
    double growth_rate = 0;                ///< max Re λ when unstable
    bool gyroscopic = false, damped = false;
};

struct ModesResult {
    std::vector<std::string> coordinates;  ///< names of the coordinates that remain (Routh: cyclic ones gone)
    std::vector<std::string> latex;        ///< their LaTeX
    std::vector<std::string> reduced;      ///< the cyclic coordinates reduced away (Routh)
    std::vector<std::string> constraints;  ///< the holonomic constraints the equilibria lie on
    std::vector<std::string> multiplier_units;  ///< the SI unit of each one's multiplier ("" where none is declared)
    GiNaC::ex V_eff;                       ///< V − T₀, the amended potential after a reduction
    /// The momenta of the reduced coordinates as symbols (p_<q>) in V_eff and the exact forms, with LaTeX.
    std::vector<std::pair<GiNaC::symbol, std::string>> momentum_symbols;
    std::vector<Equilibrium> equilibria;
    std::vector<std::string> notes;        ///< e.g. a continuum of equilibria, a scan that found none
};

/**
 * Finds the equilibria of `model` (exact where the gradient's factors in one coordinate can be solved:
 * sin, cos, tan or linear in it; otherwise numbers from the guesses in `options.at`, the model's initial
 * q, and a scan of the coordinates, angles over a period), each reported once, and linearizes about each.
 * With holonomic, time-independent constraints the equilibria lie on their manifold, with multipliers, and
 * the linearization is taken on its tangent space (constrained_equilibria.hpp). Throws ModesError for a
 * nonholonomic or moving constraint, an L that depends on t, and unknown names.
 */
ModesResult small_oscillations(const Model& model, const Equations& eq, const ModesOptions& options);

/// "stable", "marginally stable", "unstable", "gyroscopically stabilized".
const char* stability_name(Stability s);

}  // namespace eomgen
