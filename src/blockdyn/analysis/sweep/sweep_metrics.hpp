// SPDX-License-Identifier: Apache-2.0
#pragma once
// Extra per-point columns of a sweep. A metric names its columns and fills them from the point,
// its WinklerResult and (optionally) a per-point WinklerSink that watched the trajectory.
//
// Adding a metric (e.g. the response-type classifier):
//   1. derive from PointMetric (columns(), compute(); make_sink() if it must see the trajectory,
//      needs_events() if it reads WinklerResult::events);
//   2. add one entry to the catalogue in sweep_metrics.cpp (builtin list), or call
//      register_metric() before the sweep starts (e.g. from an apps/ file);
//   3. select it by name: `metrics = ["name"]` in [output] or `--metric name`.
// One PointMetric object serves all points from several threads: compute() and make_sink() must
// not modify it. Per-point state belongs in the sink. The result must depend only on the point
// (no timing, no globals), so CSV bytes stay independent of threads, ranks and resumption.
#include <functional>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "blockdyn/analysis/sweep/sweep_spec.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"

namespace blockdyn {

// One CSV cell: empty, a double (written %.17g), an integer, or text (CSV-quoted if needed).
using MetricValue = std::variant<std::monostate, double, long long, std::string>;

// What a metric may know about the point it describes.
struct PointContext {
  const SweepPoint& point;            // index, params (k, r, mu), inv_r, ic
  const WinklerRunOptions& options;   // as used for this run (t_end, tolerances, stop rules)
  const WinklerState& initial_state;  // z0 handed to simulate()
};

class PointMetric {
 public:
  virtual ~PointMetric() = default;
  virtual std::vector<std::string> columns() const = 0;
  // true: the sweep records the event list (WinklerRunOptions::record_events) for every point.
  virtual bool needs_events() const { return false; }
  // Optional observer of one point's run (segments, events; may stop the run via keep_going).
  virtual std::unique_ptr<WinklerSink> make_sink(const PointContext&) const { return nullptr; }
  // Appends exactly columns().size() values. `sink` is what make_sink returned (or nullptr).
  virtual void compute(const PointContext& ctx, const WinklerResult& result, const WinklerSink* sink,
                       std::vector<MetricValue>& out) const = 0;
};

struct MetricInfo {
  std::string name;
  std::string description;
  std::function<std::unique_ptr<PointMetric>()> make;
};

// Built-in metrics followed by registered ones.
std::vector<MetricInfo> metric_catalog();
// Adds a metric at run time (before the sweep starts); throws if the name is taken.
void register_metric(MetricInfo info);
// Throws std::invalid_argument naming the metric and listing the known names.
std::unique_ptr<PointMetric> make_metric(const std::string& name);

}  // namespace blockdyn
