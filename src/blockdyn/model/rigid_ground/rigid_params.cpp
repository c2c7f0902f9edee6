// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/rigid_ground/rigid_params.hpp"

#include "blockdyn/base/number_text.hpp"

#include <cmath>

#include "blockdyn/base/checks.hpp"

namespace blockdyn {

const char* to_string(ImpactLaw l) {
  switch (l) {
    case ImpactLaw::Housner:
      return "housner";
    case ImpactLaw::Newton:
      break;
  }
  return "newton";
}

std::optional<ImpactLaw> impact_law_from_string(const std::string& s) {
  for (const ImpactLaw l : {ImpactLaw::Housner, ImpactLaw::Newton})
    if (s == to_string(l)) return l;
  return std::nullopt;
}

void validate(const RigidBlockParams& p) {
  validate(p.shape);
  const Coulomb& c = p.interface;
  require(std::isfinite(c.mu_s) && c.mu_s >= 0.0 && c.mu_s <= 1e3, "mu-s", "in [0, 1e3]", c.mu_s);
  require(std::isfinite(c.mu_k) && c.mu_k >= 0.0, "mu-k", "finite and >= 0", c.mu_k);
  require(c.mu_k <= c.mu_s, "mu-k", "<= mu-s = " + number_text(c.mu_s), c.mu_k);
  if (p.restitution)
    require(std::isfinite(*p.restitution) && *p.restitution >= 0.0 && *p.restitution <= 1.0, "restitution", "in [0, 1]",
            *p.restitution);
}

}  // namespace blockdyn
