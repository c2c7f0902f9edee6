// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/assembly/interface_faces.hpp"

#include "blockdyn/base/number_text.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "blockdyn/model/common/polygon.hpp"

namespace blockdyn {

namespace {

// Antiparallel within this angle (rad) and collinear within this fraction of the smaller block:
// the same tolerance as the start's contact check (assembly_params.cpp).
constexpr double kFacingAngle = 0.02;
constexpr double kFacingDistance = 0.02;

struct Edge {
  Vec2 a, b, c, t, n;  // ends, midpoint, direction (counter-clockwise), outward normal
  double half;
};

Edge edge_of(const std::vector<Vec2>& v, int k) {
  const Vec2 a = v[k], b = v[(k + 1) % v.size()];
  const double len = std::hypot(b.x - a.x, b.y - a.y);
  Edge e;
  e.a = a;
  e.b = b;
  e.c = 0.5 * (a + b);
  e.t = (1.0 / len) * (b - a);
  e.n = {e.t.y, -e.t.x};
  e.half = 0.5 * len;
  return e;
}

// An edge as a contact face in its block's frame: the tangent is chosen so that both faces of an
// interface share it (the lower face's normal is its tangent turned a quarter counter-clockwise).
LocalFace as_face(const Edge& e, bool lower, const Vec2& centre) {
  LocalFace f;
  f.c = e.c - centre;
  f.n = e.n;
  f.t = lower ? Vec2{f.n.y, -f.n.x} : Vec2{-f.n.y, f.n.x};
  f.half = e.half;
  return f;
}

std::string name_of(const Assembly& a, int b) {
  return b < 0 ? std::string("the ground") : "block " + std::to_string(b) + " (" + a.blocks[b].name + ")";
}

bool is_rectangle(const AssemblyBlock& b) { return b.vertices.empty(); }

}  // namespace

std::vector<Vec2> block_outline(const AssemblyBlock& b) {
  return is_rectangle(b) ? rectangle_vertices(b.width, b.height) : b.vertices;
}

namespace {

// The outline unturned at the block's centre: the geometry at rest, where faces are found (the
// vertices as given; a rotation theta is the start's, about the centre).
std::vector<Vec2> rest_outline(const AssemblyBlock& b) {
  std::vector<Vec2> v = block_outline(b);
  for (Vec2& p : v) p = Vec2{b.x, b.y} + p;
  return v;
}

// A ground interface of a polygon: a named edge stands on its own line (an abutment); otherwise
// the block's base, its lowest edge facing straight down at rest, stands on y = 0.
InterfaceFaces ground_faces(const Assembly& a, const AssemblyInterface& f, const std::string& w) {
  const AssemblyBlock& up = a.blocks[f.upper];
  const std::vector<Vec2> vu = rest_outline(up);
  const Vec2 cu{up.x, up.y};
  InterfaceFaces out;
  if (f.upper_edge >= 0) {
    const Edge ed = edge_of(vu, f.upper_edge);
    out.upper = as_face(ed, false, cu);
    const Vec2 n{-ed.n.x, -ed.n.y};
    out.lower = {dot(ed.c, n) * n, {n.y, -n.x}, n, INFINITY};  // through the point nearest the origin
    return out;
  }
  int k = -1;
  for (int e = 0; e < int(vu.size()); ++e) {
    const Edge ed = edge_of(vu, e);
    if (ed.n.y < -std::cos(kFacingAngle) && (k < 0 || ed.c.y < edge_of(vu, k).c.y)) k = e;
  }
  if (k < 0)
    throw std::invalid_argument(w + ": " + name_of(a, f.upper) +
                                " has no horizontal base edge to stand on the ground; name its edge (upper_edge) "
                                "for an inclined abutment");
  out.upper = as_face(edge_of(vu, k), false, cu);
  out.lower = {{0, 0}, {1, 0}, {0, 1}, INFINITY};
  return out;
}

}  // namespace

double tipping_angle(const Assembly& a, int b) {
  const AssemblyBlock& k = a.blocks[std::size_t(b)];
  if (k.vertices.empty()) return std::atan2(k.width, k.height);
  for (int j = 0; j < int(a.interfaces.size()); ++j) {
    if (a.interfaces[std::size_t(j)].upper != b) continue;
    const LocalFace f = interface_faces(a, j).upper;  // relative to the centroid
    const double normal = std::fabs(dot(f.c, f.n)), along = dot(f.c, f.t);
    return std::atan2(std::fmin(std::fabs(f.half - along), std::fabs(f.half + along)), normal);
  }
  return std::atan2(k.width, k.height);
}

BodyPose initial_pose(const Assembly& a, int b) {
  BodyPose p;
  if (b < 0) return p;
  const AssemblyBlock& k = a.blocks[b];
  p.x = k.x;
  p.y = k.y;
  p.theta = k.theta;
  p.q = BodyRotation::of(k.theta);
  return p;
}

std::vector<Vec2> initial_outline(const AssemblyBlock& b) {
  std::vector<Vec2> v = block_outline(b);
  const BodyRotation q = BodyRotation::of(b.theta);
  for (Vec2& p : v) p = Vec2{b.x, b.y} + q.offset(p.x, p.y);
  return v;
}

InterfaceFaces interface_faces(const Assembly& a, int j) {
  const AssemblyInterface& f = a.interfaces[j];
  const AssemblyBlock& up = a.blocks[f.upper];
  const std::string w =
      "interface " + std::to_string(j) + " (" + name_of(a, f.upper) + " on " + name_of(a, f.lower) + ")";
  // Rectangles keep their base-on-top faces whatever their poses (a tilted frame's lintel).
  const bool rect_pair =
      is_rectangle(up) && (f.lower < 0 || is_rectangle(a.blocks[f.lower])) && f.lower_edge < 0 && f.upper_edge < 0;
  if (rect_pair) {
    InterfaceFaces out;
    out.upper = {{0, -0.5 * up.height}, {1, 0}, {0, -1}, 0.5 * up.width};
    if (f.lower < 0) {
      out.lower = {{0, 0}, {1, 0}, {0, 1}, INFINITY};
    } else {
      const AssemblyBlock& lo = a.blocks[f.lower];
      out.lower = {{0, 0.5 * lo.height}, {1, 0}, {0, 1}, 0.5 * lo.width};
    }
    return out;
  }
  const std::vector<Vec2> vu = rest_outline(up);
  const int nu = int(vu.size());
  auto check_edge = [&](int k, int n, const char* key) {
    if (k >= n)
      throw std::invalid_argument(w + ": " + key + " = " + std::to_string(k) + " must be in [0, " +
                                  std::to_string(n - 1) + "] (an edge k runs from vertex k to k + 1)");
  };
  check_edge(f.upper_edge, nu, "upper_edge");
  if (f.lower < 0) return ground_faces(a, f, w);
  const AssemblyBlock& lo = a.blocks[f.lower];
  const std::vector<Vec2> vl = rest_outline(lo);
  const int nl = int(vl.size());
  check_edge(f.lower_edge, nl, "lower_edge");
  const double tol = kFacingDistance * std::fmin(std::fmin(up.width, up.height), std::fmin(lo.width, lo.height));
  const bool named = f.upper_edge >= 0 && f.lower_edge >= 0;
  int best_u = -1, best_l = -1;
  double best_overlap = 0, best_angle = INFINITY, best_dist = INFINITY;
  for (int eu = 0; eu < nu; ++eu) {
    if (f.upper_edge >= 0 && eu != f.upper_edge) continue;
    const Edge u = edge_of(vu, eu);
    for (int el = 0; el < nl; ++el) {
      if (f.lower_edge >= 0 && el != f.lower_edge) continue;
      const Edge l = edge_of(vl, el);
      const double angle = std::acos(std::fmax(-1.0, std::fmin(1.0, -dot(u.n, l.n))));
      const double dist = std::fmax(std::fabs(dot(u.a - l.c, l.n)), std::fabs(dot(u.b - l.c, l.n)));
      // The overlap along the lower face, whose tangent runs against its edge.
      const Vec2 tl{-l.t.x, -l.t.y};
      const double s1 = dot(u.a - l.c, tl), s2 = dot(u.b - l.c, tl);
      const double ov = std::fmin(std::fmax(s1, s2), l.half) - std::fmax(std::fmin(s1, s2), -l.half);
      if (!named && !(angle <= kFacingAngle && dist <= tol && ov > 0)) continue;
      if (angle < best_angle - 1e-12 || (angle <= best_angle + 1e-12 && dist < best_dist)) {
        best_u = eu;
        best_l = el;
        best_angle = angle;
        best_dist = dist;
        best_overlap = ov;
      }
    }
  }
  if (best_u < 0 || !(best_angle <= kFacingAngle && best_dist <= tol && best_overlap > 0)) {
    const std::string why =
        best_u < 0 ? "no edge of " + name_of(a, f.upper) + " faces an edge of " + name_of(a, f.lower) +
                         " (antiparallel within " + number_text(kFacingAngle, 6) + " rad, collinear within " +
                         number_text(tol, 6) + " m, overlapping)"
                   : "the named edges do not face each other (angle " + number_text(best_angle, 6) + " rad, distance " +
                         number_text(best_dist, 6) + " m, overlap " + number_text(best_overlap, 6) + " m)";
    throw std::invalid_argument(w + ": " + why);
  }
  InterfaceFaces out;
  out.upper = as_face(edge_of(vu, best_u), false, {up.x, up.y});
  out.lower = as_face(edge_of(vl, best_l), true, {lo.x, lo.y});
  return out;
}

}  // namespace blockdyn
