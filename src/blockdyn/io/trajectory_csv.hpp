// SPDX-License-Identifier: Apache-2.0
#pragma once
// Streams a trajectory to CSV: one row per output instant (fixed interval, from the dense
// output) plus one row per event, with mode, reactions and energy components.
#include <ostream>
#include <optional>

#include "blockdyn/io/output_clock.hpp"
#include "blockdyn/simulation/simulate.hpp"
#include "blockdyn/units/physical_units.hpp"

namespace blockdyn {

class TrajectoryCsvSink : public SimulationSink {
 public:
  // interval <= 0: only step ends and events. scales: physical columns appended if given.
  TrajectoryCsvSink(std::ostream& out, double interval, std::optional<UnitScales> scales = std::nullopt);

  void on_start(const WinklerBlock& m, double t, const BlockMode& mode, const BlockStateVec& z) override;
  void on_segment(const WinklerBlock& m, const DenseSegment<kStateDim>& seg, double t0, double t1,
                  const BlockMode& mode) override;
  void on_event(const WinklerBlock& m, const EventRecord& e) override;
  long rows() const { return rows_; }

 private:
  void row(const WinklerBlock& m, double t, const BlockMode& mode, const BlockStateVec& z, const char* event);
  std::ostream& out_;
  double interval_;
  std::optional<UnitScales> scales_;
  OutputClock clock_;
  long rows_ = 0;
};

}  // namespace blockdyn
