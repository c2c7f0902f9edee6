// SPDX-License-Identifier: Apache-2.0
#pragma once
// The Winkler block's trajectory table: one row per output instant (fixed interval, from the
// dense output) plus one row per event, with mode, reactions and energy components; with unit
// scales also the physical columns.
#include <optional>

#include "blockdyn/simulation/output_clock.hpp"
#include "blockdyn/simulation/trajectory_table.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"
#include "blockdyn/units/physical_units.hpp"

namespace blockdyn {

class WinklerTrajectory : public WinklerSink {
 public:
  // interval <= 0: only step ends and events. scales: physical columns appended if given.
  WinklerTrajectory(TrajectoryTable& out, double interval, std::optional<UnitScales> scales = std::nullopt);

  void on_start(const WinklerBlock& m, double t, const WinklerMode& mode, const WinklerState& z) override;
  void on_segment(const WinklerBlock& m, const DenseSegment<kStateDim>& seg, double t0, double t1,
                  const WinklerMode& mode) override;
  void on_event(const WinklerBlock& m, const WinklerEventRecord& e) override;

 private:
  void row(const WinklerBlock& m, double t, const WinklerMode& mode, const WinklerState& z, const char* event);
  TrajectoryTable& out_;
  double interval_;
  std::optional<UnitScales> scales_;
  OutputClock clock_;
  RowBuffer cells_;
};

}  // namespace blockdyn
