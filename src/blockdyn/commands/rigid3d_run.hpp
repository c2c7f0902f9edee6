// SPDX-License-Identifier: Apache-2.0
#pragma once
// The rigid3d family's command layer (`simulate --model rigid3d`, docs/3d.md): its options, their
// parse into the typed run (a Body3d, its ground motion in three components, its initial state),
// and the report: the JSON summary, the trajectory's columns, the figure's script.
#include <memory>
#include <string>
#include <vector>

#include "blockdyn/commands/option_spec.hpp"
#include "blockdyn/commands/settings.hpp"

namespace blockdyn {

class PreparedRun;

// The options only rigid3d has (with their help), for the front ends to register.
const std::vector<StudyOption>& rigid3d_options();
// Every option `simulate --model rigid3d` reads.
const std::vector<std::string>& rigid3d_option_names();
// Throws std::invalid_argument naming the option, its value and its range.
std::unique_ptr<PreparedRun> prepare_rigid3d(const Settings& s);

// The trajectory's columns, in order.
const std::vector<std::string>& rigid3d_columns();
// A sweep's result columns (summary keys) and its axes (the numeric options) for `list-axes`.
const std::vector<std::string>& rigid3d_result_keys();
std::vector<std::pair<std::string, std::string>> rigid3d_sweep_axes();

// The body and its friction from options by name (the forced analyses' rigid3d model).
struct Body3d;
struct BodyOnGroundOptions;
Body3d body3d_from(const Settings& s);
BodyOnGroundOptions body3d_friction_from(const Settings& s);

}  // namespace blockdyn
