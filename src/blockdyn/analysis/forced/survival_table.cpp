// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/survival_table.hpp"

namespace blockdyn {

const std::vector<std::string>& survival_columns() {
  static const std::vector<std::string> c{"beta",         "omega",            "motion",      "collapse_mode", "t_failure",
                                          "t_star_class", "max_abs_rotation", "max_sliding", "cycle"};
  return c;
}

void add_survival_cells(const SurvivalPoint& p, RowBuilder& row) {
  row.add(p.beta);
  row.add(p.omega);
  row.add(csv_escape(p.motion));
  if (p.collapse_mode) row.add(static_cast<long long>(*p.collapse_mode));
  else row.empty();
  if (p.t_failure) row.add(*p.t_failure);
  else row.empty();
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

}  // namespace blockdyn
