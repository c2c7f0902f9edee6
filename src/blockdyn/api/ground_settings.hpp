// SPDX-License-Identifier: Apache-2.0
#pragma once
// The ground-motion options every run accepts, for every family: ground-h... (horizontal) and
// ground-v... (vertical), each constant, harmonic, pulse or recorded (a file, or samples), in g.
#include <string>
#include <vector>

#include "blockdyn/api/option_spec.hpp"
#include "blockdyn/api/settings.hpp"
#include "blockdyn/excitation/ground_motion.hpp"

namespace blockdyn {

// The options, with their help, for front ends that register them.
const std::vector<StudyOption>& ground_options();
// Their names (without dashes), for front ends that list or check them.
const std::vector<std::string>& ground_option_names();
// Sets the fields of g whose options were given (a record file is read here). Throws
// std::invalid_argument naming the option.
void apply_ground_settings(const Settings& s, GroundMotion& g);

}  // namespace blockdyn
