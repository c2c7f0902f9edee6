// SPDX-License-Identifier: Apache-2.0
#pragma once
// Largest Lyapunov exponent of a hybrid model whose state may jump at events (impacts) and whose
// vector field switches at events: the variational equation is integrated with the orbit
// (VariationalModel: saltation matrices at every event) and the tangent is renormalised every
// `interval` (Benettin et al. 1980): lambda = sum log |v(t_i)| / (t_n - t_0), |v(t_{i-1})| = 1.
// Unlike the two-trajectory estimator (lyapunov.hpp) nothing is compared across two orbits, so
// the copies' impact times never have to correspond; the exponent is that of the forced system
// at a fixed time (the stroboscopic map's Floquet multipliers for a periodic orbit).
//
// The run: from (t_start, mode, z) the orbit alone up to t_measure (a transient), then, once
// the mode admits perturbations (TangentTraits::moving: a block at rest has none), the tangent
// is started in a fixed direction and carried to t_end. Outcomes:
//   completed    t_end reached;
//   superstable  the tangent was annihilated (the block came to rest after an accumulation of
//                impacts: every nearby orbit merges with it in finite time, lambda = -infinity);
//   stopped      the model stopped the run (overturn, outside the model) after the tangent
//                started: the exponent is that of the transient up to then;
//   never_moved  the orbit never left a mode without tangent space (at rest to t_end);
//   failed       the integration or the tangent failed (non-finite).
#include <cmath>
#include <string>
#include <vector>

#include "blockdyn/analysis/dynamics/lyapunov.hpp"
#include "blockdyn/analysis/dynamics/variational_model.hpp"
#include "blockdyn/simulation/simulation.hpp"

namespace blockdyn {

struct TangentLyapunovOptions {
  double t_start = 0.0;
  double t_measure = 0.0;  // the tangent starts here (or at the first motion after it)
  double t_end = 100.0;
  double interval = 1.0;  // renormalisation interval
  IntegratorOptions integrator;
};

enum class TangentStatus { Completed, Superstable, Stopped, NeverMoved, Failed };

inline const char* to_string(TangentStatus s) {
  switch (s) {
    case TangentStatus::Completed:
      return "completed";
    case TangentStatus::Superstable:
      return "superstable";
    case TangentStatus::Stopped:
      return "stopped";
    case TangentStatus::NeverMoved:
      return "never_moved";
    case TangentStatus::Failed:
      return "failed";
  }
  return "?";
}

struct TangentLyapunovResult {
  TangentStatus status = TangentStatus::Completed;
  double exponent = NAN;   // -infinity when superstable
  double t_tangent = NAN;  // when the tangent started
  double t_final = 0;
  double sum_log = 0;
  long renormalisations = 0;
  long events = 0;  // events of the orbit after the tangent started
  RunStatus run_status = RunStatus::ReachedEnd;
  int stop_kind = 0;  // model-defined kind of the stopping event (stopped)
  std::string note;
  VariationalStats stats;
  std::vector<LyapunovSample> history;
};

// Exponent over the part of the run after t_from (as tail_exponent in lyapunov.hpp).
inline double tail_exponent(const TangentLyapunovResult& r, double t_from) {
  LyapunovResult l;
  l.history = r.history;
  return tail_exponent(l, t_from);
}

// Ignores everything (a run without a watcher).
struct NoWatch {
  template <class E>
  void on_event(const E&) {}
};

namespace detail {

// The orbit's observer: passes events to the watch, counts them, remembers a stopping event's
// kind and, when asked (until_moving), stops at the first mode that moves.
template <class VM, class Traits, class Watch>
class TangentObserver final : public Observer<VM> {
 public:
  BLOCKDYN_OBSERVER_TYPES(VM);
  TangentObserver(Watch& watch, bool until_first_motion) : w(watch), until_moving(until_first_motion) {}
  Watch& w;
  bool until_moving;
  bool moved = false;
  int stop_kind = 0;
  long events = 0;
  bool on_event(const VM&, const Event& e) override {
    w.on_event(e);
    ++events;
    if (e.stop) {
      stop_kind = e.kind;
      return true;
    }
    if (until_moving && Traits::moving(e.to)) {
      moved = true;
      return false;
    }
    return true;
  }
};

template <class Obs>
void mark_stopped(TangentLyapunovResult& res, RunStatus st, const Obs& ob, double t) {
  res.run_status = st;
  res.t_final = t;
  res.stop_kind = ob.stop_kind;
  res.status = st == RunStatus::ModelStop ? TangentStatus::Stopped : TangentStatus::Failed;
  res.note = std::string("the orbit stopped: ") + to_string(st);
}

// The transient: the orbit alone (tangent zero: the integrator carries it at no cost to
// accuracy) to t_measure, then on to the first motion. False when the run ends there (res says
// why).
template <class VM, class Traits, class Watch, class M>
bool tangent_transient(const M& m, typename M::Mode& md, typename VM::State& Z, double& t,
                       const TangentLyapunovOptions& o, Watch& watch, TangentLyapunovResult& res) {
  using Obs = TangentObserver<VM, Traits, Watch>;
  const VM transient(m);
  Simulation<VM> sim(transient, o.integrator, t, md, Z);
  auto leave = [&](RunStatus st) {
    t = sim.t();
    md = sim.mode();
    Z = sim.state();
    return st;
  };
  Obs ob(watch, false);
  if (o.t_measure > t) {
    const RunStatus st = leave(sim.advance(o.t_measure, ob));
    if (st != RunStatus::ReachedEnd) {
      mark_stopped(res, st, ob, t);
      res.exponent = NAN;
      return false;
    }
  }
  if (!Traits::moving(md)) {
    Obs mv(watch, true);
    const RunStatus st = leave(sim.advance(o.t_end, mv));
    if (st == RunStatus::ReachedEnd) {
      res.status = TangentStatus::NeverMoved;
      res.t_final = t;
      res.note = "the orbit never left rest after t_measure";
      return false;
    }
    if (st != RunStatus::ObserverStop) {
      mark_stopped(res, st, mv, t);
      return false;
    }
  }
  return true;
}

// The start direction: every metric component one scale unit, projected by complete() and
// normalised. False when the mode admits no perturbation in it.
template <class VM>
bool start_tangent(const VM& vm, const typename VM::Mode& md, typename VM::State& Z,
                   const std::array<bool, VM::N>& metric) {
  typename VM::Base v{};
  for (std::size_t i = 0; i < VM::N; ++i) v[i] = metric[i] ? vm.scale()[i] : 0.0;
  VM::set_tangent(Z, 0, v);
  vm.complete(md, Z);
  const double n = vm.norm(VM::tangent(Z, 0));
  if (!(n > 0.0) || !std::isfinite(n)) return false;
  for (std::size_t i = 0; i < VM::N; ++i) v[i] = VM::tangent(Z, 0)[i] / n;
  VM::set_tangent(Z, 0, v);
  return true;
}

}  // namespace detail

// Watch: receives every EventInfo of the orbit (of the variational model: e.z holds the tangents
// after the base state) from t_start on.
template <HybridModel M, class Traits = TangentTraits<M>, class Watch = NoWatch>
TangentLyapunovResult tangent_lyapunov(const M& m, typename M::Mode md, Vec<M::kDim> z, const TangentLyapunovOptions& o,
                                       Watch& watch) {
  using VM = VariationalModel<M, 1, Traits>;
  if (!(o.t_end > o.t_start) || !(o.t_measure >= o.t_start) || !(o.interval > 0) ||
      (o.t_end - o.t_start) / o.interval > 1e7)
    throw std::invalid_argument(
        "tangent lyapunov: need t_start <= t_measure, t_start < t_end, 0 < interval, "
        "at most 1e7 intervals");
  const VM vm(m);
  TangentLyapunovResult res;
  typename VM::State Z{};
  VM::set_base(Z, z);
  double t = o.t_start;
  if (!detail::tangent_transient<VM, Traits>(m, md, Z, t, o, watch, res)) return res;
  const auto metric = Traits::metric(m);
  if (!detail::start_tangent(vm, md, Z, metric)) {
    res.status = TangentStatus::Failed;
    res.note = "the mode admits no perturbation in the start direction";
    res.t_final = t;
    return res;
  }
  res.t_tangent = t;
  res.history.reserve(std::size_t(std::fmin(1e6, (o.t_end - t) / o.interval + 2)));
  Simulation<VM> sim(vm, o.integrator, t, md, Z);
  detail::TangentObserver<VM, Traits, Watch> ob(watch, false);
  while (t < o.t_end) {
    const double target = std::fmin(t + o.interval, o.t_end);
    const RunStatus st = sim.advance(target, ob);
    t = sim.t();
    typename VM::State& state = sim.state();
    res.events = ob.events;
    res.stats = vm.stats();
    typename VM::Base v = VM::tangent(state, 0);
    const double d = vm.norm(v);
    if (d == 0.0) {
      res.status = TangentStatus::Superstable;
      res.exponent = -INFINITY;
      res.t_final = t;
      res.note = "the tangent was annihilated (the orbit came to rest): every nearby orbit merges with it";
      return res;
    }
    if (!std::isfinite(d)) {
      res.status = TangentStatus::Failed;
      res.t_final = t;
      res.note = "the tangent is not finite";
      return res;
    }
    if (t > res.t_tangent) {
      res.sum_log += std::log(d);
      ++res.renormalisations;
      res.exponent = res.sum_log / (t - res.t_tangent);
      res.history.push_back({t, std::log(d), res.exponent});
    }
    if (st != RunStatus::ReachedEnd) {
      detail::mark_stopped(res, st, ob, t);
      return res;
    }
    // Components outside the metric (accumulated works, a neutral translation) never feed back;
    // left alone they would be amplified by every renormalisation of a contracting tangent.
    for (std::size_t i = 0; i < VM::N; ++i) v[i] = metric[i] ? v[i] / d : 0.0;
    VM::set_tangent(state, 0, v);
  }
  res.t_final = t;
  return res;
}

template <HybridModel M, class Traits = TangentTraits<M>>
TangentLyapunovResult tangent_lyapunov(const M& m, typename M::Mode md, Vec<M::kDim> z,
                                       const TangentLyapunovOptions& o) {
  NoWatch w;
  return tangent_lyapunov<M, Traits, NoWatch>(m, md, z, o, w);
}

// The tangent map of the orbit from (t0, mode, z) to t1: K tangents started at the columns
// dirs[k], returned with the final base state and mode (flow map Jacobian times dirs, with the
// saltations of every event on the way). status: the integrator's.
template <HybridModel M, int K, class Traits = TangentTraits<M>>
struct TangentMap {
  RunStatus status = RunStatus::ReachedEnd;
  double t = 0;
  typename M::Mode mode{};
  Vec<M::kDim> z{};
  std::array<Vec<M::kDim>, K> v{};
  VariationalStats stats;
};

template <HybridModel M, int K, class Traits = TangentTraits<M>>
TangentMap<M, K, Traits> tangent_map(const M& m, typename M::Mode md, const Vec<M::kDim>& z, double t0, double t1,
                                     const std::array<Vec<M::kDim>, K>& dirs, const IntegratorOptions& opt) {
  using VM = VariationalModel<M, K, Traits>;
  const VM vm(m);
  typename VM::State Z{};
  VM::set_base(Z, z);
  for (int k = 0; k < K; ++k) VM::set_tangent(Z, k, dirs[k]);
  Observer<VM> quiet;
  TangentMap<M, K, Traits> out;
  Simulation<VM> sim(vm, opt, t0, md, Z);
  out.status = sim.advance(t1, quiet);
  out.t = sim.t();
  out.mode = sim.mode();
  out.z = VM::base(sim.state());
  for (int k = 0; k < K; ++k) out.v[k] = VM::tangent(sim.state(), k);
  out.stats = vm.stats();
  return out;
}

}  // namespace blockdyn
