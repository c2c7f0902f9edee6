// SPDX-License-Identifier: Apache-2.0
#pragma once
// The thesis's initial-condition sets (sec. 3.2). They return the integrated state vector
// (h = y - 1/2 kept exact: for ic2 h = -1/k, not 0.5 - 1/k - 0.5).
#include <optional>

#include "blockdyn/model/winkler/winkler_params.hpp"
#include "blockdyn/model/winkler/winkler_state.hpp"

namespace blockdyn {

// ic1: tilted by w0 (default alpha/2), released from rest, resting on the springs with the
// rigid-ground reaction at release; lowest corner at x = 0. Mirrored for w0 < 0.
WinklerState ic1(const WinklerParams& p, std::optional<double> w0 = std::nullopt);

// ic2: upright block given a horizontal and a vertical impulse at its base.
WinklerState ic2(const WinklerParams& p);

// Centre height h = y - 1/2 at which the block tilted by w carries the vertical reaction Ry
// (exact Region, any number of submerged corners up to two).
double static_height(const WinklerParams& p, double w, double Ry);

}  // namespace blockdyn
