// SPDX-License-Identifier: Apache-2.0
#pragma once
// The two faces of each interface, fixed in their blocks: a rectangle's base on the top face of
// the block below (or the ground, y = 0), or for polygonal blocks the pair of edges that face each
// other at rest (the vertices as given: antiparallel, collinear, overlapping), or the edges the
// interface names. A polygon stands on the ground (y = 0) by its lowest downward edge, or on the
// line of a named edge (an abutment). Every contact law builds its contact points on these faces.
#include <vector>

#include "blockdyn/model/assembly/assembly_params.hpp"
#include "blockdyn/model/assembly/contact_point.hpp"

namespace blockdyn {

// A face in its block's frame (relative to the centre of mass, the block unturned); the ground's
// in the ground frame.
struct LocalFace {
  Vec2 c, t, n;
  double half = INFINITY;
};

struct InterfaceFaces {
  LocalFace lower, upper;  // lower: in the ground frame when the lower body is the ground
};

// The faces of interface j; throws std::invalid_argument naming the interface and the blocks when
// the edges do not face each other.
InterfaceFaces interface_faces(const Assembly& a, int j);

// A face placed with its block's pose.
inline Face face_at(const BodyPose& p, const LocalFace& f) {
  const Vec2 c = Vec2{p.x, p.y} + p.q.offset(f.c.x, f.c.y);
  return {c, p.q.offset(f.t.x, f.t.y), p.q.offset(f.n.x, f.n.y), f.half};
}

// An interface's lower face placed: with its block's pose, or as it is where the lower body is
// the ground (lower_is_ground). Every contact law places its faces so.
inline Face lower_face_at(const LocalFace& f, bool lower_is_ground, const BodyPose& lower) {
  return lower_is_ground ? Face{f.c, f.t, f.n, f.half} : face_at(lower, f);
}

// The rotation of block b about an end of the face it stands on (its first interface as the upper
// block) at which its centre of mass passes over that end: atan(width / height) for a rectangle;
// for a polygon the smaller of the two ends' angles between the face's normal and the line from
// the end to the centroid (a block standing on nothing: its bounding box's). Collapse mode 1
// compares |theta| with a fraction of it.
double tipping_angle(const Assembly& a, int b);

// A block's pose at the start (-1: the ground, at rest at the origin).
BodyPose initial_pose(const Assembly& a, int b);

// A block's outline (counter-clockwise vertices) in the block frame, and at its initial pose.
std::vector<Vec2> block_outline(const AssemblyBlock& b);
std::vector<Vec2> initial_outline(const AssemblyBlock& b);

}  // namespace blockdyn
