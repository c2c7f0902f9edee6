// SPDX-License-Identifier: Apache-2.0
// `blockdyn simulate --model rigid3d` (issue 40): the JSON summary's keys, the trajectory's
// columns, an overturn under a pulse, reproducibility and the usage errors.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "cli_test.hpp"

namespace {

std::vector<std::string> box() {
  return {"simulate", "--model", "rigid3d", "--width", "0.4", "--depth", "0.3", "--height", "1.2", "--mass", "250"};
}

std::vector<std::string> joined(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// `count` generated two-component records (strong, 15 s) in dir/suite.
void generate_two_component_suite(const std::string& dir, int count) {
  const auto gen = run_cli({"motion",  "generate", "--components", "2",   "--count", std::to_string(count),
                            "--arias", "1.5",      "--h2-arias",   "0.8", "--d5-95", "8",
                            "--t-mid", "5",        "--f-mid",      "2.5", "--t-end", "15",
                            "--out",   "suite",    "--quiet"},
                           dir);
  ASSERT_EQ(gen.code, 0) << gen.err;
}

TEST(CliRigid3d, JsonContractOfAFreeRockingBox) {
  TmpDir d("rigid3d_json");
  const json j = cli_json(joined(box(), {"--tilt", "0.12", "--t-end", "2", "--json"}), d.path);
  ASSERT_FALSE(j.is_null());
  EXPECT_EQ(j["schema"], "blockdyn.simulate.summary/1");
  EXPECT_EQ(j["model"], "rigid3d");
  EXPECT_EQ(j["status"], "t_end");
  EXPECT_TRUE(j["overturn_time"].is_null());
  EXPECT_DOUBLE_EQ(j["t_final"].get<double>(), 2.0);
  EXPECT_NEAR(j["max_tilt"].get<double>(), 0.12, 1e-12);
  EXPECT_NEAR(j["max_tilt_azimuth"].get<double>(), 0.0, 1e-9);  // leaning towards +x, as released
  EXPECT_TRUE(j["overturn_azimuth"].is_null());
  EXPECT_EQ(j["max_slide"].get<double>(), 0.0);
  EXPECT_EQ(j["body"]["shape"], "box");
  EXPECT_DOUBLE_EQ(j["body"]["depth"].get<double>(), 0.3);
  for (const char* k : {"initial", "final", "work_ground", "work_impact"}) EXPECT_TRUE(j["energy"].contains(k)) << k;
  EXPECT_LT(j["max_abs_energy_error"].get<double>(), 1e-9 * 250 * 9.81 * 1.2);
  long impacts = 0;
  for (const auto& e : j["events"])
    if (e["kind"] == "impact") {
      ++impacts;
      EXPECT_EQ(e["to"], "edge");
    }
  EXPECT_GE(impacts, 3);
  EXPECT_EQ(j["impacts"], impacts);
  EXPECT_TRUE(j["run"].contains("version"));
}

TEST(CliRigid3d, TrajectoryColumnsAndFirstRow) {
  TmpDir d("rigid3d_csv");
  const auto r = run_cli(
      joined(box(), {"--tilt", "0.1", "--tilt-azimuth", "90", "--t-end", "1", "--trajectory", "t.csv", "--quiet"}),
      d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  std::istringstream in(slurp(d.path + "/t.csv"));
  std::string header, first;
  std::getline(in, header);
  std::getline(in, first);
  EXPECT_EQ(header.rfind("t,x,y,z,qw,qx,qy,qz,tilt,tilt_azimuth,vx,vy,vz,wx,wy,wz,mode,", 0), 0u) << header;
  std::vector<std::string> cells;
  std::istringstream row(first);
  for (std::string c; std::getline(row, c, ',');) cells.push_back(c);
  ASSERT_GE(cells.size(), 17u);
  EXPECT_NEAR(std::stod(cells[8]), 0.1, 1e-14);  // tilt
  EXPECT_NEAR(std::stod(cells[9]), 90.0, 1e-9);  // leaning towards +y
  EXPECT_EQ(cells[16], "edge");
}

TEST(CliRigid3d, OutputIntervalZeroWritesARowAtEveryStep) {
  // As the planar families: 0 is every step (before, rigid3d refused it).
  TmpDir d("rigid3d_every");
  const auto r = run_cli(
      joined(box(), {"--tilt", "0.1", "--t-end", "1", "--output-interval", "0", "--trajectory", "t.csv", "--json"}),
      d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  std::istringstream in(slurp(d.path + "/t.csv"));
  std::string line;
  std::getline(in, line);
  std::vector<double> t;
  while (std::getline(in, line)) t.push_back(std::stod(line.substr(0, line.find(','))));
  // The start, every step's end, and the events' rows (before and after).
  EXPECT_GE(t.size(), j["steps"].get<std::size_t>() + 1);
  for (std::size_t i = 1; i < t.size(); ++i) EXPECT_LE(t[i - 1], t[i]);
  EXPECT_EQ(t.back(), 1.0);
}

TEST(CliRigid3d, APulseOverturnsASlenderBoxAndTheRunRepeatsBitForBit) {
  TmpDir d("rigid3d_pulse");
  const std::vector<std::string> args{"simulate", "--model",
                                      "rigid3d",  "--width",
                                      "0.3",      "--depth",
                                      "0.3",      "--height",
                                      "1.2",      "--ground-h-amplitude",
                                      "0.8",      "--ground-h-pulse",
                                      "one-sine", "--ground-h-duration",
                                      "1",        "--ground-azimuth",
                                      "25",       "--mu-s",
                                      "100",      "--t-end",
                                      "5",        "--json"};
  const auto a = run_cli(args, d.path), b = run_cli(args, d.path);
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
  const json j = json::parse(a.out);
  EXPECT_EQ(j["status"], "overturned");
  EXPECT_GT(j["overturn_time"].get<double>(), 0.5);
  // Pushed along 25 degrees, the square leaves rest about an edge, turns onto a corner and falls
  // along the line of the motion (measured: 25.4 degrees off the axis, towards 205 degrees).
  const double az = j["overturn_azimuth"].get<double>();
  EXPECT_LT(std::fabs(std::remainder(az - 25.0, 180.0)), 2.0) << az;
  EXPECT_GT(j["first_uplift_time"].get<double>(), 0.0);
}

TEST(CliRigid3d, ACylinderThrownAlongTheGroundSlidesToItsClosedFormStop) {
  // Before, a cylinder started with a velocity on its base stayed where it was, velocity kept.
  TmpDir d("rigid3d_throw");
  const auto r = run_cli({"simulate", "--model", "rigid3d", "--shape", "cylinder", "--radius", "0.2", "--height", "1",
                          "--velocity", "0.3,0.4,0", "--mu-s", "0.3", "--t-end", "1", "--json"},
                         d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["status"], "t_end");
  EXPECT_EQ(j["final_mode"], "rest");
  EXPECT_NEAR(j["max_slide"].get<double>(), 0.25 / (2 * 0.3 * 9.81), 1e-9);
  ASSERT_EQ(j["events"].size(), 1u);
  EXPECT_EQ(j["events"][0]["kind"], "stick");
  EXPECT_NEAR(j["events"][0]["t"].get<double>(), 0.5 / (0.3 * 9.81), 1e-9);
  EXPECT_NEAR(j["energy"]["work_friction"].get<double>(), -0.5 * 100 * 0.25, 1e-9);
}

TEST(CliRigid3d, AVelocityGivenOnAnEdgeSlipsARotationGivenPivots) {
  // A box resting tilted on an edge: `--velocity` across the edge is the body's own, its edge slips
  // from t = 0 and sticks as the planar 3-DOF block's (`simulate --model rigid --w0 0.1 --vx0 -0.3`:
  // 0.056112946826 s); `--angular-velocity` alone turns it about the edge, which holds (mu 0.7:
  // at 0.3 the rotation's own friction would need more, and the edge slips from rest).
  TmpDir d("rigid3d_edge_throw");
  const std::vector<std::string> start{"--tilt", "0.1", "--mu-s", "0.3", "--t-end", "0.3", "--json"};
  const auto thrown = run_cli(joined(joined(box(), start), {"--velocity", "0.3,0,0"}), d.path);
  ASSERT_EQ(thrown.code, 0) << thrown.err;
  const json a = json::parse(thrown.out);
  ASSERT_FALSE(a["events"].empty());
  EXPECT_EQ(a["events"][0]["kind"], "stick");
  EXPECT_EQ(a["events"][0]["from"], "edge_slip");
  EXPECT_NEAR(a["events"][0]["t"].get<double>(), 0.056112946826, 1e-9);
  EXPECT_GT(a["max_slide"].get<double>(), 1e-3);
  const auto turned = run_cli(
      joined(box(), {"--tilt", "0.1", "--mu-s", "0.7", "--t-end", "0.3", "--json", "--angular-velocity", "0,0.5,0"}),
      d.path);
  ASSERT_EQ(turned.code, 0) << turned.err;
  const json b = json::parse(turned.out);
  EXPECT_EQ(b["max_slide"].get<double>(), 0.0);
  for (const json& e : b["events"]) EXPECT_NE(e["to"], "edge_slip");
}

TEST(CliRigid3d, ACylinderLeavesRestUnderTwoDifferentComponents) {
  // Two independent components turn the ground's acceleration: the cylinder leaves rest onto a rim
  // point whose moment the turning motion does not allow, rolls from flat and rocks on. Before,
  // the rolling contact started below the landing's tilt landed at once and the run stopped at
  // the rest's exit ("the contact changes mode repeatedly at one instant", tilt 0).
  TmpDir d("rigid3d_cyl_two");
  ASSERT_NO_FATAL_FAILURE(generate_two_component_suite(d.path, 5));
  for (const char* k : {"0001", "0005"}) {
    const std::string h1 = std::string("suite/rezaeian_") + k + "_h1.AT2",
                      h2 = std::string("suite/rezaeian_") + k + "_h2.AT2";
    const auto r =
        run_cli({"simulate", "--model",           "rigid3d", "--shape",          "cylinder", "--radius",
                 "0.2",      "--height",          "1",       "--mass",           "100",      "--mu-s",
                 "0.5",      "--ground-h-record", h1,        "--ground-h-scale", "1.5",      "--ground-h2-record",
                 h2,         "--ground-h2-scale", "1.5",     "--t-end",          "15",       "--json"},
                d.path);
    ASSERT_EQ(r.code, 0) << r.err;
    const json j = json::parse(r.out);
    EXPECT_EQ(j["status"], "overturned") << k << " " << j.value("stop_reason", "");
    EXPECT_GT(j["first_uplift_time"].get<double>(), 0.0) << k;
    EXPECT_LT(j["max_abs_energy_error"].get<double>(), 1e-9 * 100 * 9.81 * 1) << k;
  }
}

TEST(CliRigid3d, APainleveSpanIsSteppedAcrossOrStopsTheRun) {
  // A square column under twice a record along x and across it (mu 0.7): its sticking edge reaches
  // a state where no contact state is consistent. By default Moreau-Jean steps cross that span and
  // the run goes on to its end; `--painleve stop` ends it there, invalid, with the reason.
  TmpDir d("rigid3d_painleve");
  const std::string rec = std::string(BLOCKDYN_SOURCE_DIR) + "/tests/fixtures/synthetic_60s.AT2";
  const std::vector<std::string> run{"simulate", "--model",
                                     "rigid3d",  "--width",
                                     "0.4",      "--height",
                                     "1.2",      "--mass",
                                     "300",      "--mu-s",
                                     "0.7",      "--impact",
                                     "housner",  "--t-end",
                                     "6",        "--ground-azimuth",
                                     "30",       "--ground-h-record",
                                     rec,        "--ground-h-scale",
                                     "2.5",      "--ground-h2-record",
                                     rec,        "--json"};
  const auto stepped = run_cli(run, d.path);
  ASSERT_EQ(stepped.code, 0) << stepped.err;
  const json a = json::parse(stepped.out);
  EXPECT_EQ(a["status"], "t_end") << a["stop_reason"];
  EXPECT_EQ(a["painleve"]["treatment"], "step");
  EXPECT_GE(a["painleve"]["spans"].get<int>(), 1);
  EXPECT_GT(a["painleve"]["steps"].get<int>(), 0);
  EXPECT_LT(a["max_abs_energy_error"].get<double>(), 1e-9 * 300 * 9.81 * 1.2);
  const auto stopped = run_cli(joined(run, {"--painleve", "stop"}), d.path);
  ASSERT_EQ(stopped.code, 0) << stopped.err;
  const json b = json::parse(stopped.out);
  EXPECT_EQ(b["status"], "invalid");
  EXPECT_NE(b["stop_reason"].get<std::string>().find("Painleve"), std::string::npos);
  EXPECT_EQ(b["painleve"]["spans"], 0);
  EXPECT_EQ(b["painleve"]["step"], nullptr);
}

TEST(CliRigid3d, AnEdgeAndACornerTakingTurnsAreSteppedAcrossToo) {
  // A square column under twice a generated two-component record at 30 degrees (mu 0.7): Painleve
  // spans at 3.78 and 3.94 s, then at 8.39 s a slipping corner whose mode changes repeatedly at one
  // instant (the contact of an edge and a corner at once is not in the events' catalogue: this
  // stopped the run). The time steps cross them and the run reaches its end (just before the
  // column overturns), the balance closed.
  TmpDir d("rigid3d_turns");
  ASSERT_NO_FATAL_FAILURE(generate_two_component_suite(d.path, 8));
  const auto r = run_cli({"simulate",
                          "--model",
                          "rigid3d",
                          "--width",
                          "0.4",
                          "--height",
                          "1.2",
                          "--mu-s",
                          "0.7",
                          "--t-end",
                          "8.4",
                          "--ground-azimuth",
                          "30",
                          "--ground-h-record",
                          "suite/rezaeian_0008_h1.AT2",
                          "--ground-h-scale",
                          "2",
                          "--ground-h2-record",
                          "suite/rezaeian_0008_h2.AT2",
                          "--ground-h2-scale",
                          "2",
                          "--json"},
                         d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["status"], "t_end") << j["stop_reason"];
  EXPECT_GE(j["painleve"]["spans"].get<int>(), 2);
  int turns = 0;
  for (const json& e : j["events"]) turns += e["kind"] == "not_modelled";
  EXPECT_EQ(turns, 1);
  EXPECT_LT(j["max_abs_energy_error"].get<double>(), 1e-9 * 100 * 9.81 * 1.2);
}

TEST(CliRigid3d, ACylinderTippedFromExactlyFlatOntoARollIsSteppedAcross) {
  // A cylinder under 1.5 times a generated two-component record: its slide ends in slips and
  // landings taking turns, and the base, exactly flat, tips onto a rim point that needs a moment
  // to hold: rolling would start where the rim's lowest point is not defined (the rolling's
  // equations divide by the tilt's sine). Before, the state turned NaN there and the run ended on
  // a step underflow. With `--painleve stop` the run stops at that instant with the reason, its
  // state finite; by default Moreau-Jean steps on the rim's points cross it (the base lands back
  // flat) and the run reaches its end, every event's base on or above the ground, the balance
  // closed.
  TmpDir d("rigid3d_cyl_flat_roll");
  ASSERT_NO_FATAL_FAILURE(generate_two_component_suite(d.path, 8));
  const std::vector<std::string> run{"simulate",
                                     "--model",
                                     "rigid3d",
                                     "--shape",
                                     "cylinder",
                                     "--radius",
                                     "0.2",
                                     "--height",
                                     "1",
                                     "--mass",
                                     "100",
                                     "--mu-s",
                                     "0.5",
                                     "--t-end",
                                     "15",
                                     "--ground-h-record",
                                     "suite/rezaeian_0007_h1.AT2",
                                     "--ground-h-scale",
                                     "1.5",
                                     "--ground-h2-record",
                                     "suite/rezaeian_0007_h2.AT2",
                                     "--ground-h2-scale",
                                     "1.5",
                                     "--output-interval",
                                     "0",
                                     "--json"};
  const auto stopped = run_cli(joined(run, {"--painleve", "stop"}), d.path);
  ASSERT_EQ(stopped.code, 0) << stopped.err;
  const json b = json::parse(stopped.out);
  EXPECT_EQ(b["status"], "invalid");
  EXPECT_NE(b["stop_reason"].get<std::string>().find("exactly flat"), std::string::npos) << b["stop_reason"];
  EXPECT_EQ(b["events"].back()["kind"], "not_modelled");
  EXPECT_EQ(b["events"].back()["from"], "rim");
  EXPECT_EQ(b["events"].back()["tilt"].get<double>(), 0.0);
  for (const json& v : b["final_state"]) EXPECT_TRUE(v.is_number()) << v;  // NaN is written as null
  const double t_tip = b["t_final"].get<double>();

  const auto r = run_cli(run, d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["status"], "t_end") << j["stop_reason"];
  EXPECT_GE(j["painleve"]["spans"].get<int>(), 1);
  bool crossed = false;
  for (std::size_t i = 0; i + 1 < j["events"].size(); ++i) {
    const json& e = j["events"][i];
    const double tilt = e["tilt"].get<double>();
    EXPECT_GT(e["z"].get<double>() - (0.5 * std::cos(tilt) + 0.2 * std::sin(tilt)), -1e-9) << e;
    if (e["kind"] == "not_modelled" && e["t"].get<double>() == t_tip) crossed = j["events"][i + 1]["t"] > e["t"];
  }
  EXPECT_TRUE(crossed);
  EXPECT_LT(j["max_abs_energy_error"].get<double>(), 1e-9 * 100 * 9.81 * 1.0);
}

TEST(CliRigid3d, UsageErrorsNameTheOption) {
  TmpDir d("rigid3d_usage");
  const std::vector<std::string> m{"simulate", "--model", "rigid3d"};
  expect_usage_errors({{joined(m, {"--shape", "sphere"}), "--shape"},
                       {joined(m, {"--radius", "0.3"}), "--radius"},
                       {joined(m, {"--velocity", "1,0,nan"}), "--velocity"},
                       {joined(m, {"--lift", "0.1", "--velocity", "1,0"}), "--velocity"},
                       {joined(m, {"--tilt", "2"}), "tilt"},
                       {joined(m, {"--width", "-1"}), "width"},
                       {joined(m, {"--mu-k", "-0.3"}), "mu-k"},
                       {joined(m, {"--mass", "1", "--density", "2000"}), "--density"},
                       {joined(m, {"--ground-h2-amplitude", "0.3", "--ground-h2-pulse", "wave"}), "--ground-h2-pulse"},
                       {joined(m, {"--painleve", "maybe"}), "--painleve"},
                       {joined(m, {"--painleve-step", "0"}), "painleve-step"},
                       {joined(m, {"--painleve", "stop", "--painleve-step", "1e-6"}), "--painleve-step"},
                       {{"simulate", "--model", "housner", "--painleve", "stop"}, "--painleve"}},
                      d.path);
}

}  // namespace
