// SPDX-License-Identifier: Apache-2.0
#pragma once
// `blockdyn motion info`: a record's intensity measures (pga, pgv, pgd, Arias intensity, D5-95,
// t_mid, mean period) and, on request, its pseudo-acceleration spectrum, from options by name:
// `record` (a file: PEER .AT2 or CSV "t, a" in s, g; or arrays), `spectrum`, `periods` or
// `period-min/max/points`, `damping`, `g`.
#include <memory>
#include <vector>

#include <nlohmann/json.hpp>

#include "blockdyn/commands/option_spec.hpp"
#include "blockdyn/commands/settings.hpp"
#include "blockdyn/excitation/intensity_measures.hpp"

namespace blockdyn {

const std::vector<StudyOption>& motion_info_options();
// The JSON document (schema blockdyn.motion-info.summary/1); std::invalid_argument naming the
// option for bad input (a record with non-monotone times, NaN, zero dt; periods <= 0; damping
// outside [0, 1)).
nlohmann::ordered_json motion_info(const Settings& s);
// The option `record`: a record given as arrays, or a file (PEER .AT2, CSV); std::invalid_argument
// naming "record".
std::shared_ptr<const Accelerogram> record_from(const Settings& s);
// The measures as JSON keys pga, pgv, pgd, arias, d5_95, t5, t95, t_mid, mean_period,
// final_velocity, final_displacement (null where not finite).
nlohmann::ordered_json measures_json(const IntensityMeasures& m);
// The same for a person: one measure per line, then the spectrum's rows.
std::string motion_info_text(const nlohmann::ordered_json& j);

}  // namespace blockdyn
