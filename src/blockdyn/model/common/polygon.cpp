// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/common/polygon.hpp"

#include <algorithm>
#include <cmath>

namespace blockdyn {

namespace {

double cross_at(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// The projections of a polygon on the axis n: [lo, hi].
void project(const std::vector<Vec2>& v, const Vec2& n, double& lo, double& hi) {
  lo = INFINITY;
  hi = -INFINITY;
  for (const Vec2& p : v) {
    const double s = p.x * n.x + p.y * n.y;
    lo = std::fmin(lo, s);
    hi = std::fmax(hi, s);
  }
}

}  // namespace

PolygonProperties polygon_properties(const std::vector<Vec2>& v) {
  PolygonProperties p;
  const std::size_t n = v.size();
  if (n < 3) return p;
  // Sums about the first vertex (less cancellation for a polygon far from the origin).
  const Vec2 o = v[0];
  double a2 = 0, cx = 0, cy = 0, jxx = 0, jyy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double x0 = v[i].x - o.x, y0 = v[i].y - o.y;
    const double x1 = v[(i + 1) % n].x - o.x, y1 = v[(i + 1) % n].y - o.y;
    const double c = x0 * y1 - x1 * y0;
    a2 += c;
    cx += (x0 + x1) * c;
    cy += (y0 + y1) * c;
    jyy += (x0 * x0 + x0 * x1 + x1 * x1) * c;  // integral of x^2, times 12
    jxx += (y0 * y0 + y0 * y1 + y1 * y1) * c;  // integral of y^2, times 12
  }
  p.area = 0.5 * a2;
  if (p.area == 0) return p;
  const double gx = cx / (3.0 * a2), gy = cy / (3.0 * a2);
  p.centroid = {o.x + gx, o.y + gy};
  // Polar moment about the first vertex, moved to the centroid (parallel axes).
  const double j_origin = (jxx + jyy) / 12.0;
  p.gyration_sq = j_origin / p.area - (gx * gx + gy * gy);
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
  for (const Vec2& q : v) {
    xmin = std::fmin(xmin, q.x);
    xmax = std::fmax(xmax, q.x);
    ymin = std::fmin(ymin, q.y);
    ymax = std::fmax(ymax, q.y);
  }
  p.width = xmax - xmin;
  p.height = ymax - ymin;
  return p;
}

std::string polygon_problem(const std::vector<Vec2>& v) {
  const std::size_t n = v.size();
  if (n < 3) return "needs at least 3 vertices, " + std::to_string(n) + " given";
  if (n > 64) return "has " + std::to_string(n) + " vertices, at most 64 allowed";
  double size = 0;
  for (const Vec2& p : v) {
    if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::fabs(p.x) <= 1e6 && std::fabs(p.y) <= 1e6))
      return "has a vertex that is not a finite coordinate within 1e6 m";
    size = std::fmax(size, std::fmax(std::fabs(p.x - v[0].x), std::fabs(p.y - v[0].y)));
  }
  const double tiny = 1e-12 * size * size;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &a = v[i], &b = v[(i + 1) % n];
    if (std::hypot(b.x - a.x, b.y - a.y) <= 1e-9 * size)
      return "repeats vertex " + std::to_string(i) + " (edges must have a length)";
  }
  const double area2 = 2.0 * polygon_properties(v).area;
  if (area2 < 0) return "lists its vertices clockwise (give them counter-clockwise)";
  double turning = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &a = v[i], &b = v[(i + 1) % n], &c = v[(i + 2) % n];
    const double turn = cross_at(a, b, c);
    if (turn < 0) return "is concave at vertex " + std::to_string((i + 1) % n) + " (blocks must be convex)";
    if (turn <= tiny) return "has collinear edges at vertex " + std::to_string((i + 1) % n) + " (merge them)";
    const double e1 = std::atan2(b.y - a.y, b.x - a.x), e2 = std::atan2(c.y - b.y, c.x - b.x);
    double d = e2 - e1;
    while (d <= 0) d += 2.0 * M_PI;
    while (d > 2.0 * M_PI) d -= 2.0 * M_PI;
    turning += d;
  }
  // Left turns all the way but winding more than once: a star (self-intersecting).
  if (turning > 2.0 * M_PI * (1.0 + 1e-9)) return "intersects itself (its edges wind more than once)";
  return {};
}

double penetration_depth(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  double depth = INFINITY;
  for (const std::vector<Vec2>* poly : {&a, &b}) {
    const std::vector<Vec2>& v = *poly;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Vec2 &p = v[i], &q = v[(i + 1) % v.size()];
      const double len = std::hypot(q.x - p.x, q.y - p.y);
      if (!(len > 0)) continue;
      const Vec2 n{(q.y - p.y) / len, -(q.x - p.x) / len};
      double alo, ahi, blo, bhi;
      project(a, n, alo, ahi);
      project(b, n, blo, bhi);
      depth = std::fmin(depth, std::fmin(ahi, bhi) - std::fmax(alo, blo));
    }
  }
  return depth;
}

std::vector<Vec2> rectangle_vertices(double width, double height) {
  const double b = 0.5 * width, h = 0.5 * height;
  return {{-b, -h}, {b, -h}, {b, h}, {-b, h}};
}

}  // namespace blockdyn
