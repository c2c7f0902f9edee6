// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/sweep/table_in_memory.hpp"

#include <map>
#include <string>
#include <vector>

#include "blockdyn/analysis/sweep/sweep_runner.hpp"

namespace blockdyn {

Table compute_table(const PointTable& t, int threads, PointPlan* plan,
                    const std::function<void(std::size_t, std::size_t)>& progress) {
  std::map<std::size_t, CellRow> rows;
  AllPoints all(t.size());
  PointPlan& p = plan ? *plan : all;
  std::size_t done = 0;
  const FinishedRow finished = [&rows](std::size_t i) -> const CellRow* {
    const auto it = rows.find(i);
    return it == rows.end() ? nullptr : &it->second;
  };
  for (std::vector<std::size_t> stage = p.next_stage(finished); !stage.empty(); stage = p.next_stage(finished)) {
    std::vector<std::size_t> todo;
    for (std::size_t i : stage)
      if (!rows.count(i)) todo.push_back(i);
    const std::size_t total = done + todo.size();
    compute_rows(t, todo, threads, [&](std::size_t i, const SweepRow& r) {
      rows[i] = r.cells;
      if (progress) progress(++done, total);
    });
  }
  Table out;
  out.columns = t.columns();
  for (auto& [i, cells] : rows) out.rows.push_back(TableRow{i, std::move(cells)});
  return out;
}

}  // namespace blockdyn
