// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/sweep/sweep_metrics.hpp"

#include "blockdyn/analysis/winkler/response_type.hpp"
#include "blockdyn/analysis/winkler/twin_divergence.hpp"

#include <mutex>
#include <stdexcept>

namespace blockdyn {

namespace {

// Counts of every event kind (ground breaks excluded: sweeps run without ground motion).
class EventCountsMetric : public PointMetric {
 public:
  std::vector<std::string> columns() const override {
    std::vector<std::string> c;
    for (int k = 0; k < kNumEventKinds; ++k)
      if (WinklerEventKind(k) != WinklerEventKind::GroundBreak)
        c.push_back(std::string("n_") + to_string(WinklerEventKind(k)));
    return c;
  }
  void compute(const PointContext&, const WinklerResult& r, const WinklerSink*,
               std::vector<MetricValue>& out) const override {
    for (int k = 0; k < kNumEventKinds; ++k)
      if (WinklerEventKind(k) != WinklerEventKind::GroundBreak) out.emplace_back((long long)r.event_counts[k]);
  }
};

class FinalStateMetric : public PointMetric {
 public:
  std::vector<std::string> columns() const override {
    return {"x_final", "y_final", "w_final", "vx_final", "vy_final", "vw_final", "regime_final"};
  }
  void compute(const PointContext&, const WinklerResult& r, const WinklerSink*,
               std::vector<MetricValue>& out) const override {
    const BlockState s = to_state(r.final_state);
    for (double v : {s.x, s.y, s.w, s.vx, s.vy, s.vw}) out.emplace_back(v);
    out.emplace_back(std::string(to_string(r.final_mode.regime)));
  }
};

// Time spent in each regime, summed over the integrator's segments (needs a sink).
class RegimeTimeSink : public WinklerSink {
 public:
  void on_segment(const WinklerBlock&, const DenseSegment<kStateDim>&, double t0, double t1,
                  const WinklerMode& mode) override {
    time[int(mode.regime)] += t1 - t0;
  }
  double time[3] = {0, 0, 0};
};

class RegimeTimeMetric : public PointMetric {
 public:
  std::vector<std::string> columns() const override { return {"time_contact", "time_slide", "time_flight"}; }
  std::unique_ptr<WinklerSink> make_sink(const PointContext&) const override {
    return std::make_unique<RegimeTimeSink>();
  }
  void compute(const PointContext&, const WinklerResult&, const WinklerSink* sink,
               std::vector<MetricValue>& out) const override {
    const auto& s = static_cast<const RegimeTimeSink&>(*sink);
    for (Regime g : {Regime::Contact, Regime::Slide, Regime::Flight}) out.emplace_back(s.time[int(g)]);
  }
};

// Long-term response class of the thesis (sec. 4.4), from the swings seen during the run; the late
// window is the second half of the run, as in `blockdyn response`.
class ResponseTypeMetric : public PointMetric {
 public:
  std::vector<std::string> columns() const override { return {"response_type", "response_reason"}; }
  std::unique_ptr<WinklerSink> make_sink(const PointContext& c) const override {
    SwingOptions so;
    so.late_start = ResponseOptions{}.late_fraction * c.options.t_end;
    return std::make_unique<SwingAccumulator>(c.point.params, so);
  }
  void compute(const PointContext& c, const WinklerResult& r, const WinklerSink* sink,
               std::vector<MetricValue>& out) const override {
    const ResponseCriteria crit;
    const auto& acc = static_cast<const SwingAccumulator&>(*sink);
    const ResponseReport rep = classify(c.point.params, compute_metrics(c.point.params, r, acc, crit), crit);
    out.emplace_back(std::string(to_string(rep.type)));
    out.emplace_back(rep.reason);
  }
};

// Sensitive dependence (thesis sec. 5.2, the "+" of Figs 6.1-6.2): the point is run a second time
// with y'(0) + 1e-8 and w of the two runs compared over the second half (twin_divergence.hpp).
// Doubles the cost of the point, hence opt-in.
class SensitiveDependenceMetric : public PointMetric {
 public:
  std::vector<std::string> columns() const override { return {"w_separation", "sensitive_dependence"}; }
  std::unique_ptr<WinklerSink> make_sink(const PointContext& c) const override {
    return std::make_unique<RotationSampler>(c.options.t_end, TwinOptions{});
  }
  void compute(const PointContext& c, const WinklerResult& r, const WinklerSink* sink,
               std::vector<MetricValue>& out) const override {
    const auto& ref = static_cast<const RotationSampler&>(*sink);
    const TwinDivergence d =
        twin_divergence(c.point.params, {}, c.initial_state, c.options, TwinOptions{}, ref, r.status);
    if (d.compared > 0)
      out.emplace_back(d.separation);
    else
      out.emplace_back(std::monostate{});
    out.emplace_back((long long)(d.divergent ? 1 : 0));
  }
};

std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}
std::vector<MetricInfo>& registered() {
  static std::vector<MetricInfo> r;
  return r;
}

std::vector<MetricInfo> builtin_metrics() {
  // Add new built-in metrics here (name, one-line description, factory).
  return {
      {"event_counts", "number of events of each kind (n_takeoff, n_landing, n_w_zero, ...)",
       [] { return std::make_unique<EventCountsMetric>(); }},
      {"final_state", "state and regime at the end of the run", [] { return std::make_unique<FinalStateMetric>(); }},
      {"regime_time", "time spent in contact, slide and flight", [] { return std::make_unique<RegimeTimeMetric>(); }},
      {"response_type", "long-term response class (thesis sec. 4.4) and the criterion that decided it",
       [] { return std::make_unique<ResponseTypeMetric>(); }},
      {"sensitive_dependence",
       "a second run with y'(0) + 1e-8: max |w difference| / amplitude of w over the second half, and 1 if "
       ">= 0.1 or only one run overturned (doubles the cost)",
       [] { return std::make_unique<SensitiveDependenceMetric>(); }},
  };
}

}  // namespace

std::vector<MetricInfo> metric_catalog() {
  std::vector<MetricInfo> all = builtin_metrics();
  std::lock_guard<std::mutex> lock(registry_mutex());
  all.insert(all.end(), registered().begin(), registered().end());
  return all;
}

void register_metric(MetricInfo info) {
  for (const auto& m : metric_catalog())
    if (m.name == info.name) throw std::logic_error("sweep metric '" + info.name + "' is already registered");
  std::lock_guard<std::mutex> lock(registry_mutex());
  registered().push_back(std::move(info));
}

std::unique_ptr<PointMetric> make_metric(const std::string& name) {
  std::string known;
  for (const auto& m : metric_catalog()) {
    if (m.name == name) return m.make();
    known += (known.empty() ? "" : ", ") + m.name;
  }
  throw std::invalid_argument("metric '" + name + "' is unknown (known metrics: " + known + ")");
}

}  // namespace blockdyn
