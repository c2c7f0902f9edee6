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

void add_survival_cells(const SurvivalPoint& p, RowBuilder& row) {
  row.add(p.beta);
  row.add(p.omega);
  row.add(csv_escape(p.motion));
  if (p.collapse_mode)
    row.add(static_cast<long long>(*p.collapse_mode));
  else
    row.empty();
  if (p.t_failure)
    row.add(*p.t_failure);
  else
    row.empty();
  row.add(csv_escape(p.t_star_class));
  row.add(p.max_abs_rotation);
  row.add(p.max_sliding);
  row.add(csv_escape(p.cycle));
}

SurvivalPoint survival_point_from(const Table& t, const TableRow& r) {
  auto cell = [&](const char* name) -> const std::string& { return r.cells[t.column(name)]; };
  SurvivalPoint p;
  p.beta = cell_double(cell("beta"));
  p.omega = cell_double(cell("omega"));
  p.motion = cell("motion");
  if (!cell("collapse_mode").empty()) p.collapse_mode = int(cell_integer(cell("collapse_mode")));
  p.t_failure = cell_optional_double(cell("t_failure"));
  p.t_star_class = cell("t_star_class");
  p.max_abs_rotation = cell_double(cell("max_abs_rotation"));
  p.max_sliding = cell_double(cell("max_sliding"));
  p.cycle = cell("cycle");
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
    if (with_level) x["level"] = cell_integer(r.cells[level_col]);
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
              {"theta_max_over_alpha", cell_double(r.cells[c_theta])},
              {"max_sliding_over_b", cell_double(r.cells[c_slide])},
              {"motion", p.motion},
              {"t_failure", p.t_failure ? json(*p.t_failure) : json(nullptr)}};
    if (with_friction) {
      x["phi_s"] = cell_double(r.cells[t.column("phi_s")]);
      x["phi_l"] = cell_double(r.cells[t.column("phi_l")]);
    }
    arr.push_back(x);
  }
  return arr;
}

}  // namespace blockdyn
