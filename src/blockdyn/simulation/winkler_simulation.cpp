// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/simulation/winkler_simulation.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace blockdyn {

namespace {

// The Winkler family's recorder: ihor (passages through w = 0), first flight, overturn, the event
// list and counts; forwards the trajectory and the events to the user's sink.
class WinklerRecorder final : public Observer<WinklerBlock> {
 public:
  WinklerRecorder(const WinklerRunOptions& o, WinklerResult& r, WinklerSink* s, EventSink<WinklerEventRecord>* events)
      : opt_(o), res_(r), sink_(s), events_(events) {
    if (o.record_events) res_.events.reserve(256);
  }

  bool on_segment(const WinklerBlock& m, const Segment& seg, double t0, double t1, const WinklerMode& mode) override {
    if (sink_) sink_->on_segment(m, seg, t0, t1, mode);
    return !sink_ || sink_->keep_going();
  }

  bool on_event(const WinklerBlock& m, const Event& e) override {
    const WinklerEventKind kind = WinklerEventKind(e.kind);
    if (kind == WinklerEventKind::GroundBreak) return true;
    if (kind == WinklerEventKind::WZero) ++res_.upright_passages;
    ++res_.event_counts[int(kind)];
    WinklerEventRecord rec{{e.t, kind}, e.from, e.to, e.z, res_.upright_passages};
    if (kind == WinklerEventKind::Takeoff && !res_.first_flight_time) {
      res_.first_flight_time = e.t;
      res_.upright_passages_at_first_flight = res_.upright_passages;
    }
    if (kind == WinklerEventKind::Overturn) {
      res_.overturn_time = e.t;
      res_.upright_passages_at_overturn = res_.upright_passages;
    }
    if (opt_.record_events) res_.events.push_back(rec);
    if (events_) events_->on_event(rec);
    if (sink_) sink_->on_event(m, rec);
    if (opt_.stop_at_first_flight && kind == WinklerEventKind::Takeoff) return stop();
    if (opt_.stop_at_upright_passages > 0 && res_.upright_passages >= opt_.stop_at_upright_passages) return stop();
    return !sink_ || sink_->keep_going();
  }

  bool early_stop() const { return early_; }
  bool needs_dense() const override { return sink_ && sink_->needs_dense(); }

 private:
  bool stop() {
    early_ = true;
    return false;
  }

  const WinklerRunOptions& opt_;
  WinklerResult& res_;
  WinklerSink* sink_;
  EventSink<WinklerEventRecord>* events_;
  bool early_ = false;
};

}  // namespace

WinklerResult simulate(const WinklerParams& p, const GroundMotion& g, const WinklerState& z0,
                       const WinklerRunOptions& opt, WinklerSink* sink, EventSink<WinklerEventRecord>* events) {
  validate(p);
  validate(g);
  validate(opt);
  const WinklerBlock model(p, g);
  WinklerState z = z0;
  z[kWorkFriction] = z[kWorkNonPotential] = z[kWorkGround] = 0.0;
  if (auto why = model.validity_problem(z)) throw std::invalid_argument("initial state: " + *why);
  WinklerResult res;
  const double t = opt.t_start;
  WinklerMode mode = model.initial_mode(t, z);
  model.complete(mode, z);
  res.initial_state = z;
  res.initial_mode = mode;
  res.initial_energy = energy(p, z);
  res.upright_passages = (z[kW] == 0.0) ? 1 : 0;
  if (mode.regime == Regime::Flight) {
    res.first_flight_time = t;
    res.upright_passages_at_first_flight = res.upright_passages;
  }
  if (sink) sink->on_start(model, t, mode, z);
  WinklerRecorder rec(opt, res, sink, events);
  EnergyBalance<WinklerBlock> balance;
  FanOut<WinklerBlock> obs;
  obs.add(&rec);
  if (opt.track_energy) obs.add(&balance);
  const RunClock clock;
  const RunOutcome<WinklerBlock> out = run_model(model, mode, z, t, opt.t_end, opt.integrator, obs);
  res.timing = clock.elapsed();
  res.run_status = out.status;
  res.t_final = out.t;
  res.final_state = out.z;
  res.final_mode = out.mode;
  res.final_energy = energy(p, out.z);
  res.stats = out.stats;
  res.max_abs_energy_error = balance.max_abs_error();
  res.max_abs_energy_change = balance.max_abs_change();
  res.status = sim_status(out.status, res.overturn_time.has_value());
  return res;
}

}  // namespace blockdyn
