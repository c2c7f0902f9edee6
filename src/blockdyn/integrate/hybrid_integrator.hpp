#pragma once
// Generic integrator for piecewise-smooth (hybrid) systems: adaptive Dormand-Prince 5(4),
// event location on the dense output by bracketing + TOMS 748, restart at each event.
//
// A model supplies (see HybridModel below): the state size, a Mode type, right-hand sides per
// mode, event functions that must stay >= 0 while a mode is valid, and the transition map
// applied when one of them becomes negative. The integrator knows nothing about blocks.
#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <optional>

#include "blockdyn/integrate/dopri5.hpp"
#include "blockdyn/integrate/root_bracket.hpp"

namespace blockdyn {

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
  { m.transition(t, mode, z, i) } -> std::same_as<Transition<typename M::Mode>>;
  { m.resolve_chatter(t, mode, z) } -> std::same_as<std::optional<Transition<typename M::Mode>>>;
  { m.step_hint(mode) } -> std::convertible_to<double>;
  { m.abs_tol_scale() } -> std::convertible_to<Vec<M::kDim>>;
};

enum class RunStatus { ReachedEnd, ModelStop, ObserverStop, MaxSteps, StepUnderflow, Chatter, NonFinite };

inline const char* to_string(RunStatus s) {
  switch (s) {
    case RunStatus::ReachedEnd: return "t_end";
    case RunStatus::ModelStop: return "model_stop";
    case RunStatus::ObserverStop: return "observer_stop";
    case RunStatus::MaxSteps: return "max_steps";
    case RunStatus::StepUnderflow: return "step_underflow";
    case RunStatus::Chatter: return "chatter";
    case RunStatus::NonFinite: return "non_finite";
  }
  return "?";
}

struct IntegratorOptions {
  double rtol = 1e-10;
  double atol = 1e-12;
  double h_max = std::numeric_limits<double>::infinity();
  long max_steps = 200'000'000;
  int event_samples = 4;  // event functions are checked at this many points per step
  int chatter_limit = 16;  // consecutive zero-duration events before resolve_chatter()
};

template <class Mode, std::size_t N>
struct EventInfo {
  double t;
  Vec<N> z;  // completed state at the event
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

  HybridIntegrator(const Model& model, IntegratorOptions opt) : model_(model), opt_(opt) {
    const State sc = model_.abs_tol_scale();
    for (std::size_t i = 0; i < N; ++i) {
      stepper_.atol[i] = opt_.atol * sc[i];
      stepper_.rtol[i] = opt_.rtol;
    }
  }

  const StepperStats& stats() const { return stats_; }

  template <class Observer>
  RunStatus run(double& t, double t_end, Mode& mode, State& z, Observer& obs) {
    model_.complete(mode, z);
    auto f = [&](double tt, const State& y, State& dy) { model_.rhs(tt, mode, y, dy); };
    State k1, k7, y_new;
    f(t, z, k1);
    ++stats_.rhs_evals;
    Events g_start;
    model_.events(t, mode, z, g_start);
    armed_.fill(true);
    double h = initial_step(mode);
    double err_old = 1e-4;
    int zero_time_events = 0;
    DenseSegment<N> seg;
    while (t < t_end) {
      if (stats_.accepted + stats_.rejected >= opt_.max_steps) return RunStatus::MaxSteps;
      const bool last = h >= t_end - t;
      if (last) h = t_end - t;
      const double err = stepper_.attempt(f, t, h, z, k1, y_new, k7, stats_);
      if (!(err <= 1.0)) {
        ++stats_.rejected;
        if (!std::isfinite(err) && h < 1e-300) return RunStatus::NonFinite;
        h *= std::isfinite(err) ? std::fmax(0.2, 0.9 * std::pow(err, -0.2)) : 0.1;
        if (h <= 16.0 * std::numeric_limits<double>::epsilon() * std::fmax(1.0, std::fabs(t)))
          return RunStatus::StepUnderflow;
        continue;
      }
      ++stats_.accepted;
      stepper_.dense(t, h, z, y_new, k1, k7, seg);
      const double t_next = last ? t_end : t + h;
      const auto hit = scan_events(seg, t, t_next, y_new, mode, g_start);
      // Proportional-integral step-size control (Hairer & Wanner, IV.2).
      const double e = std::fmax(err, 1e-10);
      double fac = 0.9 * std::pow(e, -0.17) * std::pow(err_old, 0.04);
      fac = std::fmin(5.0, std::fmax(0.2, fac));
      err_old = e;
      const double h_new = std::fmin(h * fac, opt_.h_max);
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
        continue;
      }
      // An event inside the step: keep the trajectory up to it, apply the transition, restart.
      const double te = hit->t;
      if (te > t && !obs.on_step(seg, t, te, mode)) return RunStatus::ObserverStop;
      zero_time_events = (te == t) ? zero_time_events + 1 : 0;
      State ze;
      seg.eval(te, ze);
      model_.complete(mode, ze);
      const Transition<Mode> tr = model_.transition(te, mode, ze, hit->index);
      EventInfo<Mode, N> info{te, ze, mode, tr.next, hit->index, tr.kind, tr.stop};
      t = te;
      z = ze;
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
      if (zero_time_events >= opt_.chatter_limit) {
        const auto held = model_.resolve_chatter(t, mode, z);
        if (!held) return RunStatus::Chatter;
        EventInfo<Mode, N> hold{t, z, mode, held->next, -1, held->kind, false};
        mode = held->next;
        model_.complete(mode, z);
        hold.z = z;
        if (!obs.on_event(hold)) return RunStatus::ObserverStop;
        model_.events(t, mode, z, g_start);
        for (std::size_t i = 0; i < NE; ++i) armed_[i] = g_start[i] > 0.0;
        zero_time_events = 0;
      }
      f(t, z, k1);
      ++stats_.rhs_evals;
      h = std::fmin(h_new, model_.step_hint(mode));
    }
    return RunStatus::ReachedEnd;
  }

 private:
  struct Hit {
    double t;
    int index;
  };

  double initial_step(const Mode& mode) const {
    return std::fmin(model_.step_hint(mode), std::fmin(opt_.h_max, 1e-2));
  }

  // Checks the event functions at `event_samples` points of the step; returns the earliest root.
  std::optional<Hit> scan_events(const DenseSegment<N>& seg, double t0, double t1,
                                 const State& y1, const Mode& mode, const Events& g0) {
    Events g_prev = g0, g;
    double t_prev = t0;
    State y;
    const int S = opt_.event_samples;
    for (int j = 1; j <= S; ++j) {
      const double tj = (j == S) ? t1 : t0 + (t1 - t0) * double(j) / S;
      if (j == S) {
        y = y1;
      } else {
        seg.eval(tj, y);
      }
      model_.complete(mode, y);
      model_.events(tj, mode, y, g);
      std::optional<Hit> best;
      for (std::size_t i = 0; i < NE; ++i) {
        if (!armed_[i] || !(g[i] < 0.0)) continue;
        auto gi = [&](double tt) {
          State yy;
          seg.eval(tt, yy);
          model_.complete(mode, yy);
          Events ge;
          model_.events(tt, mode, yy, ge);
          return ge[i];
        };
        const double tr = locate_root(gi, t_prev, tj, g_prev[i], g[i]);
        if (!best || tr < best->t) best = Hit{tr, int(i)};
      }
      if (best) return best;
      g_prev = g;
      t_prev = tj;
    }
    g_last_ = g;
    return std::nullopt;
  }

  const Model& model_;
  IntegratorOptions opt_;
  Dopri5<N> stepper_;
  StepperStats stats_;
  std::array<bool, NE> armed_{};
  Events g_last_{};
};

}  // namespace blockdyn
