// Dormand–Prince 8(5,3): the explicit Runge–Kutta method of E. Hairer's DOP853, with its
// dense output of order 7 (docs/dop853.md).
//
// Method: Hairer, Nørsett & Wanner, Solving Ordinary Differential Equations I (2nd ed.,
// Springer 1993), §II.5 (the Dormand–Prince pair of order 8 with the error estimators of
// orders 5 and 3) and §II.6 (its continuous extension of order 7, three more stages);
// §II.4 (step-size control, the starting step of "hinit"). The coefficients below are those
// Hairer publishes with dop853.f (version of 2004, http://www.unige.ch/~hairer/software.html),
// as transcribed with 30 digits in SciPy's scipy/integrate/_ivp/dop853_coefficients.py
// (BSD); the code is written from the book, not from either program.
//
// The integrator follows the contract of integration.hpp (HookedOdeIntegrator). Its own: only
// the last output time ends a step; the steps are chosen by the error alone and the outputs
// inside a step come from the dense output (three more RHS evaluations in a step that holds
// one), so the step sequence does not depend on the output times (tested).
// Templated on the scalar S and the dimension N (N = Dynamic for a size chosen at run time).
// The coefficients are long double literals (30 digits transcribed, ~19 kept): in
// __float128 the method's order conditions hold to ~1e-19 only, so it is no extended-
// precision integrator (the scenes refuse dop853 with precision long or quad).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "nanopush/numerics/integration.hpp"  // Dynamic, the status, the result, the contract
#include "nanopush/numerics/scalar.hpp"

namespace nanopush {

/// The smallest rtol dop853 accepts, in units of the scalar's epsilon (Hairer's dop853:
/// "tolerances are too small" below 10 uround): below it the difference of the embedded
/// solutions is rounding, and the step size follows it.
/// rtol_in_eps<S>(kDop853RtolEps) is that rtol in the scalar S.
inline constexpr double kDop853RtolEps = 10.0;

template <typename Scalar>
struct Dop853Options {
  Scalar rtol = Scalar(1e-10);  ///< > 10 eps of Scalar, < 1
  std::vector<Scalar> atol;     ///< per component (size n) or one value for all; each > 0
  Scalar h0 = 0;                ///< initial step; 0 = Hairer's starting-step guess (hinit, 1 RHS)
  Scalar hmax = 0;              ///< largest step; 0 = the span tout(last) - t0
  std::int64_t maxstp = 100000;  ///< attempted steps before giving up (too_many_steps)
  /// Step-size control (HNW §II.4, the constants of dop853.f): h_new = h / fac with
  /// fac = err^(1/8 - 0.2 beta) / err_old^beta / safe, clamped so that
  /// facmin <= h_new / h <= facmax.
  double safe = 0.9;
  double facmin = 0.333;
  double facmax = 6.0;
  /// Lund stabilisation (PI control), in [0, 0.2]. dop853.f's default is 0; 0.04 (DOPRI5's
  /// default) is ours: on the nanobar the 5th-order estimator, squared in err, swings by
  /// factors of 10-100 from step to step, and with beta = 0 a fifth to a quarter of the
  /// attempts were rejected (fig3_6a, rtol 1e-8..1e-12); with 0.04 3-20 %, and 4-8 % fewer
  /// RHS evaluations at matched errors 1e-5..1e-12 summed over fig3_6a/b/c (docs/dop853.md).
  double beta = 0.04;

  static Dop853Options make(Scalar rtol, std::vector<Scalar> atol) {
    Dop853Options o;
    o.rtol = rtol;
    o.atol = std::move(atol);
    return o;
  }
};

/// BsResult (status, rhs_status, nfcn, naccpt, nrejct, t_reached, message) and two counts of
/// its own. nrejct counts every rejected attempt (dop853.f leaves out those before the first
/// accepted step). A Dop853Result assigns to a BsResult (the scene's Trajectory::stats).
struct Dop853Result : BsResult {
  std::int64_t nstep = 0;   ///< attempted steps (naccpt + nrejct, and a step whose end RHS failed)
  std::int64_t ndense = 0;  ///< steps whose interpolant was built (3 RHS evaluations each)
};

namespace dop853_tableau {
// Nodes c_i, coupling a_ij, weights b_i (order 8), the error estimators of orders 5 (er_i)
// and 3 (b_i - bhh_i on stages 1, 9, 12), the three dense-output stages 14-16 and the
// dense-output coefficients d_{r,i} (r = 4..7). Stage numbers as in the book (1-based):
// stage 13 is f(t + h, y_new), the next step's stage 1. Zero entries are left out. One
// declaration a row of the tableau (a stage's a_ij, the b_i, ...), as the book prints it.
template <class S>
struct T {
  static constexpr S c2 = S(0.526001519587677318785587544488e-01L), c3 = S(0.789002279381515978178381316732e-01L), c4 = S(0.118350341907227396726757197510e+00L), c5 = S(0.281649658092772603273242802490e+00L), c6 = S(0.333333333333333333333333333333e+00L), c7 = S(0.25e+00L), c8 = S(0.307692307692307692307692307692e+00L), c9 = S(0.651282051282051282051282051282e+00L), c10 = S(0.6e+00L), c11 = S(0.857142857142857142857142857142e+00L);
  static constexpr S c14 = S(0.1e+00L), c15 = S(0.2e+00L), c16 = S(0.777777777777777777777777777778e+00L);

  static constexpr S a21 = S(5.26001519587677318785587544488e-2L);
  static constexpr S a31 = S(1.97250569845378994544595329183e-2L), a32 = S(5.91751709536136983633785987549e-2L);
  static constexpr S a41 = S(2.95875854768068491816892993775e-2L), a43 = S(8.87627564304205475450678981324e-2L);
  static constexpr S a51 = S(2.41365134159266685502369798665e-1L), a53 = S(-8.84549479328286085344864962717e-1L), a54 = S(9.24834003261792003115737966543e-1L);
  static constexpr S a61 = S(3.7037037037037037037037037037e-2L), a64 = S(1.70828608729473871279604482173e-1L), a65 = S(1.25467687566822425016691814123e-1L);
  static constexpr S a71 = S(3.7109375e-2L), a74 = S(1.70252211019544039314978060272e-1L), a75 = S(6.02165389804559606850219397283e-2L), a76 = S(-1.7578125e-2L);
  static constexpr S a81 = S(3.70920001185047927108779319836e-2L), a84 = S(1.70383925712239993810214054705e-1L), a85 = S(1.07262030446373284651809199168e-1L), a86 = S(-1.53194377486244017527936158236e-2L), a87 = S(8.27378916381402288758473766002e-3L);
  static constexpr S a91 = S(6.24110958716075717114429577812e-1L), a94 = S(-3.36089262944694129406857109825e+0L), a95 = S(-8.68219346841726006818189891453e-1L), a96 = S(2.75920996994467083049415600797e+1L), a97 = S(2.01540675504778934086186788979e+1L), a98 = S(-4.34898841810699588477366255144e+1L);
  static constexpr S a101 = S(4.77662536438264365890433908527e-1L), a104 = S(-2.48811461997166764192642586468e+0L), a105 = S(-5.90290826836842996371446475743e-1L), a106 = S(2.12300514481811942347288949897e+1L), a107 = S(1.52792336328824235832596922938e+1L), a108 = S(-3.32882109689848629194453265587e+1L), a109 = S(-2.03312017085086261358222928593e-2L);
  static constexpr S a111 = S(-9.3714243008598732571704021658e-1L), a114 = S(5.18637242884406370830023853209e+0L), a115 = S(1.09143734899672957818500254654e+0L), a116 = S(-8.14978701074692612513997267357e+0L), a117 = S(-1.85200656599969598641566180701e+1L), a118 = S(2.27394870993505042818970056734e+1L), a119 = S(2.49360555267965238987089396762e+0L), a1110 = S(-3.0467644718982195003823669022e+0L);
  static constexpr S a121 = S(2.27331014751653820792359768449e+0L), a124 = S(-1.05344954667372501984066689879e+1L), a125 = S(-2.00087205822486249909675718444e+0L), a126 = S(-1.79589318631187989172765950534e+1L), a127 = S(2.79488845294199600508499808837e+1L), a128 = S(-2.85899827713502369474065508674e+0L), a129 = S(-8.87285693353062954433549289258e+0L), a1210 = S(1.23605671757943030647266201528e+1L), a1211 = S(6.43392746015763530355970484046e-1L);

  // Weights of the order-8 solution (stages 1, 6..12).
  static constexpr S b1 = S(5.42937341165687622380535766363e-2L), b6 = S(4.45031289275240888144113950566e+0L), b7 = S(1.89151789931450038304281599044e+0L), b8 = S(-5.8012039600105847814672114227e+0L), b9 = S(3.1116436695781989440891606237e-1L), b10 = S(-1.52160949662516078556178806805e-1L), b11 = S(2.01365400804030348374776537501e-1L), b12 = S(4.47106157277725905176885569043e-2L);

  // The order-3 estimator: sum b_i k_i - bhh1 k1 - bhh2 k9 - bhh3 k12.
  static constexpr S bhh1 = S(0.244094488188976377952755905512e+00L), bhh2 = S(0.733846688281611857341361741547e+00L), bhh3 = S(0.220588235294117647058823529412e-01L);

  // The order-5 estimator (difference of the order-8 and an order-5 solution).
  static constexpr S er1 = S(0.1312004499419488073250102996e-01L), er6 = S(-0.1225156446376204440720569753e+01L), er7 = S(-0.4957589496572501915214079952e+00L), er8 = S(0.1664377182454986536961530415e+01L), er9 = S(-0.3503288487499736816886487290e+00L), er10 = S(0.3341791187130174790297318841e+00L), er11 = S(0.8192320648511571246570742613e-01L), er12 = S(-0.2235530786388629525884427845e-01L);

  // Dense-output stages 14 (c = 0.1), 15 (0.2), 16 (7/9).
  static constexpr S a141 = S(5.61675022830479523392909219681e-2L), a147 = S(2.53500210216624811088794765333e-1L), a148 = S(-2.46239037470802489917441475441e-1L), a149 = S(-1.24191423263816360469010140626e-1L), a1410 = S(1.5329179827876569731206322685e-1L), a1411 = S(8.20105229563468988491666602057e-3L), a1412 = S(7.56789766054569976138603589584e-3L), a1413 = S(-8.298e-3L);
  static constexpr S a151 = S(3.18346481635021405060768473261e-2L), a156 = S(2.83009096723667755288322961402e-2L), a157 = S(5.35419883074385676223797384372e-2L), a158 = S(-5.49237485713909884646569340306e-2L), a1511 = S(-1.08347328697249322858509316994e-4L), a1512 = S(3.82571090835658412954920192323e-4L), a1513 = S(-3.40465008687404560802977114492e-4L), a1514 = S(1.41312443674632500278074618366e-1L);
  static constexpr S a161 = S(-4.28896301583791923408573538692e-1L), a166 = S(-4.69762141536116384314449447206e+0L), a167 = S(7.68342119606259904184240953878e+0L), a168 = S(4.06898981839711007970213554331e+0L), a169 = S(3.56727187455281109270669543021e-1L), a1613 = S(-1.39902416515901462129418009734e-3L), a1614 = S(2.9475147891527723389556272149e+0L), a1615 = S(-9.15095847217987001081870187138e+0L);

  // Dense output: d_{r,i}, r = 4..7, on stages 1, 6..16.
  static constexpr S d41 = S(-0.84289382761090128651353491142e+01L), d46 = S(0.56671495351937776962531783590e+00L), d47 = S(-0.30689499459498916912797304727e+01L), d48 = S(0.23846676565120698287728149680e+01L), d49 = S(0.21170345824450282767155149946e+01L), d410 = S(-0.87139158377797299206789907490e+00L), d411 = S(0.22404374302607882758541771650e+01L), d412 = S(0.63157877876946881815570249290e+00L), d413 = S(-0.88990336451333310820698117400e-01L), d414 = S(0.18148505520854727256656404962e+02L), d415 = S(-0.91946323924783554000451984436e+01L), d416 = S(-0.44360363875948939664310572000e+01L);
  static constexpr S d51 = S(0.10427508642579134603413151009e+02L), d56 = S(0.24228349177525818288430175319e+03L), d57 = S(0.16520045171727028198505394887e+03L), d58 = S(-0.37454675472269020279518312152e+03L), d59 = S(-0.22113666853125306036270938578e+02L), d510 = S(0.77334326684722638389603898808e+01L), d511 = S(-0.30674084731089398182061213626e+02L), d512 = S(-0.93321305264302278729567221706e+01L), d513 = S(0.15697238121770843886131091075e+02L), d514 = S(-0.31139403219565177677282850411e+02L), d515 = S(-0.93529243588444783865713862664e+01L), d516 = S(0.35816841486394083752465898540e+02L);
  static constexpr S d61 = S(0.19985053242002433820987653617e+02L), d66 = S(-0.38703730874935176555105901742e+03L), d67 = S(-0.18917813819516756882830838328e+03L), d68 = S(0.52780815920542364900561016686e+03L), d69 = S(-0.11573902539959630126141871134e+02L), d610 = S(0.68812326946963000169666922661e+01L), d611 = S(-0.10006050966910838403183860980e+01L), d612 = S(0.77771377980534432092869265740e+00L), d613 = S(-0.27782057523535084065932004339e+01L), d614 = S(-0.60196695231264120758267380846e+02L), d615 = S(0.84320405506677161018159903784e+02L), d616 = S(0.11992291136182789328035130030e+02L);
  static constexpr S d71 = S(-0.25693933462703749003312586129e+02L), d76 = S(-0.15418974869023643374053993627e+03L), d77 = S(-0.23152937917604549567536039109e+03L), d78 = S(0.35763911791061412378285349910e+03L), d79 = S(0.93405324183624310003907691704e+02L), d710 = S(-0.37458323136451633156875139351e+02L), d711 = S(0.10409964950896230045147246184e+03L), d712 = S(0.29840293426660503123344363579e+02L), d713 = S(-0.43533456590011143754432175058e+02L), d714 = S(0.96324553959188282948394950600e+02L), d715 = S(-0.39177261675615439165231486172e+02L), d716 = S(-0.14972683625798562581422125276e+03L);
};
}  // namespace dop853_tableau

template <typename Scalar, int N = Dynamic>
class Dop853 : public IntegratorBase<Dop853<Scalar, N>, Scalar, Dop853Result, Dop853Options<Scalar>> {
  using Base = IntegratorBase<Dop853, Scalar, Dop853Result, Dop853Options<Scalar>>;

 public:
  using Vec = StateVec<Scalar, N>;

  explicit Dop853(Dop853Options<Scalar> opt, int n = N) : Base(std::move(opt), n) {
    for (Vec& v : k_) size_states(n_, v);
    for (Vec& v : cont_) size_states(n_, v);
    size_states(n_, y_, ynew_, ys_, atol_);
  }

  /// Integrate without a step hook, or to one output time (integration.hpp).
  using Base::integrate;

  /// Integrate as integration.hpp's contract says (y, t_reached, the step hook), in dop853.f's
  /// loop: stages, error_norm, the step size control, the outputs (dense output on demand).
  template <class Rhs, class Observer, class Hook>
  Dop853Result integrate(Rhs&& rhs, Scalar t0, Scalar* y, std::span<const Scalar> tout, Observer&& observer,
                         Hook&& hook) {
    const int n = (N == Dynamic) ? n_ : N;  // a compile-time bound lets the loops unroll
    Dop853Result res;
    res.t_reached = static_cast<double>(t0);
    if (std::string why = validate(t0, y, tout); !why.empty()) {
      res.status = BsStatus::bad_input;
      res.message = std::move(why);
      return res;
    }
    for (int i = 0; i < n; ++i)
      atol_[i] = opt_.atol.size() == 1 ? opt_.atol[0] : opt_.atol[static_cast<std::size_t>(i)];
    for (int i = 0; i < n; ++i) y_[i] = y[i];
    const std::size_t nout = tout.size();
    const Scalar tend = tout[nout - 1];
    Scalar t = t0;
    std::size_t iout = 0;
    while (iout < nout && tout[iout] <= t) {
      observer(iout, tout[iout], static_cast<const Scalar*>(&y_[0]));
      ++iout;
    }
    auto finish = [&] {
      for (int i = 0; i < n; ++i) y[i] = y_[i];
      return res;
    };
    if (iout == nout) return finish();

    const Scalar span = tend - t0;
    const Scalar hmax = opt_.hmax > 0 ? std::min(opt_.hmax, span) : span;
    const Scalar rtol = opt_.rtol;
    // k_[0] holds f(t, y) at the start of every step (stage 1; after an accepted step the
    // f(t + h, y_new) of stage 13).
    if (!eval_at(rhs, t, static_cast<const Scalar*>(&y_[0]), k_[0], res)) return finish();
    Scalar h;
    if (opt_.h0 > 0) {
      h = std::min(opt_.h0, hmax);
    } else {
      h = hinit(rhs, t, span, hmax, res);
      if (!res.ok()) return finish();
    }
    const double expo1 = 1.0 / 8.0 - opt_.beta * 0.2;
    const double facc1 = 1.0 / opt_.facmin, facc2 = 1.0 / opt_.facmax;
    double facold = 1e-4;
    bool reject = false, last = false;
    int nonfinite_run = 0;
    auto& [k1, k2, k3, k4, k5, k6, k7, k8, k9, k10, k11, k12, k13, k14, k15, k16] = k_;  // stages 1..16
    const Scalar* ys = &ys_[0];

    for (;;) {
      if (res.nstep >= opt_.maxstp) {
        res.status = BsStatus::too_many_steps;
        res.message = "more than " + std::to_string(opt_.maxstp) + " steps";
        break;
      }
      if (t + Scalar(1.01) * h >= tend) {
        h = tend - t;
        last = true;
      }
      if (h <= 0 || h < Scalar(1e-14) * std::max(num::abs(t), span)) {
        res.status = BsStatus::step_underflow;
        res.message = "step size underflow at t = " + fmt_g(static_cast<double>(t));
        break;
      }
      ++res.nstep;
      const Scalar tph = last ? tend : t + h;
      if (!stages(rhs, t, h, tph, n, res)) break;
      const double err = error_norm(h, rtol, n);
      if (!std::isfinite(err)) {
        // A non-finite state or RHS value: quarter the step, as the Bulirsch-Stoer engine does.
        ++res.nrejct;
        reject = true;
        last = false;
        if (++nonfinite_run >= kMaxNonFinite) {
          res.status = BsStatus::not_finite;
          res.message = "non-finite error estimate at t = " + fmt_g(static_cast<double>(t));
          break;
        }
        h = Scalar(0.25) * h;
        continue;
      }
      nonfinite_run = 0;
      const double fac11 = std::pow(err, expo1);
      const double fac = std::max(facc2, std::min(facc1, fac11 / std::pow(facold, opt_.beta) / opt_.safe));
      Scalar hnew = h / static_cast<Scalar>(fac);
      if (err > 1) {
        hnew = h / static_cast<Scalar>(std::min(facc1, fac11 / opt_.safe));
        ++res.nrejct;
        reject = true;
        last = false;
        h = hnew;
        continue;
      }
      // Accepted.
      facold = std::max(err, 1e-4);
      if (!eval_at(rhs, tph, static_cast<const Scalar*>(&ynew_[0]), k13, res)) break;
      ++res.naccpt;
      const int action = hook(t, static_cast<const Scalar*>(&y_[0]), tph, static_cast<const Scalar*>(&ynew_[0]));
      if (action == kHookStopBefore) {
        res.stopped_by_hook = true;
        res.t_event_end = static_cast<double>(tph);
        break;
      }
      // Outputs in (t, t + h]: the one at the end is y_new itself, the others come from the
      // interpolant, built at the first of them (three more RHS evaluations).
      bool have_dense = false;
      while (iout < nout && tout[iout] <= tph) {
        if (tout[iout] == tph) {
          observer(iout, tout[iout], static_cast<const Scalar*>(&ynew_[0]));
        } else {
          if (!have_dense) {
            if (!build_dense(rhs, t, h, res)) break;
            have_dense = true;
          }
          dense_eval((tout[iout] - t) / h, &ys_[0]);
          observer(iout, tout[iout], ys);
        }
        ++iout;
      }
      if (!res.ok()) break;
      for (int i = 0; i < n; ++i) {
        y_[i] = ynew_[i];
        k1[i] = k13[i];
      }
      t = tph;
      res.t_reached = static_cast<double>(t);
      if (action == kHookStopAfter) {
        res.stopped_by_hook = true;
        res.t_event_end = res.t_reached;
        break;
      }
      if (last) break;
      if (hnew > hmax) hnew = hmax;
      if (reject) hnew = std::min(hnew, h);
      reject = false;
      h = hnew;
    }
    return finish();
  }

 private:
  static constexpr int kMaxNonFinite = 10;

  /// Stages 2..12 of the step (t, h) from k1 = f(t, y) (11 RHS evaluations; c12 = 1, taken
  /// at tph, the step's end): false when the RHS fails (res says why).
  template <class Rhs>
  bool stages(Rhs& rhs, Scalar t, Scalar h, Scalar tph, int n, Dop853Result& res) {
    using Tb = dop853_tableau::T<Scalar>;
    auto& [k1, k2, k3, k4, k5, k6, k7, k8, k9, k10, k11, k12, k13, k14, k15, k16] = k_;
    const Scalar* ys = &ys_[0];
    auto eval = [&](Scalar c, Vec& k) { return eval_at(rhs, t + c * h, ys, k, res); };
    for (int i = 0; i < n; ++i) ys_[i] = y_[i] + h * (Tb::a21 * k1[i]);
    if (!eval(Tb::c2, k2)) return false;
    for (int i = 0; i < n; ++i) ys_[i] = y_[i] + h * (Tb::a31 * k1[i] + Tb::a32 * k2[i]);
    if (!eval(Tb::c3, k3)) return false;
    for (int i = 0; i < n; ++i) ys_[i] = y_[i] + h * (Tb::a41 * k1[i] + Tb::a43 * k3[i]);
    if (!eval(Tb::c4, k4)) return false;
    for (int i = 0; i < n; ++i) ys_[i] = y_[i] + h * (Tb::a51 * k1[i] + Tb::a53 * k3[i] + Tb::a54 * k4[i]);
    if (!eval(Tb::c5, k5)) return false;
    for (int i = 0; i < n; ++i) ys_[i] = y_[i] + h * (Tb::a61 * k1[i] + Tb::a64 * k4[i] + Tb::a65 * k5[i]);
    if (!eval(Tb::c6, k6)) return false;
    for (int i = 0; i < n; ++i)
      ys_[i] = y_[i] + h * (Tb::a71 * k1[i] + Tb::a74 * k4[i] + Tb::a75 * k5[i] + Tb::a76 * k6[i]);
    if (!eval(Tb::c7, k7)) return false;
    for (int i = 0; i < n; ++i)
      ys_[i] = y_[i] + h * (Tb::a81 * k1[i] + Tb::a84 * k4[i] + Tb::a85 * k5[i] + Tb::a86 * k6[i] + Tb::a87 * k7[i]);
    if (!eval(Tb::c8, k8)) return false;
    for (int i = 0; i < n; ++i)
      ys_[i] = y_[i] + h * (Tb::a91 * k1[i] + Tb::a94 * k4[i] + Tb::a95 * k5[i] + Tb::a96 * k6[i] +
                            Tb::a97 * k7[i] + Tb::a98 * k8[i]);
    if (!eval(Tb::c9, k9)) return false;
    for (int i = 0; i < n; ++i)
      ys_[i] = y_[i] + h * (Tb::a101 * k1[i] + Tb::a104 * k4[i] + Tb::a105 * k5[i] + Tb::a106 * k6[i] +
                            Tb::a107 * k7[i] + Tb::a108 * k8[i] + Tb::a109 * k9[i]);
    if (!eval(Tb::c10, k10)) return false;
    for (int i = 0; i < n; ++i)
      ys_[i] = y_[i] + h * (Tb::a111 * k1[i] + Tb::a114 * k4[i] + Tb::a115 * k5[i] + Tb::a116 * k6[i] +
                            Tb::a117 * k7[i] + Tb::a118 * k8[i] + Tb::a119 * k9[i] + Tb::a1110 * k10[i]);
    if (!eval(Tb::c11, k11)) return false;
    for (int i = 0; i < n; ++i)
      ys_[i] = y_[i] + h * (Tb::a121 * k1[i] + Tb::a124 * k4[i] + Tb::a125 * k5[i] + Tb::a126 * k6[i] +
                            Tb::a127 * k7[i] + Tb::a128 * k8[i] + Tb::a129 * k9[i] + Tb::a1210 * k10[i] +
                            Tb::a1211 * k11[i]);
    return eval_at(rhs, tph, ys, k12, res);  // c12 = 1
  }

  /// The order-8 solution into ynew_ and the step's weighted error (HNW's err; > 1: reject).
  double error_norm(Scalar h, Scalar rtol, int n) {
    using Tb = dop853_tableau::T<Scalar>;
    auto& [k1, k2, k3, k4, k5, k6, k7, k8, k9, k10, k11, k12, k13, k14, k15, k16] = k_;
    // The order-8 solution and the two error estimators (HNW §II.5, eq. (10.17) of §II.10:
    // err = h err5² / sqrt(n (err5² + 0.01 err3²)), both weighted by sk below).
    Scalar err5 = 0, err3 = 0;
    for (int i = 0; i < n; ++i) {
      const Scalar bk = Tb::b1 * k1[i] + Tb::b6 * k6[i] + Tb::b7 * k7[i] + Tb::b8 * k8[i] + Tb::b9 * k9[i] +
                        Tb::b10 * k10[i] + Tb::b11 * k11[i] + Tb::b12 * k12[i];
      ynew_[i] = y_[i] + h * bk;
      const Scalar sk = atol_[i] + rtol * std::max(num::abs(y_[i]), num::abs(ynew_[i]));
      const Scalar e3 = bk - Tb::bhh1 * k1[i] - Tb::bhh2 * k9[i] - Tb::bhh3 * k12[i];
      const Scalar e5 = Tb::er1 * k1[i] + Tb::er6 * k6[i] + Tb::er7 * k7[i] + Tb::er8 * k8[i] + Tb::er9 * k9[i] +
                        Tb::er10 * k10[i] + Tb::er11 * k11[i] + Tb::er12 * k12[i];
      err3 = err3 + (e3 / sk) * (e3 / sk);
      err5 = err5 + (e5 / sk) * (e5 / sk);
    }
    Scalar deno = err5 + Scalar(0.01) * err3;
    if (deno <= 0) deno = 1;
    return static_cast<double>(h * err5 * num::sqrt(Scalar(1) / (Scalar(n) * deno)));
  }


  using Base::opt_, Base::n_;
  std::array<Vec, 16> k_{};   // stages 1..16 (k_[s-1])
  std::array<Vec, 8> cont_{};  // dense-output coefficients of the last step
  Vec y_{}, ynew_{}, ys_{}, atol_{};

  static std::string fmt_g(double v) { return integration_detail::fmt_g(v); }
  static void fail_rhs(BsResult& res, int st, Scalar t) {
    integration_detail::fail_rhs(res, st, static_cast<double>(t));
  }

  template <class Rhs>
  static bool eval_at(Rhs& rhs, Scalar t, const Scalar* y, Vec& k, Dop853Result& res) {
    const int st = rhs(t, y, &k[0]);
    ++res.nfcn;
    if (st != 0) fail_rhs(res, st, t);
    return st == 0;
  }

  std::string validate(Scalar t0, const Scalar* y, std::span<const Scalar> tout) const {
    if (n_ < 1) return "n = " + std::to_string(n_) + " must be >= 1";
    if constexpr (N != Dynamic)
      if (n_ != N) return "n = " + std::to_string(n_) + " does not match the compile-time dimension " + std::to_string(N);
    const double rtol = static_cast<double>(opt_.rtol);
    const double floor = rtol_in_eps<Scalar>(kDop853RtolEps);
    if (!(num::isfinite(opt_.rtol) && rtol >= floor && rtol < 1))
      return "rtol = " + fmt_g(rtol) + " must be in [" + fmt_g(floor) + ", 1) (" + fmt_g(kDop853RtolEps) +
             " eps of " + num::name<Scalar>() + " and above)";
    if (opt_.atol.empty() || (opt_.atol.size() != 1 && opt_.atol.size() != static_cast<std::size_t>(n_)))
      return "atol has " + std::to_string(opt_.atol.size()) + " entries: must have 1 or n = " + std::to_string(n_);
    for (std::size_t i = 0; i < opt_.atol.size(); ++i)
      if (!(num::isfinite(opt_.atol[i]) && opt_.atol[i] > 0))
        return "atol[" + std::to_string(i) + "] = " + fmt_g(static_cast<double>(opt_.atol[i])) + " must be > 0";
    if (!(num::isfinite(opt_.h0) && opt_.h0 >= 0)) return "h0 = " + fmt_g(static_cast<double>(opt_.h0)) + " must be >= 0";
    if (!(num::isfinite(opt_.hmax) && opt_.hmax >= 0))
      return "hmax = " + fmt_g(static_cast<double>(opt_.hmax)) + " must be >= 0";
    if (opt_.maxstp < 1) return "maxstp = " + std::to_string(opt_.maxstp) + " must be >= 1";
    if (!(opt_.safe > 1e-4 && opt_.safe < 1)) return "safe = " + fmt_g(opt_.safe) + " must be in (1e-4, 1)";
    if (!(opt_.facmin > 0 && opt_.facmin < 1)) return "facmin = " + fmt_g(opt_.facmin) + " must be in (0, 1)";
    if (!(opt_.facmax > 1 && std::isfinite(opt_.facmax)))
      return "facmax = " + fmt_g(opt_.facmax) + " must be > 1 and finite";
    if (!(opt_.beta >= 0 && opt_.beta <= 0.2)) return "beta = " + fmt_g(opt_.beta) + " must be in [0, 0.2]";
    if (tout.empty()) return "no output times";
    if (!num::isfinite(t0)) return "t0 must be finite";
    for (std::size_t i = 0; i < tout.size(); ++i) {
      if (!num::isfinite(tout[i])) return "output times must be finite";
      if (i > 0 && tout[i] < tout[i - 1]) return "output times must be non-decreasing";
    }
    if (tout[0] < t0) return "tout(1) must be >= t0";
    for (int i = 0; i < n_; ++i)
      if (!num::isfinite(y[i])) return "initial state must be finite";
    return {};
  }

  // Hairer's starting step (HNW §II.4, "Starting step size", with the order 8): from the
  // weighted norms of y0, f0 and an estimate of y'' by one explicit Euler step, the h with
  // h^8 max(|f0|, |y''|) = 0.01. One RHS evaluation (into k_[1]). dop853.f's two absolute
  // fallbacks (1e-6 when y0 or f0 is ~0; max(1e-6, 1e-3 h) when both derivatives are ~0)
  // are taken relative to the span here: the nanobar's time scale is 1e-9 s.
  template <class Rhs>
  Scalar hinit(Rhs& rhs, Scalar t, Scalar span, Scalar hmax, Dop853Result& res) {
    const int n = (N == Dynamic) ? n_ : N;
    const Vec& f0 = k_[0];
    Vec& f1 = k_[1];
    Scalar dnf = 0, dny = 0;
    for (int i = 0; i < n; ++i) {
      const Scalar sk = atol_[i] + opt_.rtol * num::abs(y_[i]);
      dnf = dnf + (f0[i] / sk) * (f0[i] / sk);
      dny = dny + (y_[i] / sk) * (y_[i] / sk);
    }
    Scalar h = (dnf <= Scalar(1e-10) || dny <= Scalar(1e-10)) ? Scalar(1e-6) * span
                                                                : num::sqrt(dny / dnf) * Scalar(0.01);
    h = std::min(h, hmax);
    for (int i = 0; i < n; ++i) ys_[i] = y_[i] + h * f0[i];
    if (!eval_at(rhs, t + h, static_cast<const Scalar*>(&ys_[0]), f1, res)) return h;
    Scalar der2 = 0;
    for (int i = 0; i < n; ++i) {
      const Scalar sk = atol_[i] + opt_.rtol * num::abs(y_[i]);
      der2 = der2 + ((f1[i] - f0[i]) / sk) * ((f1[i] - f0[i]) / sk);
    }
    der2 = num::sqrt(der2) / h;
    const Scalar der12 = std::max(num::abs(der2), num::sqrt(dnf));
    const Scalar h1 = der12 <= Scalar(1e-15) ? std::max(Scalar(1e-6) * span, h * Scalar(1e-3))
                                              : static_cast<Scalar>(std::pow(0.01 / static_cast<double>(der12), 1.0 / 8.0));
    return std::min({Scalar(100) * h, h1, hmax});
  }

  // The dense output of the accepted step over [t, t + h] (HNW §II.6): stages 14-16 (three
  // RHS evaluations into k_[13..15]), then the coefficients of
  // P(s) = c0 + s (c1 + s1 (c2 + s (c3 + s1 (c4 + s (c5 + s1 (c6 + s c7)))))), s1 = 1 - s.
  template <class Rhs>
  bool build_dense(Rhs& rhs, Scalar t, Scalar h, Dop853Result& res) {
    using Tb = dop853_tableau::T<Scalar>;
    const int n = (N == Dynamic) ? n_ : N;
    auto& [k1, k2, k3, k4, k5, k6, k7, k8, k9, k10, k11, k12, k13, k14, k15, k16] = k_;
    const Scalar* ys = &ys_[0];
    for (int i = 0; i < n; ++i)
      ys_[i] = y_[i] + h * (Tb::a141 * k1[i] + Tb::a147 * k7[i] + Tb::a148 * k8[i] + Tb::a149 * k9[i] +
                            Tb::a1410 * k10[i] + Tb::a1411 * k11[i] + Tb::a1412 * k12[i] + Tb::a1413 * k13[i]);
    if (!eval_at(rhs, t + Tb::c14 * h, ys, k14, res)) return false;
    for (int i = 0; i < n; ++i)
      ys_[i] = y_[i] + h * (Tb::a151 * k1[i] + Tb::a156 * k6[i] + Tb::a157 * k7[i] + Tb::a158 * k8[i] +
                            Tb::a1511 * k11[i] + Tb::a1512 * k12[i] + Tb::a1513 * k13[i] + Tb::a1514 * k14[i]);
    if (!eval_at(rhs, t + Tb::c15 * h, ys, k15, res)) return false;
    for (int i = 0; i < n; ++i)
      ys_[i] = y_[i] + h * (Tb::a161 * k1[i] + Tb::a166 * k6[i] + Tb::a167 * k7[i] + Tb::a168 * k8[i] +
                            Tb::a169 * k9[i] + Tb::a1613 * k13[i] + Tb::a1614 * k14[i] + Tb::a1615 * k15[i]);
    if (!eval_at(rhs, t + Tb::c16 * h, ys, k16, res)) return false;
    ++res.ndense;
    // h times a row d_r of the dense-output coefficients on stages 1, 6..16, at component i.
    // (k_[s - 1] is stage s: a lambda may not capture the bindings k1..k16 in clang 14.)
    auto dense_row = [this, h](int i, const std::array<Scalar, 12>& d) {
      const auto& k = k_;
      return h * (d[0] * k[0][i] + d[1] * k[5][i] + d[2] * k[6][i] + d[3] * k[7][i] + d[4] * k[8][i] +
                  d[5] * k[9][i] + d[6] * k[10][i] + d[7] * k[11][i] + d[8] * k[12][i] + d[9] * k[13][i] +
                  d[10] * k[14][i] + d[11] * k[15][i]);
    };
    for (int i = 0; i < n; ++i) {
      const Scalar ydiff = ynew_[i] - y_[i];
      const Scalar bspl = h * k1[i] - ydiff;
      cont_[0][i] = y_[i];
      cont_[1][i] = ydiff;
      cont_[2][i] = bspl;
      cont_[3][i] = ydiff - h * k13[i] - bspl;
      cont_[4][i] = dense_row(i, {Tb::d41, Tb::d46, Tb::d47, Tb::d48, Tb::d49, Tb::d410, Tb::d411, Tb::d412, Tb::d413, Tb::d414, Tb::d415, Tb::d416});
      cont_[5][i] = dense_row(i, {Tb::d51, Tb::d56, Tb::d57, Tb::d58, Tb::d59, Tb::d510, Tb::d511, Tb::d512, Tb::d513, Tb::d514, Tb::d515, Tb::d516});
      cont_[6][i] = dense_row(i, {Tb::d61, Tb::d66, Tb::d67, Tb::d68, Tb::d69, Tb::d610, Tb::d611, Tb::d612, Tb::d613, Tb::d614, Tb::d615, Tb::d616});
      cont_[7][i] = dense_row(i, {Tb::d71, Tb::d76, Tb::d77, Tb::d78, Tb::d79, Tb::d710, Tb::d711, Tb::d712, Tb::d713, Tb::d714, Tb::d715, Tb::d716});
    }
    return true;
  }

  // The interpolant of the last step at s = (t_out - t) / h in (0, 1), into out.
  void dense_eval(Scalar s, Scalar* out) const {
    const int n = (N == Dynamic) ? n_ : N;
    const Scalar s1 = Scalar(1) - s;
    for (int i = 0; i < n; ++i) {
      const Scalar conpar = cont_[4][i] + s * (cont_[5][i] + s1 * (cont_[6][i] + s * cont_[7][i]));
      out[i] = cont_[0][i] + s * (cont_[1][i] + s1 * (cont_[2][i] + s * (cont_[3][i] + s1 * conpar)));
    }
  }
};

static_assert(HookedOdeIntegrator<Dop853<double, 6>, double>);
static_assert(HookedOdeIntegrator<Dop853<double>, double>);

}  // namespace nanopush
