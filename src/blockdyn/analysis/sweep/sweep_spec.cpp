// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/sweep/sweep_spec.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "blockdyn/io/json_io.hpp"
#include "blockdyn/io/scenario.hpp"
#include "blockdyn/model/winkler/winkler_block.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;

std::size_t point_count(const SweepSpec& s) {
  return s.k.values.size() * s.r.values.size() * s.mu.values.size() * s.initial.sets.size();
}

SweepPoint sweep_point(const SweepSpec& s, std::size_t index) {
  SweepPoint p;
  p.index = index;
  std::size_t i = index;
  const std::size_t nk = s.k.values.size(), nr = s.r.values.size(), nmu = s.mu.values.size();
  p.k_i = i % nk;
  i /= nk;
  p.r_i = i % nr;
  i /= nr;
  p.mu_i = i % nmu;
  p.ic_i = i / nmu;
  const double rv = s.r.values[p.r_i];
  const bool inv = s.r.name == "inv_r";
  p.params.k = s.k.values[p.k_i];
  p.params.r = inv ? 1.0 / rv : rv;
  p.inv_r = inv ? rv : 1.0 / rv;
  p.params.mu = s.mu.values[p.mu_i];
  p.ic = s.initial.sets.at(p.ic_i);
  return p;
}

WinklerState sweep_initial_state(const SweepSpec& s, const SweepPoint& p) {
  Scenario sc;
  sc.params = p.params;
  sc.initial.set = p.ic;
  const SweepInitial& in = s.initial;
  if (in.w0_over_alpha)
    sc.initial.w0 = *in.w0_over_alpha * p.params.alpha();
  else
    sc.initial.w0 = in.w0;
  sc.initial.x0 = in.x0;
  sc.initial.y0 = in.y0;
  sc.initial.vx0 = in.vx0;
  sc.initial.vy0 = in.vy0;
  sc.initial.vw0 = in.vw0;
  return initial_state(sc);
}

static std::string describe(const SweepPoint& p) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "point %zu (k=%.17g, r=%.17g, mu=%.17g, ic=%s)", p.index, p.params.k, p.params.r,
                p.params.mu, p.ic.c_str());
  return buf;
}

void validate(const SweepSpec& s) {
  require_axis_range(s.k, 0.0, false);
  if (s.r.name != "r" && s.r.name != "inv_r")
    throw std::invalid_argument("axes: the aspect-ratio axis must be named r or inv_r");
  require_axis_range(s.r, 0.0, false);
  require_axis_range(s.mu, 0.0, true);
  if (s.initial.sets.empty()) throw std::invalid_argument("initial.set: the list of sets is empty");
  for (const auto& set : s.initial.sets)
    if (set != "ic1" && set != "ic2" && set != "custom")
      throw std::invalid_argument("initial.set = '" + set + "' is not one of: ic1, ic2, custom");
  if (s.initial.w0 && s.initial.w0_over_alpha)
    throw std::invalid_argument("initial: give either w0 or w0_over_alpha, not both");
  if (s.initial.w0_over_alpha && !(std::fabs(*s.initial.w0_over_alpha) <= 1.0))
    throw std::invalid_argument("initial.w0_over_alpha is out of range: must be in [-1, 1]");
  validate(s.options);
  if (s.options.stop_at_upright_passages < 0)
    throw std::invalid_argument("run.stop_at_ihor = " + std::to_string(s.options.stop_at_upright_passages) +
                                " is out of range: must be >= 0 (0: never stop)");
  const std::size_t n = point_count(s);
  if (n == 0 || n > kMaxSweepPoints)
    throw std::invalid_argument("the sweep has " + std::to_string(n) + " points: must be in [1, 1e8]");
  // Every point's start is built up front: a definition error must not surface hours later.
  // A start that is well defined but outside the model (e.g. three corners below the surface on
  // a very soft foundation) is not a definition error: its row reports status outside_model.
  for (std::size_t i = 0; i < n; ++i) {
    const SweepPoint p = sweep_point(s, i);
    try {
      validate(p.params);
      (void)sweep_initial_state(s, p);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(describe(p) + ": " + e.what());
    }
  }
}

nlohmann::ordered_json definition_json(const SweepSpec& s) {
  json j;
  j["format"] = "blockdyn-sweep-1";
  j["order"] = "index = k_i + n_k * (r_i + n_r * (mu_i + n_mu * ic_i))";
  json axes;
  axes["k"] = to_json(s.k);
  axes[s.r.name] = to_json(s.r);
  axes["mu"] = to_json(s.mu);
  axes["ic"] = s.initial.sets;
  j["axes"] = axes;
  json init = json::object();
  auto put = [&](const char* key, const std::optional<double>& v) {
    if (v) init[key] = *v;
  };
  put("w0", s.initial.w0);
  put("w0_over_alpha", s.initial.w0_over_alpha);
  put("x0", s.initial.x0);
  put("y0", s.initial.y0);
  put("vx0", s.initial.vx0);
  put("vy0", s.initial.vy0);
  put("vw0", s.initial.vw0);
  j["initial"] = init;
  const WinklerRunOptions& o = s.options;
  j["run"] = {{"t_start", o.t_start},
              {"t_end", o.t_end},
              {"track_energy", o.track_energy},
              {"stop_at_first_flight", o.stop_at_first_flight},
              {"stop_at_ihor", o.stop_at_upright_passages}};
  json tol = to_json(o.integrator);
  tol["h_max"] = o.integrator.h_max;
  tol["chatter_limit"] = o.integrator.chatter_limit;
  j["tolerances"] = tol;
  j["metrics"] = s.metrics;
  return j;
}

std::string fingerprint_hex(const std::string& text) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace blockdyn
