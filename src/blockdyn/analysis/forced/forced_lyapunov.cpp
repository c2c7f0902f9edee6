// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/forced_lyapunov.hpp"

#include <cmath>
#include <functional>
#include <stdexcept>

#include "blockdyn/analysis/dynamics/lyapunov.hpp"
#include "blockdyn/analysis/forced/block_tangent_traits.hpp"
#include "blockdyn/model/assembly/assembly_model.hpp"
#include "blockdyn/simulation/simulation.hpp"

namespace blockdyn {

void validate(const ForcedLyapunovOptions& o) {
  if (!(o.t_end > 0 && o.t_end <= 1e7)) throw std::invalid_argument("t-end must be in (0, 1e7] s");
  if (!(o.t_transient >= 0 && o.t_transient < o.t_end))
    throw std::invalid_argument("t-transient must be in [0, t-end) s");
  if (!(o.interval > 0) || !std::isfinite(o.interval) || (o.t_end - o.t_transient) / o.interval > 1e7)
    throw std::invalid_argument("interval must be > 0 s and at least (t-end - t-transient) / 1e7");
  if (!(o.twin_d0 == 0 || (o.twin_d0 >= 1e-14 && o.twin_d0 <= 1e-2)))
    throw std::invalid_argument("twin-d0 must be 0 (no twin) or in [1e-14, 1e-2]");
}

namespace {

// How a family reads its events: impacts and failures.
template <class M>
struct EventReading {
  std::function<bool(int index, int kind)> impact;
  std::function<std::optional<int>(int kind)> collapse;  // collapse mode of a stopping event
};

template <class M>
struct Watch {
  const EventReading<M>* read;
  ForcedLyapunovOutcome* out;
  double* t_stop;
  template <class E>
  void on_event(const E& e) {
    if (read->impact(e.index, e.kind)) ++out->impacts;
    if (TangentTraits<M>::moving(e.to)) out->moved = true;
    if (e.stop) {
      *t_stop = e.t;
      if (auto c = read->collapse(e.kind)) {
        out->collapse_mode = c;
        out->t_failure = e.t;
      }
    }
  }
};

// Separation of the two copies on the metric components.
template <class M>
double separation(const M& m, const Vec<M::kDim>& a, const Vec<M::kDim>& b) {
  const auto sc = TangentTraits<M>::scale(m);
  const auto mt = TangentTraits<M>::metric(m);
  double s = 0;
  for (std::size_t i = 0; i < M::kDim; ++i)
    if (mt[i]) s += ((a[i] - b[i]) / sc[i]) * ((a[i] - b[i]) / sc[i]);
  return std::sqrt(s);
}

template <class M>
void run_twin(const M& m, typename M::Mode md, Vec<M::kDim> z, double t0, const ForcedLyapunovOptions& o,
              std::size_t rate_index, ForcedLyapunovOutcome& out) {
  using Pair = PairModel<M>;
  const Pair pair(m);
  Vec<M::kDim> zc = z;
  // The copy's rate differs by twin_d0 in scaled units, in the direction it already turns (or,
  // at rest on a pivot, towards that pivot's side) so that it starts in the same mode.
  const double sc = TangentTraits<M>::scale(m)[rate_index];
  double dir = z[rate_index] > 0 ? 1.0 : z[rate_index] < 0 ? -1.0 : 1.0;
  if constexpr (requires { dir = md.side; }) {
    if (z[rate_index] == 0.0 && md.side != 0) dir = md.side;
  }
  zc[rate_index] += dir * o.twin_d0 * sc;
  m.complete(md, zc);
  typename Pair::Mode pm{md, md};
  auto Z = Pair::join(z, zc);
  Observer<Pair> quiet;
  double t = t0;
  Simulation<Pair> sim(pair, o.integrator, t, pm, Z);
  out.twin.push_back({t, separation(m, z, zc)});
  while (t < o.t_end) {
    const RunStatus st = sim.advance_from(t, pm, Z, std::fmin(t + o.interval, o.t_end), quiet);
    Vec<M::kDim> a, b;
    Pair::split(Z, a, b);
    out.twin.push_back({t, separation(m, a, b)});
    if (st != RunStatus::ReachedEnd) {
      out.twin_note = std::string("a copy stopped: ") + to_string(st);
      return;
    }
  }
}

template <class M>
ForcedLyapunovOutcome run_forced(const M& m, typename M::Mode md, Vec<M::kDim> z, const ForcedLyapunovOptions& o,
                                 const EventReading<M>& read, std::size_t rate_index, const std::string& metric) {
  validate(o);
  ForcedLyapunovOutcome out;
  out.metric = metric;
  out.moved = TangentTraits<M>::moving(md);
  double t_stop = NAN;
  Watch<M> w{&read, &out, &t_stop};
  // The transient (and the wait for motion) on the orbit alone.
  double t = 0.0;
  struct Transient final : Observer<M> {
    Transient(Watch<M>& watch, double from, bool stop_moving) : w(watch), t_from(from), stop_when_moving(stop_moving) {}
    Watch<M>& w;
    double t_from;
    bool stop_when_moving;
    bool on_event(const M&, const EventInfo<typename M::Mode, M::kDim>& e) override {
      w.on_event(e);
      return !(stop_when_moving && e.t >= t_from && TangentTraits<M>::moving(e.to));
    }
  };
  Simulation<M> sim(m, o.integrator, t, md, z);
  if (o.t_transient > 0) {
    Transient tr(w, 0.0, false);
    const RunStatus st = sim.advance_from(t, md, z, o.t_transient, tr);
    if (st != RunStatus::ReachedEnd) {
      out.tangent.status = st == RunStatus::ModelStop ? TangentStatus::Stopped : TangentStatus::Failed;
      out.tangent.run_status = st;
      out.tangent.t_final = t;
      out.tangent.note = "the orbit stopped during the transient: " + std::string(to_string(st));
      return out;
    }
  }
  if (!TangentTraits<M>::moving(md)) {
    Transient tr(w, t, true);
    const RunStatus st = sim.advance_from(t, md, z, o.t_end, tr);
    if (st == RunStatus::ReachedEnd) {
      out.tangent.status = TangentStatus::NeverMoved;
      out.tangent.t_final = t;
      out.tangent.note = "at rest from t-transient to t-end";
      return out;
    }
    if (st != RunStatus::ObserverStop) {
      out.tangent.status = st == RunStatus::ModelStop ? TangentStatus::Stopped : TangentStatus::Failed;
      out.tangent.run_status = st;
      out.tangent.t_final = t;
      out.tangent.note = "the orbit stopped: " + std::string(to_string(st));
      return out;
    }
  }
  TangentLyapunovOptions to;
  to.t_start = to.t_measure = t;
  to.t_end = o.t_end;
  to.interval = o.interval;
  to.integrator = o.integrator;
  if (!(to.t_end > to.t_start)) {
    out.tangent.status = TangentStatus::NeverMoved;
    out.tangent.t_final = t;
    return out;
  }
  out.tangent = tangent_lyapunov<M, TangentTraits<M>, Watch<M>>(m, md, z, to, w);
  const double t0 = out.tangent.t_tangent;
  if (std::isfinite(t0)) out.exponent_second_half = tail_exponent(out.tangent, t0 + 0.5 * (out.tangent.t_final - t0));
  if (o.twin_d0 > 0 && std::isfinite(t0)) run_twin(m, md, z, t0, o, rate_index, out);
  if (!o.keep_history) out.tangent.history.clear();
  return out;
}

}  // namespace

ForcedLyapunovOutcome housner_lyapunov(const BlockShape& shape, std::optional<double> restitution,
                                       const GroundMotion& g, const RigidInitial& init,
                                       const ForcedLyapunovOptions& o) {
  validate(shape);
  validate(g);
  const double e = housner_coefficient(shape, restitution);
  const HousnerBlock m(shape, e, g);
  const HousnerBlock::State z = housner_initial_state(m, init);
  EventReading<HousnerBlock> read{
      [](int index, int) { return index == HousnerBlock::kEvImpact; },
      [](int kind) { return kind == int(RigidEventKind::Overturn) ? std::optional<int>(1) : std::nullopt; }};
  return run_forced(m, m.initial_mode(0.0, z), z, o, read, HousnerBlock::kOmega, "(theta, theta'/p)");
}

ForcedLyapunovOutcome rigid_lyapunov(const RigidBlockParams& p, const GroundMotion& g, const RigidInitial& init,
                                     const ForcedLyapunovOptions& o) {
  validate(p);
  validate(g);
  const RigidBlock m(p, g);
  RigidBlock::State z = rigid_initial_state(m, init);
  const auto md = m.initial_mode(0.0, z);
  if (!md) throw std::invalid_argument("initial state: no unique consistent mechanism (Painleve's paradox)");
  EventReading<RigidBlock> read{
      [](int, int kind) { return kind == int(RigidEventKind::Impact); },
      [](int kind) { return kind == int(RigidEventKind::Overturn) ? std::optional<int>(1) : std::nullopt; }};
  return run_forced(m, *md, z, o, read, RigidBlock::kOmega,
                    "(y/L, theta, x'/sqrt(gL), y'/sqrt(gL), theta'/p), L = height");
}

namespace {

template <int MaxBlocks>
ForcedLyapunovOutcome assembly_run(const Assembly& a, const GroundMotion& g, const ForcedLyapunovOptions& o) {
  using M = AssemblyModel<MaxBlocks>;
  const M m(a, g, std::fmax(1e-12, 10.0 * o.integrator.atol));
  typename M::State z = m.initial_state();
  typename M::Mode md = m.initial_mode(z);
  m.complete(md, z);
  if (auto why = m.validity_problem(md, z)) throw std::invalid_argument("initial state: " + *why);
  EventReading<M> read{[](int, int kind) { return kind == kAssemblyContactCloses; },
                       [](int kind) {
                         return kind == kAssemblyRotationCollapse  ? std::optional<int>(1)
                                : kind == kAssemblyBearingCollapse ? std::optional<int>(2)
                                                                   : std::nullopt;
                       }};
  // The twin differs in the rotation rate of the last block (the lintel of a trilith, the top drum).
  const std::size_t rate = M::iv(m.blocks() - 1) + 2;
  return run_forced(m, md, z, o, read, rate,
                    "every block's (x/w, y/w, theta, x'/sqrt(g w), y'/sqrt(g w), theta'/p) and the contact "
                    "points' tangential spring displacements / w, w = smallest block width");
}

}  // namespace

ForcedLyapunovOutcome assembly_lyapunov(const Assembly& a, const GroundMotion& g, const ForcedLyapunovOptions& o) {
  validate(a);
  validate(g);
  if (!info(a.contact).linearisable)
    throw std::invalid_argument(std::string("contact = ") + to_string(a.contact) +
                                ": no Lyapunov exponent (Moreau-Jean time-stepping has no event-located orbit to "
                                "linearise); use the deformable contact law");
  const std::size_t n = a.blocks.size();
  if (n == 1 && a.interfaces.size() <= 2) return assembly_run<1>(a, g, o);
  if (n <= 3 && a.interfaces.size() <= 4) return assembly_run<3>(a, g, o);
  if (n > 8 || a.interfaces.size() > 9)
    throw std::invalid_argument("blocks: " + std::to_string(n) +
                                " given; the Lyapunov exponent of an assembly takes at most 8 blocks");
  return assembly_run<8>(a, g, o);
}

}  // namespace blockdyn
