// SPDX-License-Identifier: Apache-2.0
#pragma once
// The 3D body of the rigid3d family (docs/3d.md): a box (width b along e1, depth d along e2,
// height h along e3) or a solid circular cylinder (radius a, height h), its centre of mass at the
// centroid; its principal inertias, the base boundary that touches the ground (the box's base
// corners, the cylinder's rim), its lowest point in closed form, and the ground acceleration at
// which it leaves rest in each direction.
#include <string>

#include "blockdyn/model/rigid3d/quaternion.hpp"

namespace blockdyn {

enum class BodyShape3d { Box, Cylinder };

struct Body3d {
  BodyShape3d shape = BodyShape3d::Box;
  double width = 0, depth = 0, height = 0;  // box: b, d, h (m)
  double radius = 0;                        // cylinder: a (m); its height is `height`
  double mass = 1;                          // kg
  double g = 9.81;                          // m/s^2

  // Principal moments of inertia about the centroid (kg m^2), along e1, e2, e3.
  Vec3 inertia() const;
  double half_height() const { return 0.5 * height; }  // c: the centroid's height above the base
};

// Throws std::invalid_argument naming the field, its value and its range.
void validate(const Body3d& b);

// A box b x d x h (m) or a cylinder of radius a and height h, of the given mass (kg).
inline Body3d box_body(double b, double d, double h, double mass) {
  Body3d x;
  x.width = b;
  x.depth = d;
  x.height = h;
  x.mass = mass;
  return x;
}
inline Body3d cylinder_body(double a, double h, double mass) {
  Body3d x;
  x.shape = BodyShape3d::Cylinder;
  x.radius = a;
  x.height = h;
  x.mass = mass;
  return x;
}

// The base point lowest in the world with the body at orientation r (body frame), and its height
// below the centroid (>= 0). Box: a corner (the lowest of four); cylinder: the rim point in the
// direction of steepest descent of the base plane (at zero tilt, the rim point of azimuth 0).
struct LowestPoint {
  Vec3 body;
  double depth;  // centroid height minus the point's height
};
LowestPoint lowest_point(const Body3d& b, const Mat3& r);

// The ratio A / (g + a_V) of a horizontal ground acceleration A in the direction phi (rad, from
// the body's e1 towards e2, yaw 0) above which the body resting on its base rocks: box
// min(b / (h |cos phi|), d / (h |sin phi|)), cylinder 2 a / h (docs/3d.md).
double rest_threshold(const Body3d& b, double phi);

}  // namespace blockdyn
