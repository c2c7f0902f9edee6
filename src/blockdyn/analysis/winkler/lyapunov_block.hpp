// SPDX-License-Identifier: Apache-2.0
#pragma once
// The Winkler block in LyapunovEstimator: Euclidean metric on (sqrt(k) (y - 1/2), w, x', y', w')
// (x is left out: the dynamics is invariant under horizontal translation, so an x offset never
// grows; y is scaled by sqrt(k) so that a unit of heave displacement carries the spring energy of
// a unit of heave velocity - at large k the static sink 1/k is tiny and an unscaled y
// perturbation would not be infinitesimal), rescaling
// that keeps contact mode consistent (the pivot abscissa is rescaled with the state), and the
// Poincare section w = 0.
#include "blockdyn/analysis/dynamics/lyapunov.hpp"
#include "blockdyn/model/winkler/winkler_block.hpp"

namespace blockdyn {

class BlockLyapunovAdapter {
 public:
  using Mode = WinklerMode;
  using State = WinklerState;

  explicit BlockLyapunovAdapter(const WinklerBlock& m);

  double distance(const Mode& mr, const State& zr, const Mode& mp, const State& zp) const;
  bool compatible(const Mode& mr, const Mode& mp) const;
  void rescale(const Mode& mr, const State& zr, Mode& mp, State& zp, double s) const;
  void perturb(const Mode& mr, const State& zr, double d, Mode& mp, State& zp) const;
  bool is_section_event(int event_index) const { return event_index == WinklerBlock::kEvWZero; }
  int crossing_sign(const State& z) const { return (z[kVW] > 0) - (z[kVW] < 0); }

 private:
  const WinklerBlock& m_;
  double heave_scale_;
};

// Largest Lyapunov exponent along the orbit of the unforced block from z0.
LyapunovResult block_lyapunov(const WinklerParams& p, const WinklerState& z0, const LyapunovOptions& o);

}  // namespace blockdyn
