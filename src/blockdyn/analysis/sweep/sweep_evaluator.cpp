// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/sweep/sweep_evaluator.hpp"

#include <cstdio>
#include <stdexcept>

#include "blockdyn/io/json_io.hpp"

namespace blockdyn {

namespace {

const std::vector<std::string> kBaseColumns = {"index",
                                               "k",
                                               "r",
                                               "inv_r",
                                               "mu",
                                               "ic",
                                               "status",
                                               "t_final",
                                               "first_flight_time",
                                               "ihor_at_first_flight",
                                               "overturned",
                                               "overturn_time",
                                               "ihor_at_overturn",
                                               "ihor_final",
                                               "energy_initial",
                                               "energy_lost",
                                               "max_abs_energy_error",
                                               "steps",
                                               "rhs_evals"};

// Forwards the trajectory to every metric's sink; stops when any of them asks to.
class FanOutSink : public WinklerSink {
 public:
  std::vector<WinklerSink*> sinks;
  void on_start(const WinklerBlock& m, double t, const WinklerMode& mode, const WinklerState& z) override {
    for (auto* s : sinks) s->on_start(m, t, mode, z);
  }
  void on_segment(const WinklerBlock& m, const DenseSegment<kStateDim>& seg, double t0, double t1,
                  const WinklerMode& mode) override {
    for (auto* s : sinks) s->on_segment(m, seg, t0, t1, mode);
  }
  void on_event(const WinklerBlock& m, const WinklerEventRecord& e) override {
    for (auto* s : sinks) s->on_event(m, e);
  }
  bool keep_going() const override {
    for (auto* s : sinks)
      if (!s->keep_going()) return false;
    return true;
  }
  bool needs_dense() const override {
    for (auto* s : sinks)
      if (s->needs_dense()) return true;
    return false;
  }
};

// A metric's value as a cell.
void add_value(CellRow& b, const MetricValue& v) {
  if (std::holds_alternative<double>(v))
    b.emplace_back(std::get<double>(v));
  else if (std::holds_alternative<long long>(v))
    b.emplace_back(std::get<long long>(v));
  else if (std::holds_alternative<std::string>(v))
    b.emplace_back(std::get<std::string>(v));
  else
    b.emplace_back();
}

}  // namespace

nlohmann::ordered_json SweepEvaluator::definition() const { return definition_json(spec_); }
nlohmann::ordered_json SweepEvaluator::tolerances() const { return to_json(options_.integrator); }

SweepEvaluator::SweepEvaluator(SweepSpec spec) : SweepEvaluator(std::move(spec), {}) {}

SweepEvaluator::SweepEvaluator(SweepSpec spec, std::vector<std::unique_ptr<PointMetric>> extra)
    : spec_(std::move(spec)) {
  for (const auto& name : spec_.metrics) metrics_.push_back(make_metric(name));
  for (auto& m : extra) metrics_.push_back(std::move(m));
  init();
}

void SweepEvaluator::init() {
  n_ = point_count(spec_);
  options_ = spec_.options;
  options_.record_events = false;
  columns_ = kBaseColumns;
  for (const auto& m : metrics_) {
    if (m->needs_events()) options_.record_events = true;
    const auto c = m->columns();
    metric_width_.push_back(c.size());
    columns_.insert(columns_.end(), c.begin(), c.end());
  }
  for (std::size_t i = 0; i < columns_.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (columns_[i] == columns_[j])
        throw std::invalid_argument("metrics: column '" + columns_[i] + "' appears twice");
  header_ = csv_header(columns_);
  fingerprint_ = fingerprint_hex(dump_json(definition_json(spec_), -1) + "\n" + header_);
}

SweepRow SweepEvaluator::row(std::size_t index) const {
  if (index >= n_) throw std::out_of_range("sweep point index out of range");
  const SweepPoint p = sweep_point(spec_, index);
  CellRow b;
  b.emplace_back(p.index);
  b.emplace_back(p.params.k);
  b.emplace_back(p.params.r);
  b.emplace_back(p.inv_r);
  b.emplace_back(p.params.mu);
  b.emplace_back(p.ic);
  SweepRow out;
  WinklerResult r;
  WinklerState z0{};
  const PointContext ctx{p, options_, z0};
  std::vector<std::unique_ptr<WinklerSink>> owned;
  FanOutSink fan;
  try {
    z0 = sweep_initial_state(spec_, p);
    if (auto why = WinklerBlock(p.params, GroundMotion{}).validity_problem(z0)) {
      out.error = "initial state outside the model: " + *why;  // reported, not integrated
      b.emplace_back(std::string("outside_model"));
      for (std::size_t i = 7; i < columns_.size(); ++i) b.emplace_back();
      out.cells = std::move(b);
      return out;
    }
    for (const auto& m : metrics_) {
      owned.push_back(m->make_sink(ctx));
      if (owned.back()) fan.sinks.push_back(owned.back().get());
    }
    r = simulate(p.params, GroundMotion{}, z0, options_, fan.sinks.empty() ? nullptr : &fan);
  } catch (const std::exception& e) {
    // Deterministic for a given point, so the row is still reproducible; details to the caller.
    out.error = e.what();
    b.emplace_back(std::string("error"));
    for (std::size_t i = 7; i < columns_.size(); ++i) b.emplace_back();
    out.cells = std::move(b);
    return out;
  }
  b.emplace_back(std::string(to_string(r.status)));
  b.emplace_back(r.t_final);
  if (r.first_flight_time) {
    b.emplace_back(*r.first_flight_time);
    b.emplace_back(r.upright_passages_at_first_flight);
  } else {
    b.emplace_back();
    b.emplace_back();
  }
  b.emplace_back(r.status == SimStatus::Overturned ? 1L : 0L);
  if (r.overturn_time) {
    b.emplace_back(*r.overturn_time);
    b.emplace_back(r.upright_passages_at_overturn);
  } else {
    b.emplace_back();
    b.emplace_back();
  }
  b.emplace_back(r.upright_passages);
  b.emplace_back(r.initial_energy.total());
  b.emplace_back(-r.work_friction());
  if (options_.track_energy)
    b.emplace_back(r.max_abs_energy_error);
  else
    b.emplace_back();
  b.emplace_back(r.stats.accepted);
  b.emplace_back(r.stats.rhs_evals);
  std::vector<MetricValue> vals;
  for (std::size_t m = 0; m < metrics_.size(); ++m) {
    vals.clear();
    metrics_[m]->compute(ctx, r, owned[m].get(), vals);
    if (vals.size() != metric_width_[m])
      throw std::logic_error("sweep metric produced " + std::to_string(vals.size()) + " values for " +
                             std::to_string(metric_width_[m]) + " columns");
    for (const auto& v : vals) add_value(b, v);
  }
  out.cells = std::move(b);
  return out;
}

}  // namespace blockdyn
