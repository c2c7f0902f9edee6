// SPDX-License-Identifier: Apache-2.0
#pragma once
// pi, and angles reduced to one turn.
#include <cmath>

namespace blockdyn {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2.0 * kPi;

// x reduced to [0, 2 pi) (a phase): -tiny + 2 pi, which rounds to 2 pi, gives 0.
inline double wrap_angle(double x) {
  double r = std::fmod(x, kTwoPi);
  if (r < 0) r += kTwoPi;
  return r >= kTwoPi ? 0.0 : r;
}

}  // namespace blockdyn
