// SPDX-License-Identifier: Apache-2.0
#pragma once
// A sweep of any family whose runs `simulate` prepares from options (family.prepare) and whose
// summary names its results: each axis an option of the family (`--axis NAME=SPEC`, NAME with
// '-' or '_'), each point the family's run with those values, its row the axes and the summary's
// result keys (family.result_keys). The rigid3d sweep is this one; no per-family code.
#include "blockdyn/commands/settings.hpp"
#include "blockdyn/commands/sweep_settings.hpp"
#include "blockdyn/family/family.hpp"

namespace blockdyn {

SweepDefinition settings_sweep(const Settings& s, const Family& family);

}  // namespace blockdyn
