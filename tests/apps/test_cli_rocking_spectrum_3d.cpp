// SPDX-License-Identifier: Apache-2.0
// `blockdyn rocking-spectrum --model rigid3d` (issue 40): the spectrum of a box in space over a
// suite and incidences. Its planar limit is Housner's spectrum, a square column is the same along
// either axis, each row is `simulate --model rigid3d` of that body and motion, the incidences'
// counts add up to the runs and the critical one is among them; bad input is a usage error.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "cli_test.hpp"

namespace rocking3d_test {

const std::string kRecord = std::string(BLOCKDYN_SOURCE_DIR) + "/tests/fixtures/synthetic_60s.AT2";

json spectrum(const std::vector<std::string>& extra, const std::string& dir, const std::string& out) {
  std::vector<std::string> a{"rocking-spectrum", "--alpha", "0.2",   "--p-values", "1.5,4",      "--t-after", "3",
                             "--json",           "--quiet", "--out", out + ".csv", "--overwrite"};
  a.insert(a.end(), extra.begin(), extra.end());
  const auto r = run_cli(a, dir);
  EXPECT_EQ(r.code, 0) << r.err;
  return r.code == 0 ? json::parse(r.out) : json::object();
}

TEST(CliRockingSpectrum3d, PlanarLimitIsHousnersSpectrum) {
  // One component along the box's width, friction that sticks: Newton's plastic impacts are
  // Housner's law, the box rocks in its plane as Housner's block of the same alpha and p (the
  // runs' tolerances 1e-10: agreement to 1e-7 relative, measured 4e-9).
  TmpDir d("rs3_planar");
  const json a =
      spectrum({"--model", "rigid3d", "--record", kRecord, "--scales", "1,2.5", "--mu-s", "1e6"}, d.path, "a");
  const json b = spectrum({"--model", "housner", "--record", kRecord, "--scales", "1,2.5"}, d.path, "b");
  ASSERT_EQ(a["rows"].size(), 4u);
  ASSERT_EQ(b["rows"].size(), 4u);
  int overturned = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const double x = a["rows"][i]["max_abs_rotation_over_alpha"].get<double>();
    const double y = b["rows"][i]["max_abs_rotation_over_alpha"].get<double>();
    EXPECT_NEAR(x, y, 1e-7 * y) << i;
    EXPECT_EQ(a["rows"][i]["overturned"], b["rows"][i]["overturned"]) << i;
    EXPECT_FALSE(a["rows"][i]["outside_model"].get<bool>()) << i;
    overturned += a["rows"][i]["overturned"].get<bool>();
  }
  EXPECT_EQ(overturned, 2);  // the test sees both outcomes
}

TEST(CliRockingSpectrum3d, ASquareColumnIsTheSameAlongEitherAxis) {
  TmpDir d("rs3_square");
  const json j =
      spectrum({"--model", "rigid3d", "--record", kRecord, "--incidence", "0,90", "--mu-s", "0.7"}, d.path, "s");
  ASSERT_EQ(j["rows"].size(), 4u);  // p fastest, then incidence
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(j["rows"][i]["max_abs_rotation_over_alpha"].get<double>(),
                j["rows"][i + 2]["max_abs_rotation_over_alpha"].get<double>(),
                1e-12 * j["rows"][i]["max_abs_rotation_over_alpha"].get<double>())
        << i;
    EXPECT_EQ(j["rows"][i]["overturned"], j["rows"][i + 2]["overturned"]);
  }
}

TEST(CliRockingSpectrum3d, ASuiteAtIncidencesRunsAsSimulateAndNamesTheCriticalIncidence) {
  TmpDir d("rs3_suite");
  const auto gen = run_cli({"motion",  "generate", "--arias", "1.5",   "--d5-95", "5", "--t-mid",      "4",
                            "--f-mid", "2.5",      "--t-end", "10",    "--count", "2", "--components", "2",
                            "--seed",  "5",        "--out",   "suite", "--quiet"},
                           d.path);
  ASSERT_EQ(gen.code, 0) << gen.err;
  const json j = spectrum({"--model", "rigid3d", "--suite", "suite", "--incidence", "0:60:3", "--depth-ratio", "1.5",
                           "--scales", "1,3", "--mu-s", "0.8"},
                          d.path, "t");
  const std::size_t runs = 2 * 2 * 3 * 2;  // p, scales, incidences, records
  ASSERT_EQ(j["rows"].size(), runs);
  std::size_t sum = 0;
  std::vector<double> angles;
  for (const json& c : j["incidences"]) {
    sum += c["runs"].get<std::size_t>();
    angles.push_back(c["incidence"].get<double>());
  }
  EXPECT_EQ(sum, runs);
  EXPECT_EQ(angles, (std::vector<double>{0, 30, 60}));
  EXPECT_NE(std::find(angles.begin(), angles.end(), j["critical_incidence"].get<double>()), angles.end());
  EXPECT_EQ(j["critical_incidence_by_p"].size(), 4u);
  // Row 7 (p 4, scale 3, incidence 30, record 0) is simulate's run of that body and motion.
  const json& row = j["rows"][7];
  ASSERT_EQ(row["incidence"].get<double>(), 30.0);
  const std::string csv = slurp(d.path + "/t.csv");
  std::vector<std::string> lines;
  for (std::size_t a = 0, b; (b = csv.find('\n', a)) != std::string::npos; a = b + 1)
    lines.push_back(csv.substr(a, b - a));
  std::vector<std::string> c;
  for (std::size_t a = 0, b = 0; b != std::string::npos; a = b + 1) {
    b = lines[8].find(',', a);
    c.push_back(lines[8].substr(a, b == std::string::npos ? std::string::npos : b - a));
  }
  const std::string rec = row["record"].get<std::string>(), rec2 = rec.substr(0, rec.size() - 6) + "h2.AT2";
  const auto s = run_cli({"simulate",
                          "--model",
                          "rigid3d",
                          "--width",
                          c[5],
                          "--depth",
                          c[6],
                          "--height",
                          c[7],
                          "--mu-s",
                          "0.8",
                          "--ground-h-record",
                          "suite/" + rec,
                          "--ground-h-scale",
                          "3",
                          "--ground-h2-record",
                          "suite/" + rec2,
                          "--ground-h2-scale",
                          "3",
                          "--ground-azimuth",
                          "30",
                          "--t-end",
                          "13",
                          "--json",
                          "--quiet"},
                         d.path);
  ASSERT_EQ(s.code, 0) << s.err;
  const json sj = json::parse(s.out);
  const double alpha = 0.2;
  EXPECT_EQ(row["max_abs_rotation_over_alpha"].get<double>(), sj["max_tilt"].get<double>() / alpha);
  EXPECT_EQ(row["overturned"].get<bool>(), sj["status"] == "overturned");
}

TEST(CliRockingSpectrum3d, BadInputIsAUsageError) {
  TmpDir d("rs3_bad");
  const std::vector<std::string> base{"rocking-spectrum", "--alpha", "0.2", "--p-values", "1"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = base;
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {with({"--record", kRecord, "--suite", "x"}), "suite"},
      {with({"--model", "housner", "--record", kRecord, "--incidence", "30"}), "incidence"},
      {with({"--model", "housner", "--record", kRecord, "--depth-ratio", "2"}), "depth-ratio"},
      {with({"--model", "rigid3d", "--record", kRecord, "--depth-ratio", "0"}), "depth-ratio"},
      {with({"--model", "rigid3d", "--record", kRecord, "--incidence", "400"}), "incidence"},
      {with({"--model", "rigid3d", "--suite", d.path + "/none"}), "suite"},
      {with({"--model", "rigid3d", "--record", kRecord, "--restitution", "2"}), "restitution"},
  };
  expect_usage_errors(cases, d.path);
}

}  // namespace rocking3d_test
