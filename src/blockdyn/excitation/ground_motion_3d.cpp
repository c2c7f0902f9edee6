// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/excitation/ground_motion_3d.hpp"

#include <cmath>
#include <stdexcept>

#include "blockdyn/base/number_text.hpp"

namespace blockdyn {

std::array<double, 3> GroundMotion3d::at(double t) const {
  const double a = azimuth * (M_PI / 180);
  return at(t, std::cos(a), std::sin(a));
}

GroundMotion3d record_components(std::shared_ptr<const Accelerogram> h, std::shared_ptr<const Accelerogram> h2,
                                 std::shared_ptr<const Accelerogram> v, double scale, double azimuth) {
  GroundMotion3d g;
  g.azimuth = azimuth;
  g.h.record = std::move(h);
  g.h.scale = scale;
  if (h2) {
    g.h2.record = std::move(h2);
    g.h2.scale = scale;
  }
  if (v) {
    g.v.record = std::move(v);
    g.v.scale = scale;
  }
  return g;
}

void validate(const GroundMotion3d& g) {
  validate(g.h, "ground.h");
  validate(g.h2, "ground.h2");
  validate(g.v, "ground.v");
  if (!(std::isfinite(g.azimuth) && std::fabs(g.azimuth) <= 360))
    throw std::invalid_argument("ground-azimuth = " + number_text(g.azimuth) + " is out of range: [-360, 360] degrees");
}

}  // namespace blockdyn
