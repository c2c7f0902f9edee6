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
#include "blockdyn/numerics/circle_root.hpp"

namespace blockdyn::slip_reference {

// The slip's turn from its reference that takes a new one: cos 60 degrees.
constexpr double kTurnCosine = 0.5;
// A slip below this (in sqrt(g size)) at a turn is a stick.
constexpr double kStickSlip = 1e-9;
// A slip's direction is not followed below this size (in sqrt(g size)): it is the integration's
// noise there (the velocities' absolute tolerance is 1e-12 of that scale), and a slip that small
// is about to stick. The turn's event function is offset by it.
constexpr double kSlipNoise = 1e-9;
// A slip this close to its reference (the tangent of the angle between them) has the
// reference's direction: the rounding off a planar motion's slip, whose direction's stiffness
// (a rate of mu N / (m |slip|)) would otherwise hold the steps to the slip's size as it starts.
constexpr double kDeadAngle = 1e-9;
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

// The friction's direction for a slip u followed against ref: against the slip (past its
// reversal, which only a stick's event ends, along ref: the slip's smooth continuation); below
// half the noise the reference's (a start from rest, a stick reached along it); between, turning
// from one to the other continuously (a direction that jumped at one size would make a slip that
// nears its stick off its reference chatter there).
inline Vec3 friction_direction(const Vec3& u, const Vec3& ref, double noise) {
  auto unit = [](const Vec3& v) {
    const double n = std::sqrt(dot(v, v));
    const double inv = 1.0 / n;
    return n > 1e-300 ? Vec3{v[0] * inv, v[1] * inv, v[2] * inv} : Vec3{0, 0, 0};
  };
  const double along = dot(u, ref), sense = along < 0 ? -1.0 : 1.0, size = std::sqrt(dot(u, u));
  const double share = std::fmin(1.0, std::fmax(0.0, 2 * size / noise - 1));
  // A slip off its reference by less than kDeadAngle is along it (the rounding of a planar
  // motion); the part off it is taken in fully from twice that.
  const Vec3 off = {u[0] - along * ref[0], u[1] - along * ref[1], u[2] - along * ref[2]};
  const double angle = std::sqrt(dot(off, off)) / std::fabs(along);
  const double taken = std::fmin(1.0, std::fmax(0.0, angle / kDeadAngle - 1));
  const Vec3 d =
      taken >= 1
          ? unit(u)
          : unit({along * ref[0] + taken * off[0], along * ref[1] + taken * off[1], along * ref[2] + taken * off[2]});
  if (share >= 1) return {sense * d[0], sense * d[1], sense * d[2]};
  if (share <= 0) return ref;
  return unit({sense * share * d[0] + (1 - share) * ref[0], sense * share * d[1] + (1 - share) * ref[1],
               sense * share * d[2] + (1 - share) * ref[2]});
}

// The direction d (horizontal, unit) a point at rest starts slipping in: where its slip's
// acceleration under the friction d gives, accel_of(d), is along d (a root of d x a(d) with
// a . d > 0: Coulomb's friction opposes the slip it makes), the root nearest ref, found on
// kDirectionSamples angles of the circle and refined by bisection; ref where there is none. A
// sign change through a pole (the loads' system singular there) is no root.
constexpr int kDirectionSamples = 72;
constexpr int kDirectionBisections = 60;
constexpr double kRootSine = 1e-6;
template <class AccelOf>
Vec3 slip_start_root(AccelOf&& accel_of, const Vec3& ref) {
  auto residual = [&](double phi, double* along, double* size) {
    const Vec3 d = {std::cos(phi), std::sin(phi), 0};
    const Vec3 a = accel_of(d);
    *along = dot(a, d);
    *size = std::sqrt(dot(a, a));
    return d[0] * a[1] - d[1] * a[0];
  };
  double along = 0, size = 0;
  auto sample = [&](double phi) { return CircleSample{residual(phi, &along, &size), true}; };
  auto accept = [&](double root) {
    const double f = residual(root, &along, &size);
    return along > 0 && std::fabs(f) <= kRootSine * size;
  };
  const double best = nearest_circle_root(
      std::atan2(ref[1], ref[0]), CircleRootScan{kDirectionSamples, kDirectionBisections, 1e-16}, sample, accept);
  if (std::isnan(best)) return ref;
  return {std::cos(best), std::sin(best), 0};
}

}  // namespace blockdyn::slip_reference
