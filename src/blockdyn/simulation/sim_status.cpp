// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/simulation/sim_status.hpp"

#include <iterator>

namespace blockdyn {

const char* to_string(SimStatus s) {
  // In the enumeration's order (the JSON's "status" strings).
  static const char* const names[] = {"t_end", "overturned", "invalid", "early_stop", "numerical_failure", "collapsed"};
  static_assert(std::size(names) == std::size_t(SimStatus::Collapsed) + 1);
  const auto i = std::size_t(s);
  return i < std::size(names) ? names[i] : "?";
}

SimStatus sim_status(RunStatus rs, bool overturned) {
  switch (rs) {
    case RunStatus::ReachedEnd:
      return SimStatus::TEnd;
    case RunStatus::ModelStop:
      return overturned ? SimStatus::Overturned : SimStatus::Invalid;
    case RunStatus::ObserverStop:
      return SimStatus::EarlyStop;
    default:
      return SimStatus::NumericalFailure;
  }
}

}  // namespace blockdyn
