// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/simulation/rigid3d_simulation.hpp"

#include <cmath>
#include <stdexcept>

#include "blockdyn/base/number_text.hpp"
#include "blockdyn/simulation/simulation.hpp"

namespace blockdyn {

namespace {

using Model = BodyOnGround;

// Watches the run: rows at the output clock, events, the energy balance at every step end.
class Body3dWatch final : public Observer<Model> {
 public:
  Body3dWatch(const Model& m, const Body3dRunOptions& opt, Body3dResult& r) : model(m), o(opt), res(r) {}
  const Model& model;
  const Body3dRunOptions& o;
  Body3dResult& res;
  double next_row = 0;

  void row(double t, const Model::Mode& m, const Model::State& z, const char* event = nullptr) const {
    if (o.on_sample) o.on_sample({t, m, z, event});
  }
  void track(double t, const Model::State& z) {
    res.max_abs_energy_error = std::fmax(res.max_abs_energy_error, std::fabs(model.balance(z) - res.initial_energy));
    const double tilt = model.tilt(z);
    if (tilt > res.max_tilt) {
      res.max_tilt = tilt;
      res.max_tilt_azimuth = tilt_azimuth_deg(z);
    }
    (void)t;
  }
  bool on_segment(const Model&, const Segment& seg, double t0, double t1, const Model::Mode& m) override {
    Model::State y;
    if (o.output_interval > 0 && o.on_sample) {
      while (next_row <= t1) {
        if (next_row > t0) {
          seg.eval(next_row, y);
          model.complete(m, y);
          row(next_row, m, y);
        }
        next_row += o.output_interval;
      }
    }
    if (o.track_energy) {
      seg.eval(t1, y);
      model.complete(m, y);
      track(t1, y);
    }
    return true;
  }
  bool on_event(const Model&, const Event& e) override {
    const auto kind = Body3dEventKind(e.kind);
    // A breakpoint of the ground motion (every sample of a record) is no event of the body's.
    if (kind == Body3dEventKind::GroundBreak && !e.stop) return true;
    if (kind == Body3dEventKind::Impact) ++res.impacts;
    if (res.first_uplift_time < 0 && e.from.contact == BodyContact::Rest && e.to.contact != BodyContact::Rest)
      res.first_uplift_time = e.t;
    if (kind == Body3dEventKind::Overturn) {
      res.overturn_time = e.t;
      res.overturn_azimuth = tilt_azimuth_deg(e.z);
    }
    if (e.stop) res.note = Model::stop_reason(e.from, e.index, kind);
    const Body3dEventRecord rec{{e.t, kind}, e.from.contact, e.to.contact, e.z};
    if (o.events)
      o.events->on_event(rec);
    else
      res.events.push_back(rec);
    track(e.t, e.z);
    row(e.t, e.to, e.z, to_string(kind));
    return true;
  }
};

}  // namespace

double tilt_azimuth_deg(const BodyOnGround::State& z) {
  const Mat3 r = rotation({z[BodyOnGround::kQw], z[BodyOnGround::kQx], z[BodyOnGround::kQy], z[BodyOnGround::kQz]});
  return std::atan2(r[1][2], r[0][2]) * (180 / M_PI);
}

Body3dResult simulate_body3d(const BodyOnGround& model, BodyOnGround::State z, const Body3dRunOptions& o) {
  if (!(o.t_end > 0 && std::isfinite(o.t_end)))
    throw std::invalid_argument("t-end = " + number_text(o.t_end) + " is out of range: (0, inf) s");
  if (!(o.output_interval >= 0 && std::isfinite(o.output_interval)))
    throw std::invalid_argument("output-interval = " + number_text(o.output_interval) + " is out of range: >= 0 s");
  if (o.output_interval > 0 && o.t_end / o.output_interval > 1e8)
    throw std::invalid_argument("output-interval = " + number_text(o.output_interval) +
                                " gives more than 1e8 rows: at least t-end / 1e8");
  Body3dResult res;
  double t = 0;
  Model::Mode mode = model.mode_of(t, z);
  model.complete(mode, z);
  res.initial_energy = model.balance(z);
  Body3dWatch watch{model, o, res};
  watch.row(0, mode, z);
  watch.track(0, z);
  watch.next_row = o.output_interval;
  // A body standing where rest fails leaves it at once (the transition the breakpoint would make).
  Transition<Model::Mode> start{mode, false, int(Body3dEventKind::Mode)};
  if (mode.contact == BodyContact::Rest) start = model.transition(t, mode, z, kBreakpoint);
  if (start.stop) {
    res.status = SimStatus::Invalid;
    res.note = Model::stop_reason(mode, kBreakpoint, Body3dEventKind(start.kind));
  } else {
    if (start.next.contact != mode.contact) res.first_uplift_time = 0;
    mode = start.next;
    Simulation<Model> sim(model, o.integ, t, mode, z);
    res.run_status = sim.advance(o.t_end, watch);
    res.stats = sim.stats();
    t = sim.t();
    mode = sim.mode();
    z = sim.state();
    res.status = res.overturn_time >= 0                    ? SimStatus::Overturned
                 : res.run_status == RunStatus::ReachedEnd ? SimStatus::TEnd
                                                           : SimStatus::Invalid;
    if (res.status == SimStatus::Invalid && res.note.empty())
      res.note = std::string("the integration stopped: ") + to_string(res.run_status);
  }
  res.t_final = t;
  res.z = z;
  res.mode = mode;
  return res;
}

}  // namespace blockdyn
