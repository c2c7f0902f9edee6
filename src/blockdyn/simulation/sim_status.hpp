// SPDX-License-Identifier: Apache-2.0
#pragma once
// The one status vocabulary of a run's result, shared by every model family (the JSON's
// "status"), beside the integrator's own RunStatus ("integrator_status").
#include "blockdyn/integrate/integrator_options.hpp"

namespace blockdyn {

// How a run ended, for every family: at t_end, failed (a block overturned; an assembly
// collapsed), outside the model (invalid), stopped early by a criterion, or a numerical failure.
enum class SimStatus { TEnd, Overturned, Invalid, EarlyStop, NumericalFailure, Collapsed };
const char* to_string(SimStatus s);
// The outcome users see, from the integrator's status (ModelStop: overturned, else invalid).
SimStatus sim_status(RunStatus rs, bool overturned);

}  // namespace blockdyn
