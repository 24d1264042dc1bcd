/**
 * @file saltation.hpp  The jump of the sensitivities where a motion crosses a switching surface: the saltation
 * matrix (Aizerman and Gantmacher 1958; Hiskens and Pai, "Trajectory sensitivity analysis of hybrid systems",
 * IEEE TCAS-I 47, 2000, eq. (13)).
 *
 * A model whose file writes abs, sign, heaviside, max or min has a right-hand side f that jumps or kinks where a
 * switching function s(t, x; p) changes sign (Coulomb friction's sign(ψ̇)). A motion that crosses s = 0 at τ with
 * the field f⁻ before and f⁺ after moves the crossing with the columns by
 *
 *     dτ = −(s_x S⁻ + s_p) / (s_x f⁻ + s_t),
 *
 * and the state after it by S⁺ = S⁻ + (f⁻ − f⁺) dτ: where f is continuous across the surface (a kink) nothing jumps;
 * where it jumps, S does. The integration ends its steps at each crossing (EventAction::Switch) and applies this
 * there (Event::jump). s_x, s_p and s_t are exact (M's own switching_jacobian for a compiled table, else forward
 * differentiation of M's template, linearize_switching); f⁻ and f⁺ are the one-sided fields just off the surface,
 * extrapolated to it (sliding.hpp).
 *
 * A motion that does not cross but slides along the surface (ṡ⁻ > 0 > ṡ⁺: a door held by static friction) jumps
 * onto the sliding motion (sliding_sensitivities.hpp) where the run follows it; where it does not, and where the
 * motion only grazes the surface (ṡ = 0), there is no derivative from this formula:
 * SimulationError at that time, with the surface's name.
 */
#pragma once

#include "eomgen/errors.hpp"
#include "eomgen/linearize.hpp"
#include "eomgen/model_jacobian.hpp"
#include "eomgen/model_traits.hpp"
#include "eomgen/sliding.hpp"

#include <Eigen/Core>

#include <cmath>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace eomgen {

namespace detail {

template <class M, class = void>
struct has_switching_jacobian : std::false_type {};
template <class M>
struct has_switching_jacobian<M, std::void_t<decltype(M::switching_jacobian(
                                     0.0, std::declval<const typename M::State&>(),
                                     std::declval<const typename M::Params&>(), std::declval<Eigen::MatrixXd&>(),
                                     std::declval<Eigen::MatrixXd&>(), std::declval<Eigen::VectorXd&>()))>>
    : std::true_type {};

}  // namespace detail

/// Sx = ∂s/∂x, Sp = ∂s/∂p, St = ∂s/∂t of Model M's switching functions at (t, x; p).
template <class M>
void switching_jacobians(double t, const typename M::State& x, const typename M::Params& p, Eigen::MatrixXd& Sx,
                         Eigen::MatrixXd& Sp, Eigen::VectorXd& St) {
    if constexpr (detail::has_switching_jacobian<M>::value)
        M::switching_jacobian(t, x, p, Sx, Sp, St);
    else
        linearize_switching<detail::model_template<M>::template type>(t, x, p, Sx, Sp, St);
}

/// Switching surface k of Model M with its one-sided fields (SlidingSurface), on plain vectors; `p` must outlive it.
template <class M>
SlidingSurface<Eigen::VectorXd> model_surface(const typename M::Params& p, int k) {
    return SlidingSurface<Eigen::VectorXd>(
        [&p](const double& t, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) {
            const typename M::State ys(y);
            typename M::State f = ys;
            M::rhs(t, ys, p, f);
            ydot = f;
        },
        [&p, k](const double& t, const Eigen::VectorXd& y) {
            const typename M::State ys(y);
            typename M::Switches s;
            M::switching(t, positions<M::nq>(ys), velocities<M::nq>(ys), p, s);
            return double(s(k));
        });
}

/**
 * The saltation of switching surface k of Model M for the sensitivities' columns: `parameter_of[c]` is column c's
 * parameter index (−1 for an initial value's). apply(t, x, S) replaces S⁻ by S⁺ at a crossing at (t, x).
 */
template <class M>
class Saltation {
  public:
    /// `sliding`: the run follows a motion that slides along the surface (sliding_sensitivities.hpp), so arriving
    /// where it does is the jump onto the sliding motion, not an error.
    Saltation(const typename M::Params& p, int k, std::vector<int> parameter_of, bool sliding = false)
        : p_(p), k_(k), parameter_of_(std::move(parameter_of)), sliding_(sliding) {}

    void apply(double t, const Eigen::VectorXd& x, Eigen::MatrixXd& S) const {
        const typename M::Params& p = p_;
        const int k = k_;
        const auto sides = model_surface<M>(p, k).sides(t, x);
        const Eigen::VectorXd jump = sides.minus - sides.plus;
        const double scale = 1 + sides.minus.cwiseAbs().maxCoeff() + sides.plus.cwiseAbs().maxCoeff();
        if (jump.cwiseAbs().maxCoeff() <= 1e-10 * scale) return;  // a kink: f is continuous, S does not jump
        Eigen::MatrixXd Sx, Sp;
        Eigen::VectorXd St;
        switching_jacobians<M>(t, typename M::State(x), p, Sx, Sp, St);
        // From which side: both one-sided rates of s must agree in sign, else the motion slides or grazes.
        const double rate_minus = Sx.row(k).dot(sides.minus) + St(k), rate_plus = Sx.row(k).dot(sides.plus) + St(k);
        const bool upward = rate_minus > 0 && rate_plus > 0, downward = rate_minus < 0 && rate_plus < 0;
        Eigen::RowVectorXd moved = Sx.row(k) * S;  // s_x S + s_p: how far each column moves s
        for (Eigen::Index c = 0; c < S.cols(); ++c)
            if (parameter_of_[std::size_t(c)] >= 0) moved(c) += Sp(k, parameter_of_[std::size_t(c)]);
        if (rate_minus > 0 && rate_plus < 0 && sliding_) {
            // Arriving where the motion slides along the surface: the jump onto Filippov's field, from either side
            // S made tangent to the surface (sliding_sensitivities.hpp).
            S -= jump * (moved / (rate_minus - rate_plus));
            return;
        }
        if (!upward && !downward) {
            std::ostringstream os;
            os.precision(15);
            os << "the motion " << (rate_minus > 0 && rate_plus < 0 ? "slides along" : "grazes")
               << " the switching surface " << M::switch_names[std::size_t(k)] << " = 0 at t = " << t
               << " (ds/dt is " << rate_minus << " below it and " << rate_plus
               << " above it): the sensitivities of a motion that does not cross it are not done";
            throw SimulationError(os.str(), t);
        }
        const double rate = upward ? rate_minus : rate_plus;
        const Eigen::RowVectorXd dtau = -moved / rate;
        S += (upward ? jump : Eigen::VectorXd(-jump)) * dtau;
    }

  private:
    typename M::Params p_;
    int k_;
    std::vector<int> parameter_of_;
    bool sliding_ = false;
};

}  // namespace eomgen
