// SPDX-License-Identifier: Apache-2.0
#pragma once
// sin and cos of an angle of at most a quarter turn, the range of a block's tilt (the Winkler
// block stops at |w| = atan(r) < pi/2), inlined: the right-hand side needs both at every stage,
// and libm's general sincos (a call, range checks, table lookups) was a tenth of a response
// map's time. Within one ulp of libm (tests/model/winkler/test_geometry.cpp); timings in docs/performance.md.
//
// |x| < 2^-27: sin x = x, cos x = 1 (the next terms are below half an ulp).
// |x| < 1/8: the Taylor series to x^9 and x^10 (first omitted terms below 0.1 ulp).
// |x| <= pi/4: the series to x^17 and x^18 (below 0.3 ulp), in Estrin's scheme (short chains).
// pi/4 < |x| <= pi/2 + 1/4: the complement y = pi/2 - |x| (exact by Sterbenz, plus the low part
// of pi/2), sin |x| = cos y, cos x = sin y. Anything else (and NaN) goes to libm.
#include <cmath>

namespace blockdyn {

namespace quarter_turn_detail {

// sin x and cos x for |x| <= pi/4 (a little more is harmless: the series error grows as x^19).
inline void series(double x, double& s, double& c) {
  constexpr double s1 = -1.0 / 6, s2 = 1.0 / 120, s3 = -1.0 / 5040, s4 = 1.0 / 362880, s5 = -1.0 / 39916800,
                   s6 = 1.0 / 6227020800, s7 = -1.0 / 1307674368000, s8 = 1.0 / 355687428096000;
  constexpr double c1 = -0.5, c2 = 1.0 / 24, c3 = -1.0 / 720, c4 = 1.0 / 40320, c5 = -1.0 / 3628800,
                   c6 = 1.0 / 479001600, c7 = -1.0 / 87178291200, c8 = 1.0 / 20922789888000,
                   c9 = -1.0 / 6402373705728000;
  const double z = x * x, z2 = z * z, z4 = z2 * z2;
  const double ps = (s1 + z * s2) + z2 * (s3 + z * s4) + z4 * ((s5 + z * s6) + z2 * (s7 + z * s8));
  const double pc = (c2 + z * c3) + z2 * (c4 + z * c5) + z4 * ((c6 + z * c7) + z2 * (c8 + z * c9));
  s = x + x * z * ps;
  c = 1.0 + z * (c1 + z * pc);  // the small terms summed first: within 1 ulp
}

inline constexpr double kQuarterTurnHi = 1.5707963267948966;     // pi/2 rounded to double
inline constexpr double kQuarterTurnLo = 6.123233995736766e-17;  // pi/2 - kQuarterTurnHi
inline constexpr double kEighthTurn = 0.78539816339744831;       // pi/4

}  // namespace quarter_turn_detail

inline void sincos_quarter_turn(double x, double& s, double& c) {
  using namespace quarter_turn_detail;
  const double a = std::fabs(x);
  if (a < 0x1p-27) {
    s = x;
    c = 1.0;
    return;
  }
  if (a < 0.125) {
    const double z = x * x, z2 = z * z;
    const double ps = (-1.0 / 6 + z * (1.0 / 120)) + z2 * (-1.0 / 5040 + z * (1.0 / 362880));
    const double pc = (1.0 / 24 + z * (-1.0 / 720)) + z2 * (1.0 / 40320 + z * (-1.0 / 3628800));
    s = x + x * z * ps;
    c = 1.0 + z * (-0.5 + z * pc);
    return;
  }
  if (a <= kEighthTurn) {
    series(x, s, c);
    return;
  }
  if (a <= kQuarterTurnHi + 0.25) {
    const double y = (kQuarterTurnHi - a) + kQuarterTurnLo;
    double sy, cy;
    series(y, sy, cy);
    s = std::copysign(cy, x);
    c = sy;
    return;
  }
  ::sincos(x, &s, &c);
}

}  // namespace blockdyn
