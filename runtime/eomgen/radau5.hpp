/**
 * @file radau5.hpp  Radau IIA of order 5 (three implicit stages) for stiff problems: simplified Newton with an exact
 * Jacobian, Hairer–Wanner's step-size control and error estimate, the collocation polynomial as dense output.
 *
 *     auto r = eomgen::integrate_radau5(f, jac, t0, x0, t_end, options, events, sample_times, observer);
 *
 * f(t, x, xdot) as for integrate(); jac(t, x, J) fills J = ∂f/∂x (n×n). For a generated model the Jacobian is
 * eomgen::model_jacobian<Model<double>> (model_jacobian.hpp): exact, by forward differentiation through rhs.
 */
#pragma once

#include "eomgen/errors.hpp"
#include "eomgen/integrate.hpp"
#include "eomgen/lu_factor.hpp"
#include "eomgen/step_bounds.hpp"

#include <Eigen/Core>
#include <Eigen/LU>  // the 3×3 inverses of the method's constants

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace eomgen {

/**
 * Settings of Radau5. Defaults are those of Hairer's RADAU5 code (HNW "Solving ODEs II", §IV.8), except the
 * tolerances, which mean what they mean for Dopri5 (see Radau5 for how they are used).
 */
template <class Scalar>
struct Radau5Options {
    Scalar rtol = Scalar(1e-6);        ///< relative tolerance, per component
    Scalar atol = Scalar(1e-9);        ///< absolute tolerance, per component; must be positive
    Scalar h0 = Scalar(0);             ///< first step size; 0: 1e-6 (RADAU5's default), at most |t_end - t0|
    Scalar hmin = Scalar(0);           ///< smallest |h| before an error; never below 16 ulp of t
    Scalar hmax = Scalar(0);           ///< largest |h|; 0: |t_end - t0|
    std::size_t max_steps = 100000;    ///< attempted steps (accepted + rejected) before TooManySteps
    Scalar safety = Scalar(0.9);       ///< safety factor of the step-size controller
    Scalar min_factor = Scalar(0.2);   ///< h_new / h is kept within [min_factor, max_factor]
    Scalar max_factor = Scalar(8);
    int max_newton = 7;                ///< Newton iterations per step before the step is retried with h/2
    Scalar jacobian_reuse = Scalar(0.001);  ///< keep the Jacobian while Newton's contraction rate is below this
    Scalar keep_h_low = Scalar(1);     ///< keep h (and the LU factors) when h_new / h lies in [low, high]
    Scalar keep_h_high = Scalar(1.2);
    bool gustafsson = true;            ///< Gustafsson's predictive controller (else the classical one)
    /// The leading components the error estimate counts (Newton's convergence test counts all); 0: all. As
    /// Dopri5Options::error_components.
    std::size_t error_components = 0;
};

/**
 * The 3-stage Radau IIA method (order 5, stiffly accurate, L-stable; HNW II §IV.5 and §IV.8) for x' = f(t, x),
 * one accepted step per call of step(), with the interface of Dopri5 so that detail::drive gives it events and
 * samples. `State` an Eigen column vector (fixed or dynamic size; Scalar double or long double).
 *
 * A step solves the collocation equations for the stage increments z_i = x(t + c_i h) − x(t),
 *   Z = h (A ⊗ I) F(Z),   c = ((4 − √6)/10, (4 + √6)/10, 1),
 * by simplified Newton with J = ∂f/∂x at the step's start. With T⁻¹ A⁻¹ T = diag(γ, [[α, β], [−β, α]]) (γ the real
 * eigenvalue of A⁻¹, α ± iβ the complex pair; T from their eigenvectors) the 3n×3n Newton system falls apart into
 * (γ/h I − J) Δw₁ = r₁ (real) and ((α − iβ)/h I − J)(Δw₂ + iΔw₃) = r₂ + i r₃ (complex), W = (T⁻¹ ⊗ I) Z, each
 * factored once by LU (LuFactor, lu_factor.hpp) and reused while h and J stay. Newton stops when
 * η ‖ΔW‖ ≤ κ with η = θ/(1 − θ), θ the observed contraction rate, κ = max(10 u / rtol', min(0.03, √rtol'));
 * it gives up, and the step is retried with a smaller h, after max_newton iterations, when θ ≥ 0.99, or when the
 * predicted final error is too large (HNW II §IV.8, "Stopping criterion"). The starting values are the previous
 * step's collocation polynomial extrapolated.
 *
 * Error (HNW II §IV.8, (8.19)–(8.20)): err = (γ/h I − J)⁻¹ (f(t, x) + (d₁ z₁ + d₂ z₂ + d₃ z₃)/h) with
 * d = (−(13 + 7√6)/3, (−13 + 7√6)/3, −1/3), from the difference to an embedded third-order formula, filtered by the
 * LU factors already at hand; on the first step and after a rejection an err above 1 is filtered once more with
 * f at x + err. Scaled as Dopri5's, with sc_i = atol' + rtol'·|x_i| at the step's start, where, as in RADAU5,
 * rtol' = 0.1 rtol^(2/3) and atol' = rtol'·atol/rtol (the error estimate is of order 3 while the global error is
 * of order 5: this makes the global error track rtol). Step size: h_new = h / clamp(err^(1/4)/fac,
 * 1/max_factor, 1/min_factor), fac = min(safety, safety (1 + 2 max_newton)/(newton + 2 max_newton)), with
 * Gustafsson's predictive correction after the first accepted step; J is recomputed when the last Newton
 * iteration contracted slower than jacobian_reuse, and h (with its LU factors) is kept when h_new/h is within
 * [keep_h_low, keep_h_high].
 *
 * Dense output on the last accepted step [t_prev, t]: the collocation polynomial, the cubic through
 * (0, x_prev), (c₁, x_prev + z₁), (c₂, x_prev + z₂), (1, x) in θ = (t − t_prev)/h; order 3 inside, exact at both ends.
 *
 * Errors (messages carry t and the state): NonFiniteState when x0, f at an accepted point or J is not finite, or
 * when every trial step down to hmin gave non-finite values; StepSizeUnderflow when the controller wants |h| below
 * max(hmin, 16 ulp(t)), or when Newton's iteration failed to converge for every step size down to it (the
 * message says which); SimulationError when the iteration matrix is singular five times in a row; TooManySteps
 * after max_steps attempted steps.
 */
template <class State>
class Radau5 {
  public:
    using Scalar = typename State::Scalar;
    using Options = Radau5Options<Scalar>;
    static constexpr int N = State::RowsAtCompileTime;
    using Matrix = Eigen::Matrix<Scalar, N, N>;
    using Jacobian = std::function<void(const Scalar& t, const State& x, Matrix& J)>;

    /// Prepares integration from (t0, x0) towards t_end (either direction). Evaluates f once.
    template <class System>
    Radau5(System&& f, Jacobian jac, const Scalar& t0, const State& x0, const Scalar& t_end,
           const Options& options = {})
        : opts_(options), jac_(std::move(jac)), t_end_(t_end), t_(t0), t_prev_(t0), x_(x0), x_prev_(x0) {
        using std::abs;
        using std::pow;
        using std::sqrt;
        if (!jac_) throw std::invalid_argument("Radau5: no Jacobian given");
        if (!(opts_.rtol >= Scalar(0)) || !(opts_.atol > Scalar(0)))
            throw std::invalid_argument("Radau5: need rtol >= 0 and atol > 0");
        if (!(opts_.safety > Scalar(0)) || !(opts_.min_factor > Scalar(0)) || !(opts_.min_factor < Scalar(1)) ||
            !(opts_.max_factor > Scalar(1)))
            throw std::invalid_argument("Radau5: need safety > 0 and 0 < min_factor < 1 < max_factor");
        if (opts_.max_newton < 2) throw std::invalid_argument("Radau5: need max_newton >= 2");
        const Eigen::Index n = x0.size();
        for (State* s : {&f0_, &z1_, &z2_, &z3_, &w1_, &w2_, &w3_, &f1_, &f2_, &f3_, &scal_, &tmp_, &d1_, &d2_, &d3_})
            *s = State::Zero(n);
        J_ = Matrix::Zero(n, n);
        // RADAU5's tolerances: the error estimate is of order 3, the method of order 5.
        rtol_ = opts_.rtol > Scalar(0) ? Scalar(0.1) * pow(opts_.rtol, Scalar(2) / Scalar(3)) : Scalar(0);
        atol_ = opts_.rtol > Scalar(0) ? rtol_ * (opts_.atol / opts_.rtol) : opts_.atol;
        const Scalar uround = std::numeric_limits<Scalar>::epsilon();
        const Scalar tol = rtol_ > Scalar(0) ? rtol_ : atol_;
        fnewt_ = std::max(Scalar(10) * uround / tol, std::min(Scalar(0.03), Scalar(sqrt(tol))));
        dir_ = t_end >= t0 ? Scalar(1) : Scalar(-1);
        hmax_ = opts_.hmax > Scalar(0) ? opts_.hmax : abs(t_end - t0);
        if (!x0.allFinite())
            throw NonFiniteState(describe_state("initial state is not finite", t0, x0), value_of(t0));
        if (t_end == t0) return;
        evaluate(f, t_, x_, f0_);
        if (!f0_.allFinite())
            throw NonFiniteState(describe_state("right-hand side is not finite", t_, x_), value_of(t_));
        h_ = dir_ * std::min(opts_.h0 != Scalar(0) ? Scalar(abs(opts_.h0)) : Scalar(1e-6), hmax_);
    }

    /// Takes one accepted step (rejected trials are retried internally). Call only while !done().
    template <class System>
    void step(System&& f) {
        using std::abs;
        using std::max;
        using std::min;
        using std::pow;
        if (done()) throw std::logic_error("Radau5::step called after reaching t_end");
        const Scalar one(1);
        const Scalar facr = one / opts_.max_factor, facl = one / opts_.min_factor;
        for (;;) {
            const bool last = detail::bound_trial_step(
                h_, t_, x_, t_end_, dir_, opts_.hmin, n_accepted_ + n_rejected_, opts_.max_steps,
                [this](const Scalar& hmin) { fail_below_hmin(hmin); }, Scalar(1.0001));
            if (need_jacobian_) {
                jac_(t_, x_, J_);
                ++n_jac_;
                if (!J_.allFinite())
                    throw NonFiniteState(describe_state("Jacobian of the right-hand side is not finite", t_, x_),
                                         value_of(t_));
                need_jacobian_ = false;
                jacobian_fresh_ = true;
                h_lu_ = Scalar(0);
            }
            const Scalar h = h_;
            if (h != h_lu_ && !decompose(h)) {
                if (++n_singular_ >= 5)
                    throw SimulationError(
                        describe_state("Radau5: the iteration matrix is singular five times in a row", t_, x_),
                        value_of(t_));
                retry(h, Scalar(0.5), Failure::Singular);
                continue;
            }
            n_singular_ = 0;
            Scalar factor(0.5);
            const Newton newton = solve_stages(f, h, factor);
            if (newton != Newton::Converged) {
                retry(h, factor, newton == Newton::NonFinite ? Failure::NonFinite : Failure::Newton);
                continue;
            }
            Scalar err = estimate_error(f, h);
            if (!(err <= std::numeric_limits<Scalar>::max())) {
                retry(h, Scalar(0.5), Failure::NonFinite);
                continue;
            }
            const Scalar cfac = opts_.safety * Scalar(1 + 2 * opts_.max_newton);
            const Scalar fac = min(opts_.safety, cfac / Scalar(newton_iterations_ + 2 * opts_.max_newton));
            Scalar quot = max(facr, min(facl, Scalar(pow(err, Scalar(0.25))) / fac));
            Scalar h_new = h / quot;
            if (err >= one) {  // rejected by the error test
                h_ = first_ ? h * Scalar(0.1) : h_new;
                ++n_rejected_;
                rejected_last_ = true;
                last_failure_ = Failure::Error;
                if (!jacobian_fresh_) need_jacobian_ = true;
                continue;
            }
            // The new point's derivative: the next step's error estimate needs it.
            tmp_ = x_ + z3_;
            const Scalar t_new = last ? t_end_ : t_ + h;
            evaluate(f, t_new, tmp_, f1_);
            if (!tmp_.allFinite() || !f1_.allFinite()) {
                retry(h, Scalar(0.5), Failure::NonFinite);
                continue;
            }
            if (opts_.gustafsson && n_accepted_ >= 1) {
                Scalar facgus = (h_acc_ / h) * pow(err * err / err_acc_, Scalar(0.25)) / opts_.safety;
                facgus = max(facr, min(facl, facgus));
                quot = max(quot, facgus);
                h_new = h / quot;
            }
            h_acc_ = h;
            err_acc_ = max(Scalar(1e-2), err);
            accept(t_new);
            first_ = false;
            jacobian_fresh_ = false;
            last_failure_ = Failure::None;
            if (abs(h_new) > hmax_) h_new = dir_ * hmax_;
            if (rejected_last_ && abs(h_new) > abs(h)) h_new = h;
            rejected_last_ = false;
            const Scalar qt = h_new / h;
            if (theta_ <= opts_.jacobian_reuse && qt >= opts_.keep_h_low && qt <= opts_.keep_h_high) {
                h_ = h;  // same h, same J: the LU factors stay
            } else {
                h_ = h_new;
                need_jacobian_ = theta_ > opts_.jacobian_reuse;
            }
            return;
        }
    }

    /// Dense output at t in [t_prev, t] of the last accepted step: the collocation polynomial; exact at both ends.
    void dense(const Scalar& t, State& x) const {
        if (t == t_) {
            x = x_;
            return;
        }
        if (t == t_prev_) {
            x = x_prev_;
            return;
        }
        x = x_prev_;
        add_polynomial((t - t_prev_) / h_last_, x);
    }

    bool done() const { return t_ == t_end_; }
    const Scalar& t() const { return t_; }
    const State& x() const { return x_; }
    const Scalar& t_prev() const { return t_prev_; }
    const State& x_prev() const { return x_prev_; }
    const State& derivative() const { return f0_; }  ///< f(t, x) at the current point
    const Scalar& last_step_size() const { return h_last_; }
    const Scalar& next_step_size() const { return h_; }
    std::size_t accepted_steps() const { return n_accepted_; }
    std::size_t rejected_steps() const { return n_rejected_; }  ///< by the error test, Newton or non-finite values
    std::size_t rhs_evaluations() const { return n_rhs_; }
    std::size_t jacobian_evaluations() const { return n_jac_; }
    /// Factorizations of the iteration matrices; each is one real and one complex n×n LU.
    std::size_t lu_decompositions() const { return n_lu_; }

    /// The method's constants (HNW II §IV.5 and §IV.8), exposed for the tests.
    struct Constants {
        Scalar c1, c2;           ///< nodes (c3 = 1)
        Scalar gamma, alpha, beta;  ///< eigenvalues γ, α ± iβ of A⁻¹
        Scalar d1, d2, d3;       ///< error estimate: γ times the weights e of (ŷ − y) = γ₀ h f₀ + Σ e_i z_i
        Eigen::Matrix<Scalar, 3, 3> A, T, TI;  ///< Butcher matrix; T⁻¹ A⁻¹ T = diag(γ, [[α, β], [−β, α]])
    };
    static const Constants& constants() {
        static const Constants k = make_constants();
        return k;
    }

  private:
    enum class Newton { Converged, Diverged, NonFinite };
    enum class Failure { None, Newton, NonFinite, Singular, Error };
    using Complex = std::complex<Scalar>;
    using ComplexMatrix = Eigen::Matrix<Complex, N, N>;
    using ComplexVector = Eigen::Matrix<Complex, N, 1>;

    static Constants make_constants() {
        using std::cbrt;
        using std::sqrt;
        Constants k;
        const Scalar s6 = sqrt(Scalar(6));
        k.c1 = (Scalar(4) - s6) / Scalar(10);
        k.c2 = (Scalar(4) + s6) / Scalar(10);
        k.A << (Scalar(88) - Scalar(7) * s6) / Scalar(360), (Scalar(296) - Scalar(169) * s6) / Scalar(1800),
            (Scalar(-2) + Scalar(3) * s6) / Scalar(225), (Scalar(296) + Scalar(169) * s6) / Scalar(1800),
            (Scalar(88) + Scalar(7) * s6) / Scalar(360), (Scalar(-2) - Scalar(3) * s6) / Scalar(225),
            (Scalar(16) - s6) / Scalar(36), (Scalar(16) + s6) / Scalar(36), Scalar(1) / Scalar(9);
        // Eigenvalues of A: 1/γ real, (a ± ib) complex; those of A⁻¹ are their reciprocals.
        const Scalar c81 = cbrt(Scalar(81)), c9 = cbrt(Scalar(9));
        k.gamma = Scalar(30) / (Scalar(6) + c81 - c9);
        const Scalar a = (Scalar(12) - c81 + c9) / Scalar(60), b = (c81 + c9) * sqrt(Scalar(3)) / Scalar(60);
        k.alpha = a / (a * a + b * b);
        k.beta = b / (a * a + b * b);
        const Scalar d = Scalar(1) / Scalar(3);  // d = γ e, e the weights of the embedded formula
        k.d1 = -(Scalar(13) + Scalar(7) * s6) * d;
        k.d2 = (Scalar(-13) + Scalar(7) * s6) * d;
        k.d3 = -d;
        // T's columns: the real eigenvector of A⁻¹ for γ, and the real and imaginary parts of the one for α + iβ,
        // each the cross product of two rows of A⁻¹ − λ I (their null vector).
        const Eigen::Matrix<Scalar, 3, 3> Ai = k.A.inverse();
        const auto null_vector = [&Ai](const Complex& lambda) {
            const Eigen::Matrix<Complex, 3, 3> m =
                Ai.template cast<Complex>() - lambda * Eigen::Matrix<Complex, 3, 3>::Identity();
            return Eigen::Matrix<Complex, 3, 1>(m(0, 1) * m(1, 2) - m(0, 2) * m(1, 1),
                                               m(0, 2) * m(1, 0) - m(0, 0) * m(1, 2),
                                               m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0));
        };
        const Eigen::Matrix<Complex, 3, 1> v1 = null_vector(Complex(k.gamma, 0));
        Eigen::Matrix<Complex, 3, 1> v2 = null_vector(Complex(k.alpha, k.beta));
        v2 /= v2(2);  // any complex multiple is an eigenvector; this one has a real last component
        k.T.col(0) = v1.real() / v1.real().norm();
        k.T.col(1) = v2.real();
        k.T.col(2) = v2.imag();
        k.TI = k.T.inverse();
        return k;
    }

    template <class System>
    void evaluate(System& f, const Scalar& t, const State& x, State& xdot) {
        f(t, x, xdot);
        ++n_rhs_;
    }

    /// Factors γ/h I − J and (α − iβ)/h I − J; false when either is singular (a zero or non-finite pivot).
    bool decompose(const Scalar& h) {
        const Constants& k = constants();
        Matrix e1 = -J_;
        e1.diagonal().array() += k.gamma / h;
        ComplexMatrix e2 = (-J_).template cast<Complex>();
        e2.diagonal().array() += Complex(k.alpha / h, -k.beta / h);
        ++n_lu_;
        h_lu_ = Scalar(0);
        if (!lu_real_.compute(e1) || !lu_complex_.compute(e2)) return false;
        h_lu_ = h;
        return true;
    }

    /// The polynomial's increment over x_prev at θ (of the last accepted step), added to x.
    void add_polynomial(const Scalar& th, State& x) const {
        const Constants& k = constants();
        x += th * (d1_ + (th - k.c1) * (d2_ + (th - k.c2) * d3_));
    }

    /// Simplified Newton for Z at (t_, x_) with step h; on failure `factor` is what h is to be multiplied by.
    template <class System>
    Newton solve_stages(System& f, const Scalar& h, Scalar& factor) {
        using std::max;
        using std::min;
        using std::pow;
        using std::sqrt;
        const Constants& k = constants();
        const Eigen::Index n = x_.size();
        const Scalar uround = std::numeric_limits<Scalar>::epsilon();
        for (Eigen::Index i = 0; i < n; ++i) {
            using std::abs;
            scal_(i) = atol_ + rtol_ * abs(x_(i));
        }
        if (first_) {
            z1_.setZero();
            z2_.setZero();
            z3_.setZero();
        } else {  // the last step's collocation polynomial, extrapolated
            const Scalar base = (t_ - t_prev_) / h_last_;
            const State z_end = x_ - x_prev_;
            State* z[3] = {&z1_, &z2_, &z3_};
            const Scalar c[3] = {k.c1, k.c2, Scalar(1)};
            for (int s = 0; s < 3; ++s) {
                z[s]->setZero();
                add_polynomial(base + c[s] * h / h_last_, *z[s]);
                *z[s] -= z_end;
            }
        }
        w1_ = k.TI(0, 0) * z1_ + k.TI(0, 1) * z2_ + k.TI(0, 2) * z3_;
        w2_ = k.TI(1, 0) * z1_ + k.TI(1, 1) * z2_ + k.TI(1, 2) * z3_;
        w3_ = k.TI(2, 0) * z1_ + k.TI(2, 1) * z2_ + k.TI(2, 2) * z3_;
        faccon_ = pow(max(faccon_, uround), Scalar(0.8));
        theta_ = opts_.jacobian_reuse;
        Scalar dyn_old(0), thq_old(0);
        const int nit = opts_.max_newton;
        ComplexVector r2;
        for (int newt = 0;;) {
            if (newt >= nit) return Newton::Diverged;
            tmp_ = x_ + z1_;
            evaluate(f, t_ + k.c1 * h, tmp_, f1_);
            tmp_ = x_ + z2_;
            evaluate(f, t_ + k.c2 * h, tmp_, f2_);
            tmp_ = x_ + z3_;
            evaluate(f, t_ + h, tmp_, f3_);
            if (!f1_.allFinite() || !f2_.allFinite() || !f3_.allFinite()) return Newton::NonFinite;
            ++newt;
            // Residuals in the transformed basis, then the two solves: ΔW in (tmp_, r2).
            tmp_ = k.TI(0, 0) * f1_ + k.TI(0, 1) * f2_ + k.TI(0, 2) * f3_ - (k.gamma / h) * w1_;
            const State a = k.TI(1, 0) * f1_ + k.TI(1, 1) * f2_ + k.TI(1, 2) * f3_ - (k.alpha / h) * w2_ -
                            (k.beta / h) * w3_;
            const State b = k.TI(2, 0) * f1_ + k.TI(2, 1) * f2_ + k.TI(2, 2) * f3_ + (k.beta / h) * w2_ -
                            (k.alpha / h) * w3_;
            r2 = a.template cast<Complex>() + Complex(0, 1) * b.template cast<Complex>();
            lu_real_.solve_in_place(tmp_);
            lu_complex_.solve_in_place(r2);
            Scalar sum(0);
            for (Eigen::Index i = 0; i < n; ++i) {
                const Scalar u = tmp_(i) / scal_(i), v = r2(i).real() / scal_(i), w = r2(i).imag() / scal_(i);
                sum += u * u + v * v + w * w;
            }
            const Scalar dyno = sqrt(sum / Scalar(3 * n));
            if (!(dyno <= std::numeric_limits<Scalar>::max())) return Newton::NonFinite;
            if (newt > 1 && newt < nit) {
                const Scalar thq = dyno / dyn_old;
                theta_ = newt == 2 ? thq : Scalar(sqrt(thq * thq_old));
                thq_old = thq;
                if (!(theta_ < Scalar(0.99))) return Newton::Diverged;  // factor stays 0.5
                faccon_ = theta_ / (Scalar(1) - theta_);
                const Scalar dyth = faccon_ * dyno * pow(theta_, Scalar(nit - 1 - newt)) / fnewt_;
                if (dyth >= Scalar(1)) {  // it would not converge within nit iterations
                    const Scalar qnewt = max(Scalar(1e-4), min(Scalar(20), dyth));
                    factor = Scalar(0.8) * pow(qnewt, Scalar(-1) / Scalar(4 + nit - 1 - newt));
                    return Newton::Diverged;
                }
            }
            dyn_old = max(dyno, uround);
            w1_ += tmp_;
            w2_ += r2.real();
            w3_ += r2.imag();
            z1_ = k.T(0, 0) * w1_ + k.T(0, 1) * w2_ + k.T(0, 2) * w3_;
            z2_ = k.T(1, 0) * w1_ + k.T(1, 1) * w2_ + k.T(1, 2) * w3_;
            z3_ = k.T(2, 0) * w1_ + k.T(2, 1) * w2_ + k.T(2, 2) * w3_;
            if (faccon_ * dyno <= fnewt_) {
                newton_iterations_ = newt;
                return Newton::Converged;
            }
        }
    }

    /// The scaled error of the converged step (NaN or inf when anything went non-finite).
    template <class System>
    Scalar estimate_error(System& f, const Scalar& h) {
        using std::max;
        using std::sqrt;
        const Constants& k = constants();
        const State f2 = (k.d1 / h) * z1_ + (k.d2 / h) * z2_ + (k.d3 / h) * z3_;
        tmp_ = lu_real_.solve(f0_ + f2);
        Scalar err = scaled_norm(tmp_, error_count());
        if (err >= Scalar(1) && (first_ || rejected_last_)) {  // filter once more (stiff components)
            tmp_ += x_;
            evaluate(f, t_, tmp_, f1_);
            tmp_ = lu_real_.solve(f1_ + f2);
            err = scaled_norm(tmp_, error_count());
        }
        return err;
    }

    /// How many leading components the error estimate counts (Options::error_components; all when 0 or too many).
    Eigen::Index error_count() const {
        const Eigen::Index m = Eigen::Index(opts_.error_components);
        return m > 0 && m < x_.size() ? m : x_.size();
    }

    /// sqrt((1/n) Σ (e_i / sc_i)²) over the first n components (all where n < 0), at least 1e-10.
    Scalar scaled_norm(const State& e, Eigen::Index count = -1) const {
        using std::max;
        using std::sqrt;
        const Eigen::Index n = count < 0 ? e.size() : count;
        Scalar sum(0);
        for (Eigen::Index i = 0; i < n; ++i) sum += (e(i) / scal_(i)) * (e(i) / scal_(i));
        const Scalar err = sqrt(sum / Scalar(n));
        return err != err ? err : max(err, Scalar(1e-10));
    }

    /// Commits the converged step: the collocation polynomial's Newton form, then (t, x, f) ← (t_new, x + z₃, f1_).
    void accept(const Scalar& t_new) {
        const Constants& k = constants();
        // Divided differences over the nodes 0, c1, c2, 1 (values 0, z1, z2, z3) in θ.
        const Scalar c1 = k.c1, c2 = k.c2, one(1);
        d1_ = z1_ / c1;
        const State d12 = (z2_ - z1_) / (c2 - c1);
        const State d23 = (z3_ - z2_) / (one - c2);
        d2_ = (d12 - d1_) / c2;
        d3_ = ((d23 - d12) / (one - c1) - d2_);
        t_prev_ = t_;
        x_prev_ = x_;
        x_ = tmp_;
        f0_.swap(f1_);
        t_ = t_new;
        h_last_ = t_ - t_prev_;
        ++n_accepted_;
    }

    void retry(const Scalar& h, const Scalar& factor, Failure why) {
        h_ = h * factor;
        ++n_rejected_;
        rejected_last_ = true;
        last_failure_ = why;
        if (!jacobian_fresh_) need_jacobian_ = true;
    }

    [[noreturn]] void fail_below_hmin(const Scalar& hmin) const {
        std::ostringstream why;
        switch (last_failure_) {
        case Failure::NonFinite:
            why << "right-hand side or state not finite for every step size down to " << value_of(hmin);
            throw NonFiniteState(describe_state(why.str(), t_, x_), value_of(t_));
        case Failure::Newton:
        case Failure::Singular:
            why << "Radau5: Newton's iteration for the implicit stages did not converge for any step size down to "
                << "hmin = " << value_of(hmin) << " (a discontinuity, or a Jacobian that does not match f?)";
            break;
        default: why << "step size fell below hmin = " << value_of(hmin);
        }
        throw StepSizeUnderflow(describe_state(why.str(), t_, x_), value_of(t_));
    }

    Options opts_;
    Jacobian jac_;
    Scalar t_end_, t_, t_prev_;
    Scalar dir_ = Scalar(1), hmax_ = Scalar(0), h_ = Scalar(0), h_last_ = Scalar(0), h_lu_ = Scalar(0);
    Scalar rtol_ = Scalar(0), atol_ = Scalar(0), fnewt_ = Scalar(0);
    Scalar faccon_ = Scalar(1), theta_ = Scalar(0), h_acc_ = Scalar(0), err_acc_ = Scalar(1e-2);
    State x_, x_prev_, f0_, z1_, z2_, z3_, w1_, w2_, w3_, f1_, f2_, f3_, scal_, tmp_, d1_, d2_, d3_;
    Matrix J_;
    LuFactor<Matrix> lu_real_;
    LuFactor<ComplexMatrix> lu_complex_;
    bool first_ = true, rejected_last_ = false, need_jacobian_ = true, jacobian_fresh_ = false;
    Failure last_failure_ = Failure::None;
    int newton_iterations_ = 0, n_singular_ = 0;
    std::size_t n_accepted_ = 0, n_rejected_ = 0, n_rhs_ = 0, n_jac_ = 0, n_lu_ = 0;
};

/// What integrate_radau5() returns: integrate()'s result and the implicit method's own counters.
template <class State>
struct Radau5Result : IntegrationResult<State> {
    std::size_t jacobian_evaluations = 0;
    std::size_t lu_decompositions = 0;  ///< each one real and one complex n×n LU
};

/**
 * As integrate(), with Radau IIA of order 5 (Radau5) for stiff problems; jac(t, x, J) fills J = ∂f/∂x. Events
 * and samples use the collocation polynomial.
 */
template <class System, class JacobianFn, class State>
Radau5Result<State> integrate_radau5(System&& f, JacobianFn&& jac, const typename State::Scalar& t0, const State& x0,
                                     const typename State::Scalar& t_end,
                                     const Radau5Options<typename State::Scalar>& options = {},
                                     const std::vector<Event<State>>& events = {},
                                     const std::vector<typename State::Scalar>& sample_times = {},
                                     const typename detail::NonDeduced<Observer<State>>::type& observer = {}) {
    Radau5<State> stepper(f, typename Radau5<State>::Jacobian(std::forward<JacobianFn>(jac)), t0, x0, t_end, options);
    Radau5Result<State> result;
    static_cast<IntegrationResult<State>&>(result) =
        detail::drive(stepper, f, t0, x0, t_end, events, sample_times, observer);
    result.jacobian_evaluations = stepper.jacobian_evaluations();
    result.lu_decompositions = stepper.lu_decompositions();
    return result;
}

}  // namespace eomgen
