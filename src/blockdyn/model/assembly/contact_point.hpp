// SPDX-License-Identifier: Apache-2.0
#pragma once
// The two contact points of an interface (spec: point contacts at the two ends of the overlap of
// two faces, as distinct-element codes place them). End 0 is the left end, end 1 the right end
// along the lower face. Each end is a corner of one block lying on the other's face: the upper
// block's base corner on the lower top face (owner 0) or, once sliding has carried that corner
// past the lower face's end, the lower block's top corner on the upper base (owner 1). The gap
// of a corner is its distance from the face along the face's outward normal, so its rate is
// exactly the normal relative velocity (no term from the corner moving along the face): the
// spring energy k d^2/2 then has the power of the normal force.
#include <cmath>

#include "blockdyn/model/common/block_kinematics.hpp"

namespace blockdyn {

// Position and velocity of a block (ground: everything zero, infinite faces).
struct BodyPose {
  double x = 0, y = 0, theta = 0, vx = 0, vy = 0, omega = 0;
  BodyRotation q{};
};

inline Vec2 operator-(const Vec2& a, const Vec2& b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator+(const Vec2& a, const Vec2& b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator*(double s, const Vec2& a) { return {s * a.x, s * a.y}; }
inline double dot(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }
inline double cross(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }
inline Vec2 perp(const Vec2& a) { return {-a.y, a.x}; }

// One face of an interface: its centre, unit tangent (the lower face's +x) and outward normal.
struct Face {
  Vec2 c, t, n;
  double half = INFINITY;  // half-length (ground: infinite)
};

// Corner `side` (-1 left, +1 right) of a face.
inline Vec2 face_corner(const Face& f, int side) { return f.c + (side * f.half) * f.t; }

// Velocity of the material point of a body at the ground-frame point P.
inline Vec2 material_velocity(const BodyPose& p, const Vec2& P) {
  return point_velocity(p.vx, p.vy, p.omega, P - Vec2{p.x, p.y});
}

// Coordinate along the lower face of the upper base's corner `side`.
inline double along_lower(const Face& lower, const Face& upper, int side) {
  return dot(face_corner(upper, side) - lower.c, lower.t);
}

// Overlap of the two faces along the lower one (<= 0: the upper block has lost its bearing).
inline double overlap(const Face& lower, const Face& upper) {
  return std::fmin(along_lower(lower, upper, +1), lower.half) - std::fmax(along_lower(lower, upper, -1), -lower.half);
}

// Where the upper base's centre lies along the lower face: its change is the relative sliding of
// the interface (first order in the slip, second order in a relative rocking).
inline double base_position(const Face& lower, const Face& upper) { return dot(upper.c - lower.c, lower.t); }

// >= 0 while `owner` is the right owner of end `end` (0 left, 1 right); changes sign where the
// upper corner passes the lower face's corner.
inline double owner_margin(const Face& lower, const Face& upper, int end, int owner) {
  if (!std::isfinite(lower.half)) return 1.0;
  const double d = end == 0 ? along_lower(lower, upper, -1) + lower.half : lower.half - along_lower(lower, upper, +1);
  return owner == 0 ? d : -d;
}

// The gap of an end alone (no velocities): enough for an open point clear of its face.
inline double contact_gap(const Face& lower, const Face& upper, int end, int owner) {
  const int side = end == 0 ? -1 : +1;
  return owner == 0 ? dot(face_corner(upper, side) - lower.c, lower.n)
                    : dot(face_corner(lower, side) - upper.c, upper.n);
}

// The contact point of an end: the corner P of block A on the face of block B.
struct FaceContact {
  Vec2 P, n, t;
  double gap = 0;        // (P - face centre) . n; < 0 is interpenetration
  double gap_rate = 0;   // exactly d(gap)/dt
  double slip_rate = 0;  // tangential relative velocity of A's material point against B's
  Vec2 v_rel;
  bool corner_of_upper = true;
};

inline FaceContact contact_point(const BodyPose& lower_pose, const Face& lower, const BodyPose& upper_pose,
                                 const Face& upper, int end, int owner) {
  const int side = end == 0 ? -1 : +1;
  FaceContact c;
  c.corner_of_upper = owner == 0;
  const Face& face = owner == 0 ? lower : upper;
  c.P = owner == 0 ? face_corner(upper, side) : face_corner(lower, side);
  // The tangent is the lower face's +x for both owners, so slip signs keep their meaning.
  c.n = face.n;
  c.t = owner == 0 ? face.t : upper.t;
  const Vec2 vA = material_velocity(owner == 0 ? upper_pose : lower_pose, c.P);
  const Vec2 vB = material_velocity(owner == 0 ? lower_pose : upper_pose, c.P);
  c.v_rel = owner == 0 ? vA - vB : vB - vA;  // upper relative to lower, in both cases
  c.gap = dot(c.P - face.c, c.n);
  c.gap_rate = owner == 0 ? dot(c.v_rel, c.n) : -dot(c.v_rel, c.n);
  c.slip_rate = dot(c.v_rel, c.t);
  return c;
}

}  // namespace blockdyn
