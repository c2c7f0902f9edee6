// SPDX-License-Identifier: Apache-2.0
#pragma once
// Following a slip against a reference direction (docs/3d.md), shared by the sliding base and the
// slipping edge or corner: the slip's generalised velocity u (a sliding base: (vx, vy, L omega_z);
// a corner: its velocity; an edge: its midpoint's and L omega_z) ends where u . ref reaches zero
// (the friction reverses there: a stick, located like any other event), and a slip that turns by
// 60 degrees from its reference takes a new one (an event without a mode change), so that
// u . ref reaches zero only where u does.
#include <cmath>

#include "blockdyn/model/rigid3d/quaternion.hpp"

namespace blockdyn::slip_reference {

// The slip's turn from its reference that takes a new one: cos 60 degrees.
constexpr double kTurnCosine = 0.5;
// A slip below this (in sqrt(g size)) at a turn is a stick.
constexpr double kStickSlip = 1e-9;
// A slip's direction is not followed below this size (in sqrt(g size)): it is the integration's
// noise there (the velocities' absolute tolerance is 1e-12 of that scale), and a slip that small
// is about to stick. The turn's event function is offset by it.
constexpr double kSlipNoise = 1e-9;
// A kink predicted closer than this share of the slip's own size (its minimum along the
// linear extrapolation) is a stick ahead; farther, the slip only curves.
constexpr double kStickAhead = 1e-3;

// The stick's event (u . ref) and the turn's, in units of vs = sqrt(g size).
inline double along(const Vec3& u, const Vec3& ref, double vs) { return dot(u, ref) / vs; }
inline double turn(const Vec3& u, const Vec3& ref, double vs) {
  return (dot(u, ref) - kTurnCosine * std::sqrt(dot(u, u))) / vs + kSlipNoise;
}

// A point's slip nearing a stick must enter the noise (where its friction takes the reference's
// direction) along its reference, else the friction turns there and chatters at the noise's edge:
// below kTurnNear (in sqrt(g size)) the turn allowed shrinks with the slip, to a milliradian at
// the noise.
constexpr double kTurnNear = 1e-3;
inline double turn_near_stick(const Vec3& u, const Vec3& ref, double vs) {
  const double s = std::sqrt(dot(u, u));
  const double slack = (1 - kTurnCosine) * std::fmin(1.0, s / (kTurnNear * vs));
  return (dot(u, ref) - (1 - slack) * s) / vs + kSlipNoise;
}

// The predicted time to the stick from u and its rate du (the integrator steps up to it: the
// friction jumps there), or infinity where the slip only curves.
inline double stick_ahead(const Vec3& u, const Vec3& du) {
  const double rate = dot(u, du), dd = dot(du, du);
  if (!(rate < 0) || !(dd > 0)) return INFINITY;
  const double tau = -rate / dd;
  const Vec3 closest = {u[0] + tau * du[0], u[1] + tau * du[1], u[2] + tau * du[2]};
  return dot(closest, closest) <= kStickAhead * kStickAhead * dot(u, u) ? tau : INFINITY;
}

}  // namespace blockdyn::slip_reference
