// SPDX-License-Identifier: Apache-2.0
// `blockdyn assembly` (issue 8): the JSON contract scripts rely on, an assembly file equal to the
// preset it describes, the trajectory CSV, and bad input (exit 2, one line naming the field).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include "cli_test.hpp"

namespace {

std::vector<std::string> operator+(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// Seed 002's trilith, lambda = 4, as an assembly file (the preset's upright layout, settled).
std::string trilith_file(const json& preset) {
  std::string s = "[contact]\nk_normal = 1e7\nrestitution = 0.5\nphi = 20\n\n";
  for (const auto& b : preset["assembly"]["blocks"]) {
    char buf[512];
    const auto& z = b["initial_state"];
    std::snprintf(buf, sizeof buf,
                  "[[block]]\nname = \"%s\"\nwidth = %.17g\nheight = %.17g\nmass = %.17g\nx = %.17g\ny = %.17g\n\n",
                  b["name"].get<std::string>().c_str(), b["width"].get<double>(), b["height"].get<double>(),
                  b["mass"].get<double>(), z[0].get<double>(), z[1].get<double>());
    s += buf;
  }
  s += "[[interface]]\nlower = \"ground\"\nupper = 0\n\n[[interface]]\nlower = \"ground\"\nupper = 1\n\n";
  s += "[[interface]]\nlower = 0\nupper = 2\n\n[[interface]]\nlower = 1\nupper = 2\n";
  return s;
}

const std::vector<std::string> kHarmonic{"--ground-h-amplitude", "0.4", "--ground-h-frequency", "2", "--ground-h-phase",
                                         "1.5707963267948966"};

}  // namespace

TEST(CliAssembly, JsonContract) {
  TmpDir d("asm_json");
  const auto r = run_cli(std::vector<std::string>{"assembly", "--preset", "trilith", "--phi-s", "20", "--phi-l", "20",
                                                  "--t-end", "2", "--json"} +
                             kHarmonic,
                         d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["schema"], "blockdyn.assembly.summary/1");
  EXPECT_EQ(j["model"], "assembly");
  for (const char* k : {"status", "motion", "collapse_mode", "t_failure", "blocks", "energy", "max_abs_energy_error",
                        "events", "interfaces", "run", "tolerances", "ground_motion"})
    EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_TRUE(j["status"] == "t_end" || j["status"] == "collapsed");
  EXPECT_TRUE(j["motion"] == "stable" || j["motion"] == "collapse");
  ASSERT_EQ(j["blocks"].size(), 3u);
  EXPECT_EQ(j["blocks"][2]["name"], "lintel");
  for (const auto& b : j["blocks"]) {
    EXPECT_TRUE(b.contains("max_abs_rotation"));
    EXPECT_TRUE(b.contains("max_abs_sliding"));
    EXPECT_EQ(b["final_state"].size(), 6u);
  }
  bool w_zero = false, open = false;
  for (const auto& e : j["events"]) {
    ASSERT_TRUE(e.contains("t") && e.contains("kind") && e.contains("block"));
    w_zero |= e["kind"] == "w_zero";
    open |= e["kind"] == "open";
  }
  EXPECT_TRUE(w_zero);
  EXPECT_TRUE(open);
  EXPECT_LT(j["max_abs_energy_error"].get<double>(), 1e-3);
}

TEST(CliAssembly, RigidLawJsonContract) {
  TmpDir d("asm_rigid");
  const auto r = run_cli(
      {"assembly", "--preset", "trilith", "--contact", "rigid", "--tilt", "0.05", "--t-end", "1", "--json"}, d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["contact"], "rigid");
  EXPECT_EQ(j["step"], 1e-4);
  EXPECT_EQ(j["status"], "t_end");
  EXPECT_EQ(j["motion"], "stable");
  EXPECT_EQ(j["assembly"]["interfaces"][0]["contact"]["law"], "rigid");
  EXPECT_EQ(j["assembly"]["interfaces"][0]["contact"]["restitution"], 0.0);  // plastic by default
  int impacts = 0;
  for (const auto& e : j["events"]) impacts += e["kind"] == "impact";
  EXPECT_GE(impacts, 2);
  EXPECT_EQ(j["impacts"], impacts);
}

TEST(CliAssembly, AnAssemblyFileGivesThePresetsResult) {
  TmpDir d("asm_file");
  const std::vector<std::string> common = std::vector<std::string>{"--t-end", "1.5", "--json"} + kHarmonic;
  const auto p = run_cli(
      std::vector<std::string>{"assembly", "--preset", "trilith", "--phi-s", "20", "--phi-l", "20"} + common, d.path);
  ASSERT_EQ(p.code, 0) << p.err;
  const json jp = json::parse(p.out);
  std::ofstream(d.path + "/trilith.toml") << trilith_file(jp);
  const auto f = run_cli(std::vector<std::string>{"assembly", "trilith.toml"} + common, d.path);
  ASSERT_EQ(f.code, 0) << f.err;
  const json jf = json::parse(f.out);
  EXPECT_EQ(jf["blocks"], jp["blocks"]);
  EXPECT_EQ(jf["events"], jp["events"]);
}

TEST(CliAssembly, TrajectoryAndFigures) {
  TmpDir d("asm_traj");
  const auto r = run_cli({"assembly", "--preset", "column", "--drums", "3", "--tilt", "0.05", "--t-end", "1",
                          "--trajectory", "c.csv", "--plot", "c.png", "--quiet"},
                         d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(exists(d.path + "/c.png"));
  const std::string csv = slurp(d.path + "/c.csv");
  const std::string header = csv.substr(0, csv.find('\n'));
  for (const char* c : {"t,event,x_0", "theta_2", "fn_0_0", "ft_2_1", "state_1_0", "energy_balance"})
    EXPECT_NE(header.find(c), std::string::npos) << c;
  EXPECT_NE(csv.find(",close,"), std::string::npos);
}

TEST(CliAssembly, KineticFrictionAngle) {
  // A block on a slope of 0.3 (a constant ground acceleration) between tan 15 and tan 20 deg: the
  // static angle holds it at rest; with the kinetic angle alone it slides. Both laws, and the
  // JSON records both coefficients.
  TmpDir d("asm_kinetic");
  for (const char* law : {"rigid", "deformable"}) {
    const std::vector<std::string> base{"assembly",  "--preset", "block",   "--slenderness", "0.5",
                                        "--contact", law,        "--t-end", "0.5",           "--json"};
    // The deformable law's tangential springs overshoot a sudden load: apply it slowly there.
    const std::vector<std::string> load =
        std::string(law) == "rigid"
            ? std::vector<std::string>{"--ground-h", "0.3"}
            : std::vector<std::string>{"--ground-h-amplitude", "0.3", "--ground-h-frequency", "0.5"};
    auto r = run_cli(base + load + std::vector<std::string>{"--phi-s", "20", "--phi-s-kinetic", "15"}, d.path);
    ASSERT_EQ(r.code, 0) << r.err;
    json j = json::parse(r.out);
    EXPECT_EQ(j["motion"], "rest") << law;
    EXPECT_NEAR(j["assembly"]["interfaces"][0]["contact"]["mu_k"].get<double>(), std::tan(15 * M_PI / 180), 1e-15);
    EXPECT_NEAR(j["assembly"]["interfaces"][0]["contact"]["mu_s"].get<double>(), std::tan(20 * M_PI / 180), 1e-15);
    r = run_cli(base + load + std::vector<std::string>{"--phi-s", "15"}, d.path);
    ASSERT_EQ(r.code, 0) << r.err;
    j = json::parse(r.out);
    EXPECT_EQ(j["motion"], "stable") << law;
  }
}

TEST(CliAssembly, RigidSchemes) {
  // Event-driven by default; time-stepping on request; seed 001's 5-DOF restriction runs on
  // time-stepping (the only scheme that integrates it); --scheme only with the rigid law.
  TmpDir d("asm_schemes");
  const std::vector<std::string> base{"assembly", "--preset", "trilith", "--contact", "rigid",
                                      "--tilt",   "0.05",     "--t-end", "0.5",       "--json"};
  auto r = run_cli(base, d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(json::parse(r.out)["scheme"], "event-driven");
  EXPECT_EQ(json::parse(r.out)["time_stepping"]["windows"], 0);
  r = run_cli(base + std::vector<std::string>{"--scheme", "time-stepping"}, d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(json::parse(r.out)["scheme"], "time-stepping");
  r = run_cli(base + std::vector<std::string>{"--columns-rock-only"}, d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(json::parse(r.out)["scheme"], "time-stepping");
  r = run_cli(base + std::vector<std::string>{"--columns-rock-only", "--scheme", "event-driven"}, d.path);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--columns-rock-only"), std::string::npos) << r.err;
  r = run_cli({"assembly", "--preset", "block", "--scheme", "event-driven", "--t-end", "0.1"}, d.path);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--scheme belongs to --contact rigid"), std::string::npos) << r.err;
  r = run_cli(base + std::vector<std::string>{"--scheme", "implicit"}, d.path);
  EXPECT_EQ(r.code, 2);
}

TEST(CliAssembly, BadInputIsAUsageError) {
  TmpDir d("asm_bad");
  std::ofstream(d.path + "/float.toml") << "[[block]]\nwidth = 0.1\nheight = 0.4\nmass = 5\ny = 0.25\n"
                                           "[[interface]]\nlower = \"ground\"\nupper = 0\n";
  std::ofstream(d.path + "/deep.toml") << "[[block]]\nwidth = 0.1\nheight = 0.4\nmass = 5\ny = 0.15\n"
                                          "[[interface]]\nlower = \"ground\"\nupper = 0\n";
  std::ofstream(d.path + "/negative.toml") << "[[block]]\nwidth = -0.1\nheight = 0.4\nmass = 5\ny = 0.2\n"
                                              "[[interface]]\nlower = \"ground\"\nupper = 0\n";
  std::ofstream(d.path + "/malformed.toml") << "[[block]\nwidth = 0.1\n";
  std::ofstream(d.path + "/unknown.toml") << "[[block]]\nwidth = 0.1\nheight = 0.4\nmass = 5\ny = 0.2\ncolour = 1\n"
                                             "[[interface]]\nlower = \"ground\"\nupper = 0\n";
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"assembly", "float.toml"}, "floats"},
      {{"assembly", "deep.toml"}, "overlap"},
      {{"assembly", "negative.toml"}, "width"},
      {{"assembly", "malformed.toml"}, "malformed.toml"},
      {{"assembly", "unknown.toml"}, "colour"},
      {{"assembly", "missing.toml"}, "missing.toml"},
      {{"assembly", "--preset", "dome"}, "preset"},
      {{"assembly", "--preset", "trilith", "--contact", "elastic"}, "contact"},
      {{"assembly", "--preset", "trilith", "--contact", "rigid", "--normal-stiffness", "1e8"}, "deformable"},
      {{"assembly", "--preset", "trilith", "--step", "1e-3"}, "step"},
      {{"assembly", "--preset", "trilith", "--contact", "rigid", "--step", "1"}, "step"},
      {{"assembly", "--preset", "trilith", "--phi-s", "95"}, "phi-s"},
      {{"assembly", "--preset", "trilith", "--phi-l", "-1"}, "phi-l"},
      {{"assembly", "--preset", "trilith", "--phi-s", "20", "--phi-s-kinetic", "25"}, "phi-s-kinetic"},
      {{"assembly", "--preset", "trilith", "--phi-l", "20", "--phi-l-kinetic", "-2"}, "phi-l-kinetic"},
      {{"assembly", "--preset", "trilith", "--slenderness", "-4"}, "slenderness"},
      {{"assembly", "--preset", "column", "--drums", "0"}, "drums"},
      {{"assembly", "--preset", "block", "--drums", "3"}, "drums"},
      {{"assembly", "--preset", "trilith", "--restitution", "0"}, "restitution"},
      {{"assembly", "--preset", "trilith", "--t-end", "-1"}, "t-end"},
      {{"assembly", "--preset", "trilith", "--tilt", "2"}, "tilt"},
      {{"assembly"}, "--preset"},
      {{"assembly", "--preset", "trilith", "float.toml"}, "not both"},
  };
  for (const auto& [args, word] : cases) {
    const auto r = run_cli(args, d.path);
    EXPECT_EQ(r.code, 2) << args.back() << ": " << r.err;
    EXPECT_NE(r.err.find(word), std::string::npos) << args.back() << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

TEST(CliAssembly, EventsAreStreamedToTheJsonWhole) {
  // Both contact laws: the events reach the JSON through a spool (the run keeps no list), all of
  // them, in time order, and --json and --json-out print the same text.
  for (const char* law : {"deformable", "rigid"}) {
    SCOPED_TRACE(law);
    TmpDir d(std::string("asm_spool_") + law);
    // (The rigid law's events are fewer: an impact lifts the old pivots within it; 6 s of it.)
    const std::string t_end = std::string(law) == "rigid" ? "6" : "1.5";
    const auto r = run_cli(
        std::vector<std::string>{"assembly", "--preset", "trilith", "--contact", law, "--phi-s", "30", "--phi-l", "30",
                                 "--t-end", t_end, "--json", "--json-out", d.path + "/s.json"} +
            kHarmonic,
        d.path);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(slurp(d.path + "/s.json"), r.out);
    const json j = json::parse(r.out);
    ASSERT_GT(j["events_total"].get<long>(), 10);
    EXPECT_EQ(long(j["events"].size()), j["events_total"].get<long>());
    double t_prev = -1;
    for (const auto& e : j["events"]) {
      EXPECT_GE(e["t"].get<double>(), t_prev) << e.dump();
      t_prev = e["t"].get<double>();
    }
    const auto q = run_cli(std::vector<std::string>{"assembly", "--preset", "trilith", "--contact", law, "--phi-s",
                                                    "30", "--phi-l", "30", "--t-end", t_end} +
                               kHarmonic,
                           d.path);
    ASSERT_EQ(q.code, 0) << q.err;
    EXPECT_NE(q.out.find("events: " + std::to_string(j["events_total"].get<long>()) + ","), std::string::npos) << q.out;
  }
}

TEST(CliAssembly, EveryBlockIsCarriedAndEveryJointCountedOnce) {
  // A pier standing on the ground through its side or its top carries nothing (it used to fall
  // 19.6 m in 2 s and be reported at rest); a joint given twice, once each way, is one joint.
  TmpDir d("asm_carried");
  const std::string pier =
      "[contact]\nk_normal = 1e7\nphi = 30\n[[block]]\nname = \"pier\"\nwidth = 0.3\n"
      "height = 1.0\ndensity = 2000\nthickness = 0.2\ny = 0.5\n";
  std::ofstream(d.path + "/side.toml") << pier << "[[interface]]\nlower = \"ground\"\nupper = 0\nupper_edge = 1\n";
  std::ofstream(d.path + "/top.toml") << pier << "[[interface]]\nlower = \"ground\"\nupper = 0\nupper_edge = 2\n";
  std::ofstream(d.path + "/twice.toml")
      << "[[block]]\nwidth = 0.2\nheight = 0.6\nmass = 50\ny = 0.3\n[[block]]\nwidth = 0.2\nheight = 0.6\nmass = "
         "50\ny = 0.9\n[[interface]]\nlower = \"ground\"\nupper = 0\n[[interface]]\nlower = 0\nupper = 1\n"
         "[[interface]]\nlower = 1\nupper = 0\n";
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"assembly", "side.toml", "--t-end", "2"}, "block 0 (pier) is carried by none of its interfaces"},
      {{"assembly", "side.toml", "--t-end", "2", "--contact", "rigid"}, "faces sideways"},
      {{"assembly", "top.toml", "--t-end", "2"}, "faces downwards"},
      {{"assembly", "twice.toml", "--t-end", "2"}, "interface 2 (lower = 1, upper = 0) repeats interface 1"},
  };
  expect_usage_errors(cases, d.path);
}

TEST(CliAssembly, TiltedBlocksStartOnTheirSupportsExactly) {
  // A polygon's theta turns it about its pivot (it used to turn about the centroid, 6.6 mm into the
  // ground); a rectangle placed 3 mm into the ground is projected onto it to rounding (one
  // linearised step left 1e-5 m).
  TmpDir d("asm_tilted");
  std::ofstream(d.path + "/penta.toml") << "[[block]]\nvertices = [[0,0],[0.3,0],[0.36,0.5],[0.12,1.2],[-0.05,0.7]]\n"
                                           "density = 2000\nthickness = 0.2\ntheta = 0.05\n"
                                           "[[interface]]\nlower = \"ground\"\nupper = 0\n";
  std::ofstream(d.path + "/rect.toml") << "[[block]]\nwidth = 0.3\nheight = 1.0\ndensity = 2000\nthickness = 0.2\n"
                                          "y = 0.5\ntheta = 0.02\n[[interface]]\nlower = \"ground\"\nupper = 0\n";
  for (const std::string f : {"penta.toml", "rect.toml"}) {
    const auto r = run_cli({"assembly", f, "--contact", "rigid", "--t-end", "0.2", "--trajectory", f + ".csv"}, d.path);
    ASSERT_EQ(r.code, 0) << r.err;
    std::ifstream in(d.path + "/" + f + ".csv");
    std::string header, row;
    std::getline(in, header);
    std::vector<std::string> cols;
    for (std::stringstream ss(header); std::getline(ss, row, ',');) cols.push_back(row);
    const auto col = std::find(cols.begin(), cols.end(), "py_0_0") - cols.begin();
    // The first row after the start's projection: the pivot on the ground to rounding.
    std::getline(in, row);
    if (f == "rect.toml") std::getline(in, row);
    std::vector<std::string> cells;
    for (std::stringstream ss(row); std::getline(ss, header, ',');) cells.push_back(header);
    EXPECT_LT(std::fabs(std::stod(cells[std::size_t(col)])), 1e-15) << f << ": " << row.substr(0, 120);
  }
}

TEST(CliAssembly, OneRestitutionDefaultPerLaw) {
  // A file without a restitution takes the law's default, as the presets do: 0 for the rigid law.
  TmpDir d("asm_restitution");
  std::ofstream(d.path + "/b.toml") << "[[block]]\nwidth = 0.3\nheight = 1.0\nmass = 100\ny = 0.5\n"
                                       "[[interface]]\nlower = \"ground\"\nupper = 0\n";
  for (const auto& [contact, e] : std::vector<std::pair<std::string, double>>{{"rigid", 0.0}, {"deformable", 0.5}}) {
    const json file = cli_json({"assembly", "b.toml", "--contact", contact, "--t-end", "0.01", "--json"}, d.path);
    const json preset =
        cli_json({"assembly", "--preset", "block", "--contact", contact, "--t-end", "0.01", "--json"}, d.path);
    EXPECT_EQ(file["assembly"]["interfaces"][0]["contact"]["restitution"].get<double>(), e) << contact;
    EXPECT_EQ(preset["assembly"]["interfaces"][0]["contact"]["restitution"].get<double>(), e) << contact;
  }
}
