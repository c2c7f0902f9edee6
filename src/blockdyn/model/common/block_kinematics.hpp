// SPDX-License-Identifier: Apache-2.0
#pragma once
// Planar rigid-body kinematics of a rectangle: positions, velocities and accelerations of points
// fixed in the body, in closed form (one sincos per state).
#include <cmath>

namespace blockdyn {

struct Vec2 {
  double x = 0, y = 0;
};

// A point fixed in the body at body coordinates (px, py), for a body turned by theta:
// its offset r from the centre of mass, in the ground frame.
struct BodyRotation {
  double c = 1, s = 0;
  static BodyRotation of(double theta) { return {std::cos(theta), std::sin(theta)}; }
  Vec2 offset(double px, double py) const { return {c * px - s * py, s * px + c * py}; }
};

// Velocity of the point at offset r of a body moving with (vx, vy, omega).
inline Vec2 point_velocity(double vx, double vy, double omega, const Vec2& r) {
  return {vx - omega * r.y, vy + omega * r.x};
}

// Acceleration of the point at offset r for body accelerations (ax, ay, alpha) and rate omega.
inline Vec2 point_acceleration(double ax, double ay, double alpha, double omega, const Vec2& r) {
  return {ax - alpha * r.y - omega * omega * r.x, ay + alpha * r.x - omega * omega * r.y};
}

// Base corners of a block of half-width bh and half-height hh: side +1 is the left corner A
// (body (-bh, -hh)), the pivot while theta > 0; side -1 the right corner B (body (bh, -hh)).
inline Vec2 base_corner(const BodyRotation& q, double bh, double hh, int side) { return q.offset(-side * bh, -hh); }

}  // namespace blockdyn
