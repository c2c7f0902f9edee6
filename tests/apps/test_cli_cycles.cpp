// SPDX-License-Identifier: Apache-2.0
// `blockdyn cycles` and `blockdyn impact-map` (issue 9 items 4-5): the JSON keys and CSV columns
// scripts rely on, the figures, an assembly preset, the survival map's cycle per point (the same
// for 1 and 2 threads), and bad input (exit 2 naming the field).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>

#include "cli_test.hpp"

namespace {
const std::vector<std::string> kHousner{"--model", "housner", "--width", "0.3", "--height", "1.5"};
std::vector<std::string> cycles_with(std::vector<std::string> head, const std::vector<std::string>& tail) {
  head.insert(head.end(), tail.begin(), tail.end());
  return head;
}
}  // namespace

TEST(CliCycles, JsonSegmentsStrobeCsvTraceAndPlot) {
  TmpDir d("cycles");
  const auto r = run_cli(cycles_with(cycles_with({"cycles"}, kHousner),
                                     {"--beta", "2", "--omega", "5", "--periods", "100", "--json", "--quiet", "--out",
                                      "s.csv", "--trace", "t.csv", "--trace-per-period", "8", "--plot", "c.png"}),
                         d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["schema"], "blockdyn.cycles.summary/1");
  EXPECT_NE(j["convention"].get<std::string>().find("seed 002"), std::string::npos);
  EXPECT_NE(j["convention"].get<std::string>().find("(n, k)"), std::string::npos);
  EXPECT_EQ(j["excitation"]["beta"], 2.0);
  EXPECT_EQ(j["strobe_samples"], 101);
  EXPECT_EQ(j["dominant_cycle"], "(1,1)");
  ASSERT_FALSE(j["segments"].empty());
  for (const auto& s : j["segments"])
    for (const char* k : {"t_start", "t_end", "type", "m", "n", "cycle", "impacts", "periods", "return_distance"})
      EXPECT_TRUE(s.contains(k)) << k;
  const json& last = j["segments"].back();
  EXPECT_EQ(last["type"], "periodic");
  EXPECT_EQ(last["m"], 1);
  EXPECT_EQ(last["n"], 1);
  EXPECT_DOUBLE_EQ(last["t_end"].get<double>(), 100 * j["excitation"]["period"].get<double>());
  EXPECT_TRUE(j["changes"].is_array());
  const std::string csv = slurp(d.path + "/s.csv");
  EXPECT_EQ(csv.substr(0, 48), "k,t,x_0,y_0,theta_0,vx_0,vy_0,omega_0,cycle\n0,0,");
  EXPECT_NE(csv.find("\"(1,1)\""), std::string::npos);
  // The trace: 8 samples per period, the strobe samples among them.
  std::istringstream tr(slurp(d.path + "/t.csv"));
  std::string line;
  long rows = -1;
  while (std::getline(tr, line)) ++rows;
  EXPECT_EQ(rows, 801);
  EXPECT_TRUE(exists(d.path + "/c.png"));
  EXPECT_TRUE(exists(d.path + "/c.svg"));
}

TEST(CliCycles, TrilithShowsAOneThreeTypeCycle) {
  // Seed 002's case phi = 90, beta = 4, omega = 10 over 30 s: the left column's stroboscopic
  // samples settle into three bands, the (1,3) family (docs/cycles.md has the 400 s run).
  TmpDir d("cycles_trilith");
  const auto r = run_cli({"cycles", "--model", "assembly", "--preset", "trilith", "--beta", "4", "--omega", "10",
                          "--t-end", "30", "--json", "--quiet"},
                         d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["block_name"], "left column");
  bool one_three = false;
  for (const auto& s : j["segments"]) one_three |= s["cycle"] == "(1,3)" || s["cycle"] == "(2,6)";
  EXPECT_TRUE(one_three) << j["segments"].dump();
}

TEST(CliImpactMap, PhasesPoincareAndPlot) {
  TmpDir d("impact_map");
  const auto r = run_cli(
      cycles_with(cycles_with({"impact-map"}, kHousner),
                  {"--beta",      "2",     "--omega",         "5",    "--phase", "0.5",     "--periods", "60",
                   "--transient", "20",    "--section-phase", "1",    "--json",  "--quiet", "--out",     "i.csv",
                   "--poincare",  "p.csv", "--plot",          "m.png"}),
      d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["schema"], "blockdyn.impact-map.summary/1");
  EXPECT_EQ(j["impacts"], 80);  // (1,1): 2 per period over the 40 periods after the transient
  EXPECT_EQ(j["poincare_samples"], 40);
  const double Omega = j["excitation"]["Omega"].get<double>();
  EXPECT_NEAR(std::remainder(Omega * j["section_t0"].get<double>() + 0.5 - 1.0, 2 * M_PI), 0.0, 1e-12);
  std::istringstream in(slurp(d.path + "/i.csv"));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "i,t,phase,omega_before,omega_after");
  long n = 0;
  while (std::getline(in, line)) {
    double i, t, ph, wb, wa;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf", &i, &t, &ph, &wb, &wa), 5);
    EXPECT_GE(ph, 0.0);
    EXPECT_LT(ph, 2 * M_PI);
    EXPECT_NEAR(std::remainder(Omega * t + 0.5 - ph, 2 * M_PI), 0.0, 1e-9);
    EXPECT_GE(t, 20 * j["excitation"]["period"].get<double>());
    ++n;
  }
  EXPECT_EQ(n, 80);
  EXPECT_EQ(slurp(d.path + "/p.csv").substr(0, 8), "k,t,x_0,");
  EXPECT_TRUE(exists(d.path + "/m.png"));
}

TEST(CliSurvival, CyclePerPointIsTheSameForOneAndTwoThreads) {
  TmpDir d("survival_cycles");
  std::vector<json> maps;
  for (const char* threads : {"1", "2"}) {
    const auto r = run_cli(
        cycles_with(cycles_with({"survival"}, kHousner),
                    {"--beta-min", "1.5", "--beta-max", "4", "--beta-points", "3", "--omega-min", "4", "--omega-max",
                     "12", "--omega-points", "3", "--periods", "60", "--threads", threads, "--json", "--quiet"}),
        d.path);
    ASSERT_EQ(r.code, 0) << r.err;
    maps.push_back(json::parse(r.out)["points"]);
  }
  EXPECT_EQ(maps[0], maps[1]);
  int cycles = 0;
  for (const auto& p : maps[0]) {
    if (p["motion"] == "rest") {
      EXPECT_TRUE(p["cycle"].is_null());
    }
    cycles += p["cycle"] == "(1,1)";
  }
  EXPECT_GT(cycles, 0);
  EXPECT_EQ(maps[0][0]["cycle"], "(1,1)");  // beta 1.5, omega 4: the symmetric orbit
}

TEST(CliCycles, BadInputIsAUsageError) {
  TmpDir d("cycles_bad");
  const std::vector<std::string> ok{"--beta", "2", "--omega", "5"};
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {cycles_with({"cycles"}, kHousner), "--beta"},
      {cycles_with(cycles_with({"cycles"}, kHousner), {"--beta", "2"}), "--omega"},
      {cycles_with(cycles_with({"cycles"}, kHousner), {"--beta", "-1", "--omega", "5"}), "beta"},
      {cycles_with(cycles_with({"cycles"}, kHousner), {"--beta", "2", "--omega", "0"}), "omega"},
      {cycles_with(cycles_with(cycles_with({"cycles"}, kHousner), ok), {"--block", "1"}), "block"},
      {cycles_with(cycles_with(cycles_with({"cycles"}, kHousner), ok), {"--window", "1"}), "window"},
      {cycles_with(cycles_with(cycles_with({"cycles"}, kHousner), ok), {"--max-period", "13"}), "max-period"},
      {cycles_with(cycles_with(cycles_with({"cycles"}, kHousner), ok), {"--tolerance", "0"}), "tolerance"},
      {cycles_with(cycles_with(cycles_with({"cycles"}, kHousner), ok), {"--t-end", "5", "--periods", "3"}), "not both"},
      {cycles_with(cycles_with(cycles_with({"cycles"}, kHousner), ok), {"--periods", "nan"}), "periods"},
      {cycles_with(cycles_with(cycles_with({"cycles"}, kHousner), ok), {"--excitation", "half-sine"}), "excitation"},
      {cycles_with(cycles_with(cycles_with({"cycles"}, kHousner), ok), {"--trace-per-period", "0"}),
       "trace-per-period"},
      {cycles_with(cycles_with(cycles_with({"cycles"}, kHousner), ok), {"--out", "/nonexistent/x.csv"}), "out"},
      {cycles_with({"cycles", "--model", "assembly"}, ok), "--preset"},
      {cycles_with(cycles_with(cycles_with({"impact-map"}, kHousner), ok), {"--transient", "-1"}), "transient"},
      {cycles_with(cycles_with(cycles_with({"impact-map"}, kHousner), ok), {"--periods", "10", "--transient", "10"}),
       "transient"},
      {cycles_with(cycles_with(cycles_with({"impact-map"}, kHousner), ok), {"--section-phase", "inf"}),
       "section-phase"},
      {cycles_with(cycles_with({"impact-map"}, kHousner), {"--beta", "2"}), "--omega"},
  };
  expect_usage_errors(cases, d.path);
}
