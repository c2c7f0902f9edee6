// SPDX-License-Identifier: Apache-2.0
// Validation of the integration engine (issue 2, item 2): the Dormand-Prince 5(4) stepper's
// order of convergence, its continuous extension, and the event-driven HybridIntegrator on toy
// hybrid systems whose event times are known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "blockdyn/integrate/dopri5.hpp"
#include "blockdyn/integrate/hybrid_integrator.hpp"
#include "stepper_test_problem.hpp"
#include "threshold_test_model.hpp"

using namespace blockdyn;

namespace {

using namespace stepper_test;

double dopri5_global_error(int n, double T) { return stepper_test::global_error<Dopri5<kN>>(n, T); }

}  // namespace

TEST(Dopri5, FifthOrderGlobalConvergence) {
  const double T = 3.0;
  std::vector<double> e;
  for (int n : {16, 32, 64, 128}) e.push_back(dopri5_global_error(n, T));
  stepper_test::expect_orders(e, 4.7, 5.5, "global error, steps doubled");
  EXPECT_LT(e.back(), 1e-9);
}

TEST(Dopri5, FsalAndDenseOutputOrder) {
  // One step from the exact value: the step end has local error O(h^6); the order-4 continuous
  // extension has local error O(h^5) inside the step; both ends of the interpolant are exact
  // copies of the step's start and end.
  const double t0 = 0.4;
  const double theta = 0.37;
  std::vector<double> e_end, e_mid;
  for (double h : {0.2, 0.1, 0.05, 0.025}) {
    stepper_test::OneStep<Dopri5<kN>> s(t0, h);
    DenseSegment<kN> seg;
    s.st.dense(t0, h, s.y, s.y1, s.k1, s.k_end, seg);
    stepper_test::expect_segment_ends(seg, t0, h, s.y, s.y1);
    Vec<kN> ym;
    seg.eval(t0 + theta * h, ym);
    e_end.push_back(max_err(s.y1, exact(t0 + h)));
    e_mid.push_back(max_err(ym, exact(t0 + theta * h)));
  }
  stepper_test::expect_orders(e_end, 5.6, 6.6, "step end");
  stepper_test::expect_orders(e_mid, 4.6, 5.6, "dense output");
}

TEST(Dopri5, ErrorEstimateIsFifthPowerOfStep) {
  // The embedded order-4 solution differs from the order-5 one by O(h^5).
  const std::vector<double> est = stepper_test::step_estimates<Dopri5<kN>>({0.2, 0.1, 0.05});
  stepper_test::expect_orders(est, 4.5, 5.5, "error estimate");
}

// ---- Hybrid toy models --------------------------------------------------------------------

namespace {

// A mass on a unit spring that bounces elastically off a wall at x = a (0 < a < 1), released
// from x = 1 at rest: x = cos t until the first impact at t1 = acos(a), and by the symmetry of
// elastic reflection the impacts follow at t = (2n - 1) t1. A second event function (x <= 2)
// never fires and checks that unrelated functions do not disturb the location.
struct WallOscillator {
  static constexpr std::size_t kDim = 2;
  static constexpr std::size_t kNumEvents = 2;
  using Mode = int;  // impacts so far
  using State = Vec<2>;
  double wall;
  void rhs(double, const Mode&, const State& z, State& dz) const {
    dz[0] = z[1];
    dz[1] = -z[0];
  }
  void events(double, const Mode&, const State& z, std::array<double, 2>& g) const {
    g[0] = z[0] - wall;
    g[1] = 2.0 - z[0];
  }
  void complete(const Mode&, State&) const {}
  Transition<Mode> transition(double, const Mode& m, const State&, int) const { return {m + 1, false, 0}; }
  std::optional<Transition<Mode>> resolve_chatter(double, const Mode&, const State&) const { return std::nullopt; }
  double step_hint(const Mode&) const { return 0.1; }
  State abs_tol_scale() const { return {1.0, 1.0}; }
};

struct Recorder {
  std::vector<double> times;
  std::vector<Vec<2>> states;
  template <class Seg, class M>
  bool on_step(const Seg&, double, double, const M&) {
    return true;
  }
  template <class Info>
  bool on_event(const Info& e) {
    times.push_back(e.t);
    states.push_back(e.z);
    return true;
  }
};

// Ball falling under unit gravity onto the floor y = 0 with restitution 1. The transition stops
// the run and the driver below reflects the velocity and restarts (the engine has no state
// jumps). Positions are quadratic in time, so DOPRI5 is exact and the event times test the
// root finder alone: bounce n (from 1) at (2n - 1) sqrt(2 H).
struct Ball {
  static constexpr std::size_t kDim = 2;
  static constexpr std::size_t kNumEvents = 1;
  using Mode = int;
  using State = Vec<2>;
  void rhs(double, const Mode&, const State& z, State& dz) const {
    dz[0] = z[1];
    dz[1] = -1.0;
  }
  void events(double, const Mode&, const State& z, std::array<double, 1>& g) const { g[0] = z[0]; }
  void complete(const Mode&, State&) const {}
  Transition<Mode> transition(double, const Mode& m, const State&, int) const { return {m + 1, true, 0}; }
  std::optional<Transition<Mode>> resolve_chatter(double, const Mode&, const State&) const { return std::nullopt; }
  double step_hint(const Mode&) const { return 0.1; }
  State abs_tol_scale() const { return {1.0, 1.0}; }
};

// Runs `model` from z, reflecting the velocity (component 1) at every stopping event.
template <class M>
std::vector<double> bounce_times(const M& model, Vec<2> z, double t_end, double rtol, int max_events,
                                 std::vector<Vec<2>>* states = nullptr, Method method = Method::Auto) {
  IntegratorOptions o;
  o.method = method;
  o.rtol = rtol;
  o.atol = rtol * 1e-2;
  std::vector<double> times;
  double t = 0;
  typename M::Mode mode = 0;
  while (t < t_end && int(times.size()) < max_events) {
    HybridIntegrator<M> integ(model, o);
    Recorder rec;
    const RunStatus s = integ.run(t, t_end, mode, z, rec);
    if (s != RunStatus::ModelStop) break;
    times.push_back(t);
    if (states) states->push_back(z);
    z[1] = -z[1];
  }
  return times;
}

struct WallStop : WallOscillator {
  Transition<Mode> transition(double, const Mode& m, const State&, int) const { return {m + 1, true, 0}; }
};

}  // namespace

// The event tests run on both Runge-Kutta pairs.
constexpr Method kPairs[] = {Method::Dopri5, Method::Dop853};

TEST(HybridIntegrator, BouncingBallEventTimesAreExact) {
  const double H = 1.3;
  const double t1 = std::sqrt(2 * H);
  for (Method method : kPairs) {
    SCOPED_TRACE(to_string(method));
    const auto times = bounce_times(Ball{}, {H, 0.0}, 40.0, 1e-10, 100, nullptr, method);
    ASSERT_EQ(times.size(), std::size_t(std::floor((40.0 / t1 + 1) / 2)));
    for (std::size_t n = 0; n < times.size(); ++n) {
      const double expect = (2.0 * n + 1) * t1;
      // Exact arithmetic would give the bounce times exactly; rounding accumulates over the
      // bounces, a little more in DOP853's longer stage sums (about 5 ulps per bounce).
      EXPECT_NEAR(times[n], expect, (method == Method::Dop853 ? 2e-14 : 1e-14) * expect) << "bounce " << n;
    }
  }
}

TEST(HybridIntegrator, WallOscillatorEventTimesToRoundoff) {
  const double a = 0.3;
  const double t1 = std::acos(a);
  WallStop m;
  m.wall = a;
  for (Method method : kPairs) {
    SCOPED_TRACE(to_string(method));
    std::vector<Vec<2>> states;
    const auto times = bounce_times(m, {1.0, 0.0}, 30.0, 1e-13, 100, &states, method);
    ASSERT_EQ(times.size(), std::size_t(std::floor((30.0 / t1 + 1) / 2)));
    for (std::size_t n = 0; n < times.size(); ++n) {
      const double expect = (2.0 * n + 1) * t1;
      EXPECT_NEAR(times[n], expect, 1e-13 * expect) << "impact " << n;
      EXPECT_NEAR(states[n][0], a, 1e-13);
      // The speed drifts like the global error: a few 1e-14 per half arc.
      EXPECT_NEAR(std::fabs(states[n][1]), std::sqrt(1 - a * a), 1e-13 * (n + 1));
    }
  }
}

namespace {
// x = sin t; the event function c - x dips below zero only for |t - pi/2| < acos(c), a window
// far shorter than the steps DOPRI5 takes on this smooth problem.
using Grazing = threshold_test::ThresholdCrossing<threshold_test::Harmonic>;

// Grazing with threshold c run from x = 0, x' = 1 (x = sin t) up to t_end at rtol 1e-12.
struct GrazingRun {
  RunStatus status;
  std::vector<double> times;  // event times
  long accepted;              // accepted steps
  int event_samples;          // event-function samples per step
};

GrazingRun run_grazing(double c, double t_end, Method method) {
  Grazing m;
  m.c = c;
  IntegratorOptions o;
  o.method = method;
  o.rtol = 1e-12;
  o.atol = 1e-14;
  HybridIntegrator<Grazing> integ(m, o);
  Recorder rec;
  double t = 0;
  int mode = 0;
  Vec<2> z{0.0, 1.0};
  const RunStatus s = integ.run(t, t_end, mode, z, rec);
  return {s, rec.times, integ.stats().accepted, o.event_samples};
}
}  // namespace

TEST(HybridIntegrator, EventFunctionZeroAtRestartDoesNotRefire) {
  // Each transition turns the event function round (c - x, then x - c), so it restarts at zero
  // and grows: it must not fire again at the restart instant. x = sin t crosses c = 0.3 at
  // asin(c), pi - asin(c), 2 pi + asin(c), ...: exactly these, no extra zero-time events.
  for (Method method : kPairs) {
    SCOPED_TRACE(to_string(method));
    const GrazingRun run = run_grazing(0.3, 20.0, method);
    EXPECT_EQ(run.status, RunStatus::ReachedEnd);
    std::vector<double> expect;
    for (int n = 0; n < 4; ++n) {
      expect.push_back(2 * M_PI * n + std::asin(0.3));
      expect.push_back(2 * M_PI * n + M_PI - std::asin(0.3));
    }
    while (expect.back() > 20.0) expect.pop_back();
    ASSERT_EQ(run.times.size(), expect.size());
    for (std::size_t i = 0; i < expect.size(); ++i) EXPECT_NEAR(run.times[i], expect[i], 1e-11 * expect[i]);
  }
}

TEST(HybridIntegrator, BriefExcursionBetweenSamplesIsNotSkipped) {
  for (Method method : kPairs)
    for (double depth : {1e-4, 1e-6, 1e-8}) {
      SCOPED_TRACE(to_string(method));
      const double c = 1.0 - depth;
      const GrazingRun run = run_grazing(c, 3.0, method);
      const double half = std::acos(c);  // sin t > c for |t - pi/2| < acos(c)
      ASSERT_EQ(run.times.size(), 2u) << "depth " << depth;
      // Near the peak a state error dx moves the crossing by dx / |x'| = dx / sin(half).
      const double tol = 1e-12 / std::sin(half);
      EXPECT_NEAR(run.times[0], M_PI / 2 - half, tol) << depth;
      EXPECT_NEAR(run.times[1], M_PI / 2 + half, tol) << depth;
      // For the shallowest dip the excursion is shorter than the spacing of the event samples
      // (else the test would prove nothing).
      if (depth <= 1e-8) {
        EXPECT_LT(2 * half, 3.0 / run.accepted / run.event_samples);
      }
    }
}
