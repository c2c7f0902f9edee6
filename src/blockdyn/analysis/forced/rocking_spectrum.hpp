// SPDX-License-Identifier: Apache-2.0
#pragma once
// A rocking spectrum (Makris and Konstantinidis 2003) as a typed C++ call: blocks on rigid ground
// of one slenderness alpha and a range of frequency parameters p = sqrt(3 g / (4 R)) (their size R
// set by p), each under one record at one or more scales: the largest rotation over alpha and
// whether it overturns; per p, the smallest scale of the list that overturns it. `blockdyn
// rocking-spectrum` runs the same points (rocking_spectrum_point) on the sweep runner.
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "blockdyn/excitation/accelerogram.hpp"
#include "blockdyn/model/rigid_ground/rigid_params.hpp"
#include "blockdyn/simulation/rigid_ground_model.hpp"

namespace blockdyn {

// The block of slenderness alpha and frequency parameter p, otherwise as `base` (its mass, g,
// friction, impact law): half-diagonal R = 3 g / (4 p^2), width 2 R sin(alpha), height 2 R cos(alpha).
RigidBlockParams block_of_slenderness(const RigidBlockParams& base, double alpha, double p);

struct RockingSpectrumOptions {
  double alpha = 0;               // rad, in (0, pi/4]
  std::vector<double> p;          // rad/s
  std::vector<double> scales{1};  // of the record, ascending for the overturning scales
  double t_end = 0;               // s, every run
  int threads = 1;                // rocking_spectrum's worker threads (0: all cores)
};

struct RockingSpectrumPoint {
  double p = 0, scale = 0, width = 0, height = 0;
  double max_abs_rotation_over_alpha = 0;
  bool overturned = false;
  std::optional<double> overturn_time;
};
// Point i of the spectrum: p[i % P] under the record at scales[i / P] (p fastest).
RockingSpectrumPoint rocking_spectrum_point(const RigidGroundModel& m, const RigidBlockParams& base,
                                            const RockingSpectrumOptions& o,
                                            const std::shared_ptr<const Accelerogram>& record, std::size_t i);
// Every point in memory (o.threads), indexed as rocking_spectrum_point.
std::vector<RockingSpectrumPoint> rocking_spectrum(const RigidGroundModel& m, const RigidBlockParams& base,
                                                   const RockingSpectrumOptions& o,
                                                   const std::shared_ptr<const Accelerogram>& record);

// Per p, the smallest of the scales (in the order given) under which the block overturns (none:
// it survives every one).
struct OverturningScale {
  double p = 0;
  std::optional<double> scale;
};
std::vector<OverturningScale> overturning_scales(const std::vector<RockingSpectrumPoint>& points,
                                                 const RockingSpectrumOptions& o);

}  // namespace blockdyn
