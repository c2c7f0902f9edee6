// SPDX-License-Identifier: Apache-2.0
// `blockdyn motion info` (issue 27): the JSON keys scripts rely on, the measures of a step record
// against their closed forms, the spectrum's rows, and bad records and options (exit 2 naming
// the field).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

#include "cli_test.hpp"

namespace {

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace

TEST(CliMotion, InfoOfAStepRecord) {
  TmpDir d("motion_info");
  // a = 0.2 g for 2 s, as PEER AT2 (DT = 0.01 s, 201 samples).
  std::string at2 = "PEER\nstep record\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=  201, DT=   .01000 SEC\n";
  for (int i = 0; i < 201; ++i) at2 += "0.2 ";
  write(d.path + "/step.AT2", at2 + "\n");
  const auto r = run_cli({"motion", "info", "step.AT2", "--periods", "0.2,0.5", "--json"}, d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["schema"], "blockdyn.motion-info.summary/1");
  const double g = 9.81, T = 2.0;
  EXPECT_DOUBLE_EQ(j["pga"].get<double>(), 0.2);
  EXPECT_NEAR(j["pgv"].get<double>(), 0.2 * g * T, 1e-12);
  EXPECT_NEAR(j["pgd"].get<double>(), 0.2 * g * T * T / 2, 1e-12);
  EXPECT_NEAR(j["arias"].get<double>(), M_PI * g / 2 * 0.04 * T, 1e-12);
  EXPECT_NEAR(j["d5_95"].get<double>(), 0.9 * T, 1e-12);
  EXPECT_NEAR(j["t_mid"].get<double>(), 0.45 * T, 1e-12);
  EXPECT_TRUE(j["mean_period"].is_number());
  ASSERT_EQ(j["spectrum"].size(), 2u);
  EXPECT_EQ(j["spectrum"][1]["period"], 0.5);
  EXPECT_NEAR(j["spectrum"][1]["sa"].get<double>(), 0.2 * (1 + std::exp(-0.05 * M_PI / std::sqrt(1 - 0.0025))), 1e-12);
  // The same record as CSV gives the same measures; the text names them.
  std::string csv = "t, a\n";
  for (int i = 0; i < 201; ++i) csv += std::to_string(0.01 * i) + ", 0.2\n";
  write(d.path + "/step.csv", csv);
  const auto c = run_cli({"motion", "info", "step.csv", "--json"}, d.path);
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_NEAR(json::parse(c.out)["arias"].get<double>(), j["arias"].get<double>(), 1e-12);
  const auto t = run_cli({"motion", "info", "step.csv", "--spectrum", "--period-points", "3"}, d.path);
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_NE(t.out.find("D5-95"), std::string::npos);
  EXPECT_NE(t.out.find("spectrum"), std::string::npos);
}

TEST(CliMotion, BadRecordsAndOptionsAreUsageErrors) {
  TmpDir d("motion_bad");
  write(d.path + "/back.csv", "0, 0.1\n0.02, 0.2\n0.01, 0.1\n");
  write(d.path + "/nan.csv", "0, 0.1\n0.01, nan\n");
  write(d.path + "/zero.AT2", "a\nb\nc\nNPTS=  3, DT=   0 SEC\n0.1 0.2 0.3\n");
  write(d.path + "/ok.csv", "0, 0.1\n0.01, 0.2\n0.02, 0\n");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"motion", "info", "back.csv"}, "increasing"},
      {{"motion", "info", "nan.csv"}, "nan.csv"},
      {{"motion", "info", "zero.AT2"}, "DT"},
      {{"motion", "info", "missing.csv"}, "record"},
      {{"motion", "info", "ok.csv", "--periods", "0"}, "periods"},
      {{"motion", "info", "ok.csv", "--damping", "1"}, "damping"},
      {{"motion", "info", "ok.csv", "--period-min", "2", "--period-max", "1"}, "period-max"},
      {{"motion", "info", "ok.csv", "--periods", "1", "--period-points", "4"}, "periods"},
      {{"motion", "info"}, "record"},
      {{"motion"}, "subcommand"},
  };
  for (const auto& [args, word] : cases) {
    const auto r = run_cli(args, d.path);
    EXPECT_EQ(r.code, 2) << args[2 % args.size()] << ": " << r.err;
    EXPECT_NE(r.err.find(word), std::string::npos) << r.err;
  }
}
