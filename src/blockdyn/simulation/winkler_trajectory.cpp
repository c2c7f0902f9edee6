// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/simulation/winkler_trajectory.hpp"

namespace blockdyn {

WinklerTrajectory::WinklerTrajectory(TrajectoryTable& out, double interval, std::optional<UnitScales> s)
    : out_(out), interval_(interval), scales_(s) {}

void WinklerTrajectory::on_start(const WinklerBlock& m, double t, const WinklerMode& mode, const WinklerState& z) {
  std::vector<std::string> names{"t",          "x",
                                 "y",          "w",
                                 "vx",         "vy",
                                 "vw",         "mode",
                                 "side",       "event",
                                 "Rx",         "Ry",
                                 "E_kin_x",    "E_kin_y",
                                 "E_rot",      "E_grav",
                                 "E_springs",  "E_total",
                                 "W_friction", "W_nonpotential",
                                 "W_ground",   "energy_balance"};
  if (scales_)
    for (const char* n : {"t_s", "x_m", "y_m", "vx_m_per_s", "vy_m_per_s", "vw_rad_per_s", "Rx_N", "Ry_N", "E_total_J"})
      names.emplace_back(n);
  cells_.resize(names.size());
  out_.columns(names);
  row(m, t, mode, z, "start");
  clock_.start(t, interval_);
}

void WinklerTrajectory::on_segment(const WinklerBlock& m, const DenseSegment<kStateDim>& seg, double, double t1,
                                   const WinklerMode& mode) {
  clock_.emit(t1, [&](double t) {
    WinklerState z;
    seg.eval(t, z);
    m.complete(mode, z);
    row(m, t, mode, z, "");
  });
}

void WinklerTrajectory::on_event(const WinklerBlock& m, const WinklerEventRecord& e) {
  row(m, e.t, e.to, e.z, to_string(e.kind));
}

void WinklerTrajectory::row(const WinklerBlock& m, double t, const WinklerMode& mode, const WinklerState& z,
                            const char* event) {
  const BlockForces f = m.forces(t, mode, z);
  const Energy e = energy(m.params(), z);
  const double balance = e.total() - z[kWorkFriction] - z[kWorkNonPotential] - z[kWorkGround];
  RowBuffer& c = cells_;
  c.clear();
  for (double v : {t, z[kX], z[kH] + 0.5, z[kW], z[kVX], z[kVY], z[kVW]}) c.number(v);
  c.text(to_string(mode.regime));
  c.number(mode.side);
  c.text(event);
  for (double v : {f.Rx, f.Ry, e.kinetic_x, e.kinetic_y, e.rotation, e.gravity, e.springs, e.total(), z[kWorkFriction],
                   z[kWorkNonPotential], z[kWorkGround], balance})
    c.number(v);
  if (scales_) {
    const UnitScales& s = *scales_;
    for (double v : {t * s.time, z[kX] * s.length, (z[kH] + 0.5) * s.length, z[kVX] * s.velocity, z[kVY] * s.velocity,
                     z[kVW] * s.angular_velocity, f.Rx * s.force, f.Ry * s.force, e.total() * s.energy})
      c.number(v);
  }
  c.write_to(out_);
}

}  // namespace blockdyn
