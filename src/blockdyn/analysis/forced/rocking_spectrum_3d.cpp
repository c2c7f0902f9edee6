// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/rocking_spectrum_3d.hpp"

#include <algorithm>
#include <cmath>

namespace blockdyn {

BoxSize box_of_slenderness(double alpha, double p, double depth_ratio, double g) {
  const double R = 0.75 * g / (p * p);
  BoxSize s;
  s.width = 2 * R * std::sin(alpha);
  s.height = 2 * R * std::cos(alpha);
  s.depth = depth_ratio * s.width;
  return s;
}

RockingSpectrum3dPoint rocking_spectrum_3d_point(const SpatialModelAt& model, const RockingSpectrum3dOptions& o,
                                                 const ComponentRecords& records, std::size_t i) {
  const std::size_t np = o.p.size(), ns = o.scales.size(), na = o.incidences.size();
  RockingSpectrum3dPoint pt;
  pt.p = o.p[i % np];
  pt.scale = o.scales[(i / np) % ns];
  pt.incidence = o.incidences[(i / (np * ns)) % na];
  pt.record = i / (np * ns * na);
  pt.size = box_of_slenderness(o.alpha, pt.p, o.depth_ratio, o.g);
  const GroundMotion3d g3 =
      record_components(records.h1[pt.record], records.h2.empty() ? nullptr : records.h2[pt.record],
                        records.v.empty() ? nullptr : records.v[pt.record], pt.scale, pt.incidence);
  const double t_end = o.t_end ? *o.t_end : records.h1[pt.record]->t_last() + o.t_after;
  const SurvivalOutcome out = model(pt.size).run3(g3, t_end);
  pt.max_tilt_over_alpha = out.max_abs_rotation / o.alpha;
  pt.overturned = out.collapse_mode.has_value();
  pt.outside_model = out.invalid && !pt.overturned;
  pt.overturn_time = out.t_failure;
  return pt;
}

std::vector<CriticalIncidence> incidence_summary(const std::vector<RockingSpectrum3dPoint>& points,
                                                 const RockingSpectrum3dOptions& o) {
  std::vector<CriticalIncidence> out;
  for (double a : o.incidences) {
    CriticalIncidence c;
    c.incidence = a;
    std::vector<double> tilt;
    for (const RockingSpectrum3dPoint& pt : points) {
      if (pt.incidence != a) continue;
      ++c.runs;
      c.overturned += pt.overturned;
      c.outside_model += pt.outside_model;
      if (!pt.outside_model) tilt.push_back(pt.overturned ? INFINITY : pt.max_tilt_over_alpha);
    }
    if (!tilt.empty()) {
      std::sort(tilt.begin(), tilt.end());
      const std::size_t n = tilt.size();
      c.median_tilt_over_alpha = n % 2 ? tilt[n / 2] : 0.5 * (tilt[n / 2 - 1] + tilt[n / 2]);
    }
    out.push_back(c);
  }
  return out;
}

const CriticalIncidence& critical_of(const std::vector<CriticalIncidence>& by_incidence) {
  std::size_t best = 0;
  for (std::size_t k = 1; k < by_incidence.size(); ++k) {
    const CriticalIncidence &a = by_incidence[k], &b = by_incidence[best];
    if (a.overturned > b.overturned ||
        (a.overturned == b.overturned && a.median_tilt_over_alpha > b.median_tilt_over_alpha))
      best = k;
  }
  return by_incidence[best];
}

}  // namespace blockdyn
