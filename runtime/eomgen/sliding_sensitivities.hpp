/**
 * @file sliding_sensitivities.hpp  The sensitivities of a motion that slides along a switching surface (Filippov
 * sliding: a block held to a belt, a door held by its hinges' static friction), for integrate_sensitivities.
 *
 * Along s(t, x; p) = 0 the motion follows f_s = α f⁺ + (1 − α) f⁻ with α = ṡ⁻ / (ṡ⁻ − ṡ⁺), ṡ± = s_x f± + s_t
 * (sliding.hpp). Its variational equations are Ṡ = J_s S + J_s,p with the derivatives of f_s itself, α's included:
 *
 *     J_s = α J⁺ + (1 − α) J⁻ + (f⁺ − f⁻) α_x,     α_x = (ṡ⁻ ∂ṡ⁺ − ṡ⁺ ∂ṡ⁻) / (ṡ⁻ − ṡ⁺)²,
 *     ∂ṡ± = s_x J± + f±ᵀ ∂(s_x) + ∂(s_t)            (by x; by p the same with J±_p and s_p's terms),
 *
 * and J_s,p alike. Arriving on the surface from either side, S jumps by the saltation matrix with f_s after the
 * crossing; from below, with dτ = −(s_x S + s_p)/ṡ⁻, S⁺ = S⁻ + (f⁻ − f_s) dτ = S⁻ − (f⁻ − f⁺)(s_x S + s_p)/(ṡ⁻ − ṡ⁺),
 * and from above the same expression: the side does not matter, and S⁺ is S⁻ made tangent to the surface
 * (s_x S⁺ + s_p = 0), which the variational equations then keep. Leaving, where ṡ⁺ (or ṡ⁻) reaches 0, α is 1 (or 0):
 * f_s equals the field the motion leaves with, and S does not jump.
 *
 * f±, J± and J±_p are the one-sided values just off the surface extrapolated to it, as sliding.hpp takes f±
 * (O(δ²) where each side is smooth); s_x, s_p, s_t are exact (the model's switching Jacobian), and their own
 * derivatives by central differences of those (steps of 1e-6 relative; zero for the usual s = ψ̇ or v_belt − ẋ).
 * Not model templates: one copy of this code serves every model (sensitivities.hpp gives it the model's functions).
 */
#pragma once

#include "eomgen/events.hpp"
#include "eomgen/sliding.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace eomgen {

/// A switching function's exact first derivatives at a point: ∂s/∂x, ∂s/∂p (all parameters), ∂s/∂t.
struct SurfaceDerivatives {
    Eigen::RowVectorXd sx, sp;
    double st = 0;
};

/// The variational equations of Filippov's sliding along one switching surface of a model (see the file comment).
class SlidingVariations {
  public:
    /// f, and where J is not null J = ∂f/∂x and Jp = ∂f/∂p (all parameters), at the run's parameters.
    using FieldOf = std::function<void(double t, const Eigen::VectorXd& x, Eigen::VectorXd& f, Eigen::MatrixXd* J,
                                       Eigen::MatrixXd* Jp)>;
    /// The surface's derivatives at (t, x) with the parameters' values p (all of them, in the model's order).
    using SurfaceOf = std::function<SurfaceDerivatives(double t, const Eigen::VectorXd& x, const Eigen::VectorXd& p)>;

    /// `parameter_of[c]`: column c's parameter index, −1 for an initial value's; `p`: the run's parameters' values.
    SlidingVariations(FieldOf field, SurfaceOf surface, Eigen::VectorXd p, std::vector<int> parameter_of,
                      Eigen::Index nx)
        : field_(std::move(field)), surface_(std::move(surface)), p_(std::move(p)),
          parameter_of_(std::move(parameter_of)), nx_(nx) {}

    /// The one-sided values at a point of the surface.
    struct Sides {
        Eigen::VectorXd f[2];      ///< f⁻, f⁺
        Eigen::MatrixXd J[2], Jp[2];  ///< where asked for
        double sdot[2] = {0, 0};   ///< ṡ⁻, ṡ⁺
        SurfaceDerivatives s;
    };

    Sides sides(double t, const Eigen::VectorXd& x, bool jacobians) const {
        Sides out;
        out.s = surface_(t, x, p_);
        const double norm2 = out.s.sx.squaredNorm();
        const double eps = std::numeric_limits<double>::epsilon();
        const Eigen::VectorXd n = norm2 > 0 ? Eigen::VectorXd(out.s.sx.transpose() / norm2) : Eigen::VectorXd::Zero(x.size());
        const double delta = std::sqrt(eps) * (1 + x.cwiseAbs().maxCoeff() * std::sqrt(norm2));
        Eigen::VectorXd f1, f2;
        Eigen::MatrixXd J1, J2, P1, P2;
        for (int side = 0; side < 2; ++side) {
            const double sign = side == 0 ? -1.0 : 1.0;
            field_(t, x + sign * delta * n, f1, jacobians ? &J1 : nullptr, jacobians ? &P1 : nullptr);
            field_(t, x + 2 * sign * delta * n, f2, jacobians ? &J2 : nullptr, jacobians ? &P2 : nullptr);
            out.f[side] = 2 * f1 - f2;
            if (jacobians) {
                out.J[side] = 2 * J1 - J2;
                out.Jp[side] = 2 * P1 - P2;
            }
            out.sdot[side] = out.s.sx.dot(out.f[side]) + out.s.st;
        }
        return out;
    }

    /// The augmented right-hand side while sliding: z' = [f_s, J_s S + J_s,p (the parameters' columns)].
    void operator()(const double& t, const Eigen::VectorXd& z, Eigen::VectorXd& zdot) const {
        const Eigen::VectorXd x = z.head(nx_);
        const Sides o = sides(t, x, true);
        const double gap = o.sdot[0] - o.sdot[1];
        const double alpha = o.sdot[0] / gap;
        // ∂(s_x)/∂x, ∂(s_t)/∂x and the same by p, by central differences of the exact first derivatives.
        const Eigen::Index np = p_.size();
        Eigen::MatrixXd Gx(nx_, nx_), Gp(nx_, np);
        Eigen::RowVectorXd tx(nx_), tp(np);
        // Column j of G and entry j of τ: the derivatives of s_x and s_t by entry j of `by` (x when by_x, else p).
        const auto by_entries = [&](bool by_x, Eigen::MatrixXd& G, Eigen::RowVectorXd& tau) {
            Eigen::VectorXd y = by_x ? x : p_;
            for (Eigen::Index j = 0; j < y.size(); ++j) {
                const double v = y(j), h = 1e-6 * std::max(1.0, std::abs(v));
                y(j) = v + h;
                const SurfaceDerivatives up = by_x ? surface_(t, y, p_) : surface_(t, x, y);
                y(j) = v - h;
                const SurfaceDerivatives down = by_x ? surface_(t, y, p_) : surface_(t, x, y);
                y(j) = v;
                G.col(j) = (up.sx - down.sx).transpose() / (2 * h);
                tau(j) = (up.st - down.st) / (2 * h);
            }
        };
        by_entries(true, Gx, tx);
        by_entries(false, Gp, tp);
        Eigen::RowVectorXd rate_x[2], rate_p[2];
        for (int side = 0; side < 2; ++side) {
            rate_x[side] = o.s.sx * o.J[side] + o.f[side].transpose() * Gx + tx;
            rate_p[side] = o.s.sx * o.Jp[side] + o.f[side].transpose() * Gp + tp;
        }
        const Eigen::RowVectorXd alpha_x = (o.sdot[0] * rate_x[1] - o.sdot[1] * rate_x[0]) / (gap * gap);
        const Eigen::RowVectorXd alpha_p = (o.sdot[0] * rate_p[1] - o.sdot[1] * rate_p[0]) / (gap * gap);
        const Eigen::VectorXd jump = o.f[1] - o.f[0];
        const Eigen::MatrixXd Js = alpha * o.J[1] + (1 - alpha) * o.J[0] + jump * alpha_x;
        const Eigen::MatrixXd Jps = alpha * o.Jp[1] + (1 - alpha) * o.Jp[0] + jump * alpha_p;
        const Eigen::Index k = Eigen::Index(parameter_of_.size());
        zdot.resize(z.size());
        zdot.head(nx_) = alpha * o.f[1] + (1 - alpha) * o.f[0];
        const Eigen::Map<const Eigen::MatrixXd> S(z.data() + nx_, nx_, k);
        Eigen::Map<Eigen::MatrixXd> Sdot(zdot.data() + nx_, nx_, k);
        Sdot.noalias() = Js * S;
        for (Eigen::Index c = 0; c < k; ++c)
            if (parameter_of_[std::size_t(c)] >= 0) Sdot.col(c) += Jps.col(parameter_of_[std::size_t(c)]);
    }

    /// Arriving on the surface (or starting on it): S made tangent to it, S⁻ − (f⁻ − f⁺)(s_x S + s_p)/(ṡ⁻ − ṡ⁺).
    void arrive(double t, Eigen::VectorXd& z) const {
        const Sides o = sides(t, z.head(nx_), false);
        const Eigen::Index k = Eigen::Index(parameter_of_.size());
        Eigen::Map<Eigen::MatrixXd> S(z.data() + nx_, nx_, k);
        Eigen::RowVectorXd moved = o.s.sx * S;
        for (Eigen::Index c = 0; c < k; ++c)
            if (parameter_of_[std::size_t(c)] >= 0) moved(c) += o.s.sp(parameter_of_[std::size_t(c)]);
        S -= (o.f[0] - o.f[1]) * (moved / (o.sdot[0] - o.sdot[1]));
    }

    /// The events that end the sliding, on the augmented state: ṡ⁺ rising to 0, ṡ⁻ falling to 0 (sliding.hpp's).
    std::vector<Event<Eigen::VectorXd>> exits(const std::string& name) const {
        const auto self = std::make_shared<SlidingVariations>(*this);
        const auto rate = [self](int side) {
            return [self, side](const double& t, const Eigen::VectorXd& z) {
                return self->sides(t, z.head(self->nx_), false).sdot[side];
            };
        };
        return {{name + ": leaves to s > 0", rate(1), EventDirection::Rising, EventAction::Stop},
                {name + ": leaves to s < 0", rate(0), EventDirection::Falling, EventAction::Stop}};
    }

  private:
    FieldOf field_;
    SurfaceOf surface_;
    Eigen::VectorXd p_;
    std::vector<int> parameter_of_;
    Eigen::Index nx_;
};

/**
 * The rules by which integrate_sliding_with follows sliding in a run of the augmented system [x, vec(S)]: `surfaces`
 * holds one SlidingVariations per Switch event of the run, those events being `first`, first + 1, … of `n_events`.
 */
inline SlidingRules<Eigen::VectorXd> sliding_sensitivity_rules(
    std::vector<std::shared_ptr<const SlidingVariations>> surfaces, std::size_t first, std::size_t n_events,
    std::vector<std::string> names, Eigen::Index nx) {
    SlidingRules<Eigen::VectorXd> rules;
    rules.follows.assign(n_events, false);
    for (std::size_t i = first; i < first + surfaces.size() && i < n_events; ++i) rules.follows[i] = true;
    const auto shared = std::make_shared<std::vector<std::shared_ptr<const SlidingVariations>>>(std::move(surfaces));
    rules.holds = [shared, first, nx](std::size_t i, const double& t, const Eigen::VectorXd& z) {
        const SlidingVariations::Sides o = (*shared)[i - first]->sides(t, z.head(nx), false);
        const double margin = 1e-9 * (std::abs(o.sdot[0]) + std::abs(o.sdot[1]));
        return o.sdot[0] > margin && o.sdot[1] < -margin;
    };
    rules.field = [shared, first](std::size_t i) -> SlidingRules<Eigen::VectorXd>::Field {
        const auto surface = (*shared)[i - first];
        return [surface](const double& t, const Eigen::VectorXd& z, Eigen::VectorXd& zdot) { (*surface)(t, z, zdot); };
    };
    rules.exits = [shared, first, names](std::size_t i) { return (*shared)[i - first]->exits(names[i]); };
    rules.arrive = [shared, first](std::size_t i, const double& t, Eigen::VectorXd& z) {
        (*shared)[i - first]->arrive(t, z);
    };
    return rules;
}

}  // namespace eomgen
