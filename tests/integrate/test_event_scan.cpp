// SPDX-License-Identifier: Apache-2.0
// The event scan (issue 10): the Bernstein envelope of an event function over a step (exact for
// quartics, located doubtful stretches), and grazing cases on which a scan that samples blindly
// would miss events: dips far shorter than the steps, a dip of depth 1e-9 inside a long step, a
// tangential touch (no event) next to a touch 1e-12 deep (two events), dips many steps after the
// last restart (where the scan relies on the remainder measured earlier); each with rates from
// the model (event_rates) and from difference quotients, on both Runge-Kutta pairs, with event
// times against closed forms to the rounding of the event function.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

#include "blockdyn/integrate/event_envelope.hpp"
#include "blockdyn/integrate/hybrid_integrator.hpp"
#include "threshold_test_model.hpp"

using namespace blockdyn;

namespace {

// Bernstein coefficients (degree 4) of the power-basis quartic a0 + a1 s + ... + a4 s^4.
Bernstein4 to_bernstein(const std::array<double, 5>& a) {
  // b_k = sum_{j <= k} C(k, j) / C(4, j) a_j
  const double C4[5] = {1, 4, 6, 4, 1};
  Bernstein4 b{};
  for (int k = 0; k <= 4; ++k) {
    double ck = 1;  // C(k, j) built up along j
    for (int j = 0; j <= k; ++j) {
      b[k] += ck / C4[j] * a[j];
      ck = ck * (k - j) / (j + 1);
    }
  }
  return b;
}

double power_value(const std::array<double, 5>& a, double s) {
  return a[0] + s * (a[1] + s * (a[2] + s * (a[3] + s * a[4])));
}

}  // namespace

TEST(EventEnvelope, BernsteinFormAndHalvesReproduceThePolynomial) {
  const std::array<double, 5> a{0.3, -2.0, 1.5, 0.7, -0.4};
  const Bernstein4 b = to_bernstein(a);
  Bernstein4 l, r;
  bernstein_halves(b, l, r);
  for (double s : {0.0, 0.1, 0.37, 0.5, 0.81, 1.0}) {
    EXPECT_NEAR(bernstein_value(b, s), power_value(a, s), 1e-14) << s;
    EXPECT_NEAR(to_power(b)(s), power_value(a, s), 1e-14) << s;
    if (s <= 0.5) {
      EXPECT_NEAR(bernstein_value(l, 2 * s), power_value(a, s), 1e-14) << s;
    }
    if (s >= 0.5) {
      EXPECT_NEAR(bernstein_value(r, 2 * s - 1), power_value(a, s), 1e-14) << s;
    }
  }
}

TEST(EventEnvelope, ModelIsExactForQuarticsAndTheEnvelopeBelowThem) {
  // g(s) = 1 - 3 s + 2.5 s^2 + 0.2 s^3 + q s^4 on a step of length h = 2: its Hermite remainder
  // is q s^2 (1 - s)^2 exactly, so one sample at the midpoint makes the model exact, and the
  // lower envelope lies below g everywhere.
  const double h = 2.0;
  for (double q : {-0.8, 0.0, 0.6}) {
    const std::array<double, 5> a{1.0, -3.0, 2.5, 0.2, q};
    auto g = [&](double s) { return power_value(a, s); };
    auto gd = [&](double s) { return (a[1] + s * (2 * a[2] + s * (3 * a[3] + s * 4 * a[4]))) / h; };
    const double sm = 0.5, gm = g(sm);
    const EventEnvelope e = make_event_envelope(g(0), gd(0), g(1), gd(1), h, &sm, &gm, 1, 0.0, false);
    for (double s = 0; s <= 1.0; s += 1.0 / 64) {
      EXPECT_NEAR(bernstein_value(e.model, s), g(s), 1e-13) << q << " " << s;
      EXPECT_LE(bernstein_value(e.lower, s), g(s) + 1e-15) << q << " " << s;
    }
  }
}

TEST(EventEnvelope, PositiveFunctionsPassAndDipsAreLocated) {
  const double h = 1.0;
  // (s - 0.3)^2 + 0.05 > 0 everywhere: the envelope says so.
  {
    auto g = [](double s) { return (s - 0.3) * (s - 0.3) + 0.05; };
    auto gd = [](double s) { return 2 * (s - 0.3); };
    const double sm = 0.5, gm = g(sm);
    double sa, sb;
    // The coefficients on [0, 1] alone do not show it (the convex hull reaches below zero);
    // subdivision does.
    EXPECT_FALSE(
        make_event_envelope(g(0), gd(0), g(1), gd(1), h, &sm, &gm, 1, 0.0, false).next_doubtful(5, 0.0, sa, sb));
  }
  // (s - 0.7)^2 - 1e-6: a brief dip around s = 0.7, located within 1/32.
  {
    auto g = [](double s) { return (s - 0.7) * (s - 0.7) - 1e-6; };
    auto gd = [](double s) { return 2 * (s - 0.7); };
    const double sm = 0.5, gm = g(sm);
    const EventEnvelope e = make_event_envelope(g(0), gd(0), g(1), gd(1), h, &sm, &gm, 1, 0.0, false);
    EXPECT_FALSE(e.positive());
    double sa, sb;
    ASSERT_TRUE(e.next_doubtful(5, 0.0, sa, sb));
    EXPECT_LE(sa, 0.7);
    EXPECT_GE(sb, 0.7);
    EXPECT_GT(sa, 0.5);
    EXPECT_LT(sb, 0.9);
    EXPECT_FALSE(e.next_doubtful(5, sb, sa, sb));  // one stretch only
  }
  // A function starting at zero (one that just fired) and rising passes; one falling does not.
  {
    const double sm = 0.5;
    auto rise = [](double s) { return s * (1.2 - s); };
    const double gm = rise(sm);
    EXPECT_TRUE(make_event_envelope(0.0, 1.2, rise(1), 1.2 - 2, h, &sm, &gm, 1, 0.0, true).positive());
    const double gmd = -gm;
    EXPECT_FALSE(make_event_envelope(0.0, -1.2, -rise(1), 0.8, h, &sm, &gmd, 1, 0.0, true).positive());
  }
}

namespace {

// x'' = -x (x = A sin t): g = c - x (mode 0) then x - c (mode 1), so every crossing of x = c is an
// event, and c close to A makes dips as short and shallow as wanted. With `Rates` the model
// provides event_rates (exact), else the integrator differences.
template <bool Rates>
using Sine = threshold_test::ThresholdCrossing<threshold_test::Harmonic, Rates>;

// A thrown stone: x'' = -1, x = t - t^2 / 2 (top 1/2 at t = 1). Its path is a polynomial, so both
// pairs integrate it exactly and take steps as long as h_max allows: a dip of g = c - x inside one
// step is visible only to the scan. Rates from the model or from differences.
template <bool Rates>
using Stone = threshold_test::ThresholdCrossing<threshold_test::Gravity, Rates>;

struct Times {
  std::vector<double> t;
  template <class Seg, class M>
  bool on_step(const Seg&, double, double, const M&) {
    return true;
  }
  template <class Info>
  bool on_event(const Info& e) {
    t.push_back(e.t);
    return true;
  }
};

struct RunOut {
  std::vector<double> times;
  long accepted;
};

template <class M>
RunOut run(const M& m, Vec<2> z, double t_end, Method method, double rtol, double h_max = INFINITY) {
  IntegratorOptions o;
  o.method = method;
  o.rtol = rtol;
  o.atol = rtol * 1e-2;
  o.h_max = h_max;
  HybridIntegrator<M> integ(m, o);
  Times rec;
  double t = 0;
  int mode = 0;
  EXPECT_EQ(integ.run(t, t_end, mode, z, rec), RunStatus::ReachedEnd);
  return {rec.t, integ.stats().accepted};
}

constexpr Method kScanPairs[] = {Method::Dopri5, Method::Dop853};

}  // namespace

TEST(EventScan, DipOfDepth1e9InsideALongStepIsFound) {
  // g = c - x with c = 1/2 - 1e-9: below zero for |t - 1| < sqrt(2e-9) = 4.5e-5, inside steps of
  // length 0.25 .. 2.
  const double depth = 1e-9, c = 0.5 - depth, half = std::sqrt(2 * depth);
  for (Method method : kScanPairs)
    for (double h_max : {0.25, 2.0}) {
      SCOPED_TRACE(std::string(to_string(method)) + " h_max " + std::to_string(h_max));
      const auto check = [&](const RunOut& r) {
        ASSERT_EQ(r.times.size(), 2u);
        // The path is exact up to rounding: an error of a few ulps of x = 1/2 (DOP853's stage sums
        // round more) moves a crossing by dx / |x'| = dx / half.
        const double tol = 16 * 0x1p-52 * 0.5 / half;
        EXPECT_NEAR(r.times[0], 1 - half, tol);
        EXPECT_NEAR(r.times[1], 1 + half, tol);
        EXPECT_LT(2 * half, 3.0 / r.accepted);  // far shorter than a mean step
      };
      check(run(Stone<true>{c}, {0.0, 1.0}, 3.0, method, 1e-10, h_max));
      check(run(Stone<false>{c}, {0.0, 1.0}, 3.0, method, 1e-10, h_max));
    }
}

TEST(EventScan, TangentialTouchIsNoEventAndATouch1e12DeepIsTwo) {
  // x = sin t against c = 1 + 1e-12 (never reached), c = 1 - 1e-12 (reached for 2.8e-6).
  for (Method method : kScanPairs) {
    SCOPED_TRACE(to_string(method));
    EXPECT_TRUE(run(Sine<true>{1.0 + 1e-12}, {0.0, 1.0}, 3.0, method, 1e-12).times.empty());
    EXPECT_TRUE(run(Sine<false>{1.0 + 1e-12}, {0.0, 1.0}, 3.0, method, 1e-12).times.empty());
    const double half = std::acos(1.0 - 1e-12);
    for (const RunOut& r : {run(Sine<true>{1.0 - 1e-12}, {0.0, 1.0}, 3.0, method, 1e-12),
                            run(Sine<false>{1.0 - 1e-12}, {0.0, 1.0}, 3.0, method, 1e-12)}) {
      ASSERT_EQ(r.times.size(), 2u);
      // Here the state's own error (1e-12 rtol) moves the crossings by dx / sin(half).
      EXPECT_NEAR(r.times[0], M_PI / 2 - half, 2e-12 / std::sin(half));
      EXPECT_NEAR(r.times[1], M_PI / 2 + half, 2e-12 / std::sin(half));
    }
  }
}

TEST(EventScan, DipsLongAfterTheLastRestartAreFound) {
  // x = sin t with c = 1 - 1e-8: a dip of 2.8e-4 at every pi/2 + 2 pi n, each after some fifty
  // steps without an event, where the scan bounds the remainder by the one measured earlier and
  // samples inside a step only every few steps.
  const double c = 1 - 1e-8, half = std::acos(c);
  for (Method method : kScanPairs) {
    SCOPED_TRACE(to_string(method));
    for (const RunOut& r :
         {run(Sine<true>{c}, {0.0, 1.0}, 60.0, method, 1e-11), run(Sine<false>{c}, {0.0, 1.0}, 60.0, method, 1e-11)}) {
      std::vector<double> expect;
      for (int n = 0; M_PI / 2 + 2 * M_PI * n + half < 60; ++n) {
        expect.push_back(M_PI / 2 + 2 * M_PI * n - half);
        expect.push_back(M_PI / 2 + 2 * M_PI * n + half);
      }
      ASSERT_EQ(r.times.size(), expect.size());
      for (std::size_t i = 0; i < expect.size(); ++i)
        EXPECT_NEAR(r.times[i], expect[i], 1e-10 * (1 + expect[i]) / std::sin(half)) << i;
      EXPECT_LT(2 * half, 60.0 / r.accepted);  // shorter than a mean step
    }
  }
}
