// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/units/physical_units.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace blockdyn {

namespace {
void positive(const char* field, double v) {
  if (!std::isfinite(v) || v <= 0.0) {
    std::ostringstream os;
    os << field << " = " << v << " is out of range: must be a finite number > 0";
    throw std::invalid_argument(os.str());
  }
}
}  // namespace

double mass_of(const PhysicalBlock& b) {
  if (b.mass && b.density) throw std::invalid_argument("physical block: mass and density both given: give one");
  if (b.mass) {
    positive("mass", *b.mass);
    return *b.mass;
  }
  if (!b.density || !b.thickness) throw std::invalid_argument("physical block: give mass, or density and thickness");
  positive("density", *b.density);
  positive("thickness", *b.thickness);
  return *b.density * b.height * b.width * *b.thickness;
}

WinklerParams to_nondimensional(const PhysicalBlock& b) {
  if (b.height == 0.0)
    throw std::invalid_argument("height is missing: give the block's height [m] (`height`, physical.height)");
  if (b.width == 0.0)
    throw std::invalid_argument("width is missing: give the block's width [m] (`width`, physical.width)");
  positive("height", b.height);
  positive("width", b.width);
  positive("g", b.g);
  const double m = mass_of(b);
  double k_line = 0.0;  // force per unit foundation length per unit depth [N/m^2]
  if (b.line_stiffness) {
    positive("line_stiffness", *b.line_stiffness);
    k_line = *b.line_stiffness;
  } else if (b.subgrade_modulus) {
    positive("subgrade_modulus", *b.subgrade_modulus);
    if (!b.thickness) throw std::invalid_argument("subgrade_modulus needs thickness");
    positive("thickness", *b.thickness);
    k_line = *b.subgrade_modulus * *b.thickness;
  } else {
    throw std::invalid_argument("physical block: give subgrade_modulus (with thickness) or line_stiffness");
  }
  WinklerParams p;
  p.r = b.width / b.height;
  p.mu = b.mu;
  p.k = k_line * b.height * b.width / (m * b.g);
  validate(p);
  return p;
}

UnitScales scales_of(const PhysicalBlock& b) {
  const double m = mass_of(b);
  UnitScales s;
  s.length = b.height;
  s.time = std::sqrt(b.height / b.g);
  s.velocity = std::sqrt(b.height * b.g);
  s.angular_velocity = std::sqrt(b.g / b.height);
  s.force = m * b.g;
  s.energy = m * b.g * b.height;
  s.mass = m;
  return s;
}

}  // namespace blockdyn
