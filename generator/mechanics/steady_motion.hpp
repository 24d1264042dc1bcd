/** @file steady_motion.hpp  A steady motion of a constrained model (the coordinates the equations do not depend
 * on turning at constant rates, the others at rest) and the linear equations about it on the constraint
 * manifold, in the minimal coordinates and speeds: `eomgen modes --steady` (docs/steady_motions.md). */
#pragma once

#include "mechanics/lagrangian.hpp"
#include "model/model.hpp"

#include <Eigen/Dense>

#include <complex>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace eomgen {

/// One prescribed rate of a steady motion: q̇_coordinate = value (in the parameters), e.g. thetaR' = −v/rR.
struct SteadyRate {
    std::size_t coordinate = 0;
    GiNaC::ex value;
    std::string text;  ///< as given, for messages
};

struct SteadyMotionOptions {
    std::vector<SteadyRate> rates;
    std::map<std::string, double> set;  ///< parameter values (SI); the others at the model's
    std::map<std::string, double> at;   ///< starting guesses for coordinates; the others at the model's initial values
};

/**
 * The steady motion and its linearization. Cyclic coordinates (nothing in M, f, the constraints depends on them)
 * turn at constant rates, given or found; the others are constant, found with the multipliers from
 * f + Aᵀλ = 0, A q̇ + b = 0, g = 0 by Gauss–Newton from the model's initial values. About it the equations are
 * linearized exactly (symbolic derivatives evaluated there) and restricted to the constraint manifold:
 * minimal coordinates (the non-cyclic ones less those the holonomic constraints fix) and independent speeds
 * (those the velocity constraints leave free, chosen so that they are the rates of the minimal coordinates
 * that enter the equations and the prescribed rates). With Kane's projection on the independent speeds,
 * M_r δu̇ + C_r δu + K_r δq = 0, M_r = Bᵀ M B; where the minimal coordinates whose rates are independent speeds
 * decouple from the rest (ignorable coordinates, prescribed rates), M q̈ + C q̇ + K q = 0 in them.
 */
struct SteadyMotion {
    std::vector<double> q, qd, lambda;  ///< the steady state (all coordinates) and the multipliers
    double residual = 0;                ///< max |f + Aᵀλ|, |A q̇ + b|, |g| there
    std::vector<double> parameters;     ///< the parameters' values used, in model order

    std::vector<std::size_t> cyclic;     ///< coordinates nothing depends on (dropped)
    std::vector<std::size_t> dependent;  ///< coordinates the holonomic constraints fix
    std::vector<std::size_t> coordinates;  ///< minimal coordinates
    std::vector<std::size_t> speeds;       ///< independent speeds (coordinate indices of their q̇)
    std::vector<std::size_t> ignorable;    ///< minimal coordinates the linear equations do not depend on
    std::vector<std::size_t> second_order; ///< minimal coordinates with their rates among the speeds, not ignorable
    std::vector<std::size_t> extra_speeds; ///< the other independent speeds (prescribed rates)

    Eigen::MatrixXd A;          ///< δż = A δz, z = [coordinates, speeds]
    Eigen::MatrixXd Mr, Cr, Kr; ///< Kane's form over all speeds (rows, columns: speeds; Kr columns: coordinates)
    bool decoupled = false;     ///< the second-order block stands alone
    std::string coupling;       ///< why not, when it does not
    Eigen::MatrixXd M, C, K;    ///< M q̈ + C q̇ + K q = 0 in second_order (when decoupled)
    Eigen::VectorXcd eigenvalues;   ///< of the second-order block when decoupled, else of A (neutral zeros dropped)
    Eigen::MatrixXcd eigenvectors;  ///< columns, over second_order (decoupled) or z
    std::string stability;          ///< "stable", "unstable" or "marginally stable"
    double growth_rate = 0;         ///< max Re of the eigenvalues
};

/// Solves for steady motions of one model, any number of times (a sweep of a parameter): the symbolic
/// derivatives are formed once, on the first solve.
class SteadyMotionSolver {
public:
    SteadyMotionSolver(const Model& model, const Equations& eq);
    ~SteadyMotionSolver();
    /// Throws ModesError (mechanics/small_oscillations.hpp) when no steady state is found or the constraints
    /// leave no consistent set of speeds. `guess`: a previous solution to start from (a sweep's neighbour).
    SteadyMotion solve(const SteadyMotionOptions& options, const SteadyMotion* guess = nullptr);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// One steady motion (a SteadyMotionSolver used once).
SteadyMotion steady_motion(const Model& model, const Equations& eq, const SteadyMotionOptions& options);

}  // namespace eomgen
