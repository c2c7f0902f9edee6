// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/survival_map.hpp"

#include "blockdyn/base/number_text.hpp"

#include <cmath>
#include <stdexcept>

#include "blockdyn/analysis/sweep/parallel_map.hpp"

namespace blockdyn {

void validate(const SurvivalOptions& o) {
  if (o.excitation != "harmonic" && o.excitation != "half-sine" && o.excitation != "half-cosine" &&
      o.excitation != "rect")
    throw std::invalid_argument("excitation = '" + o.excitation + "' must be harmonic, half-sine, half-cosine or rect");
  for (double b : o.betas)
    if (!(b > 0 && b <= 1e3)) throw std::invalid_argument("betas: each must be in (0, 1000]");
  if (!(o.beta_min > 0 && o.beta_max >= o.beta_min && o.beta_max <= 1e3))
    throw std::invalid_argument("beta-min, beta-max: need 0 < min <= max <= 1000");
  if (!(o.omega_min > 0 && o.omega_max >= o.omega_min && o.omega_max <= 1e4))
    throw std::invalid_argument("omega-min, omega-max: need 0 < min <= max <= 1e4");
  if (!(o.beta_points >= 1 && o.omega_points >= 1 && double(o.beta_points) * o.omega_points <= 1e7))
    throw std::invalid_argument("beta-points, omega-points: at least 1 each, at most 1e7 points");
  if (!(o.t_end > 0 && o.t_end <= 1e5)) throw std::invalid_argument("t-end must be in (0, 1e5] s");
  // A run shorter than a hundredth of a forcing period observes nothing (4.9e-324 periods gave
  // every point a t-end of 0).
  if (!(o.periods == 0 || (o.periods >= 1e-2 && o.periods <= 1e5)))
    throw std::invalid_argument("periods = " + number_text(o.periods) +
                                " is out of range: must be in [0.01, 1e5] forcing periods (or 0: use t-end)");
  if (!(std::isfinite(o.phase))) throw std::invalid_argument("phase must be finite");
}

GroundMotion survival_motion(const SurvivalOptions& o, double beta, double omega, double alpha, double p) {
  GroundMotion g;
  const double Omega = omega * p;
  if (o.excitation == "harmonic") {
    // cos(Omega t + phase) = sin(Omega t + phase + pi/2).
    g.horizontal.amplitude = beta * alpha;
    g.horizontal.frequency = Omega / (2 * M_PI);
    g.horizontal.phase = o.phase + 0.5 * M_PI;
  } else {
    g.horizontal.amplitude = beta * alpha;
    g.horizontal.duration = M_PI / Omega;  // half a forcing period
    g.horizontal.pulse = o.excitation == "half-sine"     ? PulseShape::HalfSine
                         : o.excitation == "half-cosine" ? PulseShape::HalfCosine
                                                         : PulseShape::Rect;
  }
  return g;
}

std::string t_star_class(const SurvivalOptions& o, double t) {
  static const char* names[] = {"<=5 s", "short", "medium", "long", "very long"};
  for (std::size_t k = 0; k < o.t_star_classes.size() && k < 4; ++k)
    if (t <= o.t_star_classes[k])
      return k == 0 ? "<=" + std::to_string(int(std::lround(o.t_star_classes[0]))) + " s" : names[k];
  return names[4];
}

double grid_value(double lo, double hi, int n, int i) { return n == 1 ? lo : lo + (hi - lo) * i / (n - 1); }

SurvivalPoint survival_point(const SurvivalRun& run, const SurvivalOptions& o, double alpha, double p, double beta,
                             double omega) {
  SurvivalPoint pt;
  pt.beta = beta;
  pt.omega = omega;
  const double t_end = o.periods > 0 ? o.periods * 2 * M_PI / (omega * p) : o.t_end;
  const SurvivalOutcome r = run(survival_motion(o, beta, omega, alpha, p), t_end);
  pt.max_abs_rotation = r.max_abs_rotation;
  pt.max_sliding = r.max_sliding;
  pt.collapse_mode = r.collapse_mode;
  pt.t_failure = r.t_failure;
  pt.cycle = r.cycle;
  if (r.invalid)
    pt.motion = "invalid";
  else if (r.collapse_mode)
    pt.motion = "collapse";
  else if (r.moved)
    pt.motion = "stable";
  else
    pt.motion = "rest";
  if (r.collapse_mode && r.t_failure) pt.t_star_class = t_star_class(o, *r.t_failure);
  return pt;
}

std::vector<SurvivalPoint> survival_map(const SurvivalRun& run, const SurvivalOptions& o, double alpha, double p,
                                        const std::function<void(std::size_t)>& progress) {
  validate(o);
  std::vector<SurvivalPoint> pts(std::size_t(o.beta_points) * o.omega_points);
  for_each_beta_omega(
      o, [&](std::size_t k, double beta, double omega) { pts[k] = survival_point(run, o, alpha, p, beta, omega); },
      progress);
  return pts;
}

std::pair<double, double> beta_omega_of(const SurvivalOptions& o, std::size_t k) {
  const int bi = int(k / o.omega_points);
  const double beta = o.betas.empty() ? grid_value(o.beta_min, o.beta_max, o.beta_points, bi) : o.betas[bi];
  return {beta, grid_value(o.omega_min, o.omega_max, o.omega_points, int(k % o.omega_points))};
}

void for_each_beta_omega(const SurvivalOptions& o, const std::function<void(std::size_t, double, double)>& point,
                         const std::function<void(std::size_t)>& progress) {
  if (!o.betas.empty() && int(o.betas.size()) != o.beta_points)
    throw std::invalid_argument("betas: beta-points must equal the number of betas given");
  std::size_t done = 0;
  parallel_for(
      std::size_t(o.beta_points) * o.omega_points, o.threads,
      [&](std::size_t k) {
        const auto [beta, omega] = beta_omega_of(o, k);
        point(k, beta, omega);
      },
      [&](std::size_t) {
        ++done;
        if (progress) progress(done);
      });
}

}  // namespace blockdyn
