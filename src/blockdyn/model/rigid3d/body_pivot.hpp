// SPDX-License-Identifier: Apache-2.0
#pragma once
// The rigid3d body held at a ground contact (docs/3d.md): rotating about one base point that
// sticks (a box's corner: a spherical joint), or about a fixed horizontal line through two base
// points that stick (an edge, or a cylinder's rim point with its tangent). The accelerations
// follow from Newton-Euler about the pivot in closed form, and the reaction from the centroid's
// acceleration; a line contact also carries a moment about the pivot, which its two end points
// share (split_line_reaction). All vectors in the ground's frame (world axes) unless named _body.
#include "blockdyn/model/rigid3d/quaternion.hpp"

namespace blockdyn {

struct PivotMotion {
  Vec3 domega{};  // angular acceleration
  Vec3 accel{};   // the centroid's acceleration
  Vec3 force{};   // the ground's reaction on the body (N)
  Vec3 moment{};  // the reaction's moment about the pivot (N m): zero at a point contact
};

// The body's principal inertias `inertia` (about G, body frame), its mass, orientation r, the
// vector s_body from the pivot to G (body frame), the angular velocity omega and the specific
// force f on G (m/s^2: gravity and the ground's acceleration reversed).
PivotMotion point_pivot_motion(const Vec3& inertia, double mass, const Mat3& r, const Vec3& s_body, const Vec3& omega,
                               const Vec3& f);
// The same about the fixed line through the pivot along the unit `axis` (omega parallel to it).
PivotMotion line_pivot_motion(const Vec3& inertia, double mass, const Mat3& r, const Vec3& s_body, const Vec3& axis,
                              const Vec3& omega, const Vec3& f);

// The torque-free angular acceleration of the body in flight (Euler's equations).
Vec3 free_angular_acceleration(const Vec3& inertia, const Mat3& r, const Vec3& omega);

// The inertia tensor about the point at -s_body from G (body frame; parallel axes).
Mat3 inertia_about(const Vec3& inertia, double mass, const Vec3& s_body);
// The angular momentum about a ground point at `arm` = G - point (world), of the body moving at
// velocity v and angular velocity omega.
Vec3 angular_momentum_about(const Vec3& inertia, double mass, const Mat3& r, const Vec3& arm, const Vec3& v,
                            const Vec3& omega);

// The reaction of a line contact shared by its two end points at pivot +- half_length * axis:
// the total force and the moment about the pivot (perpendicular to the axis) fix everything but
// the split of the force along the (horizontal) axis: the one leaving the most friction (mu) to
// spare at the worse end.
struct LineLoads {
  Vec3 plus, minus;  // at pivot + half_length axis, pivot - half_length axis
};
LineLoads split_line_reaction(const Vec3& force, const Vec3& moment, const Vec3& axis, double half_length, double mu);

Mat3 solve_matrix(const Mat3& a);  // the inverse of a 3x3 matrix (Cramer)
inline Vec3 scaled(const Vec3& v, double s) { return {v[0] * s, v[1] * s, v[2] * s}; }
inline Vec3 plus(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

}  // namespace blockdyn
