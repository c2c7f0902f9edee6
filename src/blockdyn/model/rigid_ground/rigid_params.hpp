// SPDX-License-Identifier: Apache-2.0
#pragma once
// Immutable parameters of a rigid block on rigid ground: the block's shape, the interface
// (Coulomb friction, static and kinetic) and the impact law. SI units throughout.
#include <optional>
#include <string>

#include "blockdyn/model/common/block_shape.hpp"
#include "blockdyn/model/common/coulomb.hpp"

namespace blockdyn {

enum class ImpactLaw {
  Housner,  // the impacting corner sticks, angular momentum about it is conserved (rocking impacts
            // then lose exactly e_H; a user restitution e replaces e_H there)
  Newton    // Newton restitution e_n at the impacting corner, Coulomb friction at impulse level
};
const char* to_string(ImpactLaw l);
std::optional<ImpactLaw> impact_law_from_string(const std::string& s);

struct RigidBlockParams {
  BlockShape shape;
  Coulomb interface { 0.7, 0.7 };
  ImpactLaw impact = ImpactLaw::Housner;
  std::optional<double> restitution;  // empty: Housner's e_H (housner law) or 0 (newton law)

  // The restitution in effect: for the housner law the rocking coefficient e, for the newton law
  // the normal coefficient e_n.
  double e() const {
    if (restitution) return *restitution;
    return impact == ImpactLaw::Housner ? shape.housner_restitution() : 0.0;
  }
};

// Throws std::invalid_argument naming the field (mu-k > mu-s, restitution outside [0, 1], ...).
void validate(const RigidBlockParams& p);

}  // namespace blockdyn
