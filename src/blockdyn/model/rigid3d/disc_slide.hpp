// SPDX-License-Identifier: Apache-2.0
#pragma once
// The rigid3d cylinder sliding flat on its base (docs/3d.md): Coulomb friction (kinetic mu_k) over
// a disc of radius a, each point's friction against its own slip, so that a base that spins as it
// slides feels both a force and a twisting moment (their coupling: a spinning base slides
// further, a sliding one spins longer). A rigid base on rigid ground is statically indeterminate;
// the pressure is taken as uniform over the disc with the share w of the load that the tilting
// moment needs carried at one rim point: w a is the resultant's offset, so the base stays flat
// until the resultant reaches the rim (the rocking threshold of the cylinder at rest, 2a/h, and of
// the sliding one, mu_k c = a, exactly), and the friction of a thin base (w = 0) is the uniform
// pressure's of the literature (Contensou's coupling). A linear pressure would go negative at the
// rim with the resultant at a/4. Vectors in the ground's frame.
#include "blockdyn/model/rigid3d/quaternion.hpp"

namespace blockdyn {

// Uniform pressure over the disc of radius a whose points slip at v + omega Z x r: the mean of
// the friction's direction over the disc, and the mean of r x (that direction) . Z divided by a.
// A pure slide gives (v / |v|, 0), a pure spin (0, 2/3 sign(omega)). In closed form: integrated
// along rays from the slip's instantaneous centre (a point's direction is the ray's), then over
// the angle as complete elliptic integrals (their series where those would cancel).
struct DiscFrictionField {
  Vec3 mean_direction{};  // horizontal, |.| <= 1
  double mean_twist = 0;  // in [-2/3, 2/3]
};
DiscFrictionField disc_friction_field(double a, const Vec3& v, double omega);

struct DiscSlide {
  double load = 0;            // the normal load N (N)
  Vec3 offset{};              // the resultant's offset from the base's centre, in a (|.| = w; 1: on the rim)
  Vec3 friction{};            // the friction's resultant (N)
  double torque = 0;          // its moment about the vertical through the centroid (N m)
  Vec3 accel{};               // the centroid's horizontal acceleration
  double spin_accel = 0;      // d(omega_z)/dt
  double friction_power = 0;  // F . v + M omega (W, <= 0)
};

// The cylinder of radius a, its base c below the centroid, sliding at v (horizontal) and spinning
// at omega_z under the specific force f (m/s^2). The friction's directions follow the slip field
// of the generalised slip (vx, vy, a omega_z) as slip_reference::friction_direction gives it
// (reversed past its reversal, turning to the reference within `noise`, m/s). The offset
// solves w a (its direction) = c mu_k ((1 - w) mean direction + w (the rim point's direction)) by
// Newton's method (a pure slide: w = mu_k c / a along the slip); |offset| >= 1 is a base that
// cannot stay flat (it tips onto the rim point along the offset).
DiscSlide disc_slide(double a, double c, double mass, double inertia_z, double mu_k, const Vec3& v, double omega_z,
                     const Vec3& f, const Vec3& reference, double noise);

}  // namespace blockdyn
