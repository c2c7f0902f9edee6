// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/winkler/lyapunov_block.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace blockdyn {

namespace {
constexpr StateIndex kMetric[] = {kH, kW, kVX, kVY, kVW};
}

BlockLyapunovAdapter::BlockLyapunovAdapter(const WinklerBlock& m)
    : m_(m), heave_scale_(std::sqrt(std::max(1.0, m.params().k))) {}

double BlockLyapunovAdapter::distance(const Mode&, const State& zr, const Mode&, const State& zp) const {
  double s = 0;
  for (StateIndex i : kMetric) {
    const double d = (zp[i] - zr[i]) * (i == kH ? heave_scale_ : 1.0);
    s += d * d;
  }
  return std::sqrt(s);
}

bool BlockLyapunovAdapter::compatible(const Mode& mr, const Mode& mp) const {
  if (mr.regime != mp.regime || mr.side != mp.side) return false;
  return mr.regime != Regime::Slide || mr.friction_sign == mp.friction_sign;
}

void BlockLyapunovAdapter::rescale(const Mode& mr, const State& zr, Mode& mp, State& zp, double s) const {
  for (std::size_t i = 0; i < 6; ++i) zp[i] = zr[i] + s * (zp[i] - zr[i]);
  if (mp.regime == Regime::Contact) mp.anchor = mr.anchor + s * (mp.anchor - mr.anchor);
  m_.complete(mp, zp);
}

void BlockLyapunovAdapter::perturb(const Mode& mr, const State& zr, double d, Mode& mp, State& zp) const {
  // A fixed generic direction with equal weights; the w component points into the current
  // side so that the copy starts in the reference's mode.
  mp = mr;
  zp = zr;
  const double e = d / std::sqrt(5.0);
  zp[kH] += e / heave_scale_;
  zp[kW] += mr.side * e;
  zp[kVX] += e;
  zp[kVY] += e;
  zp[kVW] += e;
  m_.complete(mp, zp);
}

LyapunovResult block_lyapunov(const WinklerParams& p, const WinklerState& z0, const LyapunovOptions& o) {
  validate(p);
  validate(o);
  const WinklerBlock model(p);
  WinklerState z = z0;
  z[kWorkFriction] = z[kWorkNonPotential] = z[kWorkGround] = 0.0;
  if (auto why = model.validity_problem(z)) throw std::invalid_argument("initial state: " + *why);
  const WinklerMode m0 = model.initial_mode(o.t_start, z);
  const BlockLyapunovAdapter ad(model);
  const LyapunovEstimator<WinklerBlock, BlockLyapunovAdapter> est(model, ad, o);
  return est.run(m0, z);
}

}  // namespace blockdyn
