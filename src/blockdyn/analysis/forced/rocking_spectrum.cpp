// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/rocking_spectrum.hpp"

#include <cmath>

#include "blockdyn/analysis/forced/forced_model.hpp"
#include "blockdyn/analysis/sweep/parallel_map.hpp"

namespace blockdyn {

RigidBlockParams block_of_slenderness(const RigidBlockParams& base, double alpha, double p) {
  RigidBlockParams b = base;
  const double R = 0.75 * base.shape.g / (p * p);
  b.shape.width = 2 * R * std::sin(alpha);
  b.shape.height = 2 * R * std::cos(alpha);
  return b;
}

RockingSpectrumPoint rocking_spectrum_point(const RigidGroundModel& m, const RigidBlockParams& base,
                                            const RockingSpectrumOptions& o,
                                            const std::shared_ptr<const Accelerogram>& record, std::size_t i) {
  RockingSpectrumPoint pt;
  pt.p = o.p[i % o.p.size()];
  pt.scale = o.scales[i / o.p.size()];
  const RigidBlockParams b = block_of_slenderness(base, o.alpha, pt.p);
  GroundMotion gm;
  gm.horizontal.record = record;
  gm.horizontal.scale = pt.scale;
  const SurvivalOutcome out = forced_block_model(b, m).run(gm, o.t_end);
  pt.width = b.shape.width;
  pt.height = b.shape.height;
  pt.max_abs_rotation_over_alpha = out.max_abs_rotation / o.alpha;
  pt.overturned = out.collapse_mode.has_value();
  pt.overturn_time = out.t_failure;
  return pt;
}

std::vector<RockingSpectrumPoint> rocking_spectrum(const RigidGroundModel& m, const RigidBlockParams& base,
                                                   const RockingSpectrumOptions& o,
                                                   const std::shared_ptr<const Accelerogram>& record) {
  std::vector<RockingSpectrumPoint> pts(o.p.size() * o.scales.size());
  parallel_for(pts.size(), o.threads, [&](std::size_t i) { pts[i] = rocking_spectrum_point(m, base, o, record, i); });
  return pts;
}

std::vector<OverturningScale> overturning_scales(const std::vector<RockingSpectrumPoint>& points,
                                                 const RockingSpectrumOptions& o) {
  std::vector<OverturningScale> out;
  for (double p : o.p) {
    OverturningScale s{p, std::nullopt};
    for (std::size_t k = 0; k < o.scales.size() && !s.scale; ++k)
      for (const RockingSpectrumPoint& r : points)
        if (r.p == p && r.scale == o.scales[k] && r.overturned) {
          s.scale = o.scales[k];
          break;
        }
    out.push_back(s);
  }
  return out;
}

}  // namespace blockdyn
