// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/winkler/winkler_params.hpp"

#include <cmath>

#include "blockdyn/base/checks.hpp"

namespace blockdyn {

void validate(const WinklerParams& p) {
  require(std::isfinite(p.r) && p.r >= kWinklerRMin && p.r <= kWinklerRMax, "r", "in [1e-3, 1e3]", p.r);
  require(std::isfinite(p.mu) && p.mu >= 0.0 && p.mu <= kWinklerMuMax, "mu", "in [0, 1e3]", p.mu);
  require(std::isfinite(p.k) && p.k >= kWinklerKMin && p.k <= kWinklerKMax, "k",
          "in [1e-6, 1e12] (a stiffer foundation is rigid: `model` rigid)", p.k);
}

}  // namespace blockdyn
