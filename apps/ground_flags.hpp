// SPDX-License-Identifier: Apache-2.0
#pragma once
// The ground-motion flags every command that runs a model accepts: --ground-h... (horizontal)
// and --ground-v... (vertical), each constant, harmonic, pulse or recorded, in units of g.
#include <CLI/CLI.hpp>

#include <string>

#include "blockdyn/excitation/ground_motion.hpp"

namespace blockdyn::cli {

struct GroundComponentFlags {
  double constant = 0, amplitude = 0, frequency = 0, phase = 0, start = 0, duration = 0, scale = 1;
  std::string pulse, record;
};

struct GroundFlags {
  GroundComponentFlags h, v;
};

void add_ground_flags(CLI::App& app, GroundFlags& f);
// Sets the fields of g whose flags were given (a record file is read here).
void apply_ground_flags(const CLI::App& app, const GroundFlags& f, GroundMotion& g);

}  // namespace blockdyn::cli
