// SPDX-License-Identifier: Apache-2.0
#pragma once
// The rigid3d box sliding flat on its base (docs/3d.md): its base bears on the ground at its four
// corners, each with Coulomb friction (kinetic mu_k) against its own slip, so that the base twists
// about the vertical as well as translating. A rigid base on rigid ground is statically
// indeterminate; the corner loads are the linear pressure over the base sampled at its corners
// (three unknowns for the three equations: the weight, and no tilting moment about the centroid
// in x and y); where that pressure would pull at a corner, the other three bear it. That gives the rocking thresholds
// of the standing box (a corner pair's load reaches zero exactly where rocking about the opposite edge begins) and
// makes a slide in closed form where the planar block's is (docs/3d.md). Vectors in the ground's frame unless _body.
#include <array>
#include <cmath>

#include "blockdyn/model/rigid3d/quaternion.hpp"

namespace blockdyn {

struct BaseSlide {
  std::array<double, 4> load{};    // each corner's normal load (N): corner i at (+-b/2, +-d/2) by bits 0, 1
  std::array<Vec3, 4> friction{};  // each corner's friction force (N)
  Vec3 accel{};                    // the centroid's acceleration (horizontal)
  double spin_accel = 0;           // d(omega_z)/dt
  double friction_power = 0;       // sum of F_i . (the corner's slip velocity) (W, <= 0)
};

// The box of base b x d, centroid c above the base, mass, principal inertia about the vertical
// inertia_z, turned by `yaw` about the vertical, its centroid moving at v (horizontal) and
// spinning at omega_z, under the specific force f (gravity and the ground's acceleration
// reversed, m/s^2). The corners' friction takes its directions from the slip field of the
// generalised slip (vx, vy, L omega_z) (L the base's half diagonal) as
// slip_reference::friction_direction gives it: against the slip, reversed past its reversal
// (the slide's smooth continuation, which the integrator steps across to locate the stick), and
// turning to the reference's within `noise` (m/s), where the slip's direction is the integration's
// rounding (a direction that jumped there would chatter at its edge).
// With `unloaded` >= 0 that corner carries nothing and the other three bear the base (three
// unknowns, three equations: determinate); the linear pressure's condition is dropped.
BaseSlide base_slide(double b, double d, double c, double mass, double inertia_z, double mu_k, double yaw,
                     const Vec3& v, double omega_z, const Vec3& f, const Vec3& reference, double noise,
                     int unloaded = -1);

// The base's half diagonal sqrt(b^2 + d^2) / 2: the length that makes the spin a velocity in the
// slip's generalised velocity (vx, vy, L omega_z).
inline double base_reach(double b, double d) { return 0.5 * std::sqrt(b * b + d * d); }

}  // namespace blockdyn
