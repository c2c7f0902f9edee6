// SPDX-License-Identifier: Apache-2.0
#pragma once
// A RunProbe fed by a run of the rigid-ground family (HousnerBlock, RigidBlock): pass it as the
// `extra` observer of simulate_housner / simulate_rigid. Samples come from the dense output
// (completed), impacts with theta' before and after the jump, passages of theta through 0 in
// flight.
#include "blockdyn/model/rigid_ground/mechanism.hpp"
#include "blockdyn/simulation/observer.hpp"
#include "blockdyn/simulation/run_probe.hpp"

namespace blockdyn {

template <class Model>
class RigidProbeObserver final : public Observer<Model> {
 public:
  BLOCKDYN_OBSERVER_TYPES(Model);
  static constexpr std::size_t kTh = Model::kThetaIndex, kOm = Model::kOmegaIndex;

  explicit RigidProbeObserver(RunProbe& p) : p_(p) {}

  void on_start(const Model& m, double t, const Mode& md, const State& z) override {
    p_.advance(t, 1, [&](double, RunProbe::BlockState* s) { s[0] = m.pose(md, z); });
  }
  bool on_segment(const Model& m, const Segment& seg, double, double t1, const Mode& md) override {
    p_.advance(t1, 1, [&](double t, RunProbe::BlockState* s) {
      State z;
      seg.eval(t, z);
      m.complete(md, z);
      s[0] = m.pose(md, z);
    });
    return true;
  }
  bool on_event(const Model&, const Event& e) override {
    const RigidEventKind k = RigidEventKind(e.kind);
    if (k != RigidEventKind::Impact && k != RigidEventKind::WZero) return true;
    ProbeEvent pe;
    pe.t = e.t;
    pe.block = 0;
    pe.kind = k == RigidEventKind::Impact ? ProbeEvent::Impact : ProbeEvent::Passage;
    pe.theta = e.z[kTh];
    pe.omega_before = e.z_before[kOm];
    pe.omega_after = e.z[kOm];
    p_.event(pe);
    return true;
  }
  void on_finish(const Model&, double t, const Mode&, const State&) override { p_.finish(t); }

 private:
  RunProbe& p_;
};

}  // namespace blockdyn
