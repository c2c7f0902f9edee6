// SPDX-License-Identifier: Apache-2.0
#pragma once
// A ground motion in three components for the 3D body (docs/3d.md): `h` along the azimuth (degrees
// from the world's x axis towards y; 0: the body's e1 at yaw 0), `h2` perpendicular to it
// (azimuth + 90 degrees), `v` vertical; each a GroundComponent of any kind (constant, harmonic,
// pulses, records), in g.
#include <array>
#include <cmath>
#include <memory>
#include <string>

#include "blockdyn/excitation/ground_motion.hpp"

namespace blockdyn {

struct GroundMotion3d {
  GroundComponent h, h2, v;
  double azimuth = 0;  // degrees

  bool is_zero() const { return h.is_zero() && h2.is_zero() && v.is_zero(); }
  double next_break(double t) const { return std::fmin(std::fmin(h.next_break(t), h2.next_break(t)), v.next_break(t)); }
  // The ground's acceleration in the world frame (x, y, z), in g.
  std::array<double, 3> at(double t) const;
  // The same with h's direction given (cos, sin of the azimuth: a model computes them once).
  std::array<double, 3> at(double t, double cos_az, double sin_az) const {
    const double x = h.at(t), y = h2.at(t);
    return {cos_az * x - sin_az * y, sin_az * x + cos_az * y, v.at(t)};
  }
};

// A record in up to three components (h2 and v may be null), every one at `scale`, h along
// `azimuth` degrees.
GroundMotion3d record_components(std::shared_ptr<const Accelerogram> h, std::shared_ptr<const Accelerogram> h2,
                                 std::shared_ptr<const Accelerogram> v, double scale, double azimuth);

// Checks every component (ground.h.<field>, ground.h2.<field>, ground.v.<field>) and the azimuth.
void validate(const GroundMotion3d& g);

}  // namespace blockdyn
