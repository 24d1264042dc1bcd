/** @file dop853.hpp  Adaptive Dormand–Prince 8(5,3) (Hairer's DOP853) with 7th-order dense output. */
#pragma once

#include "eomgen/embedded_rk.hpp"
#include "eomgen/errors.hpp"

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace eomgen {

/// Dopri5Options with the defaults of Hairer's DOP853 code: h_new/h within [0.333, 6], no PI term (β = 0).
template <class Scalar>
struct Dop853Options : Dopri5Options<Scalar> {
    Dop853Options() {
        this->min_factor = Scalar(0.333);
        this->max_factor = Scalar(6);
        this->beta = Scalar(0);
    }
};

namespace detail::dop853 {
// The tableau of DOP853 (Dormand & Prince, "High order embedded Runge–Kutta formulae", J. Comput. Appl. Math.
// 7 (1981); as tabulated in Hairer's dop853.f, the version of HNW I §II.10 with the stages 14–16 of its
// dense output). 30 significant digits, enough for long double. Stages are numbered 1…16 as there;
// stage 13 is f(t + h, x_new), the first stage of the next step.
constexpr long double c2 = 0.526001519587677318785587544488e-01L, c3 = 0.789002279381515978178381316732e-01L,
                      c4 = 0.118350341907227396726757197510e+00L, c5 = 0.281649658092772603273242802490e+00L,
                      c6 = 0.333333333333333333333333333333e+00L, c7 = 0.25e+00L,
                      c8 = 0.307692307692307692307692307692e+00L, c9 = 0.651282051282051282051282051282e+00L,
                      c10 = 0.6e+00L, c11 = 0.857142857142857142857142857142e+00L, c14 = 0.1e+00L,
                      c15 = 0.2e+00L, c16 = 0.777777777777777777777777777778e+00L;

constexpr long double b1 = 5.42937341165687622380535766363e-2L, b6 = 4.45031289275240888144113950566e0L,
                      b7 = 1.89151789931450038304281599044e0L, b8 = -5.8012039600105847814672114227e0L,
                      b9 = 3.1116436695781989440891606237e-1L, b10 = -1.52160949662516078556178806805e-1L,
                      b11 = 2.01365400804030348374776537501e-1L, b12 = 4.47106157277725905176885569043e-2L;

// The 3rd-order estimate: b − bhh on stages 1, 9, 12.
constexpr long double bhh1 = 0.244094488188976377952755905512e+00L,
                      bhh2 = 0.733846688281611857341361741547e+00L,
                      bhh3 = 0.220588235294117647058823529412e-01L;

// The 5th-order estimate b − b̂.
constexpr long double er1 = 0.1312004499419488073250102996e-01L, er6 = -0.1225156446376204440720569753e+01L,
                      er7 = -0.4957589496572501915214079952e+00L, er8 = 0.1664377182454986536961530415e+01L,
                      er9 = -0.3503288487499736816886487290e+00L, er10 = 0.3341791187130174790297318841e+00L,
                      er11 = 0.8192320648511571246570742613e-01L, er12 = -0.2235530786388629525884427845e-01L;

constexpr long double a21 = 5.26001519587677318785587544488e-2L, a31 = 1.97250569845378994544595329183e-2L,
                      a32 = 5.91751709536136983633785987549e-2L, a41 = 2.95875854768068491816892993775e-2L,
                      a43 = 8.87627564304205475450678981324e-2L, a51 = 2.41365134159266685502369798665e-1L,
                      a53 = -8.84549479328286085344864962717e-1L, a54 = 9.24834003261792003115737966543e-1L,
                      a61 = 3.7037037037037037037037037037e-2L, a64 = 1.70828608729473871279604482173e-1L,
                      a65 = 1.25467687566822425016691814123e-1L, a71 = 3.7109375e-2L,
                      a74 = 1.70252211019544039314978060272e-1L, a75 = 6.02165389804559606850219397283e-2L,
                      a76 = -1.7578125e-2L;
constexpr long double a81 = 3.70920001185047927108779319836e-2L, a84 = 1.70383925712239993810214054705e-1L,
                      a85 = 1.07262030446373284651809199168e-1L, a86 = -1.53194377486244017527936158236e-2L,
                      a87 = 8.27378916381402288758473766002e-3L;
constexpr long double a91 = 6.24110958716075717114429577812e-1L, a94 = -3.36089262944694129406857109825e0L,
                      a95 = -8.68219346841726006818189891453e-1L, a96 = 2.75920996994467083049415600797e1L,
                      a97 = 2.01540675504778934086186788979e1L, a98 = -4.34898841810699588477366255144e1L;
constexpr long double a101 = 4.77662536438264365890433908527e-1L, a104 = -2.48811461997166764192642586468e0L,
                      a105 = -5.90290826836842996371446475743e-1L, a106 = 2.12300514481811942347288949897e1L,
                      a107 = 1.52792336328824235832596922938e1L, a108 = -3.32882109689848629194453265587e1L,
                      a109 = -2.03312017085086261358222928593e-2L;
constexpr long double a111 = -9.3714243008598732571704021658e-1L, a114 = 5.18637242884406370830023853209e0L,
                      a115 = 1.09143734899672957818500254654e0L, a116 = -8.14978701074692612513997267357e0L,
                      a117 = -1.85200656599969598641566180701e1L, a118 = 2.27394870993505042818970056734e1L,
                      a119 = 2.49360555267965238987089396762e0L, a1110 = -3.0467644718982195003823669022e0L;
constexpr long double a121 = 2.27331014751653820792359768449e0L, a124 = -1.05344954667372501984066689879e1L,
                      a125 = -2.00087205822486249909675718444e0L, a126 = -1.79589318631187989172765950534e1L,
                      a127 = 2.79488845294199600508499808837e1L, a128 = -2.85899827713502369474065508674e0L,
                      a129 = -8.87285693353062954433549289258e0L, a1210 = 1.23605671757943030647266201528e1L,
                      a1211 = 6.43392746015763530355970484046e-1L;
// Stages 14–16, for the dense output only.
constexpr long double a141 = 5.61675022830479523392909219681e-2L, a147 = 2.53500210216624811088794765333e-1L,
                      a148 = -2.46239037470802489917441475441e-1L,
                      a149 = -1.24191423263816360469010140626e-1L, a1410 = 1.5329179827876569731206322685e-1L,
                      a1411 = 8.20105229563468988491666602057e-3L,
                      a1412 = 7.56789766054569976138603589584e-3L, a1413 = -8.298e-3L;
constexpr long double a151 = 3.18346481635021405060768473261e-2L, a156 = 2.83009096723667755288322961402e-2L,
                      a157 = 5.35419883074385676223797384372e-2L, a158 = -5.49237485713909884646569340306e-2L,
                      a1511 = -1.08347328697249322858509316994e-4L,
                      a1512 = 3.82571090835658412954920192323e-4L,
                      a1513 = -3.40465008687404560802977114492e-4L,
                      a1514 = 1.41312443674632500278074618366e-1L;
constexpr long double a161 = -4.28896301583791923408573538692e-1L, a166 = -4.69762141536116384314449447206e0L,
                      a167 = 7.68342119606259904184240953878e0L, a168 = 4.06898981839711007970213554331e0L,
                      a169 = 3.56727187455281109270669543021e-1L,
                      a1613 = -1.39902416515901462129418009734e-3L, a1614 = 2.9475147891527723389556272149e0L,
                      a1615 = -9.15095847217987001081870187138e0L;

// Dense output: row j = 4…7 on stages 1, 6…16.
constexpr long double d41 = -0.84289382761090128651353491142e+01L, d46 = 0.56671495351937776962531783590e+00L,
                      d47 = -0.30689499459498916912797304727e+01L, d48 = 0.23846676565120698287728149680e+01L,
                      d49 = 0.21170345824450282767155149946e+01L,
                      d410 = -0.87139158377797299206789907490e+00L,
                      d411 = 0.22404374302607882758541771650e+01L,
                      d412 = 0.63157877876946881815570249290e+00L,
                      d413 = -0.88990336451333310820698117400e-01L,
                      d414 = 0.18148505520854727256656404962e+02L,
                      d415 = -0.91946323924783554000451984436e+01L,
                      d416 = -0.44360363875948939664310572000e+01L;
constexpr long double d51 = 0.10427508642579134603413151009e+02L, d56 = 0.24228349177525818288430175319e+03L,
                      d57 = 0.16520045171727028198505394887e+03L, d58 = -0.37454675472269020279518312152e+03L,
                      d59 = -0.22113666853125306036270938578e+02L,
                      d510 = 0.77334326684722638389603898808e+01L,
                      d511 = -0.30674084731089398182061213626e+02L,
                      d512 = -0.93321305264302278729567221706e+01L,
                      d513 = 0.15697238121770843886131091075e+02L,
                      d514 = -0.31139403219565177677282850411e+02L,
                      d515 = -0.93529243588444783865713862664e+01L,
                      d516 = 0.35816841486394083752465898540e+02L;
constexpr long double d61 = 0.19985053242002433820987653617e+02L, d66 = -0.38703730874935176555105901742e+03L,
                      d67 = -0.18917813819516756882830838328e+03L, d68 = 0.52780815920542364900561016686e+03L,
                      d69 = -0.11573902539959630126141871134e+02L,
                      d610 = 0.68812326946963000169666922661e+01L,
                      d611 = -0.10006050966910838403183860980e+01L,
                      d612 = 0.77771377980534432092869265740e+00L,
                      d613 = -0.27782057523535084065932004339e+01L,
                      d614 = -0.60196695231264120758267380846e+02L,
                      d615 = 0.84320405506677161018159903784e+02L,
                      d616 = 0.11992291136182789328035130030e+02L;
constexpr long double d71 = -0.25693933462703749003312586129e+02L,
                      d76 = -0.15418974869023643374053993627e+03L,
                      d77 = -0.23152937917604549567536039109e+03L, d78 = 0.35763911791061412378285349910e+03L,
                      d79 = 0.93405324183624310003907691704e+02L,
                      d710 = -0.37458323136451633156875139351e+02L,
                      d711 = 0.10409964950896230045147246184e+03L,
                      d712 = 0.29840293426660503123344363579e+02L,
                      d713 = -0.43533456590011143754432175058e+02L,
                      d714 = 0.96324553959188282948394950600e+02L,
                      d715 = -0.39177261675615439165231486172e+02L,
                      d716 = -0.14972683625798562581422125276e+03L;
}  // namespace detail::dop853

/**
 * Dormand–Prince 8(5,3), Hairer's DOP853 (HNW "Solving ODEs I", §II.10, and the code dop853.f): an explicit
 * Runge–Kutta method of order 8 with 12 stages, one accepted step per call of step(), for x' = f(t, x) with
 * `System` any callable f(const Scalar& t, const State& x, State& xdot) and `State` an Eigen column vector
 * (fixed or dynamic size; Scalar double or long double). Same interface and errors as Dopri5.
 *
 * Error control (HNW I §II.10, "an 8th order method with a 5th and a 3rd order error estimator"): with
 *   E5 = Σ_i (e5_i / sc_i)²,  E3 = Σ_i (e3_i / sc_i)²,  sc_i = atol + rtol·max(|x_i|, |x_new_i|),
 * e5 = Σ (b − b̂)_j k_j and e3 = Σ b_j k_j − (bhh1 k1 + bhh2 k9 + bhh3 k12) the two embedded differences,
 *   err = |h| · E5 / sqrt( n · (E5 + 0.01 E3) ) ≤ 1
 * accepts the step: an estimate that behaves like the 5th-order one for small h but cannot be fooled by an
 * accidentally small 5th-order difference at large h. Step size, start and errors: detail::EmbeddedRk
 * (embedded_rk.hpp) with q = 8 and h_new/h = clamp(safety · err^(-(1/8 − 0.2 β)) · err_prev^β, ...).
 * Each accepted step costs 12 evaluations of f (the 13th, f(t + h, x_new), is the next step's first); a
 * rejected one 11.
 *
 * Dense output on the last accepted step [t_prev, t], 7th order (Hairer's CONTD8), θ = (t − t_prev)/h:
 *   u(θ) = r1 + θ(r2 + (1−θ)(r3 + θ(r4 + (1−θ)(r5 + θ(r6 + (1−θ)(r7 + θ r8)))))),
 *   r1 = x0, r2 = x1 − x0, r3 = h k1 − r2, r4 = r2 − h k13 − r3, r_{j+1} = h Σ_i d_{j,i} k_i (j = 4…7),
 * exact at both ends. It needs three more stages (14–16), so it is built on demand: call prepare_dense(f)
 * once after a step before dense() inside it (integrate's driver does, and only on steps where an event or
 * a sample falls); it costs three evaluations of f, counted in rhs_evaluations().
 */
template <class State>
class Dop853 : public detail::EmbeddedRk<Dop853<State>, State> {
    using Base = detail::EmbeddedRk<Dop853<State>, State>;
    friend Base;

  public:
    using Scalar = typename State::Scalar;
    using Options = Dop853Options<Scalar>;

    /// Prepares integration from (t0, x0) towards t_end (either direction). Evaluates f once or twice.
    template <class System>
    Dop853(System&& f, const Scalar& t0, const State& x0, const Scalar& t_end, const Options& options = {})
        : Base(f, t0, x0, t_end, options, "Dop853", 8, Scalar(0.2)),
          k2_(x0),
          k3_(x0),
          k4_(x0),
          k5_(x0),
          k6_(x0),
          k7_(x0),
          k8_(x0),
          k9_(x0),
          k10_(x0),
          k11_(x0),
          k12_(x0),
          k13_(x0),
          k14_(x0),
          k15_(x0),
          k16_(x0),
          e3_(x0),
          r2_(x0),
          r3_(x0),
          r4_(x0),
          r5_(x0),
          r6_(x0),
          r7_(x0),
          r8_(x0) {}

    /// Evaluates the three extra stages of the last step's dense output (once per step; no-op before the
    /// first step). Throws NonFiniteState if one of them is not finite.
    template <class System>
    void prepare_dense(System&& f) {
        namespace c = detail::dop853;
        if (dense_ready_ || this->n_accepted_ == 0) return;
        const Scalar& t = this->t_prev_;
        const State& x = this->x_prev_;
        const State& k1 = k13_;        // swapped by commit(): the old step's first stage
        const State& k13 = this->k1_;  // and f(t + h, x_new)
        const Scalar h = h_step_;
        State& xs = this->xs_;
        xs = x + h * (S(c::a141) * k1 + S(c::a147) * k7_ + S(c::a148) * k8_ + S(c::a149) * k9_ +
                      S(c::a1410) * k10_ + S(c::a1411) * k11_ + S(c::a1412) * k12_ + S(c::a1413) * k13);
        this->evaluate(f, t + S(c::c14) * h, xs, k14_);
        xs = x + h * (S(c::a151) * k1 + S(c::a156) * k6_ + S(c::a157) * k7_ + S(c::a158) * k8_ +
                      S(c::a1511) * k11_ + S(c::a1512) * k12_ + S(c::a1513) * k13 + S(c::a1514) * k14_);
        this->evaluate(f, t + S(c::c15) * h, xs, k15_);
        xs = x + h * (S(c::a161) * k1 + S(c::a166) * k6_ + S(c::a167) * k7_ + S(c::a168) * k8_ +
                      S(c::a169) * k9_ + S(c::a1613) * k13 + S(c::a1614) * k14_ + S(c::a1615) * k15_);
        this->evaluate(f, t + S(c::c16) * h, xs, k16_);
        if (!k14_.allFinite() || !k15_.allFinite() || !k16_.allFinite())
            throw NonFiniteState(
                describe_state("right-hand side is not finite at a dense-output stage", t, x), value_of(t));
        r5_ = h * (r5_ + S(c::d413) * k13 + S(c::d414) * k14_ + S(c::d415) * k15_ + S(c::d416) * k16_);
        r6_ = h * (r6_ + S(c::d513) * k13 + S(c::d514) * k14_ + S(c::d515) * k15_ + S(c::d516) * k16_);
        r7_ = h * (r7_ + S(c::d613) * k13 + S(c::d614) * k14_ + S(c::d615) * k15_ + S(c::d616) * k16_);
        r8_ = h * (r8_ + S(c::d713) * k13 + S(c::d714) * k14_ + S(c::d715) * k15_ + S(c::d716) * k16_);
        dense_ready_ = true;
    }

    /// Whether prepare_dense() has run for the last step (dense() inside the step needs it).
    bool dense_ready() const { return dense_ready_; }

    /// Dense output at t in [t_prev, t] of the last accepted step (CONTD8); exact at both ends, which need
    /// no prepare_dense(). Throws std::logic_error inside the step without it.
    void dense(const Scalar& t, State& x) const {
        if (this->dense_at_node(t, x)) return;
        if (!dense_ready_) throw std::logic_error("Dop853::dense: call prepare_dense(f) after step() first");
        const Scalar s = (t - this->t_prev_) / this->h_last_;
        const Scalar s1 = Scalar(1) - s;
        x = this->x_prev_ +
            s * (r2_ + s1 * (r3_ + s * (r4_ + s1 * (r5_ + s * (r6_ + s1 * (r7_ + s * r8_))))));
    }

  private:
    static Scalar S(long double v) { return Scalar(v); }

    /// One trial step of size h: stages 2–12, x_new, the combined error; on success also stage 13.
    template <class System>
    Scalar attempt(System& f, const Scalar& h) {
        namespace c = detail::dop853;
        using std::abs;
        using std::sqrt;
        const Scalar& t = this->t_;
        const State& x = this->x_;
        const State& k1 = this->k1_;
        State& xs = this->xs_;
        State& x_new = this->x_new_;
        xs = x + h * (S(c::a21) * k1);
        this->evaluate(f, t + S(c::c2) * h, xs, k2_);
        xs = x + h * (S(c::a31) * k1 + S(c::a32) * k2_);
        this->evaluate(f, t + S(c::c3) * h, xs, k3_);
        xs = x + h * (S(c::a41) * k1 + S(c::a43) * k3_);
        this->evaluate(f, t + S(c::c4) * h, xs, k4_);
        xs = x + h * (S(c::a51) * k1 + S(c::a53) * k3_ + S(c::a54) * k4_);
        this->evaluate(f, t + S(c::c5) * h, xs, k5_);
        xs = x + h * (S(c::a61) * k1 + S(c::a64) * k4_ + S(c::a65) * k5_);
        this->evaluate(f, t + S(c::c6) * h, xs, k6_);
        xs = x + h * (S(c::a71) * k1 + S(c::a74) * k4_ + S(c::a75) * k5_ + S(c::a76) * k6_);
        this->evaluate(f, t + S(c::c7) * h, xs, k7_);
        xs = x + h * (S(c::a81) * k1 + S(c::a84) * k4_ + S(c::a85) * k5_ + S(c::a86) * k6_ + S(c::a87) * k7_);
        this->evaluate(f, t + S(c::c8) * h, xs, k8_);
        xs = x + h * (S(c::a91) * k1 + S(c::a94) * k4_ + S(c::a95) * k5_ + S(c::a96) * k6_ + S(c::a97) * k7_ +
                      S(c::a98) * k8_);
        this->evaluate(f, t + S(c::c9) * h, xs, k9_);
        xs = x + h * (S(c::a101) * k1 + S(c::a104) * k4_ + S(c::a105) * k5_ + S(c::a106) * k6_ +
                      S(c::a107) * k7_ + S(c::a108) * k8_ + S(c::a109) * k9_);
        this->evaluate(f, t + S(c::c10) * h, xs, k10_);
        xs = x + h * (S(c::a111) * k1 + S(c::a114) * k4_ + S(c::a115) * k5_ + S(c::a116) * k6_ +
                      S(c::a117) * k7_ + S(c::a118) * k8_ + S(c::a119) * k9_ + S(c::a1110) * k10_);
        this->evaluate(f, t + S(c::c11) * h, xs, k11_);
        xs = x + h * (S(c::a121) * k1 + S(c::a124) * k4_ + S(c::a125) * k5_ + S(c::a126) * k6_ +
                      S(c::a127) * k7_ + S(c::a128) * k8_ + S(c::a129) * k9_ + S(c::a1210) * k10_ +
                      S(c::a1211) * k11_);
        this->evaluate(f, t + h, xs, k12_);
        // xs becomes Σ b_j k_j, the 8th-order increment per unit h.
        xs = S(c::b1) * k1 + S(c::b6) * k6_ + S(c::b7) * k7_ + S(c::b8) * k8_ + S(c::b9) * k9_ +
             S(c::b10) * k10_ + S(c::b11) * k11_ + S(c::b12) * k12_;
        x_new = x + h * xs;
        if (!x_new.allFinite()) return std::numeric_limits<Scalar>::quiet_NaN();
        e3_ = xs - S(c::bhh1) * k1 - S(c::bhh2) * k9_ - S(c::bhh3) * k12_;
        const Scalar err3 = this->scaled_sum_of_squares(e3_);
        e3_ = S(c::er1) * k1 + S(c::er6) * k6_ + S(c::er7) * k7_ + S(c::er8) * k8_ + S(c::er9) * k9_ +
              S(c::er10) * k10_ + S(c::er11) * k11_ + S(c::er12) * k12_;
        const Scalar err5 = this->scaled_sum_of_squares(e3_);
        Scalar deno = err5 + Scalar(0.01) * err3;
        if (deno <= Scalar(0)) deno = Scalar(1);
        const Scalar err = abs(h) * err5 / sqrt(Scalar(this->error_count()) * deno);
        if (!(err <= Scalar(1))) return err;  // rejected (or NaN): stage 13 is not needed
        this->evaluate(f, t + h, x_new, k13_);
        if (!k13_.allFinite()) return std::numeric_limits<Scalar>::quiet_NaN();
        return err;
    }

    /// The parts of the dense output that need no extra stage, then (t, x, f) ← (t + h, x_new, k13).
    void accept(const Scalar& h, bool last) {
        namespace c = detail::dop853;
        const State& k1 = this->k1_;
        r2_ = this->x_new_ - this->x_;
        r3_ = h * k1 - r2_;
        r4_ = r2_ - h * k13_ - r3_;
        r5_ = S(c::d41) * k1 + S(c::d46) * k6_ + S(c::d47) * k7_ + S(c::d48) * k8_ + S(c::d49) * k9_ +
              S(c::d410) * k10_ + S(c::d411) * k11_ + S(c::d412) * k12_;
        r6_ = S(c::d51) * k1 + S(c::d56) * k6_ + S(c::d57) * k7_ + S(c::d58) * k8_ + S(c::d59) * k9_ +
              S(c::d510) * k10_ + S(c::d511) * k11_ + S(c::d512) * k12_;
        r7_ = S(c::d61) * k1 + S(c::d66) * k6_ + S(c::d67) * k7_ + S(c::d68) * k8_ + S(c::d69) * k9_ +
              S(c::d610) * k10_ + S(c::d611) * k11_ + S(c::d612) * k12_;
        r8_ = S(c::d71) * k1 + S(c::d76) * k6_ + S(c::d77) * k7_ + S(c::d78) * k8_ + S(c::d79) * k9_ +
              S(c::d710) * k10_ + S(c::d711) * k11_ + S(c::d712) * k12_;
        h_step_ = h;
        dense_ready_ = false;
        this->commit(h, last, k13_);  // first same as last; the old k1 is now in k13_
    }

    State k2_, k3_, k4_, k5_, k6_, k7_, k8_, k9_, k10_, k11_, k12_, k13_, k14_, k15_, k16_, e3_;
    State r2_, r3_, r4_, r5_, r6_, r7_, r8_;
    Scalar h_step_ = Scalar(0);
    bool dense_ready_ = false;
};

}  // namespace eomgen
