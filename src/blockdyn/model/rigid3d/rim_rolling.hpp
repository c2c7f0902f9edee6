// SPDX-License-Identifier: Apache-2.0
#pragma once
// A cylinder rolling on its base rim without slipping (docs/3d.md): the material point of the rim
// touching the ground has no velocity, v_G = -omega x r (r = P - G), while the contact point P
// travels along the rim (the rim's lowest point, in closed form from the orientation). The
// constraint at acceleration level, differentiated with the contact point moving,
//   a_G + alpha x r + omega x (omega x r) + omega x (R p') = 0   (p' the contact point's rate
//   along the rim, body frame),
// with Newton-Euler m a_G = m f + F and I alpha = r x F - omega x I omega gives the reaction F
// from a 3 x 3 symmetric positive definite system. A nonholonomic constraint: the position on
// the ground is free, only the velocities are tied. Vectors in the ground's frame unless _body.
//
// Slipping on the rim: the contact's material point moves along the ground, resisted by the
// friction -mu_k N d against its slip d; only the vertical row of the constraint holds (the rim's
// lowest point stays on the ground), which gives the normal load N from one equation. Its
// coefficient (in units of 1/m) is the slip's consistency: where it is not positive no load is
// consistent (Painleve).
#include <cmath>

#include "blockdyn/model/rigid3d/quaternion.hpp"

namespace blockdyn {

struct RimRolling {
  Vec3 contact_body{};  // the rim's lowest point P (body frame)
  Vec3 arm{};           // r = P - G (world)
  Vec3 force{};         // the ground's reaction F (N)
  Vec3 accel{};         // the centroid's acceleration
  Vec3 domega{};        // the angular acceleration
};

struct RimSlip {
  Vec3 contact_body{};     // the rim's lowest point P (body frame)
  Vec3 arm{};              // r = P - G (world)
  Vec3 force{};            // the ground's reaction N (Z - mu_k d) (N)
  Vec3 accel{};            // the centroid's acceleration
  Vec3 domega{};           // the angular acceleration
  Vec3 slip{};             // the contact's material point's horizontal velocity
  Vec3 slip_rate{};        // the rate of the contact's slip (horizontal)
  double consistency = 1;  // m times the normal acceleration per unit load: positive where consistent
};

// The rim's lowest point (body frame) of a cylinder of radius a whose base is c below G, at
// orientation r: opposite the world's up seen in the body's base plane; its rate along the rim
// (body frame) for the body turning at omega (world). The base must be tilted (not flat).
Vec3 rim_lowest_point(double a, double c, const Mat3& r);
Vec3 rim_point_rate(double a, const Mat3& r, const Vec3& omega);

// The rolling motion of the body (principal inertias `inertia` about G, body frame; mass) at
// orientation r turning at omega under the specific force f (m/s^2).
RimRolling rim_rolling_motion(const Vec3& inertia, double mass, double a, double c, const Mat3& r, const Vec3& omega,
                              const Vec3& f);
// The same slipping on its rim at velocity v, the friction along -d (unit, horizontal). With the
// base this close to flat (sin(tilt) below kRimFlat) its lowest point is the reference rim point
// `side` (body frame: where it touched last) and does not travel.
inline constexpr double kRimFlat = 1e-9;
// The rim point a rim contact bears on (body frame): its lowest point, or the reference `side`
// where the base is that close to flat or the lowest point lies on the far half from it (just
// after the base landed about `side`, its tilt still below the landing's towards the other side).
inline bool rim_on_side(const Mat3& r, const Vec3& side) {
  const double ux = r[2][0], uy = r[2][1];
  return std::hypot(ux, uy) < kRimFlat || ux * side[0] + uy * side[1] > 0;
}
inline Vec3 rim_contact_point(double a, double c, const Mat3& r, const Vec3& side) {
  return rim_on_side(r, side) ? side : rim_lowest_point(a, c, r);
}
RimSlip rim_slip_motion(const Vec3& inertia, double mass, double a, double c, const Mat3& r, const Vec3& v,
                        const Vec3& omega, const Vec3& f, double mu_k, const Vec3& d, const Vec3& side);

}  // namespace blockdyn
