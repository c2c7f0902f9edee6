// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/simulation/sim_status.hpp"

namespace blockdyn {

const char* to_string(SimStatus s) {
  switch (s) {
    case SimStatus::TEnd:
      return "t_end";
    case SimStatus::Overturned:
      return "overturned";
    case SimStatus::Invalid:
      return "invalid";
    case SimStatus::EarlyStop:
      return "early_stop";
    case SimStatus::NumericalFailure:
      return "numerical_failure";
    case SimStatus::Collapsed:
      return "collapsed";
  }
  return "?";
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
