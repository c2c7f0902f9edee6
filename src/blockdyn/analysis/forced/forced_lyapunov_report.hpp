// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a forced Lyapunov run reports: the summary document (model, ground, options, exponent,
// saltation statistics, coarse history, sensitivity of two nearby orbits) and the twin table.

#include <nlohmann/json.hpp>

#include "blockdyn/analysis/forced/forced_model.hpp"
#include "blockdyn/io/table_cell.hpp"

namespace blockdyn {

// excitation: the seed form's parameters (null when the ground motion was given directly).
nlohmann::ordered_json forced_lyapunov_summary(const ForcedModel& fm, const GroundMotion& g,
                                               const nlohmann::ordered_json& excitation, const ForcedLyapunovOptions& o,
                                               const ForcedLyapunovOutcome& r);
// The table t, separation, predicted (the first separation grown at the exponent).
CellTable twin_table(const ForcedLyapunovOutcome& r);

}  // namespace blockdyn
