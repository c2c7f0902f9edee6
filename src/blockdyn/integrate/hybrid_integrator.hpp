// SPDX-License-Identifier: Apache-2.0
#pragma once
// Generic integrator for piecewise-smooth (hybrid) systems: adaptive Dormand-Prince, 5(4) or
// 8(5,3) chosen per run (IntegratorOptions::method), event location on the dense output by bracketing + TOMS 748,
// restart at each event. The event scan of a step (EventLocator::scan, event_locator.hpp) bounds each event function
// from below by an envelope built from its values and rates at the step ends and its values at a few interior points
// (event_envelope.hpp); the dense output is searched only where the envelope may reach zero.
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

#include "blockdyn/integrate/dop853.hpp"
#include "blockdyn/integrate/dopri5.hpp"
#include "blockdyn/integrate/event_locator.hpp"
#include "blockdyn/integrate/hybrid_model.hpp"
#include "blockdyn/integrate/integrator_options.hpp"
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
      : model_(model), opt_(opt), events_(model_, opt_), high_order_(resolved_method(opt) == Method::Dop853) {
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
      events_.polish(t, t_next, index, mode, te, ze, seg);
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
    events_.arm_positive(t, mode, z);
    return std::nullopt;
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
    events_.arm_all();
    return std::nullopt;
  }

  // At a restart (run start, after an event or a breakpoint): values and rates for the scan of
  // the step to come, of size about h.
  void start_rates(double t, const Mode& mode, const State& z, const State& k1, double h) {
    events_.start(t, mode, z, k1, h);
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

  static constexpr int kMaxEventsAtInstant = 4;         // chatter resolutions tried at one instant
  static constexpr double kKinkNear = 0.1;              // a kink this close (in steps) is stepped onto
  static constexpr double kKinkOvershoot = 1.0 + 1e-6;  // ... ending this far past it
  static constexpr double kKinkApproach = 0.9;          // a farther one approached to this fraction
  const Model& model_;
  IntegratorOptions opt_;
  EventLocator<Model> events_;
  bool high_order_;
  bool just_rejected_ = false;
  bool restarting_ = true;  // no step accepted since the last restart
  Dopri5<N> dopri5_;
  Dop853<N> dop853_;
  StepperStats stats_;
};

template <HybridModel Model>
RunStatus HybridIntegrator<Model>::run_observed(double& t, double t_end, Mode& mode, State& z, ObserverRef& obs) {
  model_.complete(mode, z);
  // Within a step that ends at a breakpoint the input is evaluated on the step's side of it.
  double t_clamp = std::numeric_limits<double>::infinity();
  auto f = [&](double tt, const State& y, State& dy) { model_.rhs(std::fmin(tt, t_clamp), mode, y, dy); };
  events_.set_clamp(&t_clamp);
  State k1, k7, y_new;
  f(t, z, k1);
  ++stats_.rhs_evals;
  double h = initial_step(mode);
  start_rates(t, mode, z, k1, h);
  events_.arm_all();
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
    events_.step_end(std::fmin(t_next, t_clamp), mode, y_end, k7, t_next - t);
    const auto hit = events_.scan(seg, t, t_next, mode, ensure_dense);
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
      events_.keep_end_values();
      h = cut_at_kink(t, mode, z, k1, h_new);
      zero_time_events = 0;
      events_at_instant = 0;
      events_.rearm_risen();
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
