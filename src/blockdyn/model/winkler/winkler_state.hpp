// SPDX-License-Identifier: Apache-2.0
#pragma once
// Mutable state of a planar block and the mode it moves in. Kept apart from WinklerParams.
#include <array>
#include <cstddef>
#include <cstdint>

namespace blockdyn {

// Layout of the integrated state vector. The vertical coordinate is stored as h = y - 1/2
// (see geometry/region.hpp). The last three entries accumulate work done by friction, by the
// non-potential part of the thesis's foundation torque, and by the ground pseudo-forces.
enum StateIndex : std::size_t { kX, kH, kW, kVX, kVY, kVW, kWorkFriction, kWorkNonPotential, kWorkGround, kStateDim };

using WinklerState = std::array<double, kStateDim>;

// The physical state a user sees (y, not h).
struct BlockState {
  double x = 0, y = 0.5, w = 0, vx = 0, vy = 0, vw = 0;
};

inline WinklerState to_vec(const BlockState& s) { return {s.x, s.y - 0.5, s.w, s.vx, s.vy, s.vw, 0.0, 0.0, 0.0}; }
inline BlockState to_state(const WinklerState& z) { return {z[kX], z[kH] + 0.5, z[kW], z[kVX], z[kVY], z[kVW]}; }

enum class Regime : std::uint8_t { Contact, Slide, Flight };

inline const char* to_string(Regime m) {
  switch (m) {
    case Regime::Contact:
      return "contact";
    case Regime::Slide:
      return "slide";
    case Regime::Flight:
      return "flight";
  }
  return "?";
}

struct WinklerMode {
  Regime regime = Regime::Slide;
  int side = 1;           // lowest corner: +1 lower-left (w > 0), -1 lower-right (w < 0)
  int friction_sign = 0;  // slide: Rx = friction_sign * mu * Ry (opposes the corner's velocity)
  double anchor = 0.0;    // contact: abscissa of the pivot corner
};

}  // namespace blockdyn
