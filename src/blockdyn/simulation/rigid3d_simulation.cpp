// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/simulation/rigid3d_simulation.hpp"

#include <cmath>
#include <stdexcept>

#include "blockdyn/base/number_text.hpp"
#include "blockdyn/integrate/root_bracket.hpp"
#include "blockdyn/simulation/simulation.hpp"

namespace blockdyn {

namespace {

using Model = BodyOnGround;

// The body leaves the ground where it stood flat (rest or slide) for a tilted contact or flight.
bool lifts(const BodyOnGroundMode& from, const BodyOnGroundMode& to) {
  const auto flat = [](BodyContact c) { return c == BodyContact::Rest || c == BodyContact::Slide; };
  return flat(from.contact) && !flat(to.contact);
}

// The centre of the body's base (world): its centroid less c along its axis.
Vec3 base_centre(const Model& m, const Model::State& z) {
  const Mat3 r = rotation({z[Model::kQw], z[Model::kQx], z[Model::kQy], z[Model::kQz]});
  const double c = m.body().half_height();
  return {z[Model::kX] - c * r[0][2], z[Model::kY] - c * r[1][2], z[Model::kZ] - c * r[2][2]};
}

// Watches the run: rows at the output clock, events, the energy balance at every step end.
class Body3dWatch final : public Observer<Model> {
 public:
  Body3dWatch(const Model& m, const Body3dRunOptions& opt, Body3dResult& r) : model(m), o(opt), res(r) {}
  const Model& model;
  const Body3dRunOptions& o;
  Body3dResult& res;
  double next_row = 0;
  // The distance slid: the displacements of the slipping point on the ground (the base's centre
  // sliding flat, the corner or the edge's midpoint slipping), summed over the slips (slid), and
  // where that point was when the current slip began.
  Model::Mode current{};
  Vec3 slid{}, slip_from{};
  // The last leg stopped where no contact state is consistent: Painleve, or modes taking turns at
  // one instant (an edge and a corner, impacts that do not end).
  bool inconsistent = false;
  static bool slipping(const Model::Mode& m) {
    return m.contact == BodyContact::Slide ||
           ((m.contact == BodyContact::Line || m.contact == BodyContact::Point || m.contact == BodyContact::Roll) &&
            m.slips());
  }
  Vec3 slip_point(const Model::Mode& m, const Model::State& z) const {
    return m.contact == BodyContact::Slide ? base_centre(model, z) : model.contact_point(m, z);
  }
  void slide_changes(const Model::Mode& from, const Model::Mode& to, const Model::State& z) {
    if (slipping(from)) {
      const Vec3 c = slip_point(from, z);
      slid = {slid[0] + c[0] - slip_from[0], slid[1] + c[1] - slip_from[1], 0};
    }
    if (slipping(to)) slip_from = slip_point(to, z);
    current = to;
  }

  void row(double t, const Model::Mode& m, const Model::State& z, const char* event = nullptr) const {
    if (o.on_sample) o.on_sample({t, m, z, event});
  }
  // A time step's end (Moreau-Jean): a row where the output clock or every step asks for one.
  void step_rows(double t, const Model::Mode& m, const Model::State& z) {
    if (!o.on_sample) return;
    bool due = o.rows_every_step;
    for (; o.output_interval > 0 && next_row <= t; next_row += o.output_interval) due = true;
    if (due) row(t, m, z);
  }
  void track(double t, const Model::State& z, bool energy = true) {
    if (energy)
      res.max_abs_energy_error = std::fmax(res.max_abs_energy_error, std::fabs(model.balance(z) - res.initial_energy));
    if (slipping(current)) {
      const Vec3 c = slip_point(current, z);
      res.max_slide =
          std::fmax(res.max_slide, std::hypot(slid[0] + c[0] - slip_from[0], slid[1] + c[1] - slip_from[1]));
    }
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
    if (o.rows_every_step && o.on_sample) {
      seg.eval(t1, y);
      model.complete(m, y);
      row(t1, m, y);
    }
    if (o.track_energy || o.track_tilt) {
      Model::State a;
      seg.eval(t1, y);
      model.complete(m, y);
      if (o.track_tilt) {
        seg.eval(t0, a);
        model.complete(m, a);
      }
      // The tilt's largest value inside the step, where its rate changes sign from rising.
      const double ra = o.track_tilt ? tilt_rate_sign(a) : 0.0, rb = tilt_rate_sign(y);
      if (ra > 0 && rb < 0) {
        auto f = [&](double t) {
          Model::State z;
          seg.eval(t, z);
          model.complete(m, z);
          return tilt_rate_sign(z);
        };
        Model::State z;
        seg.eval(locate_root(f, t0, t1, ra, rb), z);
        model.complete(m, z);
        track(t0, z, false);
      }
      track(t1, y, o.track_energy);
    }
    return true;
  }
  // A quantity with the sign of the tilt's rate: d(cos tilt)/dt = (omega x e3)_z, so the tilt
  // rises where omega_y e3_x - omega_x e3_y > 0.
  static double tilt_rate_sign(const Model::State& z) {
    const Mat3 r = rotation({z[Model::kQw], z[Model::kQx], z[Model::kQy], z[Model::kQz]});
    return z[Model::kWy] * r[0][2] - z[Model::kWx] * r[1][2];
  }
  bool on_event(const Model&, const Event& e) override {
    const auto kind = Body3dEventKind(e.kind);
    // A breakpoint of the ground motion (every sample of a record) is no event of the body's, nor
    // a slide's new reference direction.
    if ((kind == Body3dEventKind::GroundBreak || kind == Body3dEventKind::SlipTurn) && !e.stop) return true;
    if (kind == Body3dEventKind::Impact) ++res.impacts;
    if (res.first_uplift_time < 0 && lifts(e.from, e.to)) res.first_uplift_time = e.t;
    if (res.first_slide_time < 0 && slipping(e.to)) res.first_slide_time = e.t;
    if (kind == Body3dEventKind::Overturn) {
      res.overturn_time = e.t;
      res.overturn_azimuth = tilt_azimuth_deg(e.z);
    }
    if (e.stop) res.note = Model::stop_reason(e.from, e.index, kind);
    inconsistent = e.stop && (kind == Body3dEventKind::Painleve || kind == Body3dEventKind::NotModelled);
    slide_changes(e.from, e.to, e.z);
    const Body3dEventRecord rec{{e.t, kind}, e.from.contact, e.to.contact, e.from.slipping, e.to.slipping, e.z};
    ++res.event_count;
    if (o.events)
      o.events->on_event(rec);
    else if (long(res.events.size()) < o.max_events)
      res.events.push_back(rec);
    track(e.t, e.z);
    row(e.t, e.to, e.z, to_string(kind));
    return true;
  }
};

// Steps with the same corners loaded before the contact they make may take over (not inside a
// sequence of the steps' own contact changes).
constexpr long kPainleveQuietSteps = 10;

// Moreau-Jean steps from the Painleve state (t, mode, z) until the contact they leave loaded is
// consistent (true: the events take over from (t, mode, z)); false where the run ends inside the
// span: at t_end, overturned, or (invalid, res.note says why) the steps fail or the span's limit.
bool cross_painleve_span(const Model& model, const Body3dRunOptions& o, Body3dWatch& watch, Body3dResult& res,
                         double& t, Model::Mode& mode, Model::State& z) {
  const double unit = std::sqrt(model.size() / model.body().g);
  const double h = o.painleve_step > 0 ? o.painleve_step : kPainleveStep * unit;
  const double t0 = t;
  const std::string why = res.note;
  res.note.clear();
  ++res.painleve_spans;
  auto event = [&](Body3dEventKind kind, const Model::Mode& to, bool stop) {
    const EventInfo<Model::Mode, Model::kDim> e{t, z, z, mode, to, -1, int(kind), stop};
    watch.on_event(model, e);
  };
  // The step ends are t0 + k h exactly (the last one cut at t_end).
  unsigned last_loaded = 0;
  long quiet = 0;
  for (long k = 1; t < o.t_end; ++k) {
    const double t1 = std::fmin(t0 + double(k) * h, o.t_end);
    const Model::TimeStep step = model.time_step(t, t1 - t, z);
    res.painleve_time += t1 - t;
    t = t1;
    ++res.painleve_steps;
    if (!step.solved) {
      res.note = why + "; no impulses solve the Moreau-Jean step's contact problem at t = " + number_text(t, 12) + " s";
      return false;
    }
    watch.step_rows(t, mode, z);
    watch.track(t, z);
    if (rotation({z[Model::kQw], z[Model::kQx], z[Model::kQy], z[Model::kQz]})[2][2] <= 0) {
      event(Body3dEventKind::Overturn, Model::Mode{BodyContact::Flight}, true);
      return false;
    }
    quiet = step.loaded == last_loaded ? quiet + 1 : 0;
    last_loaded = step.loaded;
    if (quiet >= kPainleveQuietSteps)
      if (const auto next = model.resume_contact(t, z, step.loaded)) {
        event(Body3dEventKind(next->kind), next->next, false);
        mode = next->next;
        return true;
      }
    if (t - t0 > kPainleveSpan * unit) {
      res.note = why + "; Moreau-Jean steps of " + number_text(h, 6) + " s across it found no consistent contact in " +
                 number_text(t - t0, 6) + " s";
      return false;
    }
  }
  return false;
}

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
  // A start whose contact points move into the ground begins with an impact (its loss booked in
  // the state's impact work, the balance taken after it).
  const Transition<Model::Mode> first = model.start(t, z, o.slip_start);
  Model::Mode mode = first.next;
  model.complete(mode, z);
  res.initial_energy = model.balance(z);
  Body3dWatch watch{model, o, res};
  watch.row(0, mode, z);
  watch.track(0, z);
  watch.next_row = o.output_interval;
  // A body standing where rest fails leaves it at once (the transition the breakpoint would make).
  Transition<Model::Mode> start{mode, false, int(Body3dEventKind::Mode)};
  if (first.stop) start = first;
  if (!first.stop && mode.contact == BodyContact::Rest) start = model.transition(t, mode, z, kBreakpoint);
  if (start.stop) {
    res.status = SimStatus::Invalid;
    res.note = Model::stop_reason(mode, kBreakpoint, Body3dEventKind(start.kind));
  } else {
    if (lifts(mode, start.next)) res.first_uplift_time = 0;
    if (Body3dWatch::slipping(start.next)) res.first_slide_time = 0;
    watch.slide_changes(Model::Mode{}, start.next, z);
    mode = start.next;
    // Event-driven legs; an inconsistent contact is crossed by Moreau-Jean steps between them.
    for (;;) {
      Simulation<Model> sim(model, o.integ, t, mode, z);
      res.run_status = sim.advance(o.t_end, watch);
      res.stats += sim.stats();
      t = sim.t();
      mode = sim.mode();
      z = sim.state();
      // A stiff slip (tiny loads against a large mu_s) can underflow the events' steps too.
      const bool underflow = res.run_status == RunStatus::StepUnderflow;
      if (underflow) res.note = "the events' steps underflowed in the contact's stiff slip";
      if (!(watch.inconsistent || underflow) || !o.painleve_steps) break;
      watch.inconsistent = false;
      if (cross_painleve_span(model, o, watch, res, t, mode, z)) continue;
      if (res.note.empty()) res.run_status = RunStatus::ReachedEnd;
      break;
    }
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
