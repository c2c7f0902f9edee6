// SPDX-License-Identifier: Apache-2.0
#pragma once
// The rocking spectrum of a body in space (a family whose forced model runs under three ground
// components, ForcedModel::run3): boxes of one slenderness alpha = atan(b / h) and a range of
// frequency parameters p = sqrt(3 g / (4 R)) (R the half diagonal of the b x h section, the size
// set by p; the depth d = depth_ratio b), each under every record of a suite (one to three
// components: h1 along the incidence, h2 across it, v vertical) at every scale and every
// incidence: the largest tilt over alpha, whether it overturns, whether the run left the model.
// Per p and scale, and over the whole spectrum, the critical incidence: the one that overturns
// most bodies, then the one of the largest median tilt. `blockdyn rocking-spectrum --model
// rigid3d` runs the same points on the sweep runner.
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "blockdyn/analysis/forced/forced_model.hpp"
#include "blockdyn/excitation/accelerogram.hpp"

namespace blockdyn {

struct ComponentRecords {
  std::vector<std::shared_ptr<const Accelerogram>> h1, h2, v;  // h2 and v empty or one per h1
  std::vector<std::string> names;                              // one per record
  std::size_t size() const { return h1.size(); }
};

struct RockingSpectrum3dOptions {
  double alpha = 0;                   // rad, in (0, pi/4]
  std::vector<double> p;              // rad/s
  std::vector<double> scales{1};      // of every component
  std::vector<double> incidences{0};  // degrees: h1's direction from the body's e1
  double depth_ratio = 1;             // d / b
  double g = 9.81;                    // m/s^2 (the size from p)
  std::optional<double> t_end;        // s, every run; empty: each record's end + t_after
  double t_after = 5;
  std::size_t size(const ComponentRecords& r) const { return p.size() * scales.size() * incidences.size() * r.size(); }
};

// The body of width b, depth d and height h: what the family builds its forced model from.
struct BoxSize {
  double width = 0, depth = 0, height = 0;
};
BoxSize box_of_slenderness(double alpha, double p, double depth_ratio, double g);
using SpatialModelAt = std::function<ForcedModel(const BoxSize&)>;

struct RockingSpectrum3dPoint {
  double p = 0, scale = 0, incidence = 0;
  std::size_t record = 0;
  BoxSize size;
  double max_tilt_over_alpha = 0;
  bool overturned = false, outside_model = false;
  std::optional<double> overturn_time;
};
// Point i: p fastest, then scale, incidence, record.
RockingSpectrum3dPoint rocking_spectrum_3d_point(const SpatialModelAt& model, const RockingSpectrum3dOptions& o,
                                                 const ComponentRecords& records, std::size_t i);

struct CriticalIncidence {
  double incidence = 0;
  std::size_t runs = 0, overturned = 0, outside_model = 0;
  double median_tilt_over_alpha = 0;  // over the runs that stayed in the model
};
// Per incidence over the given points, in the order of o.incidences.
std::vector<CriticalIncidence> incidence_summary(const std::vector<RockingSpectrum3dPoint>& points,
                                                 const RockingSpectrum3dOptions& o);
// The critical one of a summary: most overturned, then the largest median tilt (first on ties).
const CriticalIncidence& critical_of(const std::vector<CriticalIncidence>& by_incidence);

}  // namespace blockdyn
