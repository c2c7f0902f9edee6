// SPDX-License-Identifier: Apache-2.0
#pragma once
// A simulation scenario: everything one `blockdyn simulate` run needs, readable from TOML so
// runs are reproducible from a file. Unknown keys are errors (a typo must not be ignored).
#include <optional>
#include <string>

#include "blockdyn/excitation/ground_motion.hpp"
#include "blockdyn/model/rigid_ground/rigid_params.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"
#include "blockdyn/units/physical_units.hpp"

namespace blockdyn {

struct InitialSpec {
  std::string set = "ic1";   // ic1 | ic2 | custom
  std::optional<double> w0;  // ic1 tilt override, or custom w
  // custom (and overrides applied on top of ic1/ic2)
  std::optional<double> x0, y0, vx0, vy0, vw0;
};

struct Scenario {
  std::string model = "winkler";  // a family that a scenario describes (scenario_family())
  WinklerParams params;
  std::optional<PhysicalBlock> physical;  // when given, params are derived from it
  // housner / rigid: the block's shape comes from [physical]; interface and impact from here.
  Coulomb interface { 0.7, 0.7 };
  ImpactLaw impact = ImpactLaw::Housner;
  std::optional<double> restitution;
  GroundMotion ground;  // times in seconds for physical blocks and the rigid models
  InitialSpec initial;
  WinklerRunOptions options;
  double output_interval = 0.01;
  std::string trajectory;        // CSV path, empty: none
  std::string plot;              // PNG path, empty: none
  std::string units = "nondim";  // nondim | physical (adds physical columns / fields)
};

struct Family;
// The family named, if a scenario describes it (winkler, housner, rigid); throws
// std::invalid_argument "<field> = '<name>' is not one of: <those families>".
const Family& scenario_family(const std::string& name, const std::string& field = "`model`");

// Reads a TOML scenario; throws std::invalid_argument with the offending key on error.
// Record paths in [ground.*] are relative to the scenario file's directory.
Scenario load_scenario(const std::string& path);
Scenario parse_scenario(const std::string& toml_text, const std::string& source_name, const std::string& base_dir = "");

// The rigid-family parameters (shape from [physical], default mass 1 kg).
RigidBlockParams rigid_params(const Scenario& s);

// The initial state vector the scenario asks for (validated against the model).
WinklerState initial_state(const Scenario& s);

}  // namespace blockdyn
