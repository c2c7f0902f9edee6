// SPDX-License-Identifier: Apache-2.0
#pragma once
// The rigid3d body in flight (no contact): its centroid falls freely and its rotation follows
// Euler's torque-free equations. State in the ground's frame (it moves with the ground motion: the
// body feels the ground's acceleration reversed): the centroid (x, y, z), the unit
// quaternion (qw, qx, qy, qz), the centroid's velocity and the angular velocity (wx, wy, wz). One
// event: the lowest base point reaching the ground (a touchdown, located on the dense output).
// The flight mode of the rigid3d family (docs/3d.md); the contact modes build on it.
#include <array>
#include <optional>

#include "blockdyn/excitation/ground_motion_3d.hpp"
#include "blockdyn/integrate/hybrid_model.hpp"
#include "blockdyn/model/rigid3d/body_shape.hpp"

namespace blockdyn {

struct BodyFlightMode {};

class BodyFlight {
 public:
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"  // the Winkler state's names, hidden on purpose (body_on_ground.hpp)
  enum : std::size_t { kX, kY, kZ, kQw, kQx, kQy, kQz, kVx, kVy, kVz, kWx, kWy, kWz, kDimF };
#pragma GCC diagnostic pop
  static constexpr std::size_t kDim = kDimF;
  static constexpr std::size_t kNumEvents = 1;
  static constexpr int kTouchdown = 1;  // the transition's kind at the event
  using Mode = BodyFlightMode;
  using State = std::array<double, kDim>;

  explicit BodyFlight(const Body3d& body, const GroundMotion3d& ground = {});

  void rhs(double t, const Mode& m, const State& z, State& dz) const;
  // The lowest base point's height above the ground (>= 0 in flight).
  void events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const;
  // The quaternion back to unit length (its norm drifts by the integration error only).
  void complete(const Mode& m, State& z) const;
  Transition<Mode> transition(double t, const Mode& m, State& z, int event) const;
  std::optional<Transition<Mode>> resolve_chatter(double, const Mode&, const State&) const { return std::nullopt; }
  double step_hint(const Mode&) const { return step_; }
  double next_breakpoint(double t) const { return ground_.next_break(t); }
  State abs_tol_scale() const { return scale_; }

  // Momentum (ground frame) and angular momentum about the centroid (torque-free: constant).
  Vec3 momentum(const State& z) const;
  Vec3 angular_momentum(const State& z) const;
  double energy(const State& z) const;  // kinetic + m g z

  const Body3d& body() const { return body_; }

 private:
  Body3d body_;
  GroundMotion3d ground_;
  Vec3 inertia_;
  double step_;
  State scale_;
};

// The body at rest on its base in the world frame, turned by `yaw` (rad) about Z and lifted by
// `lift` (m) above the ground.
BodyFlight::State standing_state(const Body3d& b, double yaw, double lift);

}  // namespace blockdyn
