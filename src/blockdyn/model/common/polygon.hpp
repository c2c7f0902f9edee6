// SPDX-License-Identifier: Apache-2.0
#pragma once
// Convex polygons: the cross-sections of masonry blocks (voussoirs, drums, wedges). Mass
// properties in closed form (the shoelace sums), validity (counter-clockwise, convex, simple) and
// the depth by which two of them interpenetrate (separating axes).
#include <string>
#include <vector>

#include "blockdyn/model/common/block_kinematics.hpp"

namespace blockdyn {

struct PolygonProperties {
  double area = 0;               // > 0 for counter-clockwise vertices
  Vec2 centroid;                 //
  double gyration_sq = 0;        // polar second moment about the centroid over the area (m^2)
  double width = 0, height = 0;  // bounding box
};

PolygonProperties polygon_properties(const std::vector<Vec2>& v);

// Why v is not a convex counter-clockwise polygon with distinct vertices (empty: it is one).
// Collinear consecutive vertices are refused: every edge must be a face.
std::string polygon_problem(const std::vector<Vec2>& v);

// The depth by which the interiors of two convex polygons overlap: the smallest overlap of their
// projections over the edge normals of both (<= 0: a separating axis exists, they do not overlap).
double penetration_depth(const std::vector<Vec2>& a, const std::vector<Vec2>& b);

// The vertices of the width x height rectangle centred at the origin, counter-clockwise from the
// bottom-left corner (edge 0 is the base, edge 2 the top).
std::vector<Vec2> rectangle_vertices(double width, double height);

}  // namespace blockdyn
