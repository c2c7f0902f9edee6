// SPDX-License-Identifier: Apache-2.0
#pragma once
// Generic integrator for piecewise-smooth (hybrid) systems: adaptive Dormand-Prince, 5(4) or
// 8(5,3) chosen per run (IntegratorOptions::method), event location on the dense output by bracketing + TOMS 748,
// restart at each event. The event scan of a step (scan_events) bounds each event function from
// below by an envelope built from its values and rates at the step ends and its values at a few
// interior points (event_envelope.hpp); the dense output is searched only where the envelope
// may reach zero.
//
// A model supplies (see HybridModel below): the state size, a Mode type, right-hand sides per
// mode, event functions that must stay >= 0 while a mode is valid, the transition map applied
// when one of them becomes negative (it may also change the state: an impact is a velocity
// jump), and the breakpoints of its time dependence (kinks and jumps of a ground motion): no
// step crosses a breakpoint; each step is integrated with the input as it is on the step's side
// of the breakpoint, and at the breakpoint the model's transition is called with event index
// kBreakpoint so it can re-select its mode. The integrator knows nothing about blocks.
#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include <boost/math/tools/minima.hpp>

#include "blockdyn/integrate/dop853.hpp"
#include "blockdyn/integrate/dopri5.hpp"
#include "blockdyn/integrate/event_envelope.hpp"
#include "blockdyn/integrate/hybrid_model.hpp"
#include "blockdyn/integrate/integrator_options.hpp"
#include "blockdyn/integrate/root_bracket.hpp"
#include "blockdyn/integrate/run_observer.hpp"

namespace blockdyn {

// Observer: on_step(seg, t_lo, t_hi, mode) for every piece of accepted trajectory,
// on_event(info) at every event; both return false to stop the run.
template <HybridModel Model>
class HybridIntegrator {
 public:
  static constexpr std::size_t N = Model::kDim;
  static constexpr std::size_t NE = Model::kNumEvents;
  using Mode = typename Model::Mode;
  using State = Vec<N>;
  using Events = std::array<double, NE>;
  using ObserverRef = RunObserver<Mode, N>;

  HybridIntegrator(const Model& model, IntegratorOptions opt)
      : model_(model), opt_(opt), high_order_(resolved_method(opt) == Method::Dop853) {
    const State sc = model_.abs_tol_scale();
    for (std::size_t i = 0; i < N; ++i) {
      dopri5_.atol[i] = dop853_.atol[i] = opt_.atol * sc[i];
      dopri5_.rtol[i] = dop853_.rtol[i] = opt_.rtol;
    }
  }

  const StepperStats& stats() const { return stats_; }

  // Runs from (t, mode, z) to t_end or an event that stops; t, mode and z are left where it ended.
  template <class Observer>
  RunStatus run(double& t, double t_end, Mode& mode, State& z, Observer& obs) {
    if constexpr (std::same_as<Observer, ObserverRef>) {
      return run_observed(t, t_end, mode, z, obs);
    } else {
      ObserverRef ref(obs);
      return run_observed(t, t_end, mode, z, ref);
    }
  }

  // The run loop itself, compiled once per model (defined below the class, so not inline: a
  // model's `extern template` declaration keeps other files from compiling it again).
  RunStatus run_observed(double& t, double t_end, Mode& mode, State& z, ObserverRef& obs);

 private:
  // The event values and rates at the accepted step's end become those at the next step's start.
  void keep_end_values() {
    g_start_ = g_end_;
    gd_start_ = gd_end_;
    gd_err_start_ = gd_err_end_;
  }

  // After an event: the new mode's derivative, next breakpoint and first step (the model's hint,
  // its restart step, cut at a kink); returns the step.
  template <class F>
  double restart_after_event(F& f, double t, const Mode& mode, const State& z, State& k1, double h_new,
                             double& t_break) {
    f(t, z, k1);
    ++stats_.rhs_evals;
    t_break = next_breakpoint_of(model_, t, mode);
    double h = std::fmin(h_new, model_.step_hint(mode));
    h = restart_step_of(model_, t, mode, z, k1, std::fmin(h, opt_.h_max));
    h = cut_at_kink(t, mode, z, k1, h);
    start_rates(t, mode, z, k1, h);
    return h;
  }

  // Observers get an accepted step without an event (its end state given; ensure: how they get the
  // full dense output if the step has only its Hermite interpolant). False: one asked to stop.
  template <class Ensure>
  bool observe_step(ObserverRef& obs, DenseSegment<N>& seg, double t, double t_next, const Mode& mode,
                    const State& y_end, Ensure* ensure) {
    if (ensure) seg.set_refine([](void* e) { (*static_cast<Ensure*>(e))(); }, ensure);
    seg.end_state = &y_end;
    const bool go = obs.on_step(seg, t, t_next, mode);
    seg.set_refine(nullptr, nullptr);
    seg.end_state = nullptr;
    return go;
  }

  // At an input breakpoint reached by a step: the model re-selects its mode (the input may jump
  // or kink), and the integration restarts from there.
  template <class F>
  std::optional<RunStatus> restart_at_breakpoint(F& f, double t, Mode& mode, State& z, State& k1, double& h,
                                                 double& t_break, ObserverRef& obs) {
    if (const auto end = apply_transition(t, kBreakpoint, mode, z, obs)) return end;
    f(t, z, k1);
    ++stats_.rhs_evals;
    t_break = next_breakpoint_of(model_, t, mode);
    h = std::fmin(h, model_.step_hint(mode));
    start_rates(t, mode, z, k1, h);
    return std::nullopt;
  }

  // The accepted step straddles the event at te, where the right-hand side is usually not smooth
  // (forces switch on or off), so its interpolant is least accurate exactly there. One fresh step
  // from t to te stays on the smooth side and gives the event state ze the accuracy of an
  // ordinary step end; observers get the piece up to te (false: one asked to stop).
  template <class F>
  bool step_to_event(F& f, double t, double t_next, int index, const Mode& mode, const State& z, const State& k1,
                     double& te, State& ze, DenseSegment<N>& seg, ObserverRef& obs) {
    State k7e;
    const double err_e = attempt(f, t, te - t, z, k1, ze, k7e);
    if (std::isfinite(err_e)) {
      dense(f, t, te - t, z, ze, k1, k7e, seg);
      polish_event(f, t, t_next, index, mode, z, k1, te, ze, seg);
    } else {
      seg.eval(te, ze);
    }
    return obs.on_step(seg, t, te, mode);
  }

  // Zero-duration events repeating at one instant: the model holds a mode (sticking, resting)
  // if it can; observers see the hold; the event functions are armed from the held mode.
  std::optional<RunStatus> hold_chatter(double t, Mode& mode, State& z, ObserverRef& obs) {
    const auto held = model_.resolve_chatter(t, mode, z);
    if (!held) return RunStatus::Chatter;
    EventInfo<Mode, N> hold{t, z, z, mode, held->next, -1, held->kind, held->stop};
    if (held->stop) {  // the model ends the run here instead (a chatter it cannot resolve)
      obs.on_event(hold);
      return RunStatus::ModelStop;
    }
    mode = held->next;
    model_.complete(mode, z);
    hold.z = z;
    if (!obs.on_event(hold)) return RunStatus::ObserverStop;
    Events g_hold;
    model_.events(t, mode, z, g_hold);
    for (std::size_t i = 0; i < NE; ++i) armed_[i] = g_hold[i] > 0.0;
    return std::nullopt;
  }

  // An event function disarmed at zero is armed again once it is positive at a step end.
  void rearm_risen() {
    for (std::size_t i = 0; i < NE; ++i)
      if (!armed_[i] && g_start_[i] > 0.0) {
        armed_[i] = true;
        remainder_known_ = false;
      }
  }

  // The transition of event `index` (or kBreakpoint) at t: the model picks the next mode and may
  // change the state; observers see it with the state before and after. Every event function is
  // armed again (one at zero fires at once unless it rises first). Returns the run's end status
  // when the model or an observer stops it.
  std::optional<RunStatus> apply_transition(double t, int index, Mode& mode, State& z, ObserverRef& obs) {
    const State z_before = z;
    const Transition<Mode> tr = model_.transition(t, mode, z, index);
    EventInfo<Mode, N> info{t, z, z_before, mode, tr.next, index, tr.kind, tr.stop};
    if (tr.stop) {
      obs.on_event(info);
      return RunStatus::ModelStop;
    }
    mode = tr.next;
    model_.complete(mode, z);
    info.z = z;
    if (!obs.on_event(info)) return RunStatus::ObserverStop;
    armed_.fill(true);
    return std::nullopt;
  }

  struct Hit {
    double t;
    int index;
  };

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

  // At a restart (run start, after an event or a breakpoint): values and rates for the scan of
  // the step to come, of size about h.
  void start_rates(double t, const Mode& mode, const State& z, const State& k1, double h) {
    values_and_rates(t, mode, z, k1, h, g_start_, gd_start_, gd_err_start_);
    remainder_known_ = false;
    restarting_ = true;
  }

  // The cubic Hermite interpolant of the step's end values and rates (the first four terms of
  // DOP853's continuous extension), for steps whose full dense output nobody asked for.
  static void hermite_segment(double t, double h, const State& y, const State& y_new, const State& k1,
                              const State& k_end, DenseSegment<N>& seg) {
    seg.set_hermite(t, h, 4, y, y_new, k1, k_end);
  }

  template <class F>
  double attempt(F& f, double t, double h, const State& y, const State& k1, State& y_new, State& k_end) {
    return high_order_ ? dop853_.attempt(f, t, h, y, k1, y_new, k_end, stats_)
                       : dopri5_.attempt(f, t, h, y, k1, y_new, k_end, stats_);
  }

  template <class F>
  void dense(F& f, double t, double h, const State& y, const State& y_new, const State& k1, const State& k_end,
             DenseSegment<N>& seg) {
    if (high_order_)
      dop853_.dense(f, t, h, y, y_new, k1, k_end, seg, stats_);
    else
      dopri5_.dense(t, h, y, y_new, k1, k_end, seg);
  }

  // The fresh step to the event time te ends where the step's own solution is, which differs
  // from the straddling step's interpolant (where te was found) by up to the local error: the
  // event function is then not quite zero there. Newton corrections on the fresh step's dense
  // output (7th order with DOP853; a move of at most 1e-3 of the step, past te an extrapolation
  // of the same smooth piece) put the event state on the event surface to rounding, without
  // another step. Each kept only if it reduces |g|.
  template <class F>
  void polish_event(F&, double t, double t_next, int index, const Mode& mode, const State&, const State&, double& te,
                    State& ze, DenseSegment<N>& seg) {
    auto g_at = [&](double tt, State y) {
      Events ge;
      complete_and_events(model_, std::fmin(tt, *t_clamp_), mode, y, ge);
      return ge[std::size_t(index)];
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

  // A step that would cross a kink the model predicts stops at it instead: across a kink the
  // error estimate is large until the step is tiny (a cascade of rejections), and the step
  // finally accepted across it can be off by more than its estimate says. A kink predicted
  // within a tenth of the step (where the Winkler block's second-order prediction is good to
  // better than 1e-5 of the distance) is stepped onto, ending past it by 1e-6 of the distance;
  // a farther one is approached to 0.9 of it first. The steps after it grow from there under
  // the step-size control (resuming the size wanted before the cut: docs/performance.md).
  double cut_at_kink(double t, const Mode& mode, const State& z, const State& dz, double h) const {
    const double tau = kink_ahead_of(model_, t, mode, z, dz);
    if (!(tau < h)) return h;
    return tau < kKinkNear * h ? kKinkOvershoot * tau : kKinkApproach * tau;
  }

  // After a rejected step: shrink h, or report why integration cannot go on.
  std::optional<RunStatus> shrink_rejected_step(double err, double t, double& h) {
    ++stats_.rejected;
    if (restarting_) ++stats_.rejected_at_restart;
    just_rejected_ = true;
    if (!std::isfinite(err) && h < 1e-300) return RunStatus::NonFinite;
    const double expo = high_order_ ? Dop853<N>::kOrderExponent : Dopri5<N>::kOrderExponent;
    const double fac_min = high_order_ ? Dop853<N>::kFacMin : Dopri5<N>::kFacMin;
    h *= std::isfinite(err) ? std::fmax(fac_min, 0.9 * std::pow(err, -expo)) : 0.1;
    if (h <= 16.0 * std::numeric_limits<double>::epsilon() * std::fmax(1.0, std::fabs(t)))
      return RunStatus::StepUnderflow;
    return std::nullopt;
  }

  // Proportional-integral step-size control after an accepted step (Hairer & Wanner, IV.2);
  // with DOP853, right after a rejection the step may not grow (Hairer's safeguard against
  // oscillating between rejection and growth).
  double next_step_size(double err, double h, double& err_old) {
    const double e = std::fmax(err, 1e-10);
    double fac;
    if (high_order_) {
      fac = std::fmin(Dop853<N>::kFacMax, std::fmax(Dop853<N>::kFacMin, 0.9 * std::pow(e, -Dop853<N>::kAlpha)));
    } else {
      fac = std::fmin(Dopri5<N>::kFacMax, std::fmax(Dopri5<N>::kFacMin, 0.9 * std::pow(e, -Dopri5<N>::kAlpha) *
                                                                            std::pow(err_old, Dopri5<N>::kBeta)));
    }
    if (just_rejected_ && high_order_) fac = std::fmin(fac, 1.0);
    just_rejected_ = false;
    err_old = e;
    return std::fmin(h * fac, opt_.h_max);
  }

  double initial_step(const Mode& mode) const { return std::fmin(model_.step_hint(mode), std::fmin(opt_.h_max, 1e-2)); }

  // The earliest event in the step [t0, t1], if any. Each armed event function is bounded from
  // below by its envelope (values and rates at both ends, values at `event_samples` interior
  // points); where the envelope may reach zero the function is sampled once more at the
  // model's minimum there, and if that does not settle it, searched on the dense output (Brent's
  // minimum, then TOMS 748 to a few ulps).
  template <class EnsureDense>
  std::optional<Hit> scan_events(const DenseSegment<N>& seg, double t0, double t1, const Mode& mode,
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
        Events ge;
        g_all(tt, ge);
        return ge[i];
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
  static constexpr int kMaxEventsAtInstant = 4;         // chatter resolutions tried at one instant
  static constexpr int kMaxRefine = 2;                  // extra samples in a doubtful stretch before a search
  static constexpr int kSubdivision = 5;                // doubtful stretches are located to 1/32 of a step
  static constexpr double kRateStep = 0x1p-20;          // difference quotients over this fraction of a step
  static constexpr int kResample = 4;                   // interior samples at least every this many steps
  static constexpr double kLagSafety = 8.0;             // margin on a remainder measured on an earlier step
  static constexpr double kKinkNear = 0.1;              // a kink this close (in steps) is stepped onto
  static constexpr double kKinkOvershoot = 1.0 + 1e-6;  // ... ending this far past it
  static constexpr double kKinkApproach = 0.9;          // a farther one approached to this fraction
  // A dip after a restart shallower than this (or rtol) times the function is not resolved.
  static constexpr double kDipRounding = 64 * std::numeric_limits<double>::epsilon();
  const Model& model_;
  IntegratorOptions opt_;
  bool high_order_;
  bool just_rejected_ = false;
  bool restarting_ = true;  // no step accepted since the last restart
  Dopri5<N> dopri5_;
  Dop853<N> dop853_;
  StepperStats stats_;
  std::array<bool, NE> armed_{};
  // Event values, rates and bounds on the rates' errors at the start and at the end of the step.
  Events g_start_{}, gd_start_{}, gd_err_start_{};
  Events g_end_{}, gd_end_{}, gd_err_end_{};
  // The remainder coefficients last measured (scan_events), on a step of size remainder_h_.
  Events remainder_{};
  double remainder_h_ = 0.0;
  bool remainder_known_ = false;
  int steps_since_samples_ = 0;
  const double* t_clamp_ = nullptr;  // the run's input-side clamp (see run())
};

template <HybridModel Model>
RunStatus HybridIntegrator<Model>::run_observed(double& t, double t_end, Mode& mode, State& z, ObserverRef& obs) {
  model_.complete(mode, z);
  // Within a step that ends at a breakpoint the input is evaluated on the step's side of it.
  double t_clamp = std::numeric_limits<double>::infinity();
  auto f = [&](double tt, const State& y, State& dy) { model_.rhs(std::fmin(tt, t_clamp), mode, y, dy); };
  t_clamp_ = &t_clamp;
  State k1, k7, y_new;
  f(t, z, k1);
  ++stats_.rhs_evals;
  double h = initial_step(mode);
  start_rates(t, mode, z, k1, h);
  armed_.fill(true);
  double err_old = 1e-4;
  int zero_time_events = 0;
  // Zero-duration events at one instant, across chatter resolutions: a resolution that does not
  // resolve would otherwise loop there for ever.
  int events_at_instant = 0;
  DenseSegment<N> seg;
  double t_break = next_breakpoint_of(model_, t, mode);
  while (t < t_end) {
    if (stats_.accepted + stats_.rejected >= opt_.max_steps) return RunStatus::MaxSteps;
    const bool last = h >= t_end - t && t_end <= t_break;
    const bool to_break = !last && h >= t_break - t;
    const double h_wanted = h;
    if (last) h = t_end - t;
    if (to_break) h = t_break - t;
    t_clamp = to_break ? std::nextafter(t_break, -INFINITY) : std::numeric_limits<double>::infinity();
    const double err = attempt(f, t, h, z, k1, y_new, k7);
    if (!(err <= 1.0)) {
      if (const auto failure = shrink_rejected_step(err, t, h)) return *failure;
      continue;
    }
    ++stats_.accepted;
    restarting_ = false;
    if (high_order_ && dop853_.stiffness() > 6.1) ++stats_.stiff_steps;
    // The dense output costs DOP853 three more stages: computed only when the scan or an
    // observer evaluates inside the step (else seg holds the cubic Hermite interpolant of the
    // step ends, which observers may refine: DenseSegment::ensure_full()).
    bool dense_done = false;
    auto ensure_dense = [&] {
      if (!dense_done) dense(f, t, h, z, y_new, k1, k7, seg);
      dense_done = true;
    };
    if (!high_order_)
      ensure_dense();
    else
      hermite_segment(t, h, z, y_new, k1, k7, seg);
    const double t_next = last ? t_end : (to_break ? t_break : t + h);
    State y_end = y_new;
    model_.complete(mode, y_end);
    values_and_rates(std::fmin(t_next, t_clamp), mode, y_end, k7, -(t_next - t), g_end_, gd_end_, gd_err_end_);
    const auto hit = scan_events(seg, t, t_next, mode, ensure_dense);
    if (obs.needs_dense()) ensure_dense();
    // A step shortened to land on t_end or a breakpoint says little about the step size the
    // solution allows: keep the size asked for before the shortening.
    double h_new = next_step_size(err, h, err_old);
    if (to_break || last) h_new = std::fmax(h_new, std::fmin(h_wanted, opt_.h_max));
    if (!hit) {
      if (!observe_step(obs, seg, t, t_next, mode, y_end, dense_done ? nullptr : &ensure_dense))
        return RunStatus::ObserverStop;
      t = t_next;
      z = y_end;
      k1 = k7;
      keep_end_values();
      h = cut_at_kink(t, mode, z, k1, h_new);
      zero_time_events = 0;
      events_at_instant = 0;
      rearm_risen();
      if (to_break) {
        // The input may jump or kink here: let the model re-select its mode, restart.
        t_clamp = std::numeric_limits<double>::infinity();
        if (const auto end = restart_at_breakpoint(f, t, mode, z, k1, h, t_break, obs)) return *end;
      }
      continue;
    }
    // An event inside the step: keep the trajectory up to it, apply the transition, restart.
    double te = hit->t;
    State ze = z;
    if (te > t && !step_to_event(f, t, t_next, hit->index, mode, z, k1, te, ze, seg, obs))
      return RunStatus::ObserverStop;
    zero_time_events = (te == t) ? zero_time_events + 1 : 0;
    events_at_instant = (te == t) ? events_at_instant + 1 : 0;
    if (events_at_instant > kMaxEventsAtInstant * opt_.chatter_limit) return RunStatus::Chatter;
    model_.complete(mode, ze);
    t_clamp = std::numeric_limits<double>::infinity();
    t = te;
    z = ze;
    if (const auto end = apply_transition(t, hit->index, mode, z, obs)) return *end;
    if (zero_time_events >= opt_.chatter_limit) {
      if (const auto end = hold_chatter(t, mode, z, obs)) return *end;
      zero_time_events = 0;
    }
    h = restart_after_event(f, t, mode, z, k1, h_new, t_break);
  }
  return RunStatus::ReachedEnd;
}

}  // namespace blockdyn
