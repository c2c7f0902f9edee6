// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/winkler/winkler_params.hpp"

#include <cmath>

#include "blockdyn/model/common/checks.hpp"

namespace blockdyn {

void validate(const BlockParams& p) {
  require(std::isfinite(p.r) && p.r > 0.0, "r", "a finite number > 0", p.r);
  require(std::isfinite(p.mu) && p.mu >= 0.0, "mu", "a finite number >= 0", p.mu);
  require(std::isfinite(p.k) && p.k > 0.0, "k", "a finite number > 0", p.k);
}

}  // namespace blockdyn
