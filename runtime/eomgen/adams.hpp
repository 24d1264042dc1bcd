/** @file adams.hpp  Variable-step, variable-order Adams–Bashforth–Moulton PECE (Shampine & Gordon's STEP),
 * with its interpolating polynomial as dense output. */
#pragma once

#include "eomgen/errors.hpp"
#include "eomgen/step_bounds.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

namespace eomgen {

/// Settings of the Adams stepper. The tolerances mean what they mean for Dopri5Options (embedded_rk.hpp).
template <class Scalar>
struct AdamsOptions {
    Scalar rtol = Scalar(1e-6);      ///< relative tolerance, per component
    Scalar atol = Scalar(1e-9);      ///< absolute tolerance, per component; must be positive
    Scalar h0 = Scalar(0);           ///< first step size; 0: STEP's, min(hmax, 0.25/sqrt(‖f(t0, x0)‖))
    Scalar hmin = Scalar(0);         ///< smallest |h| before StepSizeUnderflow; never below 16 ulp of t
    Scalar hmax = Scalar(0);         ///< largest |h|; 0: |t_end - t0|
    std::size_t max_steps = 100000;  ///< attempted steps (accepted + rejected) before TooManySteps
    int max_order = 12;              ///< highest order k of the formulas, 1 … 12 (see Adams)
    /// The leading components the error norm counts; 0: all (as Dopri5Options::error_components).
    std::size_t error_components = 0;
};

/**
 * Variable-step, variable-order Adams–Bashforth–Moulton in PECE form with local extrapolation: Shampine &
 * Gordon's STEP, "Computer Solution of Ordinary Differential Equations: the Initial Value Problem" (Freeman,
 * 1975), chapters 5–7, as in their code ode.f (netlib ode/ode.f, subroutines step and intrp; SLATEC's DSTEPS
 * is the same algorithm). One accepted step per call of step(), for x' = f(t, x) with `System` any callable
 * f(const Scalar& t, const State& x, State& xdot) and `State` an Eigen column vector (fixed or dynamic size;
 * Scalar double or long double). Same interface and errors as Dopri5 (dopri5.hpp).
 *
 * The method at order k (1 ≤ k ≤ max_order ≤ 12) keeps the modified divided differences φ_1 … φ_k of f at
 * the last k points t_n, t_{n-1}, … (unequally spaced: ψ_i = t_{n+1} − t_{n+1−i}):
 *   predict  p = x_n + h Σ_{i=1..k} g_{i,1} φ*_i          (Adams–Bashforth, k steps; φ*_i = β_i φ_i)
 *   evaluate f_p = f(t_{n+1}, p)
 *   correct  x_{n+1} = p + h g_{k+1,1} (f_p − Σ φ*_i)     (Adams–Moulton of order k + 1: local extrapolation)
 *   evaluate f_{n+1} = f(t_{n+1}, x_{n+1}), then the differences φ_i(n+1).
 * So a step accepted at order k is of order k + 1: the global error of constant steps at order k falls like
 * h^(k+1). The local error of the order-k corrector, h (g_{k,1} − g_{k+1,1}) ‖f_p − Σ φ*_i‖, is the error
 * estimate; a step is accepted when it is at most 1 in the norm
 *   ‖e‖ = sqrt( (1/n) Σ (e_i / sc_i)² ),  sc_i = atol + rtol·|x_i| at the start of the step
 * (STEP with eps = 1 and weights sc·sqrt(n), so the norm is the one of the Runge–Kutta steppers). The errors
 * that orders k − 2, k − 1, k + 1 would have made at constant steps choose the next order (lower when they
 * are no larger, higher only after steps of constant size), and the step size follows the chosen order's
 * error estimate: doubled when it is below 2^−(k+2), kept when below 1/2, else h·clamp((0.5/err)^(1/(k+1)),
 * 0.5, 0.9). The start is order 1 with STEP's first step; while every step succeeds ("phase 1") the order
 * rises by one and the step doubles each step, up to max_order and hmax. A rejected step halves h; the third
 * consecutive rejection drops to order 1, later ones take the step STEP estimates. A trial with a non-finite
 * predicted or corrected state or f is rejected with h/4 at order 1, so a model undefined past some point is
 * approached rather than stepped over. Sums are compensated (STEP's φ_15, φ_16) against round-off at tight
 * tolerances. The step never passes t_end and the last one lands on it exactly; a step whose size changed
 * (hmax, the last step, a rejection) recomputes the coefficients for unequal spacing, so nothing restarts.
 *
 * Costs: 2 evaluations of f per accepted step, 1 per rejected one, 1 at the start.
 *
 * Dense output on the last step [t_prev, t]: the corrector's interpolating polynomial of degree k + 1
 * (intrp), u(s) = x_{n+1} + (s − t_{n+1}) Σ_{i=1..k+1} g_i(s) φ_i(n+1), of the step's order, free (no
 * evaluation of f); dense() returns x() and x_prev() exactly at the ends.
 *
 * Errors: NonFiniteState when x0 or f(t0, x0) is not finite, or when every trial down to hmin produced
 * non-finite values; StepSizeUnderflow when the step must shrink below max(hmin, 16 ulp(t)); TooManySteps
 * after max_steps attempted steps. Messages carry t and the state.
 */
template <class State>
class Adams {
  public:
    using Scalar = typename State::Scalar;
    using Options = AdamsOptions<Scalar>;
    static constexpr int kMaxOrder = 12;

    /// Prepares integration from (t0, x0) towards t_end (either direction). Evaluates f once.
    template <class System>
    Adams(System&& f, const Scalar& t0, const State& x0, const Scalar& t_end, const Options& options = {})
        : opts_(options),
          t_end_(t_end),
          t_(t0),
          t_prev_(t0),
          x_(x0),
          x_prev_(x0),
          x_new_(x0),
          p_(x0),
          fp_(x0),
          fx_(x0),
          rho_(x0),
          sc_(x0) {
        using std::abs;
        using std::max;
        using std::sqrt;
        if (!(opts_.rtol >= Scalar(0)) || !(opts_.atol > Scalar(0)))
            throw std::invalid_argument("Adams: need rtol >= 0 and atol > 0");
        if (opts_.max_order < 1 || opts_.max_order > kMaxOrder)
            throw std::invalid_argument("Adams: max_order must be within 1 … 12");
        for (State& d : phi_) d = State::Zero(x0.size());
        dir_ = t_end >= t0 ? Scalar(1) : Scalar(-1);
        hmax_ = opts_.hmax > Scalar(0) ? opts_.hmax : abs(t_end - t0);
        if (!x0.allFinite())
            throw NonFiniteState(describe_state("initial state is not finite", t0, x0), value_of(t0));
        if (t_end == t0) return;
        evaluate(f, t_, x_, fx_);
        if (!fx_.allFinite())
            throw NonFiniteState(describe_state("right-hand side is not finite", t_, x_), value_of(t_));
        phi_[1] = fx_;
        if (opts_.h0 != Scalar(0)) {
            h_ = dir_ * std::min(abs(opts_.h0), hmax_);
        } else {
            // STEP's block 0: h with h²‖f‖ = 1/16 of the tolerance, unless the whole interval is shorter.
            update_scale();
            const Scalar sum = weighted_norm(fx_);
            Scalar absh = hmax_;
            if (Scalar(1) < Scalar(16) * sum * absh * absh) absh = Scalar(0.25) * sqrt(Scalar(1) / sum);
            h_ = dir_ * max(absh, Scalar(4) * std::numeric_limits<Scalar>::epsilon() * abs(t_));
        }
    }

    /// Takes one accepted step (rejected trials are retried internally). Call only while !done().
    template <class System>
    void step(System&& f) {
        using std::abs;
        using std::max;
        using std::min;
        using std::pow;
        using std::sqrt;
        if (done()) throw std::logic_error("Adams::step called after reaching t_end");
        update_scale();
        int ifail = 0;
        bool last_nonfinite = false;
        for (;;) {
            const bool last =
                detail::bound_trial_step(h_, t_, x_, t_end_, dir_, opts_.hmin, n_accepted_ + n_rejected_,
                                         opts_.max_steps, last_nonfinite);
            const Scalar h = h_, absh = abs(h);
            const int k = k_;
            coefficients(h);
            predict(h);
            const Scalar t_new = last ? t_end_ : t_ + h;
            evaluate(f, t_new, p_, fp_);
            if (!p_.allFinite() || !fp_.allFinite()) {
                reject_nonfinite(h);
                last_nonfinite = true;
                continue;
            }
            last_nonfinite = false;

            // Block 2: the error of this step at order k, and those orders k − 1, k − 2 would have made.
            Scalar erkm2(0), erkm1(0), erk(0);
            for (Eigen::Index l = 0; l < fp_.size(); ++l) {
                const Scalar d = fp_(l) - phi_[1](l), w = sc_(l);
                if (k >= 3) erkm2 += sq((phi_[k - 1](l) + d) / w);
                if (k >= 2) erkm1 += sq((phi_[k](l) + d) / w);
                erk += sq(d / w);
            }
            if (k >= 3) erkm2 = absh * sig_[k - 1] * gstr(k - 2) * sqrt(erkm2);
            if (k >= 2) erkm1 = absh * sig_[k] * gstr(k - 1) * sqrt(erkm1);
            const Scalar temp5 = absh * sqrt(erk);
            const Scalar err = temp5 * (g_[k] - g_[k + 1]);
            erk = temp5 * sig_[k + 1] * gstr(k);
            int knew = k;
            if (k >= 3 && max(erkm1, erkm2) <= erk) knew = k - 1;
            if (k == 2 && erkm1 <= Scalar(0.5) * erk) knew = k - 1;

            if (!(err <= Scalar(1))) {
                // Block 3: restore, then halve h; order 1 at the third failure, STEP's estimate after.
                phase1_ = false;
                restore(h);
                ++ifail;
                ++n_rejected_;
                Scalar factor(0.5);
                if (ifail >= 3) knew = 1;
                if (ifail > 3 && Scalar(0.5) < Scalar(0.25) * erk) factor = sqrt(Scalar(0.5) / erk);
                h_ = factor * h;
                k_ = knew;
                continue;
            }

            // Block 4: correct, evaluate, update the differences (compensated: φ_16 holds the prediction's
            // rounding error, φ_15 the correction's).
            rho_ = (h * g_[k + 1]) * (fp_ - phi_[1]) - phi_[16];
            x_new_ = p_ + rho_;
            evaluate(f, t_new, x_new_, fp_);
            if (!x_new_.allFinite() || !fp_.allFinite()) {
                reject_nonfinite(h);
                last_nonfinite = true;
                continue;
            }
            phi_[15] = (x_new_ - p_) - rho_;
            kold_ = k;
            hold_ = h;
            phi_[k + 1] = fp_ - phi_[1];
            phi_[k + 2] = phi_[k + 1] - phi_[k + 2];
            for (int i = 1; i <= k; ++i) phi_[i] += phi_[k + 1];

            // The order of the next step, from the error order k + 1 would have made (only after steps
            // of constant size, where that estimate holds).
            if (knew == k - 1 || k == opts_.max_order) phase1_ = false;
            int knext = k;
            Scalar erknext = erk;
            if (phase1_) {
                knext = k + 1;
                erknext = Scalar(0);
            } else if (knew == k - 1) {
                knext = k - 1;
                erknext = erkm1;
            } else if (k + 1 <= ns_) {
                Scalar erkp1(0);
                for (Eigen::Index l = 0; l < fp_.size(); ++l) erkp1 += sq(phi_[k + 2](l) / sc_(l));
                erkp1 = absh * gstr(k + 1) * sqrt(erkp1);
                if (k == 1) {
                    if (erkp1 < Scalar(0.5) * erk && k < opts_.max_order) knext = k + 1, erknext = erkp1;
                } else if (erkm1 <= min(erk, erkp1)) {
                    knext = k - 1, erknext = erkm1;
                } else if (erkp1 < erk && k < opts_.max_order) {
                    knext = k + 1, erknext = erkp1;
                }
            }
            k_ = knext;

            // The step size for that order.
            Scalar h_new = h + h;
            if (!phase1_ && !(Scalar(0.5) >= erknext * Scalar(std::ldexp(1.0, knext + 1)))) {
                h_new = h;
                if (!(Scalar(0.5) >= erknext)) {
                    const Scalar r = pow(Scalar(0.5) / erknext, Scalar(1) / Scalar(knext + 1));
                    h_new = dir_ * absh * max(Scalar(0.5), min(Scalar(0.9), r));
                }
            }
            if (abs(h_new) > hmax_) h_new = dir_ * hmax_;
            h_ = h_new;

            t_prev_ = t_;
            x_prev_.swap(x_);
            x_.swap(x_new_);
            fx_ = fp_;
            t_ = t_new;
            ++n_accepted_;
            return;
        }
    }

    /// Dense output at t in [t_prev, t] of the last accepted step (intrp): the step's interpolating
    /// polynomial, exact at both ends.
    void dense(const Scalar& t, State& x) const {
        if (t == t_ || t == t_prev_) {
            x = t == t_ ? x_ : x_prev_;
            return;
        }
        const Scalar hi = t - t_;
        const int ki = kold_ + 1;
        std::array<Scalar, kMaxOrder + 3> w{}, g{};
        for (int i = 1; i <= ki; ++i) w[i] = Scalar(1) / Scalar(i);
        g[1] = Scalar(1);
        Scalar term(0);
        for (int j = 2; j <= ki; ++j) {
            const Scalar psi = psi_[j - 1];
            const Scalar gamma = (hi + term) / psi, eta = hi / psi;
            for (int i = 1; i <= ki + 1 - j; ++i) w[i] = gamma * w[i] - eta * w[i + 1];
            g[j] = w[1];
            term = psi;
        }
        x = g[ki] * phi_[ki];
        for (int i = ki - 1; i >= 1; --i) x += g[i] * phi_[i];
        x = x_ + hi * x;
    }

    bool done() const { return t_ == t_end_; }

    /// Starts afresh at (t, x), as the constructor does (order 1, the differences from f(t, x) alone), with the
    /// next trial step h (0: the current one): the driver's move at a switching surface (EventAction::Switch),
    /// where the history of f before the switch says nothing about f after it.
    template <class System>
    void restart(System&& f, const Scalar& t, const State& x, const Scalar& h = Scalar(0)) {
        t_ = t;
        t_prev_ = t;
        x_ = x;
        x_prev_ = x;
        for (State& d : phi_) d = State::Zero(x.size());
        psi_ = {};
        alpha_ = {};
        beta_ = {};
        sig_ = {};
        v_ = {};
        w_ = {};
        g_ = {};
        k_ = 1;
        kold_ = 0;
        ns_ = 0;
        hold_ = Scalar(0);
        phase1_ = true;
        evaluate(f, t_, x_, fx_);
        if (!fx_.allFinite())
            throw NonFiniteState(describe_state("right-hand side is not finite", t_, x_), value_of(t_));
        phi_[1] = fx_;
        if (h != Scalar(0)) h_ = h;
    }
    /// Where the steps end: t_end, or for a while a switch's time before it (the last step lands on it exactly).
    void set_end(const Scalar& t) { t_end_ = t; }
    const Scalar& t() const { return t_; }
    const State& x() const { return x_; }
    const Scalar& t_prev() const { return t_prev_; }
    const State& x_prev() const { return x_prev_; }
    const State& derivative() const { return fx_; }  ///< f(t, x) at the current point
    Scalar last_step_size() const { return t_ - t_prev_; }
    const Scalar& next_step_size() const { return h_; }
    int last_order() const { return kold_; }  ///< the order k of the last accepted step (0 before the first)
    int next_order() const { return k_; }
    std::size_t accepted_steps() const { return n_accepted_; }
    std::size_t rejected_steps() const { return n_rejected_; }
    std::size_t rhs_evaluations() const { return n_rhs_; }

  private:
    static Scalar sq(const Scalar& v) { return v * v; }

    /// STEP's gstr: |γ*_k|, the error constants of the constant-step Adams–Moulton formulas of order k.
    static Scalar gstr(int k) {
        static constexpr double table[] = {0.5,     0.0833,  0.0417,  0.0264,  0.0188,  0.0143, 0.0114,
                                           0.00936, 0.00789, 0.00679, 0.00592, 0.00524, 0.00468};
        return Scalar(table[k - 1]);
    }

    template <class System>
    void evaluate(System& f, const Scalar& t, const State& x, State& xdot) {
        f(t, x, xdot);
        ++n_rhs_;
    }

    /// sc·sqrt(n) with sc_i = atol + rtol·|x_i|: STEP's weights, for the RMS norm against 1.
    void update_scale() {
        using std::abs;
        using std::sqrt;
        // Components past error_components count for nothing: an infinite weight.
        const Eigen::Index m = opts_.error_components > 0 && Eigen::Index(opts_.error_components) < x_.size()
                                   ? Eigen::Index(opts_.error_components)
                                   : x_.size();
        const Scalar root_n = sqrt(Scalar(m));
        for (Eigen::Index i = 0; i < x_.size(); ++i)
            sc_(i) = i < m ? (opts_.atol + opts_.rtol * abs(x_(i))) * root_n : std::numeric_limits<Scalar>::infinity();
    }

    Scalar weighted_norm(const State& v) const {
        using std::sqrt;
        Scalar sum(0);
        for (Eigen::Index i = 0; i < v.size(); ++i) sum += sq(v(i) / sc_(i));
        return sqrt(sum);
    }

    /// Block 1: ψ, α, β, σ and the integration coefficients g for step h at order k_; only those that change
    /// (ns_ counts the steps of size h so far: with k_ < ns_ nothing does).
    void coefficients(const Scalar& h) {
        const int k = k_;
        if (h != hold_) ns_ = 0;
        if (ns_ <= kold_) ++ns_;
        const int ns = ns_;
        if (k < ns) return;
        beta_[ns] = Scalar(1);
        alpha_[ns] = Scalar(1) / Scalar(ns);
        Scalar temp1 = h * Scalar(ns);
        sig_[ns + 1] = Scalar(1);
        for (int i = ns + 1; i <= k; ++i) {
            const Scalar temp2 = psi_[i - 1];
            psi_[i - 1] = temp1;
            beta_[i] = beta_[i - 1] * psi_[i - 1] / temp2;
            temp1 = temp2 + h;
            alpha_[i] = h / temp1;
            sig_[i + 1] = Scalar(i) * alpha_[i] * sig_[i];
        }
        psi_[k] = temp1;
        g_[1] = Scalar(1);
        g_[2] = Scalar(0.5);
        sig_[1] = Scalar(1);
        if (ns == 1) {
            for (int iq = 1; iq <= k; ++iq) v_[iq] = w_[iq] = Scalar(1) / Scalar(iq * (iq + 1));
        } else {
            if (k > kold_) {  // the order was raised: the diagonal part of v
                v_[k] = Scalar(1) / Scalar(k * (k + 1));
                for (int j = 1; j <= ns - 2; ++j) v_[k - j] -= alpha_[j + 1] * v_[k - j + 1];
            }
            for (int iq = 1; iq <= k + 1 - ns; ++iq) {
                v_[iq] -= alpha_[ns] * v_[iq + 1];
                w_[iq] = v_[iq];
            }
            g_[ns + 1] = w_[1];
        }
        for (int i = ns + 2; i <= k + 1; ++i) {
            for (int iq = 1; iq <= k + 2 - i; ++iq) w_[iq] -= alpha_[i - 1] * w_[iq + 1];
            g_[i] = w_[1];
        }
    }

    /// Block 2's prediction: φ → φ* (β_i φ_i), p = x + h Σ g_i φ*_i (compensated), φ_i ← φ*_i + φ*_{i+1}.
    void predict(const Scalar& h) {
        const int k = k_;
        for (int i = ns_ + 1; i <= k; ++i) phi_[i] *= beta_[i];
        phi_[k + 2] = phi_[k + 1];
        phi_[k + 1].setZero();
        p_.setZero();
        for (int i = k; i >= 1; --i) {
            p_ += g_[i] * phi_[i];
            phi_[i] += phi_[i + 1];
        }
        phi_[16] = h * p_ - phi_[15];  // τ
        p_ = x_ + phi_[16];
        phi_[16] = (p_ - x_) - phi_[16];
    }

    /// Block 3's restoration of φ and ψ after a rejected trial of size h.
    void restore(const Scalar& h) {
        const int k = k_;
        for (int i = 1; i <= k; ++i) phi_[i] = (phi_[i] - phi_[i + 1]) / beta_[i];
        for (int i = 2; i <= k; ++i) psi_[i - 1] = psi_[i] - h;
    }

    void reject_nonfinite(const Scalar& h) {
        restore(h);
        phase1_ = false;
        ++n_rejected_;
        h_ = Scalar(0.25) * h;
        k_ = 1;
    }

    Options opts_;
    Scalar t_end_, t_, t_prev_;
    Scalar dir_ = Scalar(1), hmax_ = Scalar(0), h_ = Scalar(0), hold_ = Scalar(0);
    State x_, x_prev_, x_new_, p_, fp_, fx_, rho_, sc_;
    std::array<State, 17> phi_;  ///< φ_1 … φ_14 (1-based, as in STEP), φ_15 and φ_16 the rounding errors
    std::array<Scalar, kMaxOrder + 2> psi_{}, alpha_{}, beta_{}, sig_{}, v_{}, w_{}, g_{};
    int k_ = 1, kold_ = 0, ns_ = 0;
    bool phase1_ = true;
    std::size_t n_accepted_ = 0, n_rejected_ = 0, n_rhs_ = 0;
};

}  // namespace eomgen
