// SPDX-License-Identifier: Apache-2.0
#pragma once
// The rigid family's recorder (HousnerBlock and RigidBlock): events with the velocities across
// impacts, mechanism changes, the largest |theta| (located on the dense output where theta' = 0),
// overturn and first uplift times.
#include <cmath>

#include "blockdyn/integrate/root_bracket.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"

namespace blockdyn {

template <class Model>
class RigidRecorder final : public Observer<Model> {
 public:
  BLOCKDYN_OBSERVER_TYPES(Model);
  static constexpr std::size_t kTh = Model::kThetaIndex, kOm = Model::kOmegaIndex;

  RigidRecorder(bool record_events, RigidResult& r, RigidEventSink* sink = nullptr)
      : record_(record_events), res_(r), sink_(sink) {
    if (record_) res_.events.reserve(256);
  }

  void on_start(const Model& m, double t, const Mode& md, const State& z) override {
    track(t, z[kTh]);
    moved(t, Mechanism::Rest, m.mechanism(md));
    if (const unsigned other = m.alternatives(md); other != 0) {
      RigidEventRecord r;
      r.t = t;
      r.kind = RigidEventKind::AmbiguousOnset;
      r.from = r.to = m.mechanism(md);
      r.state = m.pose(md, z);
      r.pivot = m.pivot(md);
      r.slip = m.slip(md);
      r.mechanisms = other | mechanism_bit(r.to);
      add(r);
    }
  }

  bool on_segment(const Model& m, const Segment& seg, double t0, double t1, const Mode& md) override {
    State a, b;
    seg.eval(t0, a);
    seg.eval(t1, b);
    if ((a[kOm] > 0.0) != (b[kOm] > 0.0) && a[kOm] != 0.0 && b[kOm] != 0.0) {
      // theta' changes sign inside the step: the extreme of theta lies there.
      const double s = a[kOm] > 0.0 ? 1.0 : -1.0;
      auto f = [&](double t) {
        State z;
        seg.eval(t, z);
        return s * z[kOm];
      };
      const double tr = locate_root(f, t0, t1, s * a[kOm], s * b[kOm]);
      State z;
      seg.eval(tr, z);
      m.complete(md, z);
      track(tr, z[kTh]);
    }
    m.complete(md, b);
    track(t1, b[kTh]);
    return true;
  }

  bool on_event(const Model& m, const Event& e) override {
    const RigidEventKind kind = RigidEventKind(e.kind);
    if (kind == RigidEventKind::GroundBreak && m.mechanism(e.from) == m.mechanism(e.to) &&
        m.slip(e.from) == m.slip(e.to))
      return true;
    track(e.t, e.z[kTh]);
    const Mechanism from = m.mechanism(e.from), to = m.mechanism(e.to);
    if (kind == RigidEventKind::Impact) {
      RigidEventRecord r = record(m, e, kind, from, to);
      r.corner = m.impact_corner(e.from, e.index);
      r.vw_before = e.z_before[kOm];
      r.vw_after = e.z[kOm];
      ++res_.impacts;
      add(r);
    } else if (kind != RigidEventKind::Mode && kind != RigidEventKind::GroundBreak) {
      add(record(m, e, kind, from, to));
      if (kind == RigidEventKind::Overturn) res_.overturn_time = e.t;
      if (kind == RigidEventKind::BeyondAlpha && !res_.first_beyond_alpha_time) res_.first_beyond_alpha_time = e.t;
    }
    // A change of mechanism, or of pivot or slip direction within one (an impact moves the pivot
    // by definition: there only the mechanism counts).
    const bool changed = from != to || (kind != RigidEventKind::Impact &&
                                        (m.pivot(e.from) != m.pivot(e.to) || m.slip(e.from) != m.slip(e.to)));
    if (changed && !e.stop) {
      ++res_.mode_changes;
      add(record(m, e, RigidEventKind::Mode, from, to));
      moved(e.t, from, to);
    }
    if (const unsigned other = m.alternatives(e.to); other != 0 && !e.stop) {
      RigidEventRecord r = record(m, e, RigidEventKind::AmbiguousOnset, from, to);
      r.mechanisms = other | mechanism_bit(to);
      add(r);
    }
    return true;
  }

 private:
  RigidEventRecord record(const Model& m, const Event& e, RigidEventKind k, Mechanism from, Mechanism to) const {
    RigidEventRecord r;
    r.t = e.t;
    r.kind = k;
    r.from = from;
    r.to = to;
    r.state = m.pose(e.to, e.z);
    r.pivot = m.pivot(e.to);
    r.slip = m.slip(e.to);
    return r;
  }
  void add(const RigidEventRecord& r) {
    ++res_.event_counts[int(r.kind)];
    if (record_) res_.events.push_back(r);
    if (sink_) sink_->on_event(r);
  }
  void moved(double t, Mechanism from, Mechanism to) {
    if (to != Mechanism::Rest && !res_.first_motion_time) res_.first_motion_time = t;
    const bool lifted = to == Mechanism::Rock || to == Mechanism::SlideRock || to == Mechanism::Flight;
    if (lifted && from != to && !res_.first_uplift_time) res_.first_uplift_time = t;
  }
  void track(double t, double th) {
    if (std::fabs(th) > res_.max_abs_rotation) {
      res_.max_abs_rotation = std::fabs(th);
      res_.t_max_abs_rotation = t;
    }
  }

  bool record_;
  RigidResult& res_;
  RigidEventSink* sink_;
};

}  // namespace blockdyn
