// SPDX-License-Identifier: Apache-2.0
#pragma once
// Poincare section w = 0 (thesis sec. 5.2.1): the states at the w_zero events, which the
// integrator locates on the dense output to machine precision. Records (y, y', w', x, x') and the
// energy there (for mu = 0 all points must lie on the energy surface E = E0).
#include <vector>

#include "blockdyn/io/table_cell.hpp"
#include "blockdyn/model/winkler/energy.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"

namespace blockdyn {

struct PoincarePoint {
  double t = 0;
  long upright_passages = 0;  // passage count after this crossing
  double w = 0;               // residual (rounding level)
  double h = 0;               // y - 1/2, exact
  double y = 0, vy = 0, vw = 0, x = 0, vx = 0;
  Regime regime = Regime::Slide;  // regime the block continues in
  double energy = 0;              // total energy at the crossing
  // Work done since the start by friction and by the non-potential part of the thesis's
  // foundation torque: energy - E0 - these = integration error.
  double work_friction = 0, work_nonpotential = 0;
};

enum class CrossingDirection { Both, Positive, Negative };  // sign of w' at the crossing

class PoincareCollector : public WinklerSink {
 public:
  explicit PoincareCollector(const WinklerParams& p, CrossingDirection dir = CrossingDirection::Both,
                             double t_min = 0.0);
  void on_event(const WinklerBlock& m, const WinklerEventRecord& e) override;
  const std::vector<PoincarePoint>& points() const { return points_; }

 private:
  WinklerParams p_;
  CrossingDirection dir_;
  double t_min_;
  std::vector<PoincarePoint> points_;
};

CellTable poincare_table(const std::vector<PoincarePoint>& pts);

}  // namespace blockdyn
