// SPDX-License-Identifier: Apache-2.0
// Sweeps of the rigid-ground family (issue 7: sweeps take their axes from the model family):
// axes named after the family's parameters, the same bytes for any thread count, a definition
// file equivalent to the flags, unknown axes rejected, and every row equal to its single run.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

#include "blockdyn/analysis/sweep/rigid_sweep.hpp"
#include "test_sweep_util.hpp"

using namespace sweep_test;
using nlohmann::json;

namespace {

std::vector<std::string> rect_sweep(const std::string& out, const std::string& threads) {
  return {"sweep",
          "--model",
          "housner",
          "--width",
          "0.25",
          "--height",
          "1.5",
          "--ground-h-pulse",
          "rect",
          "--axis",
          "ground_h_duration=0.1:1.0:6",
          "--axis",
          "ground_h_amplitude=0.12:0.6:8",
          "--t-end",
          "6",
          "-o",
          out,
          "--threads",
          threads,
          "--quiet"};
}

}  // namespace

TEST(RigidSweep, SameBytesForAnyThreadCount) {
  TmpDir d("rsweep");
  ASSERT_EQ(run_cli(rect_sweep("a.csv", "1"), d.path).code, 0);
  const auto r2 = run_cli(rect_sweep("b.csv", "2"), d.path);
  ASSERT_EQ(r2.code, 0) << r2.err;
  const std::string a = slurp(d.path + "/a.csv");
  EXPECT_TRUE(a == slurp(d.path + "/b.csv"));
  EXPECT_EQ(count_lines(a), 49u);
  EXPECT_EQ(a.rfind("index,ground_h_duration,ground_h_amplitude,status,t_final,final_mode,max_abs_rotation,", 0), 0u);
  const json side = json::parse(slurp(d.path + "/a.json"));
  EXPECT_EQ(side["schema"], "blockdyn.sweep.sidecar/1");
  EXPECT_EQ(side["definition"]["model"], "housner");
  EXPECT_EQ(side["status"], "complete");
}

TEST(RigidSweep, DefinitionFileEqualsFlags) {
  TmpDir d("rsweepfile");
  std::ofstream(d.path + "/def.toml")
      << "model = \"housner\"\n[physical]\nwidth = 0.25\nheight = 1.5\n"
      << "[ground.horizontal]\npulse = \"rect\"\n[run]\nt_end = 6\n"
      << "[axes]\nground_h_duration = \"0.1:1.0:6\"\nground_h_amplitude = \"0.12:0.6:8\"\n"
      << "[output]\ncsv = \"f.csv\"\n";
  ASSERT_EQ(run_cli(rect_sweep("a.csv", "2"), d.path).code, 0);
  const auto r = run_cli({"sweep", "def.toml", "--quiet"}, d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(slurp(d.path + "/f.csv") == slurp(d.path + "/a.csv"));
}

TEST(RigidSweep, RowsEqualSingleRuns) {
  blockdyn::RigidSweepSpec s;
  s.model = &blockdyn::three_dof_on_rigid_ground();
  s.block.shape.width = 0.3;
  s.block.shape.height = 1.0;
  s.ground.horizontal.frequency = 1.5;
  s.axes.push_back(blockdyn::axis_list("mu", {0.2, 0.5}));
  s.axes.push_back(blockdyn::axis_list("ground_h_amplitude", {0.2, 0.4, 0.6}));
  s.options.t_end = 4.0;
  validate(s);
  const blockdyn::RigidSweepEvaluator ev(s);
  ASSERT_EQ(ev.size(), 6u);
  // Point 3: mu index 1, amplitude index 1 (the first axis varies fastest).
  const blockdyn::RigidSweepPoint p = sweep_point(s, 3);
  EXPECT_EQ(p.block.interface.mu_s, 0.5);
  EXPECT_EQ(p.ground.horizontal.amplitude, 0.4);
  const auto r = blockdyn::simulate_rigid(p.block, p.ground, p.initial, s.options);
  const std::string row = blockdyn::csv_line(ev.row(3).cells);
  EXPECT_NE(row.find(std::string(",") + to_string(r.status) + ","), std::string::npos) << row;
  EXPECT_NE(row.find("," + blockdyn::format_double(r.max_abs_rotation) + ","), std::string::npos) << row;
}

TEST(RigidSweep, BadAxesAreUsageErrors) {
  TmpDir d("rsweepbad");
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"sweep", "--model", "rigid", "--width", "0.3", "--height", "1", "--axis", "k=1,2"},
        std::vector<std::string>{"sweep", "--model", "housner", "--width", "0.3", "--height", "1", "--axis",
                                 "mu=0.1,0.2"},
        std::vector<std::string>{"sweep", "--model", "rigid", "--width", "0.3", "--height", "1", "--axis", "mu_k"},
        std::vector<std::string>{"sweep", "--model", "rigid", "--axis", "mu=0.1"},
        std::vector<std::string>{"sweep", "--model", "rigid", "--width", "0.3", "--height", "1", "--k", "1e3"},
        std::vector<std::string>{"sweep", "--model", "rigid", "--width", "0.3", "--height", "1", "--axis",
                                 "mu_k=0.1,0.9"}}) {
    const auto r = run_cli(args, d.path);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
  }
}
