// SPDX-License-Identifier: Apache-2.0
// `blockdyn spectrum` (issue 9): the JSON rows scripts rely on, the CSV and plot, an assembly
// preset, and bad input (exit 2 naming the field).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_test.hpp"

TEST(CliSpectrum, JsonRowsCsvAndPlot) {
  TmpDir d("spectrum");
  const auto r = run_cli({"spectrum", "--model", "housner", "--width", "0.3", "--height", "1.5", "--pulse", "rect",
                          "--durations", "0.1,0.5", "--json", "--quiet", "--csv", "s.csv", "--plot", "s.png"},
                         d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["schema"], "blockdyn.spectrum.summary/1");
  ASSERT_EQ(j["rows"].size(), 2u);
  EXPECT_EQ(j["rows"][0]["duration"], 0.1);
  EXPECT_GT(j["rows"][0]["min_overturning_amplitude"].get<double>(),
            j["rows"][1]["min_overturning_amplitude"].get<double>());
  EXPECT_TRUE(exists(d.path + "/s.png"));
  EXPECT_EQ(slurp(d.path + "/s.csv").substr(0, 41), "index,duration,min_overturning_amplitude,");
}

TEST(CliSpectrum, AssemblyPreset) {
  TmpDir d("spectrum_asm");
  const auto r =
      run_cli({"spectrum", "--model", "assembly", "--preset", "block", "--contact", "rigid", "--pulse", "half-sine",
               "--durations", "0.2", "--scan-points", "8", "--rel-tol", "1e-3", "--t-after", "2", "--json", "--quiet"},
              d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["model"]["contact"], "rigid");
  EXPECT_GT(j["rows"][0]["min_overturning_amplitude"].get<double>(), 0.25);  // above uplift, tan(alpha)
}

TEST(CliSpectrum, BadInputIsAUsageError) {
  TmpDir d("spectrum_bad");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"spectrum", "--model", "housner", "--width", "0.3", "--height", "1.5"}, "durations"},
      {{"spectrum", "--model", "housner", "--width", "0.3", "--height", "1.5", "--durations", "0.1", "--duration-min",
        "0.1"},
       "not both"},
      {{"spectrum", "--model", "housner", "--width", "0.3", "--height", "1.5", "--durations", "-1"}, "duration"},
      {{"spectrum", "--model", "housner", "--height", "1.5", "--durations", "1"}, "--width"},
      {{"spectrum", "--model", "housner", "--width", "0.3", "--height", "1.5", "--durations", "1", "--pulse", "square"},
       "pulse"},
      {{"spectrum", "--model", "housner", "--width", "0.3", "--height", "1.5", "--durations", "1", "--amplitude-min",
        "2", "--amplitude-max", "1"},
       "amplitude"},
      {{"spectrum", "--model", "assembly", "--durations", "1"}, "--preset"},
  };
  expect_usage_errors(cases, d.path);
}

TEST(CliSurvival, JsonPointsAndPlot) {
  TmpDir d("survival");
  const auto r =
      run_cli({"survival", "--model",        "housner", "--width",       "0.3", "--height",    "1.5",   "--beta-min",
               "0.5",      "--beta-max",     "4",       "--beta-points", "4",   "--omega-min", "1",     "--omega-max",
               "10",       "--omega-points", "3",       "--t-end",       "10",  "--out",       "s.csv", "--plot",
               "s.png",    "--json",         "--quiet"},
              d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["schema"], "blockdyn.survival.summary/1");
  ASSERT_EQ(j["points"].size(), 12u);
  for (const auto& p : j["points"]) {
    for (const char* k : {"beta", "omega", "motion", "collapse_mode", "t_failure", "max_abs_rotation", "cycle"})
      EXPECT_TRUE(p.contains(k)) << k;
    EXPECT_TRUE(p["motion"] == "rest" || p["motion"] == "stable" || p["motion"] == "collapse");
  }
  EXPECT_EQ(j["points"][0]["motion"], "rest");  // beta 0.5: below uplift
  EXPECT_TRUE(exists(d.path + "/s.png"));
  EXPECT_EQ(slurp(d.path + "/s.csv").substr(0, 23), "index,beta,omega,motion");
}

TEST(CliSurvival, BadInputIsAUsageError) {
  TmpDir d("survival_bad");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"survival", "--model", "housner", "--width", "0.3", "--height", "1.5", "--excitation", "square"}, "excitation"},
      {{"survival", "--model", "housner", "--width", "0.3", "--height", "1.5", "--beta-min", "2", "--beta-max", "1"},
       "beta"},
      {{"survival", "--model", "housner", "--width", "0.3", "--height", "1.5", "--omega-points", "0"}, "omega-points"},
      {{"survival", "--model", "housner", "--width", "0.3", "--height", "1.5", "--t-end", "5", "--periods", "3"},
       "not both"},
      {{"survival", "--model", "assembly"}, "--preset"},
  };
  expect_usage_errors(cases, d.path);
}

TEST(CliResponseCurve, RotationVersusFrequencyPerAmplitude) {
  TmpDir d("curve");
  const auto r = run_cli({"response-curve",
                          "--model",
                          "housner",
                          "--width",
                          "0.3",
                          "--height",
                          "1.5",
                          "--betas",
                          "0.5,3",
                          "--omega-min",
                          "2",
                          "--omega-max",
                          "20",
                          "--omega-points",
                          "5",
                          "--t-end",
                          "10",
                          "--plot",
                          "c.png",
                          "--json",
                          "--quiet"},
                         d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["schema"], "blockdyn.response-curve.summary/1");
  ASSERT_EQ(j["points"].size(), 10u);
  for (int k = 0; k < 5; ++k) EXPECT_EQ(j["points"][k]["theta_max_over_alpha"], 0.0);  // beta 0.5: below uplift
  // beta = 3: the response falls as the frequency rises (seed 001/002's trend).
  EXPECT_GT(j["points"][6]["theta_max_over_alpha"].get<double>(), j["points"][9]["theta_max_over_alpha"].get<double>());
  EXPECT_TRUE(exists(d.path + "/c.png"));
  const auto bad = run_cli({"response-curve", "--model", "housner", "--width", "0.3", "--height", "1.5"}, d.path);
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--betas"), std::string::npos) << bad.err;
}
