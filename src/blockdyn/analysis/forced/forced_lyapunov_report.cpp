// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/forced_lyapunov_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "blockdyn/io/json_io.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;

json forced_lyapunov_summary(const ForcedModel& fm, const GroundMotion& g, const json& excitation,
                             const ForcedLyapunovOptions& o, const ForcedLyapunovOutcome& r) {
  const TangentLyapunovResult& tl = r.tangent;
  json j;
  j["run_info"] = run_info();
  j["model"] = fm.description;
  j["alpha"] = fm.alpha;
  j["p"] = fm.p;
  j["ground"] = to_json(g);
  if (!excitation.is_null()) j["excitation"] = excitation;
  j["integrator"] = to_json(o.integrator);
  j["options"] = {{"method", "tangent"},    {"t_end", o.t_end},     {"t_transient", o.t_transient},
                  {"interval", o.interval}, {"twin_d0", o.twin_d0}, {"metric", r.metric}};
  j["exponent"] = finite_or_null(tl.exponent);
  j["exponent_nondim"] = finite_or_null(tl.exponent / fm.p);
  j["exponent_second_half"] = finite_or_null(r.exponent_second_half);
  j["status"] = to_string(tl.status);
  j["superstable"] = tl.status == TangentStatus::Superstable;
  j["note"] = tl.note;
  j["t_tangent"] = finite_or_null(tl.t_tangent);
  j["t_final"] = tl.t_final;
  j["renormalisations"] = tl.renormalisations;
  j["impacts"] = r.impacts;
  j["collapse_mode"] = r.collapse_mode ? json(*r.collapse_mode) : json(nullptr);
  j["t_failure"] = r.t_failure ? json(*r.t_failure) : json(nullptr);
  j["saltation"] = {{"events", tl.stats.saltations},
                    {"one_sided", tl.stats.one_sided},
                    {"unmatched", tl.stats.unmatched},
                    {"grazing", tl.stats.grazing},
                    {"max_gain", tl.stats.max_gain}};
  json h = json::array();
  const std::size_t n = tl.history.size(), stride = std::max<std::size_t>(1, n / 20);
  for (std::size_t i = stride - 1; i < n; i += stride)
    h.push_back({{"t", tl.history[i].t}, {"estimate", tl.history[i].estimate}});
  j["history_coarse"] = h;
  if (!r.twin.empty()) {
    // Sensitive dependence: when the two orbits' separation first exceeds 1e-3 (metric units),
    // against the time the exponent predicts for that growth.
    json tw;
    tw["d0"] = o.twin_d0;
    tw["t_start"] = r.twin.front().t;
    tw["separation_final"] = r.twin.back().separation;
    tw["max_separation"] = 0.0;
    double mx = 0;
    json t_sep = nullptr;
    for (const auto& x : r.twin) {
      mx = std::fmax(mx, x.separation);
      if (t_sep.is_null() && x.separation > 1e-3) t_sep = x.t - r.twin.front().t;
    }
    tw["max_separation"] = mx;
    tw["time_to_1e-3"] = t_sep;
    tw["predicted_time_to_1e-3"] = tl.exponent > 0 ? json(std::log(1e-3 / o.twin_d0) / tl.exponent) : json(nullptr);
    tw["note"] = r.twin_note;
    j["sensitivity"] = tw;
  }
  return j;
}

CellTable twin_table(const ForcedLyapunovOutcome& r) {
  const TangentLyapunovResult& tl = r.tangent;
  CellTable t;
  t.columns = {"t", "separation", "predicted"};
  for (const auto& x : r.twin) {
    const double pred = std::isfinite(tl.exponent) && !r.twin.empty()
                            ? r.twin.front().separation * std::exp(tl.exponent * (x.t - r.twin.front().t))
                            : NAN;
    t.rows.push_back({x.t, x.separation, pred});
  }
  return t;
}

}  // namespace blockdyn
