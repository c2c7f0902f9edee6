// SPDX-License-Identifier: Apache-2.0
// Grid analyses on the sweep runner: a GridTable's rows read back to the same values (survival
// points, spectrum rows), the refinement plan's stages on a constructed boundary, and a refined
// run through run_sweep that is the same for 1 and 2 threads and computes only near the boundary.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "blockdyn/analysis/forced/spectrum_table.hpp"
#include "blockdyn/analysis/forced/survival_table.hpp"
#include "blockdyn/analysis/sweep/grid_table.hpp"
#include "blockdyn/analysis/sweep/refinement_plan.hpp"
#include "blockdyn/analysis/sweep/sweep_runner.hpp"
#include "blockdyn/io/progress.hpp"
#include "test_sweep_util.hpp"

using namespace blockdyn;

namespace {

SweepRunOptions quiet(int threads) {
  SweepRunOptions o;
  o.threads = threads;
  o.progress = ProgressMode::None;
  return o;
}

// Drives a plan as the runner does, with rows from a class function of the lattice point; returns
// the stages.
std::vector<std::vector<std::size_t>> drive(RefinementPlan& plan, const std::function<int(std::size_t)>& cls) {
  std::map<std::size_t, CellRow> rows;
  std::vector<std::vector<std::size_t>> stages;
  const FinishedRow lookup = [&](std::size_t i) -> const CellRow* {
    const auto it = rows.find(i);
    return it == rows.end() ? nullptr : &it->second;
  };
  for (;;) {
    const auto st = plan.next_stage(lookup);
    if (st.empty()) break;
    stages.push_back(st);
    for (std::size_t i : st) rows.emplace(i, CellRow{i, cls(i)});
  }
  return stages;
}

std::string class_cell(const CellRow& row) { return row.at(1).text(); }

}  // namespace

TEST(GridTable, SurvivalPointsAndSpectrumRowsReadBackExactly) {
  const sweep_test::TmpDir tmp("grid-codec");
  SurvivalPoint a;
  a.beta = 0.1 + 0.2;  // not a short decimal: %.17g must round-trip it
  a.omega = std::sqrt(2.0);
  a.motion = "collapse";
  a.collapse_mode = 2;
  a.t_failure = 1.0 / 3.0;
  a.t_star_class = "<=5 s";
  a.max_abs_rotation = 0.2449786631268641;
  a.max_sliding = 1e-300;
  a.cycle = "(1,3)";
  SurvivalPoint b;  // rest: every optional empty
  SpectrumRow s;
  s.duration = 0.7;
  s.min_overturning_amplitude = 0.123456789012345678;
  s.safe_islands = {{0.2, 0.25}, {1.0 / 7.0, 2.0 / 7.0}};
  s.runs = 61;
  s.scan = {0, 0, 1, 0, 1};
  // Two tables: one per codec (their columns differ).
  const GridTable ts(
      "survival", survival_columns(), 2, [&](std::size_t i, CellRow& r) { add_survival_cells(i == 0 ? a : b, r); }, {},
      {}, tmp.path + "/s.csv");
  const GridTable tp(
      "spectrum", spectrum_columns(), 1, [&](std::size_t, CellRow& r) { add_spectrum_cells(s, 0.5, r); }, {}, {},
      tmp.path + "/p.csv");
  run_sweep(ts, quiet(1));
  run_sweep(tp, quiet(1));
  const Table t1 = read_table(tmp.path + "/s.csv", ts.header());
  ASSERT_EQ(t1.rows.size(), 2u);
  const SurvivalPoint a2 = survival_point_from(t1, t1.rows[0]), b2 = survival_point_from(t1, t1.rows[1]);
  EXPECT_EQ(a2.beta, a.beta);
  EXPECT_EQ(a2.omega, a.omega);
  EXPECT_EQ(a2.motion, a.motion);
  EXPECT_EQ(a2.collapse_mode, a.collapse_mode);
  EXPECT_EQ(a2.t_failure, a.t_failure);
  EXPECT_EQ(a2.t_star_class, a.t_star_class);
  EXPECT_EQ(a2.max_abs_rotation, a.max_abs_rotation);
  EXPECT_EQ(a2.max_sliding, a.max_sliding);
  EXPECT_EQ(a2.cycle, a.cycle);
  EXPECT_EQ(b2.motion, "rest");
  EXPECT_FALSE(b2.collapse_mode);
  EXPECT_FALSE(b2.t_failure);
  EXPECT_EQ(b2.cycle, "");
  const Table t2 = read_table(tmp.path + "/p.csv", tp.header());
  const SpectrumRow s2 = spectrum_row_from(t2, t2.rows.at(0));
  EXPECT_EQ(s2.duration, s.duration);
  EXPECT_EQ(s2.min_overturning_amplitude, s.min_overturning_amplitude);
  ASSERT_EQ(s2.safe_islands.size(), 2u);
  EXPECT_EQ(s2.safe_islands[1].from, s.safe_islands[1].from);
  EXPECT_EQ(s2.safe_islands[1].to, s.safe_islands[1].to);
  EXPECT_EQ(s2.runs, 61);
  EXPECT_EQ(s2.scan, s.scan);
  // A table read with another header is refused; a row of the wrong width is a programming error.
  EXPECT_THROW(read_table(tmp.path + "/p.csv", ts.header()), std::runtime_error);
  const GridTable bad(
      "x", {"a", "b"}, 1, [](std::size_t, CellRow& r) { r.emplace_back(1.0); }, {}, {}, tmp.path + "/x.csv");
  EXPECT_THROW(bad.row(0), std::logic_error);
}

TEST(RefinementPlan, RefinesOnlyCellsWhoseCornersDiffer) {
  // 9 x 7 coarse points, 3 levels: a 65 x 49 lattice; the class is inside/outside a disc.
  RefinementPlan plan(9, 7, 3, class_cell);
  ASSERT_EQ(plan.nx_fine(), 65u);
  ASSERT_EQ(plan.ny_fine(), 49u);
  const double cx = 30.3, cy = 22.7, rad = 17.9;
  auto inside = [&](std::size_t i) {
    const double x = double(i % 65), y = double(i / 65);
    return int(std::hypot(x - cx, y - cy) < rad);
  };
  const auto stages = drive(plan, inside);
  ASSERT_EQ(stages.size(), 4u);
  EXPECT_EQ(stages[0].size(), 63u);  // the coarse grid
  std::set<std::size_t> all;
  for (std::size_t l = 0; l < stages.size(); ++l)
    for (std::size_t i : stages[l]) {
      if (all.insert(i).second) {
        EXPECT_EQ(plan.level_of(i), int(l)) << i;
      }
    }
  // Every lattice point within one fine step of the circle is computed, and far fewer than all.
  for (std::size_t i = 0; i < plan.size(); ++i) {
    const double d = std::hypot(double(i % 65) - cx, double(i / 65) - cy) - rad;
    if (std::fabs(d) < 1.0) {
      EXPECT_TRUE(all.count(i)) << "missed " << i % 65 << ',' << i / 65;
    }
  }
  EXPECT_LT(all.size(), plan.size() / 3);
  // Uniform class: the coarse grid only.
  RefinementPlan flat(9, 7, 3, class_cell);
  EXPECT_EQ(drive(flat, [](std::size_t) { return 0; }).size(), 1u);
}

TEST(RefinementPlan, OneAxisBracketsTheThreshold) {
  // 5 points along x, one along y, 4 levels: 65 points; class changes between 40 and 41.
  RefinementPlan plan(5, 1, 4, class_cell);
  ASSERT_EQ(plan.size(), 65u);
  const auto stages = drive(plan, [](std::size_t i) { return int(i > 40); });
  ASSERT_EQ(stages.size(), 5u);
  EXPECT_EQ(stages[0], (std::vector<std::size_t>{0, 16, 32, 48, 64}));
  EXPECT_EQ(stages[4], (std::vector<std::size_t>{40, 41, 42}));
}

TEST(RefinementPlan, RefinedRunIsTheSameForOneAndTwoThreadsAndSparse) {
  const sweep_test::TmpDir tmp("grid-refine");
  auto make = [&](const std::string& out, RefinementPlan& plan) {
    return GridTable(
        "test", {"x", "y", "cls", "level"}, plan.size(),
        [&plan](std::size_t i, CellRow& r) {
          const double x = double(i % plan.nx_fine()) / double(plan.nx_fine() - 1);
          const double y = double(i / plan.nx_fine()) / double(plan.ny_fine() - 1);
          r.emplace_back(x);
          r.emplace_back(y);
          r.emplace_back(y > 0.3 + 0.4 * x * x ? "above" : "below");
          r.emplace_back(static_cast<long long>(plan.level_of(i)));
        },
        {{"what", "a parabola"}}, {}, out);
  };
  auto cls = [](const CellRow& row) { return row.at(3).text(); };
  RefinementPlan p1(6, 6, 3, cls), p2(6, 6, 3, cls);
  const GridTable t1 = make(tmp.path + "/a.csv", p1), t2 = make(tmp.path + "/b.csv", p2);
  const SweepOutcome o1 = run_sweep(t1, quiet(1), &p1);
  const SweepOutcome o2 = run_sweep(t2, quiet(2), &p2);
  EXPECT_EQ(sweep_test::slurp(tmp.path + "/a.csv"), sweep_test::slurp(tmp.path + "/b.csv"));
  EXPECT_EQ(o1.computed, o2.computed);
  EXPECT_LT(o1.computed, t1.size() / 2);  // sparse: only near the curve
  EXPECT_GT(o1.computed, 36u);
  EXPECT_NE(sweep_test::slurp(tmp.path + "/a.json").find("\"rows_in_table\": " + std::to_string(o1.computed)),
            std::string::npos);
  EXPECT_NE(sweep_test::slurp(tmp.path + "/a.json").find("blockdyn.test.sidecar/1"), std::string::npos);
}
