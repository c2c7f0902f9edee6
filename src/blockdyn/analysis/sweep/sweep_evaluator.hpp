// SPDX-License-Identifier: Apache-2.0
#pragma once
// Turns a sweep point into its CSV row. The row is a pure function of the definition and the
// index (same bytes on any thread, rank or rerun), so it is computed once and stored verbatim.
// Fixed columns (then the metrics' columns, in the order the metrics were selected):
//   index,k,r,inv_r,mu,ic,status,t_final,first_flight_time,ihor_at_first_flight,overturned,
//   overturn_time,ihor_at_overturn,ihor_final,energy_initial,energy_lost,max_abs_energy_error,
//   steps,rhs_evals
// Doubles use %.17g; an absent value (no flight, no overturn, energy not tracked) is empty.
// status is t_end | overturned | invalid | early_stop | numerical_failure, outside_model (the
// initial state is outside the model: reported, not integrated), or error when the
// simulation threw (the message goes to SweepRow::error, not to the CSV).
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "blockdyn/analysis/sweep/point_table.hpp"
#include "blockdyn/analysis/sweep/sweep_metrics.hpp"
#include "blockdyn/analysis/sweep/sweep_spec.hpp"

namespace blockdyn {

class SweepEvaluator final : public PointTable {
 public:
  // Builds the metrics named in spec.metrics (throws std::invalid_argument for unknown names).
  explicit SweepEvaluator(SweepSpec spec);
  // For tests and embedders: metrics given directly, appended after those named in the spec.
  SweepEvaluator(SweepSpec spec, std::vector<std::unique_ptr<PointMetric>> extra);

  const SweepSpec& spec() const { return spec_; }
  std::size_t size() const override { return n_; }
  const std::vector<std::string>& columns() const override { return columns_; }
  const std::string& header() const override { return header_; }  // with '\n'
  // Identifies the definition and the columns (a journal is only resumed under the same one).
  const std::string& fingerprint() const override { return fingerprint_; }
  const WinklerRunOptions& options() const { return options_; }
  nlohmann::ordered_json definition() const override;
  nlohmann::ordered_json tolerances() const override;
  const std::string& output() const override { return spec_.output; }

  SweepRow row(std::size_t index) const override;  // thread-safe

 private:
  void init();
  SweepSpec spec_;
  std::vector<std::unique_ptr<PointMetric>> metrics_;
  std::vector<std::size_t> metric_width_;
  std::vector<std::string> columns_;
  std::string header_, fingerprint_;
  WinklerRunOptions options_;
  std::size_t n_ = 0;
};

}  // namespace blockdyn
