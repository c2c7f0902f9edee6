// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/common/block_shape.hpp"

#include "blockdyn/base/checks.hpp"

namespace blockdyn {

void validate(const BlockShape& s) {
  require(std::isfinite(s.width) && s.width > 0.0 && s.width <= 1e4, "width", "in (0, 1e4] m", s.width);
  require(std::isfinite(s.height) && s.height > 0.0 && s.height <= 1e4, "height", "in (0, 1e4] m", s.height);
  require(s.width / s.height >= 1e-4 && s.width / s.height <= 1e4, "width/height", "in [1e-4, 1e4]",
          s.width / s.height);
  require(std::isfinite(s.mass) && s.mass > 0.0 && s.mass <= 1e12, "mass", "in (0, 1e12] kg", s.mass);
  require(std::isfinite(s.g) && s.g > 0.0 && s.g <= 1e3, "g", "in (0, 1e3] m/s^2", s.g);
}

}  // namespace blockdyn
