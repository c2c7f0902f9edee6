// SPDX-License-Identifier: Apache-2.0
#pragma once
// The JSON summary of an assembly run (docs/assemblies.md lists the keys).
#include <nlohmann/json.hpp>

#include "blockdyn/excitation/ground_motion.hpp"
#include "blockdyn/simulation/assembly_simulation.hpp"

namespace blockdyn {

nlohmann::ordered_json to_json(const Assembly& a);
// One event of the summary's "events" list.
nlohmann::ordered_json to_json(const AssemblyEventRecord& e);
nlohmann::ordered_json assembly_result_json(const Assembly& a, const GroundMotion& g, const AssemblyRunOptions& o,
                                            const AssemblyResult& r);

}  // namespace blockdyn
