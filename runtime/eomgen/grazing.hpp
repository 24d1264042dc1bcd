/**
 * @file grazing.hpp  Where a motion touches a switching surface without crossing it (a graze), which a run with
 * sensitivities must say: there the motion has no derivative in general.
 *
 * A crossing of s(t, x) = 0 is transversal (ṡ ≠ 0) and S jumps by the saltation matrix (saltation.hpp). A graze is a
 * touch, s = 0 and ṡ = s_x f + s_t = 0 at once, that crosses nothing: an event on s never sees it (s keeps its sign),
 * yet a motion with a slightly other parameter or start may cross there or miss by a little, so the motion depends on
 * them with a square root's infinite slope, one-sidedly, or (where a whole family grazes, as the undamped block that
 * left the belt's speed tangentially and returns to it once a period) smoothly. The run cannot tell which; it says
 * where (Di Bernardo et al., "Piecewise-smooth Dynamical Systems", 2008, §2.5 and ch. 4).
 *
 * GrazeWatch finds them as the places where ṡ changes sign (an event, recorded, one per surface: s has an extremum)
 * and s is there within what the integration can resolve, |s| ≤ 100 |s_x| (atol + rtol |x|), on surfaces where f
 * jumps (a kink's graze keeps the derivative, see jumps()). While the motion slides
 * along a surface, ṡ is not that of f (SlidingRules::idle_while_sliding keeps the events out), and where sliding begins
 * or ends the touch is the arrival or the exit, no graze.
 */
#pragma once

#include "eomgen/events.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/saltation.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace eomgen {

/// The suffix of the touch events' names ("<switch>: touches").
inline constexpr const char* kTouchSuffix = ": touches";

inline bool is_touch_event(const std::string& name) {
    const std::string suffix = kTouchSuffix;
    return name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
}

template <class M>
class GrazeWatch {
  public:

    GrazeWatch(const typename M::Params& p, Eigen::Index nx) : p_(p), nx_(nx) {}

    /// One recorded event per surface of M, on ṡ_k of an augmented state z = [x, …] (x its first nx entries).
    std::vector<Event<Eigen::VectorXd>> events() const {
        std::vector<Event<Eigen::VectorXd>> out;
        for (int k = 0; k < M::n_switches; ++k)
            out.push_back({std::string(M::switch_names[std::size_t(k)]) + kTouchSuffix,
                           [p = p_, k, nx = nx_](const double& t, const Eigen::VectorXd& z) {
                               return rate(p, k, t, Eigen::VectorXd(z.head(nx)));
                           },
                           EventDirection::Both, EventAction::Record});
        return out;
    }

    /**
     * The grazes among `hits` (the run's events; the touches' states hold x first): "<switch>: grazes" and the time,
     * for each touch where s is within the integration's resolution (rtol, atol), but not where a sliding interval of
     * that surface begins or ends ("<switch>: slides", "<switch>: leaves …" among `hits`).
     */
    std::vector<std::pair<std::string, double>> grazes(const std::vector<EventHit<Eigen::VectorXd>>& hits, double rtol,
                                                       double atol) const {
        std::vector<std::pair<std::string, double>> out;
        for (const EventHit<Eigen::VectorXd>& hit : hits) {
            if (!is_touch_event(hit.name)) continue;
            const std::string surface = hit.name.substr(0, hit.name.size() - std::string(kTouchSuffix).size());
            const double margin = 1e-6 * (1 + std::abs(hit.t));
            const bool at_sliding = std::any_of(hits.begin(), hits.end(), [&](const EventHit<Eigen::VectorXd>& e) {
                return (e.name == surface + ": slides" || e.name.rfind(surface + ": leaves", 0) == 0) &&
                       std::abs(e.t - hit.t) <= margin;
            });
            if (at_sliding) continue;
            int k = 0;
            while (k < M::n_switches && surface != M::switch_names[std::size_t(k)]) ++k;
            if (k == M::n_switches) continue;
            const typename M::State x(Eigen::VectorXd(hit.x.head(nx_)));
            typename M::Switches s;
            M::switching(hit.t, positions<M::nq>(x), velocities<M::nq>(x), p_, s);
            Eigen::MatrixXd Sx, Sp;
            Eigen::VectorXd St;
            switching_jacobians<M>(hit.t, x, p_, Sx, Sp, St);
            const double resolution = 100 * Sx.row(k).cwiseAbs().sum() * (atol + rtol * x.cwiseAbs().maxCoeff());
            if (std::abs(double(s(k))) <= resolution && jumps(k, hit.t, x)) out.emplace_back(surface + ": grazes", hit.t);
        }
        return out;
    }

  private:
    /// Whether f jumps across surface k at (t, x) (sign, heaviside). Across a kink (abs, max, min) f is continuous, and
    /// a motion that grazes one still has a derivative: the correction to a nearby motion is of order 3/2 in its
    /// distance from the surface (Di Bernardo et al. §4.4), not of order 1/2.
    bool jumps(int k, double t, const typename M::State& x) const {
        const auto sides = model_surface<M>(p_, k).sides(t, Eigen::VectorXd(x));
        const double scale = 1 + sides.minus.cwiseAbs().maxCoeff() + sides.plus.cwiseAbs().maxCoeff();
        return (sides.minus - sides.plus).cwiseAbs().maxCoeff() > 1e-10 * scale;
    }

    /// ṡ_k = s_x f + s_t at (t, x).
    static double rate(const typename M::Params& p, int k, double t, const Eigen::VectorXd& xv) {
        const typename M::State x(xv);
        typename M::State f = x;
        M::rhs(t, x, p, f);
        Eigen::MatrixXd Sx, Sp;
        Eigen::VectorXd St;
        switching_jacobians<M>(t, x, p, Sx, Sp, St);
        return Sx.row(k).dot(Eigen::VectorXd(f)) + St(k);
    }

    typename M::Params p_;
    Eigen::Index nx_;
};

}  // namespace eomgen
