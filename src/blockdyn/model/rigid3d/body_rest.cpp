// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/rigid3d/body_rest.hpp"

#include <cmath>
#include <stdexcept>

#include "blockdyn/base/number_text.hpp"
#include "blockdyn/excitation/rest_exit.hpp"

namespace blockdyn {

BodyRestExit first_rest_exit(const Body3d& b, double yaw, double mu_s, const GroundMotion3d& g, double t0, double t1) {
  validate(b);
  validate(g);
  if (!(mu_s >= 0 && std::isfinite(mu_s)))
    throw std::invalid_argument("mu-s = " + number_text(mu_s) + " is out of range: finite and >= 0");
  if (!g.h2.is_zero())
    throw std::invalid_argument("ground-h2: the exit from rest under two horizontal components is not available yet");
  const double rock = rest_threshold(b, g.azimuth * (M_PI / 180) - yaw);
  BodyRestExit out;
  out.way = rock <= mu_s ? RestExitWay::Rocks : RestExitWay::Slides;
  out.coefficient = std::fmin(rock, mu_s);
  GroundMotion planar;
  planar.horizontal = g.h;
  planar.vertical = g.v;
  out.t = first_rest_failure(planar, out.coefficient, t0, t1);
  if (!std::isfinite(out.t)) out.way = RestExitWay::None;
  return out;
}

}  // namespace blockdyn
