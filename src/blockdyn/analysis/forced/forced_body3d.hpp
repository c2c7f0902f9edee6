// SPDX-License-Identifier: Apache-2.0
#pragma once
// The rigid3d body as the model of the forced analyses (forced_model.hpp): the planar analyses'
// horizontal ground motion acts along `incidence_deg` (degrees from the body's e1 towards e2; the
// body stands at yaw 0), their vertical as the vertical; one run reduced to what they classify
// (overturned, when, the largest tilt, the distance slid). Its slenderness alpha is the rest
// threshold in that direction (atan of it: b/h along e1, d/h along e2, the nearer corner's between,
// 2a/h for a cylinder) and p the frequency parameter of the rocking that threshold starts.
#include "blockdyn/analysis/forced/forced_model.hpp"
#include "blockdyn/model/rigid3d/body_on_ground.hpp"

namespace blockdyn {

ForcedModel forced_body3d_model(const Body3d& body, const BodyOnGroundOptions& friction, double incidence_deg);

}  // namespace blockdyn
