// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/chaos_map.hpp"

#include "blockdyn/io/json_io.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace blockdyn {

using json = nlohmann::ordered_json;

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
  std::vector<ChaosPoint> pts(std::size_t(o.grid.beta_points) * o.grid.omega_points);
  for_each_beta_omega(
      o.grid, [&](std::size_t k, double beta, double omega) { pts[k] = chaos_point(run, o, beta, omega, alpha, p); },
      progress);
  return pts;
}

const std::vector<std::string>& chaos_motions() {
  static const std::vector<std::string> m{"rest",    "superstable", "periodic", "neutral",
                                          "chaotic", "collapse",    "failed"};
  return m;
}

nlohmann::ordered_json chaos_points_json(const std::vector<ChaosPoint>& pts) {
  json arr = json::array();
  for (const ChaosPoint& p : pts) {
    json x;
    x["beta"] = p.beta;
    x["omega"] = p.omega;
    x["motion"] = p.motion;
    x["exponent"] = finite_or_null(p.exponent);
    x["exponent_nondim"] = finite_or_null(p.exponent_nondim);
    x["exponent_second_half"] = finite_or_null(p.exponent_second_half);
    x["status"] = p.status;
    x["impacts"] = p.impacts;
    x["collapse_mode"] = p.collapse_mode ? json(*p.collapse_mode) : json(nullptr);
    x["t_failure"] = p.t_failure ? json(*p.t_failure) : json(nullptr);
    arr.push_back(x);
  }
  return arr;
}

nlohmann::ordered_json chaos_counts_json(const std::vector<ChaosPoint>& pts) {
  nlohmann::ordered_json c;
  for (const std::string& m : chaos_motions()) {
    long n = 0;
    for (const ChaosPoint& p : pts) n += p.motion == m;
    c[m] = n;
  }
  return c;
}

CellTable chaos_table(const std::vector<ChaosPoint>& pts) {
  CellTable t;
  t.columns = {"beta",   "omega",   "motion",        "exponent", "exponent_nondim", "exponent_second_half",
               "status", "impacts", "collapse_mode", "t_failure"};
  for (const ChaosPoint& p : pts)
    t.rows.push_back({p.beta, p.omega, p.motion, p.exponent, p.exponent_nondim, p.exponent_second_half, p.status,
                      p.impacts, p.collapse_mode ? Cell(*p.collapse_mode) : Cell(), Cell::maybe(p.t_failure)});
  return t;
}

}  // namespace blockdyn
