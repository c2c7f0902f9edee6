// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/io/trajectory_csv.hpp"

#include <cmath>
#include <cstdio>

namespace blockdyn {

TrajectoryCsvSink::TrajectoryCsvSink(std::ostream& out, double interval, std::optional<UnitScales> s)
    : out_(out), interval_(interval), scales_(s) {}

void TrajectoryCsvSink::on_start(const WinklerBlock& m, double t, const BlockMode& mode,
                                 const BlockStateVec& z) {
  out_ << "t,x,y,w,vx,vy,vw,mode,side,event,Rx,Ry,E_kin_x,E_kin_y,E_rot,E_grav,E_springs,E_total,"
          "W_friction,W_nonpotential,W_ground,energy_balance";
  if (scales_) out_ << ",t_s,x_m,y_m,vx_m_per_s,vy_m_per_s,vw_rad_per_s,Rx_N,Ry_N,E_total_J";
  out_ << '\n';
  row(m, t, mode, z, "start");
  clock_.start(t, interval_);
}

void TrajectoryCsvSink::on_segment(const WinklerBlock& m, const DenseSegment<kStateDim>& seg,
                                   double t0, double t1, const BlockMode& mode) {
  auto write = [&](double t) {
    BlockStateVec z;
    seg.eval(t, z);
    m.complete(mode, z);
    row(m, t, mode, z, "");
  };
  clock_.emit(t1, write);
}

void TrajectoryCsvSink::on_event(const WinklerBlock& m, const EventRecord& e) {
  row(m, e.t, e.to, e.z, to_string(e.kind));
}

void TrajectoryCsvSink::row(const WinklerBlock& m, double t, const BlockMode& mode,
                            const BlockStateVec& z, const char* event) {
  const BlockForces f = m.forces(t, mode, z);
  const Energy e = energy(m.params(), z);
  const double balance = e.total() - z[kWorkFriction] - z[kWorkNonPotential] - z[kWorkGround];
  char buf[1024];
  int n = std::snprintf(buf, sizeof buf,
                        "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%s,%d,%s,%.17g,%.17g,%.17g,%.17g,"
                        "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g",
                        t, z[kX], z[kH] + 0.5, z[kW], z[kVX], z[kVY], z[kVW], to_string(mode.regime),
                        mode.side, event, f.Rx, f.Ry, e.kinetic_x, e.kinetic_y, e.rotation, e.gravity,
                        e.springs, e.total(), z[kWorkFriction], z[kWorkNonPotential], z[kWorkGround],
                        balance);
  out_.write(buf, n);
  if (scales_) {
    const UnitScales& s = *scales_;
    n = std::snprintf(buf, sizeof buf, ",%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g",
                      t * s.time, z[kX] * s.length, (z[kH] + 0.5) * s.length, z[kVX] * s.velocity,
                      z[kVY] * s.velocity, z[kVW] * s.angular_velocity, f.Rx * s.force, f.Ry * s.force,
                      e.total() * s.energy);
    out_.write(buf, n);
  }
  out_ << '\n';
  ++rows_;
}

}  // namespace blockdyn
