// SPDX-License-Identifier: Apache-2.0
#pragma once
// Parameter sweeps of the rigid-ground family (housner, rigid): axes named after the family's
// own parameters (block shape, interface, impact, initial state, ground motion) over a base run
// given like a `simulate` scenario. Point order: the first axis varies fastest.
//   index = i_0 + n_0 * (i_1 + n_1 * (i_2 + ...))
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "blockdyn/analysis/sweep/point_table.hpp"
#include "blockdyn/analysis/sweep/sweep_axis.hpp"
#include "blockdyn/simulation/rigid_ground_model.hpp"

namespace blockdyn {

struct RigidSweepSpec {
  const RigidGroundModel* model = &three_dof_on_rigid_ground();
  RigidBlockParams block;  // the base point
  GroundMotion ground;
  RigidInitial initial;
  std::optional<double> w0_over_alpha;  // initial tilt as a fraction of each point's alpha
  RigidRunOptions options = [] {
    RigidRunOptions o;
    o.t_end = 10.0;
    o.record_events = false;
    return o;
  }();
  std::vector<SweepAxis> axes;  // names from rigid_axis_catalog()

  std::string output = "sweep.csv";
  std::string plot, plot_column;
};

// Axis names of the family with what each sets, in the order they are applied to a point.
const std::vector<std::pair<std::string, std::string>>& rigid_axis_catalog();

std::size_t point_count(const RigidSweepSpec& s);
// The parameters, ground motion and initial state of point `index`.
struct RigidSweepPoint {
  std::size_t index = 0;
  std::vector<double> values;  // one per axis
  RigidBlockParams block;
  GroundMotion ground;
  RigidInitial initial;
};
RigidSweepPoint sweep_point(const RigidSweepSpec& s, std::size_t index);

// Checks the axes, the base and every point (parameters, ground motion, initial state); throws
// std::invalid_argument naming the key or the point.
void validate(const RigidSweepSpec& s);
nlohmann::ordered_json definition_json(const RigidSweepSpec& s);

// A rigid-family sweep file: a `simulate` scenario (model, [physical], [interface], [impact],
// [initial], [run], [ground.*]) plus [axes] (name = axis) and [output] (csv, plot, plot_column);
// [initial] also takes w0_over_alpha.
// The file's model is `model`'s family (the caller resolved its `model` key).
RigidSweepSpec parse_rigid_sweep(const std::string& toml_text, const std::string& source, const RigidGroundModel& model,
                                 const std::string& base_dir = "");
RigidSweepSpec load_rigid_sweep(const std::string& path, const RigidGroundModel& model);

class RigidSweepEvaluator final : public PointTable {
 public:
  explicit RigidSweepEvaluator(RigidSweepSpec spec);
  const RigidSweepSpec& spec() const { return spec_; }
  std::size_t size() const override { return n_; }
  const std::vector<std::string>& columns() const override { return columns_; }
  const std::string& header() const override { return header_; }
  const std::string& fingerprint() const override { return fingerprint_; }
  SweepRow row(std::size_t index) const override;
  nlohmann::ordered_json definition() const override { return definition_json(spec_); }
  nlohmann::ordered_json tolerances() const override;
  const std::string& output() const override { return spec_.output; }

 private:
  RigidSweepSpec spec_;
  std::size_t n_ = 0;
  std::vector<std::string> columns_;
  std::string header_, fingerprint_;
};

}  // namespace blockdyn
