// SPDX-License-Identifier: Apache-2.0
#pragma once
// Generic integrator for piecewise-smooth (hybrid) systems: adaptive Dormand-Prince, 5(4) or
// 8(5,3) chosen per run (IntegratorOptions::method), event location on the dense output by bracketing + TOMS 748,
// restart at each event.
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
#include "blockdyn/integrate/root_bracket.hpp"

namespace blockdyn {

// Event index passed to transition() when the integration reaches a breakpoint of the input.
inline constexpr int kBreakpoint = -2;

template <class Mode>
struct Transition {
  Mode next{};
  bool stop = false;  // the run ends at this event (overturn, state outside the model, ...)
  int kind = 0;       // model-defined event kind, reported to observers
};

template <class M>
concept HybridModel = requires(const M& m, typename M::Mode mode, Vec<M::kDim> z, Vec<M::kDim>& dz,
                               std::array<double, M::kNumEvents>& g, double t, int i) {
  { M::kDim } -> std::convertible_to<std::size_t>;
  { M::kNumEvents } -> std::convertible_to<std::size_t>;
  m.rhs(t, mode, z, dz);
  m.events(t, mode, z, g);
  m.complete(mode, z);
  { m.transition(t, mode, dz, i) } -> std::same_as<Transition<typename M::Mode>>;  // may change z
  { m.resolve_chatter(t, mode, z) } -> std::same_as<std::optional<Transition<typename M::Mode>>>;
  { m.step_hint(mode) } -> std::convertible_to<double>;
  { m.abs_tol_scale() } -> std::convertible_to<Vec<M::kDim>>;
};

enum class RunStatus { ReachedEnd, ModelStop, ObserverStop, MaxSteps, StepUnderflow, Chatter, NonFinite };

inline const char* to_string(RunStatus s) {
  switch (s) {
    case RunStatus::ReachedEnd:
      return "t_end";
    case RunStatus::ModelStop:
      return "model_stop";
    case RunStatus::ObserverStop:
      return "observer_stop";
    case RunStatus::MaxSteps:
      return "max_steps";
    case RunStatus::StepUnderflow:
      return "step_underflow";
    case RunStatus::Chatter:
      return "chatter";
    case RunStatus::NonFinite:
      return "non_finite";
  }
  return "?";
}

// The Runge-Kutta pair. Auto: DOP853 at tolerances where its higher order pays (rtol below
// kDop853BelowRtol), Dopri5 above.
enum class Method { Auto, Dopri5, Dop853 };
inline constexpr double kDop853BelowRtol = 1e-6;

inline const char* to_string(Method m) {
  switch (m) {
    case Method::Auto:
      return "auto";
    case Method::Dopri5:
      return "dopri5";
    case Method::Dop853:
      return "dop853";
  }
  return "?";
}

inline std::optional<Method> method_from_string(const std::string& s) {
  for (Method m : {Method::Auto, Method::Dopri5, Method::Dop853})
    if (s == to_string(m)) return m;
  return std::nullopt;
}

struct IntegratorOptions {
  double rtol = 1e-10;
  double atol = 1e-12;
  double h_max = std::numeric_limits<double>::infinity();
  long max_steps = 200'000'000;
  int event_samples = 4;   // event functions are checked at this many points per step
  int chatter_limit = 16;  // consecutive zero-duration events before resolve_chatter()
  Method method = Method::Auto;
};

// The pair a run with these options uses.
inline Method resolved_method(const IntegratorOptions& o) {
  if (o.method != Method::Auto) return o.method;
  return o.rtol < kDop853BelowRtol ? Method::Dop853 : Method::Dopri5;
}

// The model's first input breakpoint after t that matters in mode `mode`:
// `double next_breakpoint(double t, const Mode&) const` or `double next_breakpoint(double t) const`
// (optional; without either the input is smooth and there is none).
template <class M>
double next_breakpoint_of(const M& m, double t, const typename M::Mode& mode) {
  if constexpr (requires {
                  { m.next_breakpoint(t, mode) } -> std::convertible_to<double>;
                })
    return m.next_breakpoint(t, mode);
  else if constexpr (requires {
                       { m.next_breakpoint(t) } -> std::convertible_to<double>;
                     })
    return m.next_breakpoint(t);
  return std::numeric_limits<double>::infinity();
}

// Whether a model's transitions may change the state (impacts). Models declare
// `static constexpr bool kStateJumps = true;` (absent: false).
template <class M>
constexpr bool has_state_jumps() {
  if constexpr (requires { M::kStateJumps; }) return M::kStateJumps;
  return false;
}

template <class Mode, std::size_t N>
struct EventInfo {
  double t;
  Vec<N> z;         // completed state right after the event (after any jump)
  Vec<N> z_before;  // completed state at the event, before the transition
  Mode from, to;
  int index;  // which event function
  int kind;   // model-defined
  bool stop;
};

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

  HybridIntegrator(const Model& model, IntegratorOptions opt)
      : model_(model), opt_(opt), high_order_(resolved_method(opt) == Method::Dop853) {
    const State sc = model_.abs_tol_scale();
    for (std::size_t i = 0; i < N; ++i) {
      dopri5_.atol[i] = dop853_.atol[i] = opt_.atol * sc[i];
      dopri5_.rtol[i] = dop853_.rtol[i] = opt_.rtol;
    }
  }

  const StepperStats& stats() const { return stats_; }

  template <class Observer>
  RunStatus run(double& t, double t_end, Mode& mode, State& z, Observer& obs) {
    model_.complete(mode, z);
    // Within a step that ends at a breakpoint the input is evaluated on the step's side of it.
    double t_clamp = std::numeric_limits<double>::infinity();
    auto f = [&](double tt, const State& y, State& dy) { model_.rhs(std::fmin(tt, t_clamp), mode, y, dy); };
    t_clamp_ = &t_clamp;
    State k1, k7, y_new;
    f(t, z, k1);
    ++stats_.rhs_evals;
    Events g_start;
    model_.events(t, mode, z, g_start);
    armed_.fill(true);
    reset_falling(g_start, -1);
    double h = initial_step(mode);
    double err_old = 1e-4;
    int zero_time_events = 0;
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
      if (high_order_ && dop853_.stiffness() > 6.1) ++stats_.stiff_steps;
      dense(f, t, h, z, y_new, k1, k7, seg);
      const double t_next = last ? t_end : (to_break ? t_break : t + h);
      const auto hit = scan_events(seg, t, t_next, y_new, mode, g_start);
      // A step shortened to land on t_end or a breakpoint says little about the step size the
      // solution allows: keep the size asked for before the shortening.
      double h_new = next_step_size(err, h, err_old);
      if (to_break || last) h_new = std::fmax(h_new, std::fmin(h_wanted, opt_.h_max));
      if (!hit) {
        if (!obs.on_step(seg, t, t_next, mode)) return RunStatus::ObserverStop;
        t = t_next;
        z = y_new;
        model_.complete(mode, z);
        k1 = k7;
        g_start = g_last_;
        h = h_new;
        zero_time_events = 0;
        for (std::size_t i = 0; i < NE; ++i)
          if (!armed_[i] && g_start[i] > 0.0) armed_[i] = true;
        if (to_break) {
          // The input may jump or kink here: let the model re-select its mode, restart.
          t_clamp = std::numeric_limits<double>::infinity();
          if (const auto end = apply_transition(t, kBreakpoint, mode, z, g_start, obs)) return *end;
          f(t, z, k1);
          ++stats_.rhs_evals;
          t_break = next_breakpoint_of(model_, t, mode);
          h = std::fmin(h, model_.step_hint(mode));
        }
        continue;
      }
      // An event inside the step: keep the trajectory up to it, apply the transition, restart.
      double te = hit->t;
      State ze = z;
      if (te > t) {
        // The accepted step straddles the event, where the right-hand side is usually not
        // smooth (forces switch on or off), so its interpolant is least accurate exactly there.
        // One fresh step from t to te stays on the smooth side and gives the event state the
        // accuracy of an ordinary step end.
        State k7e;
        const double err_e = attempt(f, t, te - t, z, k1, ze, k7e);
        if (std::isfinite(err_e)) {
          dense(f, t, te - t, z, ze, k1, k7e, seg);
          polish_event(f, t, t_next, hit->index, mode, z, k1, te, ze, seg);
        } else {
          seg.eval(te, ze);
        }
        if (!obs.on_step(seg, t, te, mode)) return RunStatus::ObserverStop;
      }
      zero_time_events = (te == t) ? zero_time_events + 1 : 0;
      model_.complete(mode, ze);
      t_clamp = std::numeric_limits<double>::infinity();
      t = te;
      z = ze;
      if (const auto end = apply_transition(t, hit->index, mode, z, g_start, obs)) return *end;
      if (zero_time_events >= opt_.chatter_limit) {
        const auto held = model_.resolve_chatter(t, mode, z);
        if (!held) return RunStatus::Chatter;
        EventInfo<Mode, N> hold{t, z, z, mode, held->next, -1, held->kind, false};
        mode = held->next;
        model_.complete(mode, z);
        hold.z = z;
        if (!obs.on_event(hold)) return RunStatus::ObserverStop;
        model_.events(t, mode, z, g_start);
        for (std::size_t i = 0; i < NE; ++i) armed_[i] = g_start[i] > 0.0;
        reset_falling(g_start, -1);
        zero_time_events = 0;
      }
      f(t, z, k1);
      ++stats_.rhs_evals;
      t_break = next_breakpoint_of(model_, t, mode);
      h = std::fmin(h_new, model_.step_hint(mode));
    }
    return RunStatus::ReachedEnd;
  }

 private:
  // The transition of event `index` (or kBreakpoint) at t: the model picks the next mode and may
  // change the state; observers see it with the state before and after; the event functions
  // restart. Returns the run's end status when the model or an observer stops it.
  template <class Observer>
  std::optional<RunStatus> apply_transition(double t, int index, Mode& mode, State& z, Events& g_start, Observer& obs) {
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
    model_.events(t, mode, z, g_start);
    armed_.fill(true);
    reset_falling(g_start, index);
    return std::nullopt;
  }

  struct Hit {
    double t;
    int index;
  };

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
  // event function is then not quite zero there. One Newton correction on the fresh step's dense
  // output, and a fresh step to the corrected time, put the event state on the event surface to
  // rounding. Kept only if it reduces |g| and stays a small move inside the step.
  template <class F>
  void polish_event(F& f, double t, double t_next, int index, const Mode& mode, const State& z, const State& k1,
                    double& te, State& ze, DenseSegment<N>& seg) {
    auto g_at = [&](double tt, State y) {
      Events ge;
      model_.complete(mode, y);
      model_.events(std::fmin(tt, *t_clamp_), mode, y, ge);
      return ge[std::size_t(index)];
    };
    const double g_e = g_at(te, ze);
    if (g_e == 0.0 || !std::isfinite(g_e)) return;
    const double d = 1e-3 * (te - t);
    State zd;
    seg.eval(te - d, zd);
    const double slope = (g_e - g_at(te - d, zd)) / d;
    if (!(std::fabs(slope) > 0.0) || !std::isfinite(slope)) return;
    const double tn = te - g_e / slope;
    if (!(tn > t) || !(tn <= t_next) || tn == te || std::fabs(tn - te) > 1e-3 * (te - t)) return;
    State zn, kn;
    if (!std::isfinite(attempt(f, t, tn - t, z, k1, zn, kn))) return;
    if (!(std::fabs(g_at(tn, zn)) < std::fabs(g_e))) return;
    te = tn;
    ze = zn;
    dense(f, t, tn - t, z, zn, k1, kn, seg);
  }

  // After a rejected step: shrink h, or report why integration cannot go on.
  std::optional<RunStatus> shrink_rejected_step(double err, double t, double& h) {
    ++stats_.rejected;
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

  // Checks the event functions at `event_samples` points of the step; returns the earliest root.
  // Besides sign changes between samples it looks for excursions below zero that start and end
  // between two samples (a brief flight, a short slide): wherever the samples of a function
  // have a local minimum, the minimum is located on the dense output and checked.
  std::optional<Hit> scan_events(const DenseSegment<N>& seg, double t0, double t1, const State& y1, const Mode& mode,
                                 const Events& g0) {
    const int S = std::clamp(opt_.event_samples, 1, kMaxSamples);
    std::array<double, kMaxSamples + 1> ts;
    std::array<Events, kMaxSamples + 1> gs;
    ts[0] = t0;
    gs[0] = g0;
    State y;
    for (int j = 1; j <= S; ++j) {
      ts[j] = (j == S) ? t1 : t0 + (t1 - t0) * double(j) / S;
      if (j == S) {
        y = y1;
      } else {
        seg.eval(ts[j], y);
      }
      model_.complete(mode, y);
      model_.events(std::fmin(ts[j], *t_clamp_), mode, y, gs[j]);
    }
    auto g_all = [&](double tt, Events& ge) {
      State yy;
      seg.eval(tt, yy);
      model_.complete(mode, yy);
      model_.events(std::fmin(tt, *t_clamp_), mode, yy, ge);
    };
    // After a restart the slope of each event function is unknown: one value just after t0
    // tells which ones start by falling (only those can dip below zero and come back inside the
    // first interval).
    if (slope_unknown_) {
      Events g_after_start;
      g_all(t0 + 1e-3 * (ts[1] - t0), g_after_start);
      for (std::size_t i = 0; i < NE; ++i) falling_[i] = falling_[i] && g_after_start[i] < g0[i];
      slope_unknown_ = false;
    }
    // Falling into the step end: one more value just before t1 tells whether a minimum lies
    // inside the last interval (the next step could not see it).
    bool any_falling_end = false;
    for (std::size_t i = 0; i < NE; ++i) any_falling_end |= armed_[i] && gs[S][i] > 0.0 && gs[S][i] < gs[S - 1][i];
    Events g_before_end{};
    if (any_falling_end) g_all(t1 - 1e-3 * (t1 - ts[S - 1]), g_before_end);

    std::optional<Hit> best;
    std::array<bool, NE> falling_next{};
    for (std::size_t i = 0; i < NE; ++i) {
      if (!armed_[i]) continue;
      auto gi = [&](double tt) {
        Events ge;
        g_all(tt, ge);
        return ge[i];
      };
      std::optional<double> root;
      bool falling = falling_[i];
      for (int j = 1; j <= S && !root; ++j) {
        if (best && ts[j - 1] >= best->t) break;
        const double ga = gs[j - 1][i], gb = gs[j][i];
        if (gb < 0.0) {
          double lo = ts[j - 1], glo = ga;
          if (glo <= 0.0) {
            // Zero at a restart point (the event that just fired, e.g. theta = 0 after an
            // impact): it fires there unless it rises first. Where it rises it is positive on
            // (t0, root); halving towards t0 finds a positive value however brief the rise (a
            // swing of 1e-7 inside a step of 1e-3), and the root is bracketed from there.
            for (int k = 1; k <= 60; ++k) {
              const double tt = ts[j - 1] + std::ldexp(ts[j] - ts[j - 1], -k);
              if (!(tt > ts[j - 1])) break;
              const double gt = gi(tt);
              if (gt > 0.0) {
                lo = tt;
                glo = gt;
                break;
              }
            }
          }
          root = locate_root(gi, lo, ts[j], glo, gb);
        } else if (falling && ga > 0.0 && gb > ga) {
          const int a = (j >= 2) ? j - 2 : 0;
          // A smooth minimum lies at most about the variation seen around it below the lowest
          // sample: a dip can only reach zero if that sample is within a multiple of it. (At rest
          // the samples wobble at rounding level far from zero: no search.)
          const double variation = std::fmax(gb - ga, gs[a][i] - ga);
          if (ga < kDipReach * variation) root = dip_root(gi, ts[a], ts[j], gs[a][i]);
        }
        falling = gb < ga;
      }
      if (!root && any_falling_end && gs[S][i] > 0.0 && gs[S][i] < gs[S - 1][i]) {
        if (g_before_end[i] < gs[S][i]) {  // rising again at the end: minimum inside
          if (g_before_end[i] < kDipReach * (gs[S - 1][i] - g_before_end[i]))
            root = dip_root(gi, ts[S - 1], t1, gs[S - 1][i]);
        } else {
          falling_next[i] = true;
        }
      }
      if (root && (!best || *root < best->t)) best = Hit{*root, int(i)};
    }
    if (!best) {
      g_last_ = gs[S];
      falling_ = falling_next;
    }
    return best;
  }

  // Minimum of g on [a, b] (Brent): (location, value).
  template <class G>
  static std::pair<double, double> minimum(double a, double b, G&& g) {
    std::uintmax_t iters = 60;
    return boost::math::tools::brent_find_minima(g, a, b, 26, iters);
  }

  // Root of g before its minimum on [a, b] if that minimum is below zero (g(a) = ga > 0).
  template <class G>
  static std::optional<double> dip_root(G&& g, double a, double b, double ga) {
    const auto mn = minimum(a, b, g);
    if (!(mn.second < 0.0)) return std::nullopt;
    return locate_root(g, a, mn.first, ga, mn.second);
  }

  // After a restart the slope of each event function is unknown: every one that is clearly
  // positive may be falling, except the one that just fired (it starts at zero); the first scan
  // probes them (slope_unknown_).
  void reset_falling(const Events& g_start, int fired) {
    for (std::size_t i = 0; i < NE; ++i) falling_[i] = int(i) != fired && g_start[i] > 0.0;
    slope_unknown_ = true;
  }

  static constexpr int kMaxSamples = 64;
  static constexpr double kDipReach = 100.0;
  const Model& model_;
  IntegratorOptions opt_;
  bool high_order_;
  bool just_rejected_ = false;
  Dopri5<N> dopri5_;
  Dop853<N> dop853_;
  StepperStats stats_;
  std::array<bool, NE> armed_{};
  std::array<bool, NE> falling_{};  // event function still decreasing at the last step end
  bool slope_unknown_ = false;      // first step after a restart: probe the slopes
  Events g_last_{};
  const double* t_clamp_ = nullptr;  // the run's input-side clamp (see run())
};

}  // namespace blockdyn
