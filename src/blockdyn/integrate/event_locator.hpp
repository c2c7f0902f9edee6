// SPDX-License-Identifier: Apache-2.0
#pragma once
// Where, inside an accepted step, the first event function of a hybrid model crosses zero
// (hybrid_integrator.hpp calls it at every step): each armed function is bounded from below by an
// envelope built from its values and rates at the step ends and its values at a few interior
// points (event_envelope.hpp); only where the envelope may reach zero is the dense output searched
// (Brent's minimum, then TOMS 748 to a few ulps). Keeps which functions are armed, their values
// and rates at the step's ends, and the Hermite remainder last measured, which lets most steps
// go without interior samples.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>

#include <boost/math/tools/minima.hpp>

#include "blockdyn/integrate/event_envelope.hpp"
#include "blockdyn/integrate/hybrid_model.hpp"
#include "blockdyn/integrate/integrator_options.hpp"
#include "blockdyn/integrate/root_bracket.hpp"

namespace blockdyn {

template <HybridModel Model>
class EventLocator {
 public:
  static constexpr std::size_t N = Model::kDim;
  static constexpr std::size_t NE = Model::kNumEvents;
  using Mode = typename Model::Mode;
  using State = Vec<N>;
  using Events = std::array<double, NE>;

  EventLocator(const Model& model, const IntegratorOptions& opt) : model_(model), opt_(opt) {}

  // The run's input-side clamp: within a step that ends at a breakpoint the input is evaluated
  // on the step's side of it.
  void set_clamp(const double* t_clamp) { t_clamp_ = t_clamp; }

  // At a restart (run start, after an event or a breakpoint): values and rates for the scan of
  // the step to come, of size about h.
  void start(double t, const Mode& mode, const State& z, const State& k1, double h) {
    values_and_rates(t, mode, z, k1, h, g_start_, gd_start_, gd_err_start_);
    remainder_known_ = false;
  }
  // At an accepted step's end t (z completed, dz its rate): values and rates, by differences
  // backwards (on the step's side of a breakpoint) over a fraction of the step h.
  void step_end(double t, const Mode& mode, const State& z, const State& dz, double h) {
    values_and_rates(t, mode, z, dz, -h, g_end_, gd_end_, gd_err_end_);
  }
  // Every function armed (after a transition: one at zero fires at once unless it rises first).
  void arm_all() { armed_.fill(true); }
  // Only those positive at (t, z) in `mode` armed (a mode held at a chatter).
  void arm_positive(double t, const Mode& mode, const State& z) {
    Events g;
    model_.events(t, mode, z, g);
    for (std::size_t i = 0; i < NE; ++i) armed_[i] = g[i] > 0.0;
  }

  // The event values and rates at the accepted step's end become those at the next step's start.
  void keep_end_values() {
    g_start_ = g_end_;
    gd_start_ = gd_end_;
    gd_err_start_ = gd_err_end_;
  }

  // An event function disarmed at zero is armed again once it is positive at a step end.
  void rearm_risen() {
    for (std::size_t i = 0; i < NE; ++i)
      if (!armed_[i] && g_start_[i] > 0.0) {
        armed_[i] = true;
        remainder_known_ = false;
      }
  }

  struct Hit {
    double t;
    int index;
  };

  // The earliest event in the step [t0, t1], if any. Each armed event function is bounded from
  // below by its envelope (values and rates at both ends, values at `event_samples` interior
  // points); where the envelope may reach zero the function is sampled once more at the
  // model's minimum there, and if that does not settle it, searched on the dense output (Brent's
  // minimum, then TOMS 748 to a few ulps).
  template <class EnsureDense>
  std::optional<Hit> scan(const DenseSegment<N>& seg, double t0, double t1, const Mode& mode,
                          EnsureDense&& ensure_dense) {
    const int S = std::clamp(opt_.event_samples, 1, kMaxSamples);
    const double h = t1 - t0;
    if (no_event_by_last_remainder(h)) return std::nullopt;
    ensure_dense();
    int n = 0;
    std::array<double, kMaxSamples + kMaxRefine> s_at;
    std::array<Events, kMaxSamples + kMaxRefine> g_at;
    auto g_all = [&](double tt, Events& ge) {
      State yy;
      seg.eval(tt, yy);
      complete_and_events(model_, std::fmin(tt, *t_clamp_), mode, yy, ge);
    };
    for (int j = 1; j <= S; ++j, ++n) {
      s_at[n] = double(j) / (S + 1);
      g_all(t0 + s_at[n] * h, g_at[n]);
    }
    std::optional<Hit> best;
    for (std::size_t i = 0; i < NE; ++i) {
      if (!armed_[i]) continue;
      const double g0 = g_start_[i], g1 = g_end_[i];
      auto gi = [&](double tt) {
        State yy;
        seg.eval(tt, yy);
        return complete_and_event(model_, std::fmin(tt, *t_clamp_), mode, yy, int(i));
      };
      // A function at or below zero at the step start (one that just fired, or any other at a
      // restart) fires there unless it rises first.
      const bool at_zero = !(g0 > 0.0);
      std::array<double, kMaxSamples + kMaxRefine> ss, gs;
      int m = 0;
      for (int j = 0; j < n; ++j, ++m) {
        ss[m] = s_at[j];
        gs[m] = g_at[j][i];
      }
      // The remainder measured here bounds it on the steps that follow (no_event_by_last_remainder).
      remainder_[i] = measured_remainder(g0, gd_start_[i], g1, gd_end_[i], h, ss.data(), gs.data(), m, at_zero);
      if (at_zero && gs[0] < 0.0) {
        const double tb = t0 + ss[0] * h;
        const double root = restart_root(gi, t0, tb, gs[0]);
        if (!best || root < best->t) best = Hit{root, int(i)};
        continue;
      }
      const double rate_err = std::fmax(gd_err_start_[i], gd_err_end_[i]);
      EventEnvelope env =
          make_event_envelope(g0, gd_start_[i], g1, gd_end_[i], h, ss.data(), gs.data(), m, rate_err, at_zero);
      if (g1 >= 0.0 && env.positive()) continue;
      std::optional<double> root;
      double from = 0.0, sa, sb;
      while (!root && env.next_doubtful(kSubdivision, from, sa, sb)) {
        sa = std::fmax(sa, from);
        if (best && t0 + sa * h >= best->t) break;
        if (sb >= 1.0 && g1 < 0.0) {
          root = final_crossing(gi, env, t0, h, sa, g0, g1, at_zero);
          break;
        }
        // A doubtful stretch inside the step: sample at the model's minimum there; a negative
        // value brackets a root, a positive one sharpens the envelope.
        bool settled = false;
        for (int r = 0; r < kMaxRefine && !settled; ++r) {
          const double sm = model_minimum(env.model, sa, sb);
          const double tm = t0 + sm * h;
          if (!(tm > t0) || !(tm < t1)) break;
          Events gm_all;
          g_all(tm, gm_all);
          const double gm = gm_all[i];
          if (gm < 0.0) {
            root = dip_crossing(gi, t0, h, sa, tm, g0, gm, at_zero);
            settled = true;
            break;
          }
          ss[m] = sm;
          gs[m] = gm;
          ++m;
          env = make_event_envelope(g0, gd_start_[i], g1, gd_end_[i], h, ss.data(), gs.data(), m, rate_err, at_zero);
          double sa2, sb2;
          if (!env.next_doubtful(kSubdivision, from, sa2, sb2) || sa2 > sb) {
            settled = true;
          } else {
            sa = std::fmax(sa2, from);
            sb = sb2;
          }
        }
        if (!root && !settled) {
          // Still doubtful: the minimum of the function itself on the stretch.
          const double ta = t0 + sa * h, tb = t0 + sb * h;
          const auto mn = minimum(ta, tb, gi);
          if (mn.second < 0.0 && !(at_zero && gd_start_[i] >= 0.0 && unresolved_dip(mn.second, g1, gs.data(), m)))
            root = dip_crossing(gi, t0, h, sa, mn.first, g0, mn.second, at_zero);
        }
        from = sb;
        if (from >= 1.0) break;
      }
      if (root && (!best || *root < best->t)) best = Hit{*root, int(i)};
    }
    remainder_known_ = true;
    remainder_h_ = h;
    steps_since_samples_ = 0;
    return best;
  }

  // The fresh step to the event time te ends where the step's own solution is, which differs
  // from the straddling step's interpolant (where te was found) by up to the local error: the
  // event function is then not quite zero there. Newton corrections on the fresh step's dense
  // output (7th order with DOP853; a move of at most 1e-3 of the step, past te an extrapolation
  // of the same smooth piece) put the event state on the event surface to rounding, without
  // another step. Each kept only if it reduces |g|.
  void polish(double t, double t_next, int index, const Mode& mode, double& te, State& ze,
              const DenseSegment<N>& seg) const {
    auto g_at = [&](double tt, State y) {
      return complete_and_event(model_, std::fmin(tt, *t_clamp_), mode, y, index);
    };
    double g_e = g_at(te, ze);
    const double reach = 1e-3 * (te - t), t_fresh = te;
    for (int iter = 0; iter < kPolishIterations; ++iter) {
      if (g_e == 0.0 || !std::isfinite(g_e)) return;
      const double d = 1e-3 * (t_fresh - t);
      State zd;
      seg.eval(te - d, zd);
      const double slope = (g_e - g_at(te - d, zd)) / d;
      if (!(std::fabs(slope) > 0.0) || !std::isfinite(slope)) return;
      const double tn = te - g_e / slope;
      if (!(tn > t) || !(tn <= t_next) || tn == te || std::fabs(tn - t_fresh) > reach) return;
      State zn;
      seg.eval(tn, zn);
      const double g_n = g_at(tn, zn);
      if (!(std::fabs(g_n) < std::fabs(g_e))) return;
      te = tn;
      ze = zn;
      g_e = g_n;
    }
  }

 private:
  // Values g and rates gd of the event functions at (t, z) (z completed, dz = f(t, z)), and a
  // bound gd_err on the error of each rate. Rates the model does not provide are difference
  // quotients over a small time step `delta` along dz: delta > 0 at a restart (forward, into the
  // step to come), < 0 at a step end (backward, on the step's side of a breakpoint).
  void values_and_rates(double t, const Mode& mode, const State& z, const State& dz, double delta, Events& g,
                        Events& gd, Events& gd_err) {
    bool need_difference = true;
    if constexpr (has_event_rates<Model>()) {
      model_.event_rates(t, mode, z, dz, g, gd);
      need_difference = false;
      for (std::size_t i = 0; i < NE; ++i) need_difference |= std::isnan(gd[i]);
    } else {
      model_.events(t, mode, z, g);
      gd.fill(std::numeric_limits<double>::quiet_NaN());
    }
    gd_err.fill(0.0);
    if (!need_difference) return;
    const double d = kRateStep * delta;
    State zd;
    for (std::size_t i = 0; i < N; ++i) zd[i] = z[i] + d * dz[i];
    Events gdd;
    const double td = t + d;
    complete_and_events(model_, std::fmin(td, *t_clamp_), mode, zd, gdd);
    const double dt = td - t;  // the step actually taken in t
    for (std::size_t i = 0; i < NE; ++i) {
      if (!std::isnan(gd[i])) continue;
      gd[i] = (gdd[i] - g[i]) / dt;
      // Rounding of the two values over the small step; the truncation error (dt g''/2) is far
      // below the envelope's relative floor.
      gd_err[i] = 8.0 * std::numeric_limits<double>::epsilon() * (std::fabs(g[i]) + std::fabs(gdd[i])) / std::fabs(dt);
    }
  }

  // A function that starts the step at zero (a restart) without falling (a motion that starts
  // from rest when a force balance tips, like Housner's uplift at the threshold: value, rate and
  // curvature all zero) and is positive everywhere it was sampled can show a tiny minimum just
  // after the start: -1e-24 where it rises to 1e-5 over the step (DOP853), -7e-19 for 3e-7
  // (Dopri5). That is the dense output's error, not a crossing; taking it for one restarts the
  // same motion at the same instant for ever. A dip shallower than the step's relative accuracy
  // (rtol, at least 64 ulps) times the largest value seen on the step is not resolved: no event.
  bool unresolved_dip(double g_min, double g1, const double* gs, int n) const {
    double scale = std::fabs(g1);
    for (int j = 0; j < n; ++j) scale = std::fmax(scale, std::fabs(gs[j]));
    return -g_min <= std::fmax(kDipRounding, opt_.rtol) * scale;
  }

  // Largest |phi| of the Hermite remainder s^2 (1 - s)^2 phi(s) at the samples.
  static double measured_remainder(double g0, double gd0, double g1, double gd1, double h, const double* s,
                                   const double* gs, int n, bool at_zero) {
    const double a0 = at_zero ? 0.0 : g0;
    const double b1 = a0 + h * gd0 / 3.0, b2 = g1 - h * gd1 / 3.0;
    double phi = 0.0;
    for (int j = 0; j < n; ++j) {
      const double u = s[j], v = 1.0 - u;
      const double hermite = v * v * v * a0 + 3.0 * u * v * v * b1 + 3.0 * u * u * v * b2 + u * u * u * g1;
      phi = std::fmax(phi, std::fabs((gs[j] - hermite) / (u * u * v * v)));
    }
    return std::isfinite(phi) ? phi : INFINITY;
  }

  // Between samplings the remainder of each function is bounded by kLagSafety times the one last
  // measured, scaled as h^4 (phi = h^4 g^(4) / 24); a step on which every armed function's
  // envelope with that bound stays positive needs no interior sample and no dense output. The
  // measurement is renewed at least every kResample steps and after every restart.
  bool no_event_by_last_remainder(double h) {
    if (!remainder_known_ || steps_since_samples_ >= kResample) return false;
    const double q = h / remainder_h_;
    const double scale = kLagSafety * (q * q) * (q * q);
    for (std::size_t i = 0; i < NE; ++i) {
      if (!armed_[i]) continue;
      const double g0 = g_start_[i], g1 = g_end_[i];
      if (!(g0 > 0.0) || !(g1 > 0.0)) return false;
      const double rate_err = std::fmax(gd_err_start_[i], gd_err_end_[i]);
      const EventEnvelope env =
          make_event_envelope_bounded(g0, gd_start_[i], g1, gd_end_[i], h, scale * remainder_[i], rate_err);
      double sa, sb;
      if (!env.positive() && env.next_doubtful(kSubdivision, 0.0, sa, sb)) return false;
    }
    ++steps_since_samples_;
    return true;
  }

  // The root of a function at or below zero at t0 that is negative at tb: the root after the
  // last positive value found by halving towards t0 (a rise of 1e-7 inside a step of 1e-3 is
  // found), else t0 (it fires at once).
  template <class G>
  static double restart_root(G&& g, double t0, double tb, double gb) {
    for (int k = 1; k <= 60; ++k) {
      const double tt = t0 + std::ldexp(tb - t0, -k);
      if (!(tt > t0)) break;
      const double gt = g(tt);
      if (gt > 0.0) return locate_root(g, tt, tb, gt, gb);
    }
    return t0;
  }

  // A positive point of g in (t0, t0 + s h] for the left end of a bracket: the stretch start
  // itself, or (at a restart with g(t0) <= 0) the first positive value halving towards t0.
  template <class G>
  static std::optional<std::pair<double, double>> left_end(G&& g, double t0, double h, double sa, double tb, double g0,
                                                           bool at_zero) {
    if (sa <= 0.0) {
      if (!at_zero) return std::make_pair(t0, g0);
      for (int k = 1; k <= 60; ++k) {
        const double tt = t0 + std::ldexp(tb - t0, -k);
        if (!(tt > t0)) break;
        const double gt = g(tt);
        if (gt > 0.0) return std::make_pair(tt, gt);
      }
      return std::nullopt;
    }
    const double ta = t0 + sa * h;
    const double ga = g(ta);
    if (ga > 0.0) return std::make_pair(ta, ga);
    // The envelope was positive before the stretch but the function is not: start at t0.
    return left_end(g, t0, h, 0.0, ta, g0, at_zero);
  }

  // The root before a negative value gm at tm inside the step (a dip found in the stretch from sa).
  template <class G>
  static double dip_crossing(G&& g, double t0, double h, double sa, double tm, double g0, double gm, bool at_zero) {
    const auto lo = left_end(g, t0, h, sa, tm, g0, at_zero);
    if (!lo) return t0;
    return locate_root(g, lo->first, tm, lo->second, gm);
  }

  // The first root in the last stretch [sa, 1] of a function that ends the step negative. If the
  // model of the function dips inside the stretch before its end, a crossing there comes first.
  template <class G>
  double final_crossing(G&& g, const EventEnvelope& env, double t0, double h, double sa, double g0, double g1,
                        bool at_zero) const {
    const double t1 = t0 + h;
    const auto lo = left_end(g, t0, h, sa, t1, g0, at_zero);
    if (!lo) return t0;
    const double s_lo = (lo->first - t0) / h;
    // A local minimum of the model strictly inside: look at the function's own minimum first.
    constexpr int kGrid = 16;
    std::array<double, kGrid + 1> q;
    const Power4 model = to_power(env.model);
    for (int k = 0; k <= kGrid; ++k) q[k] = model(s_lo + (1.0 - s_lo) * k / kGrid);
    for (int k = 1; k < kGrid; ++k) {
      if (!(q[k] <= q[k - 1] && q[k] < q[k + 1])) continue;
      const double a = t0 + (s_lo + (1.0 - s_lo) * (k - 1) / kGrid) * h;
      const double b = t0 + (s_lo + (1.0 - s_lo) * (k + 1) / kGrid) * h;
      const auto mn = minimum(std::fmax(a, lo->first), std::fmin(b, t1), g);
      if (mn.second < 0.0) return locate_root(g, lo->first, mn.first, lo->second, mn.second);
      break;
    }
    return locate_root(g, lo->first, t1, lo->second, g1);
  }

  // Where a model of the function (Bernstein form on the step) is smallest on [sa, sb].
  static double model_minimum(const Bernstein4& q, double sa, double sb) {
    constexpr int kGrid = 16;
    const Power4 model = to_power(q);
    double best_s = 0.5 * (sa + sb), best_q = INFINITY;
    for (int k = 0; k <= kGrid; ++k) {
      const double s = sa + (sb - sa) * k / kGrid;
      const double v = model(s);
      if (v < best_q) {
        best_q = v;
        best_s = s;
      }
    }
    // Keep away from the ends of the step (known there).
    return std::clamp(best_s, 1.0 / 64, 1.0 - 1.0 / 64);
  }

  // Minimum of g on [a, b] (Brent): (location, value).
  template <class G>
  static std::pair<double, double> minimum(double a, double b, G&& g) {
    std::uintmax_t iters = 60;
    return boost::math::tools::brent_find_minima(g, a, b, 26, iters);
  }

  static constexpr int kMaxSamples = 64;
  static constexpr int kPolishIterations = 2;
  static constexpr int kMaxRefine = 2;          // extra samples in a doubtful stretch before a search
  static constexpr int kSubdivision = 5;        // doubtful stretches are located to 1/32 of a step
  static constexpr double kRateStep = 0x1p-20;  // difference quotients over this fraction of a step
  static constexpr int kResample = 4;           // interior samples at least every this many steps
  static constexpr double kLagSafety = 8.0;     // margin on a remainder measured on an earlier step
  // A dip after a restart shallower than this (or rtol) times the function is not resolved.
  static constexpr double kDipRounding = 64 * std::numeric_limits<double>::epsilon();
  const Model& model_;
  IntegratorOptions opt_;
  std::array<bool, NE> armed_{};
  // Event values, rates and bounds on the rates' errors at the start and at the end of the step.
  Events g_start_{}, gd_start_{}, gd_err_start_{};
  Events g_end_{}, gd_end_{}, gd_err_end_{};
  // The remainder coefficients last measured (scan), on a step of size remainder_h_.
  Events remainder_{};
  double remainder_h_ = 0.0;
  bool remainder_known_ = false;
  int steps_since_samples_ = 0;
  const double* t_clamp_ = nullptr;
};

}  // namespace blockdyn
