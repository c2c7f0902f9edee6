// SPDX-License-Identifier: Apache-2.0
#pragma once
// Input checks shared by every parameter set: a failed check throws std::invalid_argument
// "<field> = <value> is out of range: must be <range>".
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace blockdyn {

inline void require(bool ok, const std::string& field, const std::string& range, double v) {
  if (ok) return;
  std::ostringstream os;
  os << field << " = " << v << " is out of range: must be " << range;
  throw std::invalid_argument(os.str());
}

inline void require_finite_positive(const std::string& field, double v) {
  require(std::isfinite(v) && v > 0.0, field, "a finite number > 0", v);
}

}  // namespace blockdyn
