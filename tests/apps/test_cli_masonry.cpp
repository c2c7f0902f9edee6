// SPDX-License-Identifier: Apache-2.0
// `blockdyn limit-analysis` and polygonal blocks from the command line (issue 28): the JSON keys
// scripts rely on (lambda, status, mechanism, min_thickness_ratio), the figure, assembly files
// with vertices in the dynamics and the statics, the arch preset in `assembly`, and bad input
// (exit 2 naming the block or the option).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

#include "cli_test.hpp"

namespace {

void masonry_write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// A 0.2 x 0.8 m block given by its vertices, with a wedge on top (a triangle standing on the
// block's top edge), as an assembly file.
const char* kStack = R"(
[[block]]
name = "pier"
vertices = [[-0.1, 0.0], [0.1, 0.0], [0.1, 0.8], [-0.1, 0.8]]
density = 2000
thickness = 0.3

[[block]]
name = "wedge"
vertices = [[-0.1, 0.8], [0.1, 0.8], [0.0, 0.9]]
density = 2000
thickness = 0.3

[[interface]]
lower = "ground"
upper = 0

[[interface]]
lower = 0
upper = 1
)";

}  // namespace

TEST(CliMasonry, LimitAnalysisKeysAndClosedForms) {
  TmpDir d("limit_analysis");
  json j = cli_json({"limit-analysis", "--preset", "block", "--slenderness", "5", "--json"}, d.path);
  EXPECT_EQ(j["schema"], "blockdyn.limit-analysis/1");
  EXPECT_NEAR(j["lambda"].get<double>(), 0.2, 1e-12);
  EXPECT_EQ(j["status"], "ok");
  EXPECT_EQ(j["direction"], 1);
  EXPECT_TRUE(j["exact_for_non_associative"].get<bool>());
  EXPECT_EQ(j["mechanism"]["interfaces"][0]["state"], "hinge");
  EXPECT_EQ(j["mechanism"]["interfaces"][0]["hinge_end"], 0);
  EXPECT_EQ(j["mechanism"]["blocks"].size(), 1u);
  for (const char* k : {"vx", "vy", "omega"}) EXPECT_TRUE(j["mechanism"]["blocks"][0][k].is_number());
  EXPECT_EQ(j["thrust"].size(), 1u);
  // The other way: the mirror hinge.
  j = cli_json({"limit-analysis", "--preset", "trilith", "--direction", "-1", "--json"}, d.path);
  EXPECT_NEAR(j["lambda"].get<double>(), 0.25, 1e-12);
  EXPECT_EQ(j["mechanism"]["interfaces"][0]["hinge_end"], 1);
  // Sliding governs at phi-s = 10 degrees.
  j = cli_json({"limit-analysis", "--preset", "block", "--phi-s", "10", "--json"}, d.path);
  EXPECT_NEAR(j["lambda"].get<double>(), std::tan(10 * M_PI / 180), 1e-12);
  EXPECT_EQ(j["mechanism"]["interfaces"][0]["state"], "sliding");
  EXPECT_FALSE(j["exact_for_non_associative"].get<bool>());
  // A 20-voussoir arch: well under a second, its minimum thickness below Milankovitch's 0.1075.
  j = cli_json({"limit-analysis", "--preset", "arch", "--voussoirs", "20", "--thickness-ratio", "0.15",
                "--min-thickness", "--json"},
               d.path);
  EXPECT_EQ(j["status"], "ok");
  EXPECT_GT(j["lambda"].get<double>(), 0.1);
  const double t = j["min_thickness_ratio"].get<double>();
  EXPECT_GT(t, 0.105);
  EXPECT_LT(t, 0.1075);
  EXPECT_LT(j["timing_s"].get<double>(), 1.0);
  // The text names lambda; the figure is written.
  const auto r = run_cli(
      {"limit-analysis", "--preset", "arch", "--voussoirs", "12", "--min-thickness", "--plot", "arch.png"}, d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("lambda = "), std::string::npos);
  EXPECT_NE(r.out.find("min_thickness_ratio = "), std::string::npos);
  EXPECT_TRUE(std::ifstream(d.path + "/arch.png").good());
  EXPECT_TRUE(std::ifstream(d.path + "/arch.svg").good());
}

TEST(CliMasonry, PolygonFilesInTheStaticsAndTheDynamics) {
  TmpDir d("polygon_file");
  masonry_write(d.path + "/stack.toml", kStack);
  // The pier and its wedge tip over the pier's corner together: lambda = b / h of the whole, whose
  // centre of mass is at (0, 0.4 m1 + 0.8333 m2) / (m1 + m2).
  const json j = cli_json({"limit-analysis", "stack.toml", "--json"}, d.path);
  const double m1 = 0.16, m2 = 0.01, yc = (0.4 * m1 + (0.8 + 0.1 / 3) * m2) / (m1 + m2);
  EXPECT_NEAR(j["lambda"].get<double>(), 0.1 / yc, 1e-12);
  EXPECT_EQ(j["assembly"]["blocks"][1]["outline"].size(), 3u);
  // The same file runs in both contact laws, and its summary carries the vertices.
  for (const char* contact : {"deformable", "rigid"}) {
    const json s = cli_json({"assembly", "stack.toml", "--contact", contact, "--t-end", "0.3", "--json"}, d.path);
    EXPECT_EQ(s["status"], "t_end") << contact;
    EXPECT_EQ(s["assembly"]["blocks"][1]["vertices"].size(), 3u);
  }
  // The arch preset in the dynamics.
  const json a = cli_json(
      {"assembly", "--preset", "arch", "--voussoirs", "7", "--contact", "rigid", "--t-end", "0.5", "--json"}, d.path);
  EXPECT_EQ(a["motion"], "rest");
  EXPECT_EQ(a["assembly"]["blocks"].size(), 7u);
}

TEST(CliMasonry, ATwentyVoussoirRigidArchRunsByTimeSteppingAndSaysHow) {
  TmpDir d("rigid_arch");
  // Above 8 blocks the rigid law's default scheme is time-stepping; the JSON names it and counts
  // the contact solves. 0.3 g at 1 Hz brings the arch down.
  const json a =
      cli_json({"simulate", "--model", "assembly", "--preset", "arch", "--voussoirs", "20", "--contact", "rigid",
                "--ground-h-amplitude", "0.3", "--ground-h-frequency", "1", "--t-end", "2", "--json"},
               d.path);
  EXPECT_EQ(a["scheme"], "time-stepping");
  EXPECT_EQ(a["status"], "collapsed");
  EXPECT_EQ(a["collapse_mode"], 1);
  const json& c = a["contact_solves"];
  EXPECT_GT(c["direct"].get<long>(), 7000);
  EXPECT_EQ(c["gauss_seidel"].get<long>(), 0);
  for (const char* k : {"lemke", "active_set_iterations", "gauss_seidel_sweeps"}) EXPECT_TRUE(c.contains(k)) << k;
  // Up to 8 blocks the default stays event-driven.
  const json b = cli_json(
      {"assembly", "--preset", "arch", "--voussoirs", "7", "--contact", "rigid", "--t-end", "0.1", "--json"}, d.path);
  EXPECT_EQ(b["scheme"], "event-driven");
  // The integrator's tolerances belong to the event-driven scheme: refused where the default is
  // time-stepping, accepted once event-driven is asked for.
  const auto r =
      run_cli({"assembly", "--preset", "arch", "--voussoirs", "12", "--contact", "rigid", "--rtol", "1e-9"}, d.path);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--rtol belongs to --scheme event-driven"), std::string::npos) << r.err;
  const auto ok = run_cli({"assembly", "--preset", "arch", "--voussoirs", "12", "--contact", "rigid", "--scheme",
                           "event-driven", "--rtol", "1e-9", "--t-end", "0.05", "--quiet"},
                          d.path);
  EXPECT_EQ(ok.code, 0) << ok.err;
}

TEST(CliMasonry, BadInputIsAUsageErrorNamingTheBlock) {
  TmpDir d("polygon_bad");
  std::string stack = kStack;
  auto with = [&](const std::string& from, const std::string& to) {
    std::string s = stack;
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  masonry_write(d.path + "/clockwise.toml", with("[[-0.1, 0.0], [0.1, 0.0], [0.1, 0.8], [-0.1, 0.8]]",
                                                 "[[-0.1, 0.0], [-0.1, 0.8], [0.1, 0.8], [0.1, 0.0]]"));
  masonry_write(d.path + "/concave.toml",
                with("[[-0.1, 0.8], [0.1, 0.8], [0.0, 0.9]]", "[[-0.1, 0.8], [0.1, 0.8], [0.0, 0.82], [0.0, 0.9]]"));
  masonry_write(d.path + "/through.toml",
                with("[[-0.1, 0.8], [0.1, 0.8], [0.0, 0.9]]", "[[-0.1, 0.7], [0.1, 0.7], [0.0, 0.9]]"));
  masonry_write(d.path + "/apart.toml",
                with("[[-0.1, 0.8], [0.1, 0.8], [0.0, 0.9]]", "[[0.2, 0.0], [0.4, 0.0], [0.3, 0.1]]"));
  masonry_write(d.path + "/both.toml",
                with("vertices = [[-0.1, 0.0], [0.1, 0.0], [0.1, 0.8], [-0.1, 0.8]]",
                     "vertices = [[-0.1, 0.0], [0.1, 0.0], [0.1, 0.8], [-0.1, 0.8]]\nwidth = 0.2"));
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"limit-analysis", "clockwise.toml"}, "block[0].vertices"},
      {{"assembly", "clockwise.toml"}, "clockwise"},
      {{"limit-analysis", "concave.toml"}, "concave"},
      {{"assembly", "through.toml"}, "block 0 (pier) and block 1 (wedge) overlap"},
      {{"limit-analysis", "apart.toml"}, "no edge of block 1 (wedge) faces an edge of block 0"},
      {{"assembly", "both.toml"}, "block[0].width"},
      {{"limit-analysis", "--preset", "block", "--direction", "0"}, "direction"},
      {{"limit-analysis", "--preset", "block", "--min-thickness"}, "--preset arch"},
      {{"limit-analysis", "--preset", "arch", "--tolerance", "1e-6"}, "min-thickness"},
      {{"limit-analysis", "--preset", "arch", "--voussoirs", "0"}, "voussoirs"},
      {{"limit-analysis", "--preset", "arch", "--thickness-ratio", "2.5"}, "thickness-ratio"},
      {{"limit-analysis", "--preset", "arch", "--embrace", "200"}, "embrace"},
      {{"limit-analysis", "--preset", "arch", "--slenderness", "3"}, "slenderness"},
      {{"limit-analysis", "--preset", "trilith", "--voussoirs", "3"}, "voussoirs"},
      {{"limit-analysis", "--preset", "block", "--contact", "rigid"}, "contact"},
      {{"assembly", "--preset", "arch", "--voussoirs", "30"}, "limit-analysis takes"},
      {{"assembly", "--preset", "arch", "--tilt", "0.1"}, "tilt"},
  };
  for (const auto& [args, word] : cases) {
    const auto r = run_cli(args, d.path);
    EXPECT_EQ(r.code, 2) << args.back() << ": " << r.err;
    EXPECT_NE(r.err.find(word), std::string::npos) << args.back() << ": " << r.err;
  }
}
