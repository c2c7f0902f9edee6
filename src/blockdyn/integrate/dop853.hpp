// SPDX-License-Identifier: Apache-2.0
#pragma once
// Dormand-Prince 8(5,3): the explicit Runge-Kutta pair of order 8 with the combined 5th/3rd-order
// error estimate and the 7th-order continuous extension of Hairer's DOP853 (Hairer, Norsett &
// Wanner, Solving ODEs I, sec. II.10). Twelve stages per step, one more (the right-hand side at
// the step end) shared with the next step, three more only for the dense output of an accepted
// step. Fixed-size state, no allocation.
#include <array>
#include <cmath>
#include <cstddef>

#include "blockdyn/integrate/dense_segment.hpp"

namespace blockdyn {

// The tableau as published with DOP853 (30-digit decimals; stages numbered from 0, stage 0 at
// the step start, stage 11 at its end, stages 13-15 for the continuous extension).
namespace dop853 {
inline constexpr double c[16] = {0.0,
                                 0.526001519587677318785587544488e-01,
                                 0.789002279381515978178381316732e-01,
                                 0.118350341907227396726757197510,
                                 0.281649658092772603273242802490,
                                 0.333333333333333333333333333333,
                                 0.25,
                                 0.307692307692307692307692307692,
                                 0.651282051282051282051282051282,
                                 0.6,
                                 0.857142857142857142857142857142,
                                 1.0,
                                 1.0,
                                 0.1,
                                 0.2,
                                 0.777777777777777777777777777778};

// Nonzero entries of each stage's row: a row lists the stage indices it uses and their weights.
template <std::size_t M>
struct Row {
  std::array<int, M> j;
  std::array<double, M> a;
};

inline constexpr Row<1> a1{{0}, {5.26001519587677318785587544488e-2}};
inline constexpr Row<2> a2{{0, 1}, {1.97250569845378994544595329183e-2, 5.91751709536136983633785987549e-2}};
inline constexpr Row<2> a3{{0, 2}, {2.95875854768068491816892993775e-2, 8.87627564304205475450678981324e-2}};
inline constexpr Row<3> a4{
    {0, 2, 3},
    {2.41365134159266685502369798665e-1, -8.84549479328286085344864962717e-1, 9.24834003261792003115737966543e-1}};
inline constexpr Row<3> a5{
    {0, 3, 4},
    {3.7037037037037037037037037037e-2, 1.70828608729473871279604482173e-1, 1.25467687566822425016691814123e-1}};
inline constexpr Row<4> a6{
    {0, 3, 4, 5},
    {3.7109375e-2, 1.70252211019544039314978060272e-1, 6.02165389804559606850219397283e-2, -1.7578125e-2}};
inline constexpr Row<5> a7{
    {0, 3, 4, 5, 6},
    {3.70920001185047927108779319836e-2, 1.70383925712239993810214054705e-1, 1.07262030446373284651809199168e-1,
     -1.53194377486244017527936158236e-2, 8.27378916381402288758473766002e-3}};
inline constexpr Row<6> a8{
    {0, 3, 4, 5, 6, 7},
    {6.24110958716075717114429577812e-1, -3.36089262944694129406857109825, -8.68219346841726006818189891453e-1,
     2.75920996994467083049415600797e1, 2.01540675504778934086186788979e1, -4.34898841810699588477366255144e1}};
inline constexpr Row<7> a9{
    {0, 3, 4, 5, 6, 7, 8},
    {4.77662536438264365890433908527e-1, -2.48811461997166764192642586468, -5.90290826836842996371446475743e-1,
     2.12300514481811942347288949897e1, 1.52792336328824235832596922938e1, -3.32882109689848629194453265587e1,
     -2.03312017085086261358222928593e-2}};
inline constexpr Row<8> a10{
    {0, 3, 4, 5, 6, 7, 8, 9},
    {-9.3714243008598732571704021658e-1, 5.18637242884406370830023853209, 1.09143734899672957818500254654,
     -8.14978701074692612513997267357, -1.85200656599969598641566180701e1, 2.27394870993505042818970056734e1,
     2.49360555267965238987089396762, -3.0467644718982195003823669022}};
inline constexpr Row<9> a11{
    {0, 3, 4, 5, 6, 7, 8, 9, 10},
    {2.27331014751653820792359768449, -1.05344954667372501984066689879e1, -2.00087205822486249909675718444,
     -1.79589318631187989172765950534e1, 2.79488845294199600508499808837e1, -2.85899827713502369474065508674,
     -8.87285693353062954433549289258, 1.23605671757943030647266201528e1, 6.43392746015763530355970484046e-1}};
// The 8th-order weights (the solution at the step end).
inline constexpr Row<8> b{
    {0, 5, 6, 7, 8, 9, 10, 11},
    {5.42937341165687622380535766363e-2, 4.45031289275240888144113950566, 1.89151789931450038304281599044,
     -5.8012039600105847814672114227, 3.1116436695781989440891606237e-1, -1.52160949662516078556178806805e-1,
     2.01365400804030348374776537501e-1, 4.47106157277725905176885569043e-2}};
// The 3rd-order embedded solution differs from b at stages 0, 8 and 11 by these weights.
inline constexpr double bhh0 = 0.244094488188976377952755905512;
inline constexpr double bhh8 = 0.733846688281611857341361741547;
inline constexpr double bhh11 = 0.220588235294117647058823529412e-1;
// The 5th-order error estimate.
inline constexpr Row<8> e5{
    {0, 5, 6, 7, 8, 9, 10, 11},
    {0.1312004499419488073250102996e-1, -0.1225156446376204440720569753e1, -0.4957589496572501915214079952,
     0.1664377182454986536961530415e1, -0.3503288487499736816886487290, 0.3341791187130174790297318841,
     0.8192320648511571246570742613e-1, -0.2235530786388629525884427845e-1}};
// Stages of the continuous extension (stage 12 is the right-hand side at the step end).
inline constexpr Row<8> a13{
    {0, 6, 7, 8, 9, 10, 11, 12},
    {5.61675022830479523392909219681e-2, 2.53500210216624811088794765333e-1, -2.46239037470802489917441475441e-1,
     -1.24191423263816360469010140626e-1, 1.5329179827876569731206322685e-1, 8.20105229563468988491666602057e-3,
     7.56789766054569976138603589584e-3, -8.298e-3}};
inline constexpr Row<8> a14{
    {0, 5, 6, 7, 10, 11, 12, 13},
    {3.18346481635021405060768473261e-2, 2.83009096723667755288322961402e-2, 5.35419883074385676223797384372e-2,
     -5.49237485713909884646569340306e-2, -1.08347328697249322858509316994e-4, 3.82571090835658412954920192323e-4,
     -3.40465008687404560802977114492e-4, 1.41312443674632500278074618366e-1}};
inline constexpr Row<8> a15{
    {0, 5, 6, 7, 8, 12, 13, 14},
    {-4.28896301583791923408573538692e-1, -4.69762141536116384314449447206, 7.68342119606259904184240953878,
     4.06898981839711007970213554331, 3.56727187455281109270669543021e-1, -1.39902416515901462129418009734e-3,
     2.9475147891527723389556272149, -9.15095847217987001081870187138}};
// Weights of the four highest coefficient vectors of the continuous extension.
inline constexpr Row<12> d4{
    {0, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15},
    {-0.84289382761090128651353491142e1, 0.56671495351937776962531783590, -0.30689499459498916912797304727e1,
     0.23846676565120698287728149680e1, 0.21170345824450282767155149946e1, -0.87139158377797299206789907490,
     0.22404374302607882758541771650e1, 0.63157877876946881815570249290, -0.88990336451333310820698117400e-1,
     0.18148505520854727256656404962e2, -0.91946323924783554000451984436e1, -0.44360363875948939664310572000e1}};
inline constexpr Row<12> d5{
    {0, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15},
    {0.10427508642579134603413151009e2, 0.24228349177525818288430175319e3, 0.16520045171727028198505394887e3,
     -0.37454675472269020279518312152e3, -0.22113666853125306036270938578e2, 0.77334326684722638389603898808e1,
     -0.30674084731089398182061213626e2, -0.93321305264302278729567221706e1, 0.15697238121770843886131091075e2,
     -0.31139403219565177677282850411e2, -0.93529243588444783865713862664e1, 0.35816841486394083752465898540e2}};
inline constexpr Row<12> d6{
    {0, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15},
    {0.19985053242002433820987653617e2, -0.38703730874935176555105901742e3, -0.18917813819516756882830838328e3,
     0.52780815920542364900561016686e3, -0.11573902539959630126141871134e2, 0.68812326946963000169666922661e1,
     -0.10006050966910838403183860980e1, 0.77771377980534432092869265740, -0.27782057523535084065932004339e1,
     -0.60196695231264120758267380846e2, 0.84320405506677161018159903784e2, 0.11992291136182789328035130030e2}};
inline constexpr Row<12> d7{
    {0, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15},
    {-0.25693933462703749003312586129e2, -0.15418974869023643374053993627e3, -0.23152937917604549567536039109e3,
     0.35763911791061412378285349910e3, 0.93405324183624310003907691704e2, -0.37458323136451633156875139351e2,
     0.10409964950896230045147246184e3, 0.29840293426660503123344363579e2, -0.43533456590011143754432175058e2,
     0.96324553959188282948394950600e2, -0.39177261675615439165231486172e2, -0.14972683625798562581422125276e3}};
}  // namespace dop853

// One attempted step. `Rhs` is a callable (t, y, dy). k1 must hold f(t, y) on entry. On return
// y_new, k_end = f(t + h, y_new) (the next step's first stage), err = Hairer's error norm.
template <std::size_t N>
class Dop853 {
 public:
  // Step-size control of DOP853 (Hairer): err^(-1/8), no PI term, changes within [1/3, 6].
  static constexpr double kAlpha = 1.0 / 8;
  static constexpr double kBeta = 0.0;
  static constexpr double kOrderExponent = 1.0 / 8;
  static constexpr double kFacMin = 1.0 / 3, kFacMax = 6.0;
  Vec<N> atol{}, rtol{};

  template <class Rhs>
  double attempt(Rhs&& f, double t, double h, const Vec<N>& y, const Vec<N>& k1, Vec<N>& y_new, Vec<N>& k_end,
                 StepperStats& st) {
    using namespace dop853;
    k_[0] = k1;
    stage(f, t, h, y, a1, 1);
    stage(f, t, h, y, a2, 2);
    stage(f, t, h, y, a3, 3);
    stage(f, t, h, y, a4, 4);
    stage(f, t, h, y, a5, 5);
    stage(f, t, h, y, a6, 6);
    stage(f, t, h, y, a7, 7);
    stage(f, t, h, y, a8, 8);
    stage(f, t, h, y, a9, 9);
    stage(f, t, h, y, a10, 10);
    stage_state(y, h, a11, y_stage11_);
    f(t + h, y_stage11_, k_[11]);
    stage_state(y, h, b, y_new);
    f(t + h, y_new, k_end);
    k_[12] = k_end;
    st.rhs_evals += 12;
    double err5 = 0.0, err3 = 0.0, stnum = 0.0, stden = 0.0;
    const Vec<N> c5 = combine_all(e5), cb = combine_all(b);
    for (std::size_t i = 0; i < N; ++i) {
      const double sk = atol[i] + rtol[i] * std::fmax(std::fabs(y[i]), std::fabs(y_new[i]));
      const double est5 = c5[i] / sk;
      const double est3 = (cb[i] - bhh0 * k_[0][i] - bhh8 * k_[8][i] - bhh11 * k_[11][i]) / sk;
      err5 += est5 * est5;
      err3 += est3 * est3;
      const double dk = k_end[i] - k_[11][i], dy = y_new[i] - y_stage11_[i];
      stnum += dk * dk;
      stden += dy * dy;
    }
    stiffness_ = stden > 0.0 ? std::fabs(h) * std::sqrt(stnum / stden) : 0.0;
    if (err5 == 0.0 && err3 == 0.0) return 0.0;
    const double deno = err5 + 0.01 * err3;
    return std::fabs(h) * err5 / std::sqrt(deno * double(N));
  }

  // Estimate h|lambda| of the step just attempted (Hairer's stiffness test; > 6.1 means the step
  // size is limited by stability rather than accuracy).
  double stiffness() const { return stiffness_; }

  // Dense output of the step just attempted (call only if accepted): three more stages.
  template <class Rhs>
  void dense(Rhs&& f, double t, double h, const Vec<N>& y, const Vec<N>& y_new, const Vec<N>& k1, const Vec<N>& k_end,
             DenseSegment<N>& seg, StepperStats& st) {
    using namespace dop853;
    k_[0] = k1;
    k_[12] = k_end;
    stage(f, t, h, y, a13, 13);
    stage(f, t, h, y, a14, 14);
    stage(f, t, h, y, a15, 15);
    st.rhs_evals += 3;
    seg.set_hermite(t, h, 8, y, y_new, k1, k_end);
    const Vec<N> c4 = combine_all(d4), c5 = combine_all(d5), c6 = combine_all(d6), c7 = combine_all(d7);
    for (std::size_t i = 0; i < N; ++i) {
      seg.r[4][i] = h * c4[i];
      seg.r[5][i] = h * c5[i];
      seg.r[6][i] = h * c6[i];
      seg.r[7][i] = h * c7[i];
    }
  }

 private:
  // sum_m a_m k_{j_m} for every component at once: the loop over components innermost, so it
  // vectorizes (each component still adds its terms in the row's order).
  // The first term is added to an explicit 0.0 (the same sums, bit for bit, as from a zeroed
  // vector) instead of zeroing the vector first, which larger systems did with a `rep stos`.
  template <std::size_t M>
  Vec<N> combine_all(const dop853::Row<M>& row) const {
    Vec<N> s;
    const Vec<N>& k0 = k_[row.j[0]];
    for (std::size_t i = 0; i < N; ++i) s[i] = 0.0 + row.a[0] * k0[i];
    for (std::size_t m = 1; m < M; ++m) {
      const double a = row.a[m];
      const Vec<N>& k = k_[row.j[m]];
      for (std::size_t i = 0; i < N; ++i) s[i] += a * k[i];
    }
    return s;
  }

  template <std::size_t M>
  void stage_state(const Vec<N>& y, double h, const dop853::Row<M>& row, Vec<N>& out) const {
    const Vec<N> s = combine_all(row);
    for (std::size_t i = 0; i < N; ++i) out[i] = y[i] + h * s[i];
  }

  template <class Rhs, std::size_t M>
  void stage(Rhs& f, double t, double h, const Vec<N>& y, const dop853::Row<M>& row, int s) {
    stage_state(y, h, row, tmp_);
    f(t + dop853::c[s] * h, tmp_, k_[s]);
  }

  std::array<Vec<N>, 16> k_{};
  Vec<N> tmp_{}, y_stage11_{};
  double stiffness_ = 0.0;
};

}  // namespace blockdyn
