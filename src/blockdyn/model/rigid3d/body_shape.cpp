// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/rigid3d/body_shape.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "blockdyn/base/number_text.hpp"

namespace blockdyn {

namespace {

void require_length(const char* field, double v) {
  if (!(v > 0 && v <= 1e3))
    throw std::invalid_argument(std::string(field) + " = " + number_text(v) + " is out of range: (0, 1000] m");
}

}  // namespace

Vec3 Body3d::inertia() const {
  if (shape == BodyShape3d::Box)
    return {mass * (depth * depth + height * height) / 12, mass * (width * width + height * height) / 12,
            mass * (width * width + depth * depth) / 12};
  const double c = half_height(), a2 = radius * radius;
  const double i1 = mass * (a2 / 4 + c * c / 3);
  return {i1, i1, mass * a2 / 2};
}

void validate(const Body3d& b) {
  if (b.shape == BodyShape3d::Box) {
    require_length("width", b.width);
    require_length("depth", b.depth);
  } else {
    require_length("radius", b.radius);
  }
  require_length("height", b.height);
  if (!(b.mass > 0 && b.mass <= 1e12))
    throw std::invalid_argument("mass = " + number_text(b.mass) + " is out of range: (0, 1e12] kg");
  if (!(b.g > 0 && b.g <= 1e3))
    throw std::invalid_argument("g = " + number_text(b.g) + " is out of range: (0, 1000] m/s^2");
}

LowestPoint lowest_point(const Body3d& b, const Mat3& r) {
  // A body point p sits at height z_G + (R p)_z = z_G + r[2] . p.
  const Vec3& up = r[2];
  const double c = b.half_height();
  if (b.shape == BodyShape3d::Box) {
    // Each base corner's height is linear in its signs: the lowest takes the signs against up.
    const double sx = up[0] > 0 ? -1.0 : 1.0, sy = up[1] > 0 ? -1.0 : 1.0;
    const Vec3 p{0.5 * sx * b.width, 0.5 * sy * b.depth, -c};
    return {p, -dot(up, p)};
  }
  // The rim point (a cos f, a sin f, -c) is lowest where (up_x, up_y) . (cos f, sin f) is least.
  const double s = std::hypot(up[0], up[1]);
  const double cx = s > 0 ? -up[0] / s : 1.0, cy = s > 0 ? -up[1] / s : 0.0;
  const Vec3 p{b.radius * cx, b.radius * cy, -c};
  return {p, b.radius * s + c * up[2]};
}

double rest_threshold(const Body3d& b, double phi) {
  if (b.shape == BodyShape3d::Cylinder) return 2 * b.radius / b.height;
  const double inf = std::numeric_limits<double>::infinity();
  const double cx = std::fabs(std::cos(phi)), sy = std::fabs(std::sin(phi));
  return std::fmin(cx > 0 ? b.width / (b.height * cx) : inf, sy > 0 ? b.depth / (b.height * sy) : inf);
}

}  // namespace blockdyn
