// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/winkler/poincare.hpp"

namespace blockdyn {

PoincareCollector::PoincareCollector(const WinklerParams& p, CrossingDirection dir, double t_min)
    : p_(p), dir_(dir), t_min_(t_min) {
  points_.reserve(1024);
}

void PoincareCollector::on_event(const WinklerBlock&, const WinklerEventRecord& e) {
  if (e.kind != WinklerEventKind::WZero || e.t < t_min_) return;
  const double vw = e.z[kVW];
  if ((dir_ == CrossingDirection::Positive && !(vw > 0)) || (dir_ == CrossingDirection::Negative && !(vw < 0))) return;
  PoincarePoint q;
  q.t = e.t;
  q.upright_passages = e.upright_passages;
  q.w = e.z[kW];
  q.h = e.z[kH];
  q.y = e.z[kH] + 0.5;
  q.vy = e.z[kVY];
  q.vw = vw;
  q.x = e.z[kX];
  q.vx = e.z[kVX];
  q.regime = e.to.regime;
  q.energy = energy(p_, e.z).total();
  q.work_friction = e.z[kWorkFriction];
  q.work_nonpotential = e.z[kWorkNonPotential];
  points_.push_back(q);
}

CellTable poincare_table(const std::vector<PoincarePoint>& pts) {
  CellTable t;
  t.columns = {
      "t", "ihor", "w", "h", "y", "vy", "vw", "x", "vx", "regime", "energy", "work_friction", "work_nonpotential"};
  for (const auto& q : pts)
    t.rows.push_back({q.t, q.upright_passages, q.w, q.h, q.y, q.vy, q.vw, q.x, q.vx, to_string(q.regime), q.energy,
                      q.work_friction, q.work_nonpotential});
  return t;
}

}  // namespace blockdyn
