// SPDX-License-Identifier: Apache-2.0
#pragma once
// The observer that writes a model family's trajectory table: the start row, one row per output
// instant (fixed interval, from the dense output) and whatever rows the family writes at events.
// The family (Derived) gives columns(m), started(m, mode, z) and fill(cells, m, t, mode, z, event).
#include <string>
#include <vector>

#include "blockdyn/simulation/observer.hpp"
#include "blockdyn/simulation/output_clock.hpp"
#include "blockdyn/simulation/trajectory_table.hpp"

namespace blockdyn {

template <class Model, class Derived>
class TrajectoryRows : public Observer<Model> {
 public:
  BLOCKDYN_OBSERVER_TYPES(Model);

  TrajectoryRows(TrajectoryTable& out, double interval) : out_(out), interval_(interval) {}

  void on_start(const Model& m, double t, const Mode& md, const State& z) override {
    const std::vector<std::string> names = derived().columns(m);
    cells_.resize(names.size());
    out_.columns(names);
    derived().started(m, md, z);
    row(m, t, md, z, "start");
    clock_.start(t, interval_);
  }
  bool on_segment(const Model& m, const Segment& seg, double, double t1, const Mode& md) override {
    clock_.emit(t1, [&](double t) {
      State z;
      seg.eval(t, z);
      m.complete(md, z);
      row(m, t, md, z, "");
    });
    return true;
  }

 protected:
  void row(const Model& m, double t, const Mode& md, const State& z, const char* event) {
    cells_.clear();
    derived().fill(cells_, m, t, md, z, event);
    cells_.write_to(out_);
  }

 private:
  Derived& derived() { return static_cast<Derived&>(*this); }
  TrajectoryTable& out_;
  double interval_;
  OutputClock clock_;
  RowBuffer cells_;
};

}  // namespace blockdyn
