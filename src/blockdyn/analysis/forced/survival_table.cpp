// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/survival_table.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;

const std::vector<std::string>& survival_columns() {
  static const std::vector<std::string> c{"beta",      "omega",        "motion",           "collapse_mode",
                                          "t_failure", "t_star_class", "max_abs_rotation", "max_sliding",
                                          "cycle"};
  return c;
}

void add_survival_cells(const SurvivalPoint& p, CellRow& row) {
  row.emplace_back(p.beta);
  row.emplace_back(p.omega);
  row.emplace_back(p.motion);
  if (p.collapse_mode)
    row.emplace_back(static_cast<long long>(*p.collapse_mode));
  else
    row.emplace_back();
  if (p.t_failure)
    row.emplace_back(*p.t_failure);
  else
    row.emplace_back();
  row.emplace_back(p.t_star_class);
  row.emplace_back(p.max_abs_rotation);
  row.emplace_back(p.max_sliding);
  row.emplace_back(p.cycle);
}

SurvivalPoint survival_point_from(const Table& t, const TableRow& r) {
  auto cell = [&](const char* name) -> const Cell& { return r.cells[t.column(name)]; };
  SurvivalPoint p;
  p.beta = cell("beta").number();
  p.omega = cell("omega").number();
  p.motion = cell("motion").text();
  if (!cell("collapse_mode").empty()) p.collapse_mode = int(cell("collapse_mode").integer());
  p.t_failure = cell("t_failure").optional_number();
  p.t_star_class = cell("t_star_class").text();
  p.max_abs_rotation = cell("max_abs_rotation").number();
  p.max_sliding = cell("max_sliding").number();
  p.cycle = cell("cycle").text();
  return p;
}

nlohmann::ordered_json SurvivalPoints::counts_json() const {
  return {{"rest", counts[0]}, {"stable", counts[1]}, {"collapse", counts[2]}, {"invalid", counts[3]}};
}

SurvivalPoints survival_points(const Table& t, bool with_level) {
  SurvivalPoints out;
  const std::size_t level_col = with_level ? t.column("level") : 0;
  for (const TableRow& r : t.rows) {
    const SurvivalPoint p = survival_point_from(t, r);
    json x;
    x["beta"] = p.beta;
    x["omega"] = p.omega;
    x["motion"] = p.motion;
    x["collapse_mode"] = p.collapse_mode ? json(*p.collapse_mode) : json(nullptr);
    x["t_failure"] = p.t_failure ? json(*p.t_failure) : json(nullptr);
    x["t_star_class"] = p.t_star_class.empty() ? json(nullptr) : json(p.t_star_class);
    x["max_abs_rotation"] = p.max_abs_rotation;
    x["cycle"] = p.cycle.empty() ? json(nullptr) : json(p.cycle);
    if (with_level) x["level"] = r.cells[level_col].integer();
    out.points.push_back(x);
    ++out.counts[p.motion == "rest" ? 0 : p.motion == "stable" ? 1 : p.motion == "collapse" ? 2 : 3];
  }
  return out;
}

nlohmann::ordered_json response_curve_points(const Table& t, bool with_friction) {
  json arr = json::array();
  const std::size_t c_theta = t.column("theta_max_over_alpha"), c_slide = t.column("max_sliding_over_b");
  for (const TableRow& r : t.rows) {
    const SurvivalPoint p = survival_point_from(t, r);
    json x = {{"beta", p.beta},
              {"omega", p.omega},
              {"theta_max_over_alpha", r.cells[c_theta].number()},
              {"max_sliding_over_b", r.cells[c_slide].number()},
              {"motion", p.motion},
              {"t_failure", p.t_failure ? json(*p.t_failure) : json(nullptr)}};
    if (with_friction) {
      x["phi_s"] = r.cells[t.column("phi_s")].number();
      x["phi_l"] = r.cells[t.column("phi_l")].number();
    }
    arr.push_back(x);
  }
  return arr;
}

}  // namespace blockdyn
