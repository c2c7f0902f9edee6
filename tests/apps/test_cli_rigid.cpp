// SPDX-License-Identifier: Apache-2.0
// `blockdyn simulate --model housner|rigid` (issue 7): the JSON contract scripts rely on, the
// trajectory CSV, ground-motion flags (pulses, records) and bad input (exit 2, one line naming
// the field, no partial output).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

#include "cli_test.hpp"

namespace {

const std::string kRecord = std::string(BLOCKDYN_SOURCE_DIR) + "/tests/fixtures/synthetic_60s.AT2";

std::vector<std::string> base(const std::string& model) {
  return {"simulate", "--model", model, "--width", "0.3", "--height", "1.2", "--mass", "50"};
}

std::vector<std::string> operator+(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace

TEST(CliRigid, HousnerJsonContract) {
  TmpDir d("housner");
  const auto r = run_cli(base("housner") + std::vector<std::string>{"--w0", "0.1", "--t-end", "3", "--json"}, d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["schema"], "blockdyn.simulate.summary/1");  // docs/output-formats.md
  EXPECT_EQ(j["model"], "housner");
  EXPECT_EQ(j["status"], "t_end");
  EXPECT_EQ(j["final_mode"], "rock");
  EXPECT_DOUBLE_EQ(j["max_abs_rotation"].get<double>(), 0.1);
  EXPECT_TRUE(j["overturn_time"].is_null());
  for (const char* k : {"initial", "kinetic_final", "potential_final", "work_ground", "work_impact", "balance_final"})
    EXPECT_TRUE(j["energy"].contains(k)) << k;
  EXPECT_LT(j["max_abs_energy_error"].get<double>(), 1e-8);
  int impacts = 0;
  for (const auto& e : j["events"]) {
    ASSERT_TRUE(e.contains("t"));
    if (e["kind"] == "impact") {
      ++impacts;
      EXPECT_TRUE(e["corner"] == "A" || e["corner"] == "B");
      const double ratio = e["vw_after"].get<double>() / e["vw_before"].get<double>();
      EXPECT_NEAR(ratio, j["parameters"]["restitution"].get<double>(), 1e-12);
    }
  }
  EXPECT_GE(impacts, 3);
  EXPECT_EQ(j["impacts"], impacts);
}

TEST(CliRigid, RigidPulseOverturnsWithEvents) {
  TmpDir d("rigidpulse");
  const auto r = run_cli(
      base("rigid") + std::vector<std::string>{"--mu-s", "0.8", "--mu-k", "0.6", "--ground-h-pulse", "half-sine",
                                               "--ground-h-amplitude", "0.8", "--ground-h-duration", "0.6", "--t-end",
                                               "5", "--json", "--trajectory", "run.csv"},
      d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["status"], "overturned");
  ASSERT_FALSE(j["overturn_time"].is_null());
  bool mode = false, beyond = false, overturn = false;
  for (const auto& e : j["events"]) {
    if (e["kind"] == "mode") {
      mode = true;
      EXPECT_TRUE(e.contains("from") && e.contains("to"));
    }
    beyond |= e["kind"] == "beyond_alpha";
    if (e["kind"] == "overturn") {
      overturn = true;
      EXPECT_NEAR(std::fabs(e["state"]["w"].get<double>()), M_PI / 2, 1e-9);
    }
  }
  EXPECT_TRUE(mode && beyond && overturn);
  const std::string csv = slurp(d.path + "/run.csv");
  EXPECT_EQ(csv.rfind("t,x,y,w,vx,vy,vw,mode,event,a_h,a_v,N_A,T_A,N_B,T_B,", 0), 0u);
  EXPECT_NE(csv.find(",overturn,"), std::string::npos);
}

TEST(CliRigid, RecordAndScenarioGiveTheSameRun) {
  TmpDir d("rigidrec");
  const auto a = run_cli(base("rigid") + std::vector<std::string>{"--mu-s", "0.5", "--ground-h-record", kRecord,
                                                                  "--ground-h-scale", "1.2", "--t-end", "20", "--json"},
                         d.path);
  ASSERT_EQ(a.code, 0) << a.err;
  std::ofstream(d.path + "/s.toml") << "model = \"rigid\"\n[physical]\nwidth = 0.3\nheight = 1.2\nmass = 50\n"
                                    << "[interface]\nmu_s = 0.5\n[ground.horizontal]\nrecord = \"" << kRecord
                                    << "\"\nscale = 1.2\n[run]\nt_end = 20\n";
  const auto b = run_cli({"simulate", "s.toml", "--json"}, d.path);
  ASSERT_EQ(b.code, 0) << b.err;
  const json ja = json::parse(a.out), jb = json::parse(b.out);
  EXPECT_EQ(ja["events"], jb["events"]);
  EXPECT_EQ(ja["ground_motion"]["horizontal"]["record"]["samples"], 6000);
  EXPECT_GT(ja["impacts"].get<int>(), 0);
}

TEST(CliRigid, BadInputExitsTwoNamingTheField) {
  TmpDir d("rigidbad");
  std::ofstream(d.path + "/trunc.AT2") << "a\nb\nc\nNPTS=  10, DT=   .01000 SEC\n0.1 0.2 0.3\n";
  std::ofstream(d.path + "/bad.AT2") << "a\nb\nc\nNPTS=  3, DT=   .01000 SEC\n0.1 abc 0.3\n";
  struct Case {
    std::vector<std::string> args;
    std::string field;
  };
  const std::vector<Case> cases = {
      {{"simulate", "--model", "rigid", "--width", "-0.3", "--height", "1"}, "width"},
      {{"simulate", "--model", "housner", "--height", "1"}, "width"},
      {base("rigid") + std::vector<std::string>{"--mu-s", "0.3", "--mu-k", "0.5"}, "mu-k"},
      {base("housner") + std::vector<std::string>{"--restitution", "1.5"}, "restitution"},
      {base("rigid") + std::vector<std::string>{"--restitution", "-0.1"}, "restitution"},
      {base("rigid") + std::vector<std::string>{"--ground-h-record", "trunc.AT2"}, "truncated"},
      {base("rigid") + std::vector<std::string>{"--ground-h-record", "bad.AT2"}, "bad.AT2"},
      {base("rigid") + std::vector<std::string>{"--ground-h-record", "missing.AT2"}, "ground-h-record"},
      {base("rigid") + std::vector<std::string>{"--ground-h-pulse", "sine", "--ground-h-duration", "1"},
       "ground-h-pulse"},
      {base("rigid") + std::vector<std::string>{"--ground-h-pulse", "rect", "--ground-h-amplitude", "1"}, "duration"},
      {base("housner") + std::vector<std::string>{"--mu-s", "0.5"}, "mu-s"},
      {base("housner") + std::vector<std::string>{"--x0", "0.5"}, "x0"},
      {base("rigid") + std::vector<std::string>{"--k", "5"}, "--k"},
      {base("rigid") + std::vector<std::string>{"--w0", "1.6"}, "w0"},
      {base("rigid") + std::vector<std::string>{"--y0", "0.1"}, "below the ground"},
      {{"simulate", "--model", "stone"}, "model"},
      {{"simulate", "--r", "0.2", "--restitution", "0.5"}, "restitution"},
  };
  for (const Case& c : cases) {
    const auto r = run_cli(c.args + std::vector<std::string>{"--trajectory", "out.csv"}, d.path);
    EXPECT_EQ(r.code, 2) << c.field << ": " << r.err;
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(c.field), std::string::npos) << "expected '" << c.field << "' in: " << r.err;
    EXPECT_FALSE(exists(d.path + "/out.csv")) << c.field;
  }
}

TEST(CliRigid, PlotIsWritten) {
  TmpDir d("rigidplot");
  const auto r = run_cli(
      base("housner") + std::vector<std::string>{"--ground-h-pulse", "one-sine", "--ground-h-amplitude", "0.5",
                                                 "--ground-h-duration", "0.8", "--t-end", "4", "--plot", "p.png"},
      d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(exists(d.path + "/p.png"));
  EXPECT_TRUE(exists(d.path + "/p.svg"));
}

// Issue 25 item 3: under a constant 0.5 g a block with b/h = 0.25, mu_s = 0.35, mu_k = 0.2 can
// start rocking (friction holds the pivot) or sliding (kinetic friction 0.2 g keeps both corners
// loaded: N_B = N (1 - mu_k h / b) / 2 > 0): both are consistent. The choice is reported, with
// the rule; with mu_k = 0.3 sliding would unload a corner (1 - 0.3 * 4 < 0): rocking is unique.
TEST(CliRigid, AmbiguousOnsetIsReported) {
  TmpDir d("ambiguous");
  auto run = [&](const char* mu_k) {
    const auto r = run_cli({"simulate", "--model", "rigid", "--width", "0.25", "--height", "1", "--mass", "10",
                            "--mu-s", "0.35", "--mu-k", mu_k, "--ground-h", "0.5", "--t-end", "0.2", "--json"},
                           d.path);
    EXPECT_EQ(r.code, 0) << r.err;
    return json::parse(r.out);
  };
  const json j = run("0.2");
  EXPECT_EQ(j["ambiguous_onsets"], 1);
  EXPECT_EQ(j["event_counts"]["ambiguous_onset"], 1);
  int seen = 0;
  for (const auto& e : j["events"]) {
    if (e["kind"] != "ambiguous_onset") continue;
    ++seen;
    EXPECT_EQ(e["t"], 0.0);
    EXPECT_EQ(e["mechanisms"], json::array({"rock", "slide"}));
    EXPECT_EQ(e["chosen"], "rock");
    EXPECT_EQ(e["chosen"], j["initial_mode"]);
  }
  EXPECT_EQ(seen, 1);
  const json u = run("0.3");
  EXPECT_EQ(u["ambiguous_onsets"], 0);
  EXPECT_EQ(u["initial_mode"], "rock");
}
