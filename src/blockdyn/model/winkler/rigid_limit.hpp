// SPDX-License-Identifier: Apache-2.0
#pragma once
// The rigid block on rigid ground (R-R) check model of the thesis (sec. 2.4): the pivot corner
// stays on the ground (y = B(w)), w >= 0, contact or slide, no impact (the run stops at w = 0).
// It is the k -> infinity limit of the Winkler model's rocking before the first impact.
#include <array>
#include <optional>

#include "blockdyn/integrate/hybrid_model.hpp"
#include "blockdyn/model/common/coulomb.hpp"
#include "blockdyn/model/winkler/region.hpp"
#include "blockdyn/model/winkler/winkler_params.hpp"

namespace blockdyn {

struct RigidLimitMode {
  bool contact = true;
  int friction_sign = 0;  // slide: Rx = friction_sign * mu * Ry
  double anchor = 0.0;    // contact: abscissa of the pivot corner
};

struct RigidLimitReactions {
  double Rx, Ry, aw, ax;
};

class RigidGroundBlock {
 public:
  // State: x, w, x', w' (y follows from w).
  enum : std::size_t { kRX, kRW, kRVX, kRVW, kRDim };
  static constexpr std::size_t kDim = kRDim;
  static constexpr std::size_t kNumEvents = 4;  // w = 0, overturn, friction, lift-off (Ry = 0)
  enum Kind : int { kWZero, kOverturn, kContactToSlide, kSlideToContact, kSlideReversal, kLiftOff };
  using Mode = RigidLimitMode;
  using State = std::array<double, kDim>;

  explicit RigidGroundBlock(const WinklerParams& p) : p_(p) {}

  RigidLimitReactions reactions(const Mode& m, const State& z) const;
  void rhs(double t, const Mode& m, const State& z, State& dz) const;
  void events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const;
  void complete(const Mode& m, State& z) const;
  Transition<Mode> transition(double t, const Mode& m, State& z, int event) const;
  double next_breakpoint(double) const { return INFINITY; }
  std::optional<Transition<Mode>> resolve_chatter(double, const Mode&, const State&) const { return std::nullopt; }
  double step_hint(const Mode&) const { return 1e-2; }
  State abs_tol_scale() const { return {1, 1, 1, 1}; }

  // Released from rest at tilt w0 > 0 with the pivot at x = 0.
  Mode initial_mode(const State& z) const;
  // Ry at rest at tilt w (contact if friction suffices, else slide); used by ic1.
  double rest_reaction(double w) const;

 private:
  Mode stick_or_slip(const State& z, int slip_sign) const;
  WinklerParams p_;
};

}  // namespace blockdyn
