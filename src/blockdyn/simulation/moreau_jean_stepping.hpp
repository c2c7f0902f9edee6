// SPDX-License-Identifier: Apache-2.0
#pragma once
// Time-stepping (Moreau-Jean) as a stepping strategy of a rigid assembly's simulation
// (simulation.hpp): the scheme's steps reported to the same Observer<Model> as the event-driven
// integrator's, each step a segment (the cubic Hermite interpolant of its end states, cut at the
// interpolated passages of the rotations and at a collapse) and its contact changes events at its
// end. run_rigid_assembly (rigid_assembly_run.cpp) uses it for a whole run or for windows of
// chattering contacts inside an event-driven one.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "blockdyn/base/number_text.hpp"
#include "blockdyn/model/assembly/moreau_jean.hpp"
#include "blockdyn/model/assembly/rigid_assembly_model.hpp"
#include "blockdyn/simulation/observer.hpp"

namespace blockdyn {

template <int MaxBlocks>
class MoreauJeanStepping {
 public:
  using M = RigidAssemblyModel<MaxBlocks>;
  using Mode = typename M::Mode;
  using State = typename M::State;
  using Event = EventInfo<Mode, M::kDim>;
  // Steps without a contact change before the events take over again.
  static constexpr int kQuietSteps = 50;

  MoreauJeanStepping(const M& m, const Assembly& a, const GroundMotion& g, double h, Observer<M>& obs)
      : m_(m), obs_(obs), mj_(a, g, options(h)), nb_(m.blocks()), ni_(m.interfaces()), q_(3 * nb_), v_(3 * nb_) {}

  // Steps from (t, z) until the contacts keep their states for kQuietSteps steps (then true: the
  // events may take over) or the run ends (t_end, a failure: false, `stopped` says which).
  bool run(double& t, Mode& mode, State& z, double t_end, long& steps, bool& stopped, bool hand_back = true) {
    for (int b = 0; b < nb_; ++b)
      for (int k = 0; k < 3; ++k) q_[3 * b + k] = z[M::ix(b) + k], v_[3 * b + k] = z[M::iv(b) + k];
    int quiet = 0;
    stopped = false;
    // Steps counted from the window's start, so that the step ends are k h exactly.
    const double t_start = t;
    long k = 0;
    while (t < t_end) {
      const State z0 = z;
      if (!mj_.step(t, q_, v_)) {
        m_.report("the contact problem (LCP) has no solution at t = " + number_text(t, 6) + " s");
        emit(t, z, z, mode, mode, 0, kAssemblyOutsideModel, true);
        stopped = true;
        return false;
      }
      ++steps;
      const double t1 = t_start + double(++k) * mj_.h();
      for (int b = 0; b < nb_; ++b)
        for (int c = 0; c < 3; ++c) z[M::ix(b) + c] = q_[3 * b + c], z[M::iv(b) + c] = v_[3 * b + c];
      z[M::kWGround] += mj_.work_ground;
      z[M::kWNormal] += mj_.work_normal;
      z[M::kWFriction] += mj_.work_tangential;
      if (!segment_with_passages(t, t1, z0, z, mode)) {
        t = t1;
        stopped = true;
        return false;
      }
      const bool changed = contact_events(t1, mode, z0, z);
      if (!ground_kept(t1, mode, z) || !bearings_kept(t1, mode, z)) {
        t = t1;
        stopped = true;
        return false;
      }
      t = t1;
      quiet = changed ? 0 : quiet + 1;
      if (hand_back && quiet >= kQuietSteps) return true;
    }
    return false;
  }

  const MoreauJean& scheme() const { return mj_; }

 private:
  // A passage through theta = 0 counts once theta is this far on the other side (rounding).
  static constexpr double kPassageBand = 1e-12;

  static MoreauJeanOptions options(double h) {
    MoreauJeanOptions mo;
    mo.h = h;
    return mo;
  }

  // The step as a segment (the cubic Hermite interpolant of its end states), cut at the passages
  // of the rotations through 0 and at a collapse, each interpolated linearly within the step (the
  // scheme is first order) and reported there. False: a block collapsed.
  bool segment_with_passages(double t0, double t1, const State& z0, const State& z1, Mode& mode) {
    State k0{}, k1{};
    const double h = t1 - t0;
    for (int b = 0; b < nb_; ++b)
      for (int k = 0; k < 3; ++k) {
        k0[M::ix(b) + k] = z0[M::iv(b) + k];
        k1[M::ix(b) + k] = z1[M::iv(b) + k];
        k0[M::iv(b) + k] = k1[M::iv(b) + k] = (z1[M::iv(b) + k] - z0[M::iv(b) + k]) / h;
      }
    for (std::size_t w : {M::kWGround, M::kWNormal, M::kWFriction, M::kWSwitch}) k0[w] = k1[w] = (z1[w] - z0[w]) / h;
    seg_.set_hermite(t0, h, 4, z0, z1, k0, k1);
    // The crossings in time order (a few blocks: insertion order).
    std::array<std::pair<double, int>, M::kBlocks + 1> cuts{};
    int n = 0;
    int failed = -1;
    double t_fail = t1;
    for (int b = 0; b < nb_; ++b) {
      const double th0 = z0[M::ix(b) + 2], th1 = z1[M::ix(b) + 2];
      if (mode.side[b] * th1 < -kPassageBand) {
        const double tc = std::clamp(t0 + h * (th0 / (th0 - th1)), t0, t1);
        int j = n++;
        for (; j > 0 && cuts[j - 1].first > tc; --j) cuts[j] = cuts[j - 1];
        cuts[j] = {tc, b};
      }
      const double lim = m_.rotation_limit(b);
      if (std::fabs(th1) >= lim) {
        const double s = th1 > 0 ? 1.0 : -1.0;
        const double tf = std::clamp(t0 + h * (lim - s * th0) / (s * th1 - s * th0), t0, t1);
        if (tf < t_fail || failed < 0) t_fail = tf, failed = b;
      }
    }
    double from = t0;
    // Every piece's completed end is the step's end state: the scheme reaches no state inside a
    // step (a velocity jumps within it), so balances are checked where it does.
    seg_.end_state = &z1;
    for (int j = 0; j < n; ++j) {
      const auto [tc, b] = cuts[j];
      if (failed >= 0 && tc > t_fail) break;
      if (tc > from) obs_.on_segment(m_, seg_, from, tc, mode);
      from = tc;
      // The event carries the step's end states (before: its start): a state interpolated inside
      // a step with an impact would not be one the scheme reached.
      Mode next = mode;
      next.side[b] = std::int8_t(-mode.side[b]);
      emit(tc, z0, z1, mode, next, M::ev_wzero(b), kAssemblyUprightPassage);
      mode = next;
    }
    if (failed >= 0) {
      if (t_fail > from) obs_.on_segment(m_, seg_, from, t_fail, mode);
      seg_.end_state = nullptr;
      emit(t_fail, z0, z1, mode, mode, M::ev_collapse(failed), kAssemblyRotationCollapse, true);
      return false;
    }
    obs_.on_segment(m_, seg_, from, t1, mode);
    seg_.end_state = nullptr;
    return true;
  }

  void emit(double t, const State& z_before, const State& z, const Mode& from, const Mode& to, int index, int kind,
            bool stop = false) {
    Event e{t, z, z_before, from, to, index, kind, stop};
    obs_.on_event(m_, e);
  }

  // The contact ends' states after the step; an event per change (an impact carries the step's
  // velocity jump: the state before is the step's start).
  bool contact_events(double t1, Mode& mode, const State& z0, const State& z) {
    bool changed = false;
    const auto& ends = mj_.ends();
    for (int p = 0; p < 2 * ni_; ++p) {
      const auto& e = ends[std::size_t(p)];
      // An end is closed while it touches (active), whether or not this step needed an impulse.
      PointState s = PointState::Open;
      if (e.active) s = e.slipping ? (e.slip > 0 ? PointState::SlipPos : PointState::SlipNeg) : PointState::Stick;
      const PointState was = mode.point[p];
      Mode next = mode;
      next.point[p] = s;
      next.owner[p] = std::uint8_t(e.owner);
      if (s == was) {
        mode = next;
        continue;
      }
      changed = true;
      int kind = kAssemblyStickStarts;
      if (!is_closed(was))
        kind = kAssemblyContactCloses;
      else if (!is_closed(s))
        kind = kAssemblyContactOpens;
      else if (slip_sign(s) != 0)
        kind = kAssemblySlipStarts;
      // An impact when the end approached faster than one step of free fall.
      const bool impact = kind == kAssemblyContactCloses && e.un_before < -m_.assembly().g * mj_.h();
      if (impact) kind = kAssemblyImpact;
      emit(t1, impact ? z0 : z, z, mode, next,
           kind == kAssemblySlipStarts || kind == kAssemblyStickStarts ? M::ev_tangent(p) : M::ev_normal(p), kind);
      mode = next;
    }
    return changed;
  }

  // Seed 001's 5-DOF restriction: a block standing on the ground that leaves it is reported.
  bool ground_kept(double t1, const Mode& mode, const State& z) {
    if (!m_.assembly().rock_only_on_ground) return true;
    for (int i = 0; i < ni_; ++i)
      if (m_.assembly().interfaces[i].lower < 0 && !is_closed(mode.point[2 * i]) && !is_closed(mode.point[2 * i + 1])) {
        m_.report("block " + std::to_string(m_.assembly().interfaces[i].upper) + " left the ground at t = " +
                  number_text(t1, 6) + " s: outside seed 001's 5-DOF restriction (blocks on the ground only rock)");
        emit(t1, z, z, mode, mode, M::ev_normal(2 * i), kAssemblyOutsideModel, true);
        return false;
      }
    return true;
  }

  // Collapse mode 2: an interface between blocks lost its bearing.
  bool bearings_kept(double t1, const Mode& mode, const State& z) {
    for (int i = 0; i < ni_; ++i)
      if (m_.assembly().interfaces[i].lower >= 0 && m_.overlap_of(z, i) <= m_.assembly().min_bearing) {
        emit(t1, z, z, mode, mode, M::ev_bearing(i), kAssemblyBearingCollapse, true);
        return false;
      }
    return true;
  }

  const M& m_;
  Observer<M>& obs_;
  MoreauJean mj_;
  int nb_, ni_;
  std::vector<double> q_, v_;
  DenseSegment<M::kDim> seg_;
};

}  // namespace blockdyn
