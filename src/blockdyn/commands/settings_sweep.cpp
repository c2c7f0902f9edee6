// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/commands/settings_sweep.hpp"

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "blockdyn/analysis/sweep/point_table.hpp"
#include "blockdyn/analysis/sweep/sweep_axis.hpp"
#include "blockdyn/analysis/sweep/sweep_spec.hpp"
#include "blockdyn/commands/simulate_run.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;

namespace {

// The sweep's own options: not passed to the family's runs.
const char* const kSweepOwn[] = {"axis", "output", "plot", "plot-column", "definition"};

std::string option_of(const std::string& axis) {
  std::string o = axis;
  std::replace(o.begin(), o.end(), '_', '-');
  return o;
}

class SettingsSweepTable final : public PointTable {
 public:
  SettingsSweepTable(const Family& family, Settings base, std::vector<SweepAxis> axes, std::string output)
      : family_(family), base_(std::move(base)), axes_(std::move(axes)), output_(std::move(output)) {
    n_ = 1;
    for (const SweepAxis& a : axes_) n_ = std::min(n_ * a.values.size(), kMaxSweepPoints + 1);
    if (n_ == 0 || n_ > kMaxSweepPoints)
      throw std::invalid_argument("the sweep has " + std::to_string(n_) + " points: must be in [1, 1e8]");
    columns_.push_back("index");
    for (const SweepAxis& a : axes_) columns_.push_back(a.name);
    for (const std::string& k : family_.result_keys()) columns_.push_back(k);
    header_ = csv_header(columns_);
    fingerprint_ = fingerprint_hex(dump_json(definition(), -1) + "\n" + header_);
    // Every value of every axis checked before any point runs (each prepared with the other axes
    // at their first values: preparing validates, it does not run).
    for (std::size_t k = 0; k < axes_.size(); ++k)
      for (double v : axes_[k].values) {
        Settings one = settings_at(0);
        one.set(option_of(axes_[k].name), Settings::exact(v));
        prepare_run(one);
      }
    // The tolerances as given (the family's defaults where not).
    tolerances_ = json::object();
    for (const char* n : {"rtol", "atol", "method", "max-steps"})
      tolerances_[n] = base_.has(n) ? json(base_.text(n)) : json("the family's default");
  }
  std::size_t size() const override { return n_; }
  const std::vector<std::string>& columns() const override { return columns_; }
  const std::string& header() const override { return header_; }
  const std::string& fingerprint() const override { return fingerprint_; }
  nlohmann::ordered_json tolerances() const override { return tolerances_; }
  const std::string& output() const override { return output_; }
  nlohmann::ordered_json definition() const override {
    json given = json::object();
    for (const std::string& n : base_.names()) given[n] = base_.values(n);
    json axes = json::array();
    for (const SweepAxis& a : axes_) axes.push_back({{"name", a.name}, {"values", a.values}});
    return {{"model", family_.name},
            {"options", given},
            {"axes", axes},
            {"index", "the first axis fastest"},
            {"results", family_.result_keys()}};
  }
  SweepRow row(std::size_t index) const override {
    SweepRow out;
    out.cells.emplace_back(index);
    std::size_t i = index;
    for (const SweepAxis& a : axes_) {
      out.cells.emplace_back(a.values[i % a.values.size()]);
      i /= a.values.size();
    }
    try {
      const json summary = prepare_run(settings_at(index))->run({}).summary.take();
      for (const std::string& k : family_.result_keys()) out.cells.push_back(cell_of(summary.value(k, json())));
      if (summary.contains("stop_reason") && summary["stop_reason"].is_string())
        out.error = summary["stop_reason"].get<std::string>();
    } catch (const std::exception& e) {
      out.error = e.what();
      out.cells.emplace_back("error");
      while (out.cells.size() < columns_.size()) out.cells.emplace_back();
    }
    return out;
  }

 private:
  Settings settings_at(std::size_t index) const {
    Settings s = base_;
    for (const SweepAxis& a : axes_) {
      s.set(option_of(a.name), Settings::exact(a.values[index % a.values.size()]));
      index /= a.values.size();
    }
    return s;
  }
  static Cell cell_of(const json& v) {
    if (v.is_number_integer()) return Cell(v.get<long long>());
    if (v.is_number()) return Cell(v.get<double>());
    if (v.is_boolean()) return Cell(v.get<bool>() ? 1 : 0);
    if (v.is_string()) return Cell(v.get<std::string>());
    return Cell();
  }
  const Family& family_;
  Settings base_;
  std::vector<SweepAxis> axes_;
  std::string output_, header_, fingerprint_;
  std::vector<std::string> columns_;
  std::size_t n_ = 0;
  json tolerances_;
};

}  // namespace

SweepDefinition settings_sweep(const Settings& s, const Family& family) {
  if (s.has("definition"))
    throw std::invalid_argument(std::string("`definition` files are not read by the ") + family.name +
                                " sweep: give its options and `axis`");
  const std::vector<std::string>& known = family.options();
  std::vector<SweepAxis> axes;
  for (const std::string& a : s.values("axis")) {
    const auto eq = a.find('=');
    if (eq == std::string::npos || eq == 0)
      throw std::invalid_argument("`axis` '" + a + "': expected NAME=SPEC, e.g. ground_h_scale=0.5:2:4");
    const std::string name = a.substr(0, eq);
    if (std::find(known.begin(), known.end(), option_of(name)) == known.end() || name == "model")
      throw std::invalid_argument("`axis` " + name + ": not an option of the " + family.name +
                                  " model (see `list-axes`)");
    for (const SweepAxis& x : axes)
      if (option_of(x.name) == option_of(name)) throw std::invalid_argument("`axis` " + name + ": given twice");
    axes.push_back(parse_axis(name, a.substr(eq + 1), AxisSpacing::Linear));
  }
  if (axes.empty())
    throw std::invalid_argument("`axis`: the " + std::string(family.name) + " sweep needs one (NAME=SPEC)");
  Settings base;
  for (const std::string& n : s.names()) {
    if (std::find(std::begin(kSweepOwn), std::end(kSweepOwn), n) != std::end(kSweepOwn)) continue;
    for (const std::string& v : s.values(n)) base.add(n, v);
    if (const auto rec = s.record(n)) base.add_record(n, rec);
  }
  SweepDefinition d;
  d.model = family.name;
  d.output = s.text("output", "sweep.csv");
  if (d.output.empty()) throw std::invalid_argument("output: the CSV path is empty");
  d.plot = s.text("plot");
  d.plot_column = s.text("plot-column", family.result_keys().size() > 1 ? family.result_keys()[1] : "t_final");
  auto table = std::make_shared<SettingsSweepTable>(family, base, axes, d.output);
  d.definition = table->definition();
  d.table = table;
  for (const SweepAxis& a : axes) d.plot_axes.push_back({a.name, a.values, false});
  d.t_end = s.number("t-end", 10.0);
  return d;
}

}  // namespace blockdyn
