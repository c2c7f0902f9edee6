// SPDX-License-Identifier: Apache-2.0
#pragma once
// JSON views of parameters, options, states and results (nlohmann::json). Doubles are written
// with full round-trip precision by nlohmann's serializer.
#include <nlohmann/json.hpp>

#include <cmath>

#include "blockdyn/excitation/ground_motion.hpp"
#include "blockdyn/simulation/rigid_ground_model.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"
#include "blockdyn/units/physical_units.hpp"

namespace blockdyn {

nlohmann::ordered_json to_json(const WinklerParams& p);
nlohmann::ordered_json to_json(const GroundComponent& c);
nlohmann::ordered_json to_json(const GroundMotion& g);
nlohmann::ordered_json to_json(const IntegratorOptions& o);
nlohmann::ordered_json state_json(const WinklerState& z);                       // x, y, w, vx, vy, vw
nlohmann::ordered_json state_json(const WinklerState& z, const UnitScales& s);  // physical units
nlohmann::ordered_json to_json(const Energy& e);
nlohmann::ordered_json to_json(const WinklerEventRecord& e);
nlohmann::ordered_json run_info();  // program version, for every output
// A number, or null where it is not finite (JSON has no NaN or infinity).
inline nlohmann::ordered_json finite_or_null(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}
// Version of the JSON layouts documented in docs/output-formats.md: raised when a key is removed
// or changes meaning (new keys may be added within a version).
inline constexpr int kJsonSchemaVersion = 1;
// "blockdyn.<command>.<kind>/<kJsonSchemaVersion>", e.g. "blockdyn.simulate.summary/1".
std::string schema_name(const std::string& command, const std::string& kind);
// Everything `simulate --json` prints (physical block and scales optional).
nlohmann::ordered_json result_json(const WinklerParams& p, const GroundMotion& g, const WinklerRunOptions& o,
                                   const WinklerResult& r, const PhysicalBlock* phys = nullptr);

// Everything `simulate --json` prints of a block on rigid ground (either model).
nlohmann::ordered_json to_json(const RigidEventRecord& e);
nlohmann::ordered_json rigid_result_json(const RigidBlockParams& p, const RigidGroundModel& m, const GroundMotion& g,
                                         const RigidRunOptions& o, const RigidResult& r);

// The integration's wall and CPU time: {"integration_wall_s", "integration_cpu_s"}.
nlohmann::ordered_json to_json(const RunTiming& t);

// Prints JSON with non-finite numbers as null (JSON has no inf/nan).
std::string dump_json(const nlohmann::ordered_json& j, int indent = 2);

}  // namespace blockdyn
