// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/chaos_map.hpp"

#include <cmath>
#include <stdexcept>

#include "blockdyn/analysis/sweep/parallel_map.hpp"

namespace blockdyn {

void validate(const ChaosMapOptions& o) {
  validate(o.grid);
  if (o.grid.excitation != "harmonic")
    throw std::invalid_argument("excitation = " + o.grid.excitation + ": the chaos map needs harmonic excitation");
  if (!(o.transient_periods >= 0 && o.transient_periods <= 1e5))
    throw std::invalid_argument("transient-periods must be in [0, 1e5]");
  if (!o.use_t_end && !(o.total_periods > o.transient_periods && o.total_periods <= 1e6))
    throw std::invalid_argument("periods must be > transient-periods and <= 1e6");
  if (!(o.interval_periods > 0 && o.interval_periods <= 1e3))
    throw std::invalid_argument("interval-periods must be in (0, 1000]");
  if (!(o.threshold >= 0 && std::isfinite(o.threshold)))
    throw std::invalid_argument("threshold must be finite and >= 0");
}

ChaosPoint chaos_point(const ForcedLyapunovRun& run, const ChaosMapOptions& o, double beta, double omega, double alpha,
                       double p) {
  ChaosPoint pt;
  pt.beta = beta;
  pt.omega = omega;
  const double T = 2 * M_PI / (omega * p);
  ForcedLyapunovOptions fo;
  fo.t_end = o.use_t_end ? o.grid.t_end : o.total_periods * T;
  fo.t_transient = std::fmin(o.transient_periods * T, 0.999 * fo.t_end);
  fo.interval = o.interval_periods * T;
  fo.integrator = o.integrator;
  fo.keep_history = true;
  const ForcedLyapunovOutcome r = run(survival_motion(o.grid, beta, omega, alpha, p), fo);
  pt.status = to_string(r.tangent.status);
  pt.impacts = r.impacts;
  pt.collapse_mode = r.collapse_mode;
  pt.t_failure = r.t_failure;
  pt.t_tangent = r.tangent.t_tangent;
  switch (r.tangent.status) {
    case TangentStatus::NeverMoved:
      pt.motion = "rest";
      break;
    case TangentStatus::Superstable:
      pt.motion = "superstable";
      pt.exponent = pt.exponent_nondim = pt.exponent_second_half = -INFINITY;
      break;
    case TangentStatus::Stopped:
    case TangentStatus::Failed:
      pt.motion = r.collapse_mode ? "collapse" : "failed";
      pt.exponent = r.tangent.exponent;
      pt.exponent_nondim = r.tangent.exponent / p;
      break;
    case TangentStatus::Completed: {
      pt.exponent = r.tangent.exponent;
      pt.exponent_nondim = r.tangent.exponent / p;
      pt.exponent_second_half = r.exponent_second_half;
      pt.motion = pt.exponent_nondim > o.threshold    ? "chaotic"
                  : pt.exponent_nondim < -o.threshold ? "periodic"
                                                      : "neutral";
      break;
    }
  }
  return pt;
}

std::vector<ChaosPoint> chaos_map(const ForcedLyapunovRun& run, const ChaosMapOptions& o, double alpha, double p,
                                  const std::function<void(std::size_t)>& progress) {
  validate(o);
  const SurvivalOptions& g = o.grid;
  if (!g.betas.empty() && int(g.betas.size()) != g.beta_points)
    throw std::invalid_argument("betas: beta-points must equal the number of betas given");
  auto axis = [](double lo, double hi, int n, int i) { return n == 1 ? lo : lo + (hi - lo) * i / (n - 1); };
  const std::size_t n = std::size_t(g.beta_points) * g.omega_points;
  std::vector<ChaosPoint> pts(n);
  std::size_t done = 0;
  parallel_for(
      n, g.threads,
      [&](std::size_t k) {
        const int bi = int(k / g.omega_points);
        const double beta = g.betas.empty() ? axis(g.beta_min, g.beta_max, g.beta_points, bi) : g.betas[bi];
        const double omega = axis(g.omega_min, g.omega_max, g.omega_points, int(k % g.omega_points));
        pts[k] = chaos_point(run, o, beta, omega, alpha, p);
      },
      [&](std::size_t) {
        ++done;
        if (progress) progress(done);
      });
  return pts;
}

}  // namespace blockdyn
