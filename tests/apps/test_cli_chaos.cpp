// SPDX-License-Identifier: Apache-2.0
// `blockdyn lyapunov --model housner|rigid|assembly`, `blockdyn chaos-map` and
// `blockdyn periodic-orbits` (issue 9, items 6-7): the JSON keys and CSV columns scripts rely on,
// the figures, the identical output for 1 and 2 threads, and bad input (exit 2 naming the field).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

#include "cli_test.hpp"

TEST(CliChaos, ForcedLyapunovJsonHistoryTwinAndPlot) {
  TmpDir d("lyap_forced");
  const auto r = run_cli({"lyapunov", "--model", "housner",    "--width", "0.3",    "--height",      "1.5", "--beta",
                          "1.5",      "--omega", "3",          "--t-end", "40",     "--t-transient", "10",  "--json",
                          "--csv",    "h.csv",   "--twin-csv", "t.csv",   "--plot", "l.png"},
                         d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["schema"], "blockdyn.lyapunov.summary/1");
  EXPECT_EQ(j["status"], "completed");
  EXPECT_LT(j["exponent"].get<double>(), 0.0);  // a stable rocking orbit
  EXPECT_NEAR(j["exponent_nondim"].get<double>(), j["exponent"].get<double>() / j["p"].get<double>(), 1e-12);
  EXPECT_GT(j["impacts"].get<long>(), 10);
  EXPECT_EQ(j["saltation"]["unmatched"], 0);
  EXPECT_EQ(j["options"]["method"], "tangent");
  EXPECT_EQ(j["options"]["t_transient"], 10.0);
  EXPECT_LT(j["sensitivity"]["separation_final"].get<double>(), 1e-9);
  EXPECT_EQ(slurp(d.path + "/h.csv").substr(0, 18), "t,growth,estimate\n");
  EXPECT_EQ(slurp(d.path + "/t.csv").substr(0, 23), "t,separation,predicted\n");
  EXPECT_TRUE(exists(d.path + "/l.png"));
}

TEST(CliChaos, RigidBlockAgreesWithHousnerWithoutSliding) {
  TmpDir d("lyap_rigid");
  std::vector<double> ex;
  for (const std::string model : {"housner", "rigid"}) {
    std::vector<std::string> args = {"lyapunov", "--model",       model, "--width",   "0.3", "--height",
                                     "1.5",      "--beta",        "1.5", "--omega",   "3",   "--t-end",
                                     "60",       "--t-transient", "20",  "--twin-d0", "0",   "--json"};
    // High friction: the 3-DOF block does not slide (--mu-s is the rigid model's flag only).
    if (model == "rigid") args.insert(args.end(), {"--mu-s", "2"});
    const auto r = run_cli(args, d.path);
    ASSERT_EQ(r.code, 0) << r.err;
    ex.push_back(json::parse(r.out)["exponent"].get<double>());
  }
  EXPECT_NEAR(ex[1], ex[0], 0.02 * std::fabs(ex[0]));
}

TEST(CliChaos, ChaosMapCsvJsonPlotAndThreads) {
  TmpDir d("chaos_map");
  std::vector<std::string> base{"chaos-map", "--model",
                                "housner",   "--width",
                                "0.3",       "--height",
                                "1.5",       "--beta-min",
                                "0.8",       "--beta-max",
                                "2",         "--beta-points",
                                "2",         "--omega-min",
                                "3",         "--omega-max",
                                "6",         "--omega-points",
                                "2",         "--periods",
                                "30",        "--transient-periods",
                                "10",        "--quiet"};
  auto a1 = base, a2 = base;
  for (const char* x : {"--threads", "1", "--out", "m1.csv", "--json-out", "m1.json", "--plot", "m.png"})
    a1.push_back(x);
  for (const char* x : {"--threads", "2", "--out", "m2.csv"}) a2.push_back(x);
  const auto r1 = run_cli(a1, d.path), r2 = run_cli(a2, d.path);
  ASSERT_EQ(r1.code, 0) << r1.err;
  ASSERT_EQ(r2.code, 0) << r2.err;
  const std::string c1 = slurp(d.path + "/m1.csv");
  EXPECT_EQ(c1, slurp(d.path + "/m2.csv"));
  EXPECT_EQ(c1.substr(0, c1.find('\n')),
            "beta,omega,motion,exponent,exponent_nondim,exponent_second_half,status,impacts,collapse_mode,t_failure");
  const json j = json::parse(slurp(d.path + "/m1.json"));
  EXPECT_EQ(j["schema"], "blockdyn.chaos-map.summary/1");
  ASSERT_EQ(j["points"].size(), 4u);
  EXPECT_EQ(j["points"][0]["motion"], "rest");  // beta 0.8: below uplift
  EXPECT_TRUE(j["points"][0]["exponent"].is_null());
  EXPECT_EQ(j["points"][3]["motion"], "periodic");
  for (const char* k :
       {"beta", "omega", "motion", "exponent", "exponent_nondim", "status", "impacts", "collapse_mode", "t_failure"})
    EXPECT_TRUE(j["points"][3].contains(k)) << k;
  EXPECT_TRUE(exists(d.path + "/m.png"));
}

TEST(CliChaos, PeriodicOrbitsAgainstTheClosedForm) {
  TmpDir d("orbits");
  // alpha = atan(0.05): the nonlinear orbit is within alpha^2 of the linearised closed form.
  const auto r = run_cli({"periodic-orbits", "--width", "0.05", "--height", "1", "--restitution", "0.9", "--beta",
                          "1.2", "--omega", "2", "--json", "--quiet", "--out", "o.csv", "--plot", "o.png"},
                         d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["schema"], "blockdyn.periodic-orbits.summary/1");
  EXPECT_EQ(j["convention"]["seed_002"], "(m, n): 2m impacts per n forcing periods");
  EXPECT_EQ(j["convention"]["seed_001"]["k"], 2);
  ASSERT_EQ(j["orbits"].size(), 2u);
  ASSERT_EQ(j["linear_theory"].size(), 2u);
  int stable = 0;
  for (const auto& o : j["orbits"]) {
    stable += o["stable"].get<bool>();
    bool matched = false;
    for (const auto& l : j["linear_theory"])
      matched = matched || (std::fabs(o["phase"].get<double>() - l["phase"].get<double>()) < 5e-3 &&
                            std::fabs(o["velocity"].get<double>() - l["velocity"].get<double>()) < 5e-3);
    EXPECT_TRUE(matched) << o.dump();
    EXPECT_EQ(o["impacts"].size(), 2u);
  }
  EXPECT_EQ(stable, 1);
  EXPECT_EQ(slurp(d.path + "/o.csv").substr(0, 23), "orbit,phase,velocity,ve");
  EXPECT_TRUE(exists(d.path + "/o.png"));
}

TEST(CliChaos, PeriodicOrbitsContinuationAndRegion) {
  TmpDir d("orbits_cont");
  const auto c = run_cli({"periodic-orbits",
                          "--width",
                          "0.151",
                          "--height",
                          "1",
                          "--restitution",
                          "0.9",
                          "--beta",
                          "1.2",
                          "--omega",
                          "2",
                          "--continue",
                          "ks",
                          "--continue-min",
                          "0.01",
                          "--continue-max",
                          "0.4",
                          "--json",
                          "--quiet",
                          "--out",
                          "b.csv",
                          "--plot",
                          "b.png"},
                         d.path);
  ASSERT_EQ(c.code, 0) << c.err;
  const json j = json::parse(c.out);
  EXPECT_EQ(j["mode"], "continue");
  ASSERT_EQ(j["branches"].size(), 4u);  // two orbits, both directions
  bool fold = false, breaking = false;
  for (const auto& b : j["branches"])
    for (const auto& p : b["points"]) {
      fold = fold || p["event"].get<std::string>().find("fold") != std::string::npos;
      breaking = breaking || p["event"].get<std::string>().find("symmetry_breaking") != std::string::npos;
    }
  EXPECT_TRUE(fold);
  EXPECT_TRUE(breaking);
  EXPECT_TRUE(exists(d.path + "/b.png"));
  std::vector<std::string> reg{"periodic-orbits",
                               "--width",
                               "0.151",
                               "--height",
                               "1",
                               "--restitution",
                               "0.9",
                               "--region",
                               "--ks-min",
                               "0.05",
                               "--ks-max",
                               "0.4",
                               "--ks-points",
                               "3",
                               "--omega-min",
                               "1",
                               "--omega-max",
                               "5",
                               "--omega-points",
                               "3",
                               "--quiet"};
  auto r1 = reg, r2 = reg;
  for (const char* x : {"--threads", "1", "--out", "r1.csv", "--plot", "r.png", "--json-out", "r.json"})
    r1.push_back(x);
  for (const char* x : {"--threads", "2", "--out", "r2.csv"}) r2.push_back(x);
  ASSERT_EQ(run_cli(r1, d.path).code, 0);
  ASSERT_EQ(run_cli(r2, d.path).code, 0);
  EXPECT_EQ(slurp(d.path + "/r1.csv"), slurp(d.path + "/r2.csv"));
  const json rj = json::parse(slurp(d.path + "/r.json"));
  ASSERT_EQ(rj["points"].size(), 9u);
  EXPECT_GT(rj["counts"]["with_stable_orbits"].get<long>(), 0);
  EXPECT_TRUE(rj.contains("linear_fold"));
  EXPECT_TRUE(exists(d.path + "/r.png"));
}

TEST(CliChaos, BadInputIsAUsageError) {
  TmpDir d("chaos_bad");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"lyapunov", "--model", "housner", "--height", "1.5", "--beta", "1", "--omega", "2"}, "--width"},
      {{"lyapunov", "--model", "housner", "--width", "0.3", "--height", "1.5", "--beta", "1"}, "--omega"},
      {{"lyapunov", "--model", "housner", "--width", "0.3", "--height", "1.5", "--r", "0.2"}, "--r"},
      {{"lyapunov", "--model", "housner", "--width", "0.3", "--height", "1.5", "--method", "section"}, "section"},
      {{"lyapunov", "--model", "housner", "--width", "0.3", "--height", "1.5", "--twin-d0", "1"}, "twin-d0"},
      {{"lyapunov", "--model", "housner", "--width", "0.3", "--height", "1.5", "--t-transient", "300"}, "t-transient"},
      {{"lyapunov", "--model", "assembly", "--preset", "block", "--contact", "rigid"}, "rigid"},
      {{"lyapunov", "--r", "0.2", "--beta", "1", "--omega", "2"}, "--beta"},
      {{"chaos-map", "--model", "housner", "--width", "0.3", "--height", "1.5", "--excitation", "half-sine"},
       "harmonic"},
      {{"chaos-map", "--model", "housner", "--width", "0.3", "--height", "1.5", "--periods", "10",
        "--transient-periods", "20"},
       "periods"},
      {{"chaos-map", "--model", "housner", "--width", "0.3", "--height", "1.5", "--beta-min", "-1"}, "beta"},
      {{"periodic-orbits", "--width", "0.3", "--height", "1.5", "--omega", "2"}, "--ks"},
      {{"periodic-orbits", "--width", "0.3", "--height", "1.5", "--ks", "0.3", "--cycle", "0,1"}, "cycle m"},
      {{"periodic-orbits", "--width", "0.3", "--height", "1.5", "--ks", "0.3", "--restitution", "2"}, "restitution"},
      {{"periodic-orbits", "--width", "0.3", "--height", "1.5", "--ks", "0.3", "--continue", "ks"}, "--continue-min"},
      {{"periodic-orbits", "--width", "0.3", "--height", "1.5", "--region", "--ks-min", "0.5", "--ks-max", "0.1"},
       "ks-min"},
  };
  expect_usage_errors(cases, d.path);
}
