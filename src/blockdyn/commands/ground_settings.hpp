// SPDX-License-Identifier: Apache-2.0
#pragma once
// The ground-motion options every run accepts, for every family: ground-h... (horizontal) and
// ground-v... (vertical), each constant, harmonic, pulse or recorded (a file, or samples), in g.
#include <string>
#include <vector>

#include "blockdyn/commands/option_spec.hpp"
#include "blockdyn/commands/settings.hpp"
#include "blockdyn/excitation/ground_motion.hpp"
#include "blockdyn/excitation/ground_motion_3d.hpp"

namespace blockdyn {

// The options, with their help, for front ends that register them.
const std::vector<StudyOption>& ground_options();
// The rigid3d family's further components: ground-h2... (the second horizontal) and ground-azimuth.
const std::vector<StudyOption>& ground_3d_options();
// Their names (without dashes), for front ends that list or check them.
const std::vector<std::string>& ground_option_names();
// Sets the fields of g whose options were given (a record file is read here). Throws
// std::invalid_argument naming the option.
void apply_ground_settings(const Settings& s, GroundMotion& g);
// The same for three components (ground-h, ground-h2, ground-v, ground-azimuth).
void apply_ground_settings(const Settings& s, GroundMotion3d& g);

}  // namespace blockdyn
