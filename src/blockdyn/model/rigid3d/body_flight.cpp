// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/rigid3d/body_flight.hpp"

#include <cmath>

#include "blockdyn/model/rigid3d/body_pivot.hpp"
#include "blockdyn/model/rigid3d/body_state.hpp"

namespace blockdyn {

namespace {

Quat orientation(const BodyFlight::State& z) { return quat_at(z, BodyFlight::kQw); }

}  // namespace

BodyFlight::BodyFlight(const Body3d& body, const GroundMotion3d& ground)
    : body_(body), ground_(ground), inertia_(body.inertia()) {
  validate(body_);
  validate(ground_);
  const double len = body_.shape == BodyShape3d::Box ? std::fmax(body_.width, body_.depth) : 2 * body_.radius;
  const double size = std::fmax(len, body_.height);
  step_ = 0.05 * std::sqrt(size / body_.g);
  // Lengths in body sizes, velocities in sqrt(g size), rates in sqrt(g / size); the quaternion is unit.
  const double v = std::sqrt(body_.g * size), w = std::sqrt(body_.g / size);
  scale_ = {size, size, size, 1, 1, 1, 1, v, v, v, w, w, w};
}

void BodyFlight::rhs(double t, const Mode&, const State& z, State& dz) const {
  const Quat q = orientation(z);
  const Mat3 r = rotation(q);
  const Vec3 w = vec_at(z, kWx);
  const Vec3 dw = free_angular_acceleration(inertia_, r, w);
  // q' = (0, omega) q / 2 with omega in the world frame.
  const Quat dq = Quat{0, w[0], w[1], w[2]} * q;
  dz[kX] = z[kVx];
  dz[kY] = z[kVy];
  dz[kZ] = z[kVz];
  dz[kQw] = 0.5 * dq.w;
  dz[kQx] = 0.5 * dq.x;
  dz[kQy] = 0.5 * dq.y;
  dz[kQz] = 0.5 * dq.z;
  const std::array<double, 3> a = ground_.at(t);  // g
  dz[kVx] = -body_.g * a[0];
  dz[kVy] = -body_.g * a[1];
  dz[kVz] = -body_.g * (1.0 + a[2]);
  dz[kWx] = dw[0];
  dz[kWy] = dw[1];
  dz[kWz] = dw[2];
}

void BodyFlight::events(double, const Mode&, const State& z, std::array<double, kNumEvents>& g) const {
  g[0] = z[kZ] - lowest_point(body_, rotation(orientation(z))).depth;
}

void BodyFlight::complete(const Mode&, State& z) const {
  const Quat q = normalized(orientation(z));
  set_quat_at(z, kQw, q);
}

Transition<BodyFlight::Mode> BodyFlight::transition(double, const Mode& m, State&, int) const {
  Transition<Mode> tr;
  tr.next = m;
  tr.stop = true;  // the contact modes take over from here (not in this model)
  tr.kind = kTouchdown;
  return tr;
}

Vec3 BodyFlight::momentum(const State& z) const {
  return {body_.mass * z[kVx], body_.mass * z[kVy], body_.mass * z[kVz]};
}

Vec3 BodyFlight::angular_momentum(const State& z) const {
  const Mat3 r = rotation(orientation(z));
  const Vec3 om = transposed_times(r, vec_at(z, kWx));
  return r * Vec3{inertia_[0] * om[0], inertia_[1] * om[1], inertia_[2] * om[2]};
}

double BodyFlight::energy(const State& z) const {
  const Mat3 r = rotation(orientation(z));
  const Vec3 om = transposed_times(r, vec_at(z, kWx));
  const Vec3 v = vec_at(z, kVx);
  return 0.5 * body_.mass * dot(v, v) +
         0.5 * (inertia_[0] * om[0] * om[0] + inertia_[1] * om[1] * om[1] + inertia_[2] * om[2] * om[2]) +
         body_.mass * body_.g * z[kZ];
}

BodyFlight::State standing_state(const Body3d& b, double yaw, double lift) {
  BodyFlight::State z{};
  const Quat q = axis_angle({0, 0, 1}, yaw);
  z[BodyFlight::kZ] = b.half_height() + lift;
  z[BodyFlight::kQw] = q.w;
  z[BodyFlight::kQx] = q.x;
  z[BodyFlight::kQy] = q.y;
  z[BodyFlight::kQz] = q.z;
  return z;
}

}  // namespace blockdyn
