// SPDX-License-Identifier: Apache-2.0
#pragma once
// Observers of a simulation, shared by every model family: they receive the start, each accepted
// piece of trajectory (dense output), each event (with the state before and after any jump) and
// the end. A FanOut passes one run to several observers (recorder, energy balance, CSV, ...),
// so a run is integrated once whatever is recorded. Observers never change the motion; they
// can only ask the run to stop (return false).
#include <array>
#include <cstddef>

#include "blockdyn/integrate/hybrid_model.hpp"

// The types of Observer<Model> in a class template derived from it (names of a dependent base
// are not found without these declarations).
#define BLOCKDYN_OBSERVER_TYPES(ModelType)               \
  using typename ::blockdyn::Observer<ModelType>::Mode;  \
  using typename ::blockdyn::Observer<ModelType>::State; \
  using typename ::blockdyn::Observer<ModelType>::Event; \
  using typename ::blockdyn::Observer<ModelType>::Segment

namespace blockdyn {

template <class Model>
class Observer {
 public:
  using Mode = typename Model::Mode;
  using State = Vec<Model::kDim>;
  using Event = EventInfo<Mode, Model::kDim>;
  using Segment = DenseSegment<Model::kDim>;

  virtual ~Observer() = default;
  virtual void on_start(const Model&, double /*t*/, const Mode&, const State&) {}
  virtual bool on_segment(const Model&, const Segment&, double /*t0*/, double /*t1*/, const Mode&) { return true; }
  virtual bool on_event(const Model&, const Event&) { return true; }
  virtual void on_finish(const Model&, double /*t*/, const Mode&, const State&) {}
  // Whether on_segment evaluates the dense output inside every step; if no observer does, a step
  // with no event nearby skips the dense output's extra stages (DOP853): the segment is then the
  // cubic Hermite interpolant of the step ends (exact at both), and an observer that needs the
  // full accuracy inside a particular step calls its ensure_full().
  virtual bool needs_dense() const { return true; }
};

// Several observers as one; the run stops as soon as one of them asks to.
template <class Model>
class FanOut final : public Observer<Model> {
 public:
  BLOCKDYN_OBSERVER_TYPES(Model);

  FanOut& add(Observer<Model>* o) {
    if (o && n_ < list_.size()) list_[n_++] = o;
    return *this;
  }
  void on_start(const Model& m, double t, const Mode& md, const State& z) override {
    for (std::size_t i = 0; i < n_; ++i) list_[i]->on_start(m, t, md, z);
  }
  bool on_segment(const Model& m, const Segment& s, double t0, double t1, const Mode& md) override {
    bool go = true;
    for (std::size_t i = 0; i < n_; ++i) go &= list_[i]->on_segment(m, s, t0, t1, md);
    return go;
  }
  bool on_event(const Model& m, const Event& e) override {
    bool go = true;
    for (std::size_t i = 0; i < n_; ++i) go &= list_[i]->on_event(m, e);
    return go;
  }
  void on_finish(const Model& m, double t, const Mode& md, const State& z) override {
    for (std::size_t i = 0; i < n_; ++i) list_[i]->on_finish(m, t, md, z);
  }
  bool needs_dense() const override {
    for (std::size_t i = 0; i < n_; ++i)
      if (list_[i]->needs_dense()) return true;
    return false;
  }

 private:
  std::array<Observer<Model>*, 8> list_{};
  std::size_t n_ = 0;
};

// The closed energy balance of any model that provides energy(mode, z) (mechanical energy) and
// work(z) (the accumulated works of the non-conservative forces and the impact losses, carried in
// the state): E - E0 - W stays at the integration error. Checked at every step end and on both
// sides of every event.
template <class Model>
class EnergyBalance final : public Observer<Model> {
 public:
  BLOCKDYN_OBSERVER_TYPES(Model);

  double initial() const { return e0_; }
  double max_abs_error() const { return max_err_; }
  double max_abs_change() const { return max_change_; }

  void on_start(const Model& m, double, const Mode& md, const State& z) override {
    e0_ = m.energy(md, z) - m.work(z);
    max_err_ = max_change_ = 0.0;
    e0_energy_ = m.energy(md, z);
  }
  bool on_segment(const Model& m, const Segment& s, double, double t1, const Mode& md) override {
    State z;
    s.completed_end(t1, z, [&](State& y) { m.complete(md, y); });
    track(m, md, z);
    return true;
  }
  bool on_event(const Model& m, const Event& e) override {
    track(m, e.from, e.z_before);
    track(m, e.to, e.z);
    return true;
  }
  bool needs_dense() const override { return false; }  // step ends only

 private:
  void track(const Model& m, const Mode& md, const State& z) {
    const double e = m.energy(md, z);
    max_change_ = std::fmax(max_change_, std::fabs(e - e0_energy_));
    max_err_ = std::fmax(max_err_, std::fabs(e - m.work(z) - e0_));
  }
  double e0_ = 0, e0_energy_ = 0, max_err_ = 0, max_change_ = 0;
};

}  // namespace blockdyn
