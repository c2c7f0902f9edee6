// SPDX-License-Identifier: Apache-2.0
#pragma once
// Which of the thesis's initial-condition sets a parameter study starts from: ic2, ic1 with the
// default tilt alpha/2, or an ic1 variant tilted by a fraction of alpha (alpha/4, ...). Studies
// vary k and r, so the tilt is given relative to alpha = atan(r), not as an angle.
#include <string>

#include "blockdyn/model/winkler/winkler_params.hpp"
#include "blockdyn/model/winkler/winkler_state.hpp"

namespace blockdyn {

struct IcChoice {
  enum class Set { Ic1, Ic2 } set = Set::Ic1;
  double w0_fraction = 0.5;  // ic1 only: w0 = w0_fraction * alpha, in (0, 1]

  WinklerState state(const WinklerParams& p) const;
  // "ic1", "ic2", or "ic1:<fraction>" for variants; parse(name()) round-trips.
  std::string name() const;
  bool is_ic1() const { return set == Set::Ic1; }
};

// Parses "ic1", "ic2" or "ic1:F" (0 < F <= 1, w0 = F alpha); throws std::invalid_argument.
IcChoice parse_ic_choice(const std::string& s);

}  // namespace blockdyn
