// SPDX-License-Identifier: Apache-2.0
#pragma once
// The rigid3d state's parts: the orientation quaternion at qw (qw, qx, qy, qz) and 3-vectors
// (position, velocity, angular velocity) at their first index.
#include <array>
#include <cstddef>

#include "blockdyn/model/rigid3d/quaternion.hpp"

namespace blockdyn {

template <std::size_t N>
Quat quat_at(const std::array<double, N>& z, std::size_t qw) {
  return {z[qw], z[qw + 1], z[qw + 2], z[qw + 3]};
}
template <std::size_t N>
void set_quat_at(std::array<double, N>& z, std::size_t qw, const Quat& q) {
  z[qw] = q.w;
  z[qw + 1] = q.x;
  z[qw + 2] = q.y;
  z[qw + 3] = q.z;
}
template <std::size_t N>
Vec3 vec_at(const std::array<double, N>& z, std::size_t i) {
  return {z[i], z[i + 1], z[i + 2]};
}
template <std::size_t N>
void set_vec_at(std::array<double, N>& z, std::size_t i, const Vec3& v) {
  z[i] = v[0];
  z[i + 1] = v[1];
  z[i + 2] = v[2];
}

}  // namespace blockdyn
