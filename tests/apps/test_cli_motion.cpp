// SPDX-License-Identifier: Apache-2.0
// `blockdyn motion info` and `rocking-spectrum` (issue 27): the JSON keys scripts rely on, the measures of a step
// record against their closed forms, the spectrum's rows, and bad records and options (exit 2 naming the field).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "blockdyn/excitation/accelerogram.hpp"
#include "cli_test.hpp"

namespace {

void motion_write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace

TEST(CliMotion, InfoOfAStepRecord) {
  TmpDir d("motion_info");
  // a = 0.2 g for 2 s, as PEER AT2 (DT = 0.01 s, 201 samples).
  std::string at2 = "PEER\nstep record\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=  201, DT=   .01000 SEC\n";
  for (int i = 0; i < 201; ++i) at2 += "0.2 ";
  motion_write(d.path + "/step.AT2", at2 + "\n");
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
  motion_write(d.path + "/step.csv", csv);
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
  motion_write(d.path + "/back.csv", "0, 0.1\n0.02, 0.2\n0.01, 0.1\n");
  motion_write(d.path + "/nan.csv", "0, 0.1\n0.01, nan\n");
  motion_write(d.path + "/zero.AT2", "a\nb\nc\nNPTS=  3, DT=   0 SEC\n0.1 0.2 0.3\n");
  motion_write(d.path + "/ok.csv", "0, 0.1\n0.01, 0.2\n0.02, 0\n");
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
  expect_usage_errors(cases, d.path);
}

TEST(CliRockingSpectrum, EqualsSimulatePointByPoint) {
  TmpDir d("rocking_spectrum");
  const std::string rec = std::string(BLOCKDYN_SOURCE_DIR) + "/tests/fixtures/synthetic_60s.AT2";
  for (const std::string model : {"housner", "rigid"}) {
    const auto r =
        run_cli({"rocking-spectrum", "--model", model, "--record", rec, "--alpha", "0.2", "--p-values", "1.5,4",
                 "--scales", "1,2.5", "--t-after", "3", "--json", "--quiet", "--out", "rs.csv", "--overwrite"},
                d.path);
    ASSERT_EQ(r.code, 0) << r.err;
    const json j = json::parse(r.out);
    EXPECT_EQ(j["schema"], "blockdyn.rocking-spectrum.summary/1");
    ASSERT_EQ(j["rows"].size(), 4u);
    // Each row is the run of `simulate` for the block of that size: width, height from the CSV.
    const std::string csv = slurp(d.path + "/rs.csv");
    std::istringstream lines(csv);
    std::string line;
    std::getline(lines, line);
    int checked = 0;
    for (const json& row : j["rows"]) {
      std::getline(lines, line);
      std::vector<std::string> c;
      std::stringstream ss(line);
      for (std::string x; std::getline(ss, x, ',');) c.push_back(x);
      const auto s = run_cli({"simulate", "--model", model, "--width", c[3], "--height", c[4], "--ground-h-record", rec,
                              "--ground-h-scale", c[2], "--t-end", "62.99", "--json", "--quiet"},
                             d.path);
      ASSERT_EQ(s.code, 0) << s.err;
      const json sj = json::parse(s.out);
      EXPECT_EQ(row["max_abs_rotation_over_alpha"].get<double>(), sj["max_abs_rotation"].get<double>() / 0.2);
      EXPECT_EQ(row["overturned"].get<bool>(), sj["status"] == "overturned");
      ++checked;
    }
    EXPECT_EQ(checked, 4);
  }
}

TEST(CliRockingSpectrum, RectangularPulseOverturnsAtTheClosedForm) {
  // A rectangular pulse a_p for t_p overturns a slender Housner block when
  // a_p / (g alpha) > 1 / (1 - exp(-p t_p)) (linearised; alpha = 0.05 makes it exact to 0.1 %).
  TmpDir d("rocking_rect");
  const double alpha = 0.05, p = 2.0, tp = 0.5, ap = alpha / (1 - std::exp(-p * tp));
  char text[256];
  std::snprintf(text, sizeof text, "0, %.17g\n%.17g, %.17g\n%.17g, 0\n%.17g, 0\n", ap, tp, ap, tp + 1e-6, tp + 1);
  motion_write(d.path + "/rect.csv", text);
  const auto r = run_cli({"rocking-spectrum", "--record", "rect.csv", "--alpha", "0.05", "--p-values", "2", "--scales",
                          "0.98,1.02", "--t-after", "30", "--json", "--quiet"},
                         d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_FALSE(j["rows"][0]["overturned"].get<bool>());
  EXPECT_TRUE(j["rows"][1]["overturned"].get<bool>());
  EXPECT_EQ(j["overturning_scales"][0]["min_overturning_scale"], 1.02);
}

TEST(CliRockingSpectrum, BadInputIsAUsageError) {
  TmpDir d("rocking_bad");
  const std::string rec = std::string(BLOCKDYN_SOURCE_DIR) + "/tests/fixtures/synthetic_60s.AT2";
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"rocking-spectrum", "--record", rec, "--p-values", "1"}, "alpha"},
      {{"rocking-spectrum", "--record", rec, "--alpha", "0.2"}, "p-values"},
      {{"rocking-spectrum", "--record", rec, "--alpha", "1.2", "--p-values", "1"}, "alpha"},
      {{"rocking-spectrum", "--record", rec, "--alpha", "0.2", "--p-values", "0"}, "p-values"},
      {{"rocking-spectrum", "--alpha", "0.2", "--p-values", "1"}, "record"},
      {{"rocking-spectrum", "--record", rec, "--alpha", "0.2", "--p-values", "1", "--mu-s", "0.3"}, "mu-s"},
      {{"rocking-spectrum", "--model", "assembly", "--record", rec, "--alpha", "0.2", "--p-values", "1"}, "model"},
      {{"rocking-spectrum", "--record", rec, "--alpha", "0.2", "--p-values", "1", "--scales", "-1"}, "scales"},
  };
  expect_usage_errors(cases, d.path);
}

TEST(CliMotion, GeneratedSuiteMeetsItsTargetsEndsAtRestAndReproduces) {
  TmpDir d("motion_generate");
  const std::vector<std::string> args = {"motion",  "generate", "--arias",   "0.5",  "--d5-95",  "8",   "--t-mid", "5",
                                         "--f-mid", "4",        "--f-slope", "-0.1", "--zeta-f", "0.3", "--t-end", "20",
                                         "--seed",  "11",       "--json"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = args;
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  const auto one = run_cli(with({"--count", "60", "--out", "a", "--threads", "1"}), d.path);
  ASSERT_EQ(one.code, 0) << one.err;
  const json j = json::parse(one.out);
  EXPECT_EQ(j["schema"], "blockdyn.motion-generate.summary/1");
  ASSERT_EQ(j["records"].size(), 60u);
  // The suite's medians near the targets (single records scatter: the Arias intensity's spread is
  // 15 %, so its median over 60 records about 2 %; the high-pass takes some 4 % of the energy).
  EXPECT_NEAR(j["median"]["arias"].get<double>(), 0.5, 0.12 * 0.5);
  EXPECT_NEAR(j["median"]["d5_95"].get<double>(), 8, 0.05 * 8);
  EXPECT_NEAR(j["median"]["t_mid"].get<double>(), 5, 0.05 * 5);
  for (const json& r : j["records"]) {
    // Every record ends at rest, to rounding (the file holds the samples exactly).
    EXPECT_LT(std::fabs(r["final_velocity"].get<double>()), 1e-11 * r["pgv"].get<double>()) << r["file"];
    EXPECT_LT(std::fabs(r["final_displacement"].get<double>()), 1e-10 * r["pgd"].get<double>()) << r["file"];
  }
  // motion info reads the files back to the same measures.
  const auto info = run_cli({"motion", "info", "a/" + j["records"][3]["file"].get<std::string>(), "--json"}, d.path);
  ASSERT_EQ(info.code, 0) << info.err;
  EXPECT_EQ(json::parse(info.out)["arias"], j["records"][3]["arias"]);
  // Same seed, any thread count (and any count): the same bytes; another seed: other records.
  ASSERT_EQ(run_cli(with({"--count", "30", "--out", "b", "--threads", "2"}), d.path).code, 0);
  for (const char* f : {"rezaeian_0001.AT2", "rezaeian_0017.AT2", "rezaeian_0030.AT2"})
    EXPECT_EQ(slurp(d.path + "/a/" + f), slurp(d.path + "/b/" + f)) << f;
  auto other = with({"--count", "1", "--out", "c"});
  other[std::find(other.begin(), other.end(), "--seed") - other.begin() + 1] = "12";
  ASSERT_EQ(run_cli(other, d.path).code, 0);
  EXPECT_NE(slurp(d.path + "/a/rezaeian_0001.AT2"), slurp(d.path + "/c/rezaeian_0001.AT2"));
  // An existing suite is not overwritten silently.
  const auto again = run_cli(with({"--count", "1", "--out", "a"}), d.path);
  EXPECT_EQ(again.code, 2);
  EXPECT_NE(again.err.find("overwrite"), std::string::npos) << again.err;
}

TEST(CliMotion, PulseRecordHasItsPgv) {
  TmpDir d("motion_pulse");
  const json j = cli_json({"motion", "generate", "--model", "pulse", "--pulse-pgv", "0.6", "--pulse-period", "1.2",
                           "--gamma", "2", "--nu", "0", "--dt", "0.005", "--out", "p", "--json"},
                          d.path);
  ASSERT_FALSE(j.is_null());
  const json rec = j["records"][0];
  EXPECT_NEAR(rec["pgv"].get<double>(), 0.6, 1e-4);  // v peaks at A where the envelope does (nu = 0)
  EXPECT_NEAR(rec["final_velocity"].get<double>(), 0.0, 1e-6);
}

TEST(CliMotion, GenerateBadInputIsAUsageError) {
  TmpDir d("motion_generate_bad");
  const std::vector<std::string> base = {"motion",  "generate", "--arias", "0.5", "--d5-95", "8",
                                         "--t-mid", "5",        "--f-mid", "4",   "--t-end", "20"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = base;
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {with({}), "--out"},
      {with({"--out", "o", "--count", "0"}), "count"},
      {with({"--out", "o", "--d5-95", "30"}), "d5-95"},
      {with({"--out", "o", "--f-slope", "-2"}), "f-slope"},
      {with({"--out", "o", "--zeta-f", "1"}), "zeta-f"},
      {with({"--out", "o", "--pulse-pgv", "1"}), "pulse-pgv"},
      {with({"--out", "o", "--model", "ricker"}), "model"},
      {{"motion", "generate", "--model", "pulse", "--pulse-period", "1", "--out", "o"}, "pulse-pgv"},
      {{"motion", "generate", "--arias", "0.5", "--t-mid", "5", "--f-mid", "4", "--t-end", "20", "--out", "o"},
       "d5-95"},
  };
  expect_usage_errors(cases, d.path);
}

TEST(CliMotion, ComponentsAreIndependentRecordsWithTheirOwnTargets) {
  // Three components per record: each meets its own targets over the suite, the first is the
  // single-component suite's record (the same stream), and the components are uncorrelated.
  TmpDir d("motion_components");
  const std::vector<std::string> base = {"motion",  "generate", "--arias", "0.5", "--d5-95", "8",  "--t-mid", "5",
                                         "--f-mid", "4",        "--t-end", "20",  "--seed",  "11", "--json"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = base;
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  const json j = cli_json(with({"--count", "40", "--components", "3", "--h2-arias", "0.3", "--v-arias", "0.1",
                                "--v-f-mid", "8", "--out", "c"}),
                          d.path);
  ASSERT_FALSE(j.is_null());
  EXPECT_EQ(j["components"], json::array({"h1", "h2", "v"}));
  EXPECT_EQ(j["component_targets"]["v"]["f_mid"], 8.0);
  const json single = cli_json(with({"--count", "40", "--out", "s"}), d.path);
  ASSERT_FALSE(single.is_null());
  std::vector<double> arias_h2, arias_v, correlation;
  for (std::size_t k = 0; k < 40; ++k) {
    const json& r = j["records"][k];
    ASSERT_EQ(r["components"].size(), 3u);
    EXPECT_EQ(r["components"]["h1"]["arias"], single["records"][k]["arias"]) << k;
    arias_h2.push_back(r["components"]["h2"]["arias"].get<double>());
    arias_v.push_back(r["components"]["v"]["arias"].get<double>());
    const auto a = blockdyn::load_accelerogram(d.path + "/c/" + r["components"]["h1"]["file"].get<std::string>(), "h1");
    const auto b = blockdyn::load_accelerogram(d.path + "/c/" + r["components"]["h2"]["file"].get<std::string>(), "h2");
    double ab = 0, aa = 0, bb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      ab += a.values()[i] * b.values()[i];
      aa += a.values()[i] * a.values()[i];
      bb += b.values()[i] * b.values()[i];
    }
    correlation.push_back(ab / std::sqrt(aa * bb));
  }
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
  };
  EXPECT_NEAR(median(arias_h2), 0.3, 0.12 * 0.3);
  EXPECT_NEAR(median(arias_v), 0.1, 0.12 * 0.1);
  // Independent streams: the correlations scatter about zero (their spread over ~400 effective
  // samples is about 0.05; the mean of 40 about 0.01).
  double mean = 0;
  for (double c : correlation) mean += c / double(correlation.size());
  EXPECT_LT(std::fabs(mean), 0.04);
  EXPECT_LT(*std::max_element(correlation.begin(), correlation.end(),
                              [](double x, double y) { return std::fabs(x) < std::fabs(y); }),
            0.3);
  // A one-component suite over it removes its component files.
  ASSERT_EQ(run_cli(with({"--count", "2", "--out", "c", "--overwrite"}), d.path).code, 0);
  std::ifstream gone(d.path + "/c/rezaeian_0001_h2.AT2");
  EXPECT_FALSE(gone.good());
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {with({"--out", "o", "--components", "4"}), "components"},
      {with({"--out", "o", "--components", "2", "--v-arias", "0.1"}), "v-arias"},
      {with({"--out", "o", "--components", "3", "--v-f-mid", "8"}), "v-arias"},
      {with({"--out", "o", "--components", "2", "--h2-arias", "-1"}), "h2-arias"},
      {{"motion", "generate", "--model", "pulse", "--pulse-pgv", "1", "--pulse-period", "1", "--components", "2",
        "--out", "o"},
       "components"},
  };
  expect_usage_errors(cases, d.path);
}

TEST(CliMotion, GeneratedRecordsReadBackWhateverTheirSamples) {
  // Samples with three-digit exponents (1e-219 before the burst), a target of 1e-300 m/s, and a late
  // short burst: every record is written, reads back, and motion info measures it as motions.json does.
  TmpDir d("motion_extremes");
  const std::vector<std::vector<std::string>> suites = {
      {"--arias", "0.8", "--d5-95", "2", "--t-mid", "8", "--f-mid", "3", "--t-end", "30"},
      {"--arias", "0.44", "--d5-95", "5.478", "--t-mid", "16.43", "--f-mid", "1.8", "--t-end", "41.5"},
      {"--arias", "1e-300", "--d5-95", "5", "--t-mid", "10", "--f-mid", "3", "--t-end", "30"},
      {"--arias", "0.8", "--d595", "1", "--t-mid", "25", "--f-mid", "3", "--t-end", "30"}};
  int k = 0;
  for (const auto& targets : suites) {
    const std::string out = "s" + std::to_string(k++);
    std::vector<std::string> args = {"motion", "generate", "--out", out, "--count", "2", "--json"};
    args.insert(args.end(), targets.begin(), targets.end());
    const json j = cli_json(args, d.path);
    ASSERT_FALSE(j.is_null()) << out;
    for (const json& r : j["records"]) {
      const json info = cli_json({"motion", "info", out + "/" + r["file"].get<std::string>(), "--json"}, d.path);
      ASSERT_FALSE(info.is_null());
      for (const char* key : {"pga", "pgv", "arias", "d5_95", "t_mid"}) EXPECT_EQ(info[key], r[key]) << out << key;
      EXPECT_GT(r["pga"].get<double>(), 0.0);
    }
  }
}

TEST(CliMotion, TargetsThatCannotBeMetWriteNothing) {
  TmpDir d("motion_refused");
  const std::vector<std::string> rz = {"motion", "generate", "--arias", "0.8", "--f-mid", "3", "--out", "o"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = rz;
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {with({"--d5-95", "1", "--t-mid", "29.9", "--t-end", "30"}), "t-end = 30 s cuts"},
      {with({"--d5-95", "1", "--t-mid", "31", "--t-end", "30"}), "t-mid = 31 s lies outside"},
      {with({"--d5-95", "29", "--t-mid", "12", "--t-end", "30"}), "D5-95 of 22.59 s"},
      {with({"--d5-95", "0.1", "--t-mid", "5", "--t-end", "30"}), "d5-95 = 0.1 s spans fewer than 20 samples"},
      {with({"--d5-95", "5", "--d595", "5", "--t-mid", "5", "--t-end", "30"}), "d5-95"},
      {with({"--d5-95", "20", "--t-mid", "12", "--t-end", "200", "--dt", "1e-4", "--count", "100000"}),
       "at most 16 GiB"},
      {with({"--d5-95", "5", "--t-mid", "10", "--t-end", "1000", "--dt", "0.001", "--f-slope", "-0.0029", "--zeta-f",
             "0.001"}),
       "kernel terms"},
      {{"motion", "generate", "--model", "pulse", "--pulse-pgv", "100", "--pulse-period", "0.1", "--t-end", "10",
        "--out", "o"},
       "the pulse peaks at"},
      {{"motion", "generate", "--model", "pulse", "--pulse-pgv", "0.5", "--pulse-period", "0.05", "--t-end", "10",
        "--out", "o"},
       "pulse-period = 0.05 s is sampled by fewer than 10 samples"},
      {{"motion", "generate", "--model", "pulse", "--pulse-pgv", "0.5", "--pulse-period", "1", "--pulse-t0", "0.5",
        "--out", "o"},
       "starts the pulse at -0.5 s"},
      {with({"--d5-95", "5", "--t-mid", "10", "--t-end", "30", "--threads", "-1"}), "threads = -1"},
  };
  expect_usage_errors(cases, d.path);
  EXPECT_FALSE(exists(d.path + "/o")) << "a refused suite made its directory";
}

TEST(CliMotion, OverwriteReplacesTheWholeSuite) {
  TmpDir d("motion_overwrite");
  const std::vector<std::string> base = {"motion",  "generate", "--arias", "0.3", "--d5-95", "5", "--t-mid", "4",
                                         "--f-mid", "4",        "--t-end", "12",  "--out",   "s", "--quiet"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = base;
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  ASSERT_EQ(run_cli(with({"--count", "3"}), d.path).code, 0);
  for (const char* f : {"rezaeian_0001.AT2", "rezaeian_0002.AT2", "rezaeian_0003.AT2"})
    EXPECT_TRUE(exists(d.path + "/s/" + f));
  const std::string first = slurp(d.path + "/s/rezaeian_0001.AT2");
  // A suite's records alone (motions.json lost) still count as a suite.
  std::remove((d.path + "/s/motions.json").c_str());
  EXPECT_EQ(run_cli(with({"--count", "1"}), d.path).code, 2);
  ASSERT_EQ(run_cli(with({"--count", "1", "--overwrite"}), d.path).code, 0);
  EXPECT_TRUE(exists(d.path + "/s/rezaeian_0001.AT2"));
  EXPECT_FALSE(exists(d.path + "/s/rezaeian_0002.AT2"));
  EXPECT_FALSE(exists(d.path + "/s/rezaeian_0003.AT2"));
  EXPECT_EQ(slurp(d.path + "/s/rezaeian_0001.AT2"), first);
  // A file of the user's beside the suite is left alone.
  std::ofstream(d.path + "/s/notes.txt") << "mine";
  ASSERT_EQ(run_cli(with({"--count", "2", "--overwrite"}), d.path).code, 0);
  EXPECT_TRUE(exists(d.path + "/s/notes.txt"));
  // The alias --d595 is --d5-95: the same records.
  std::vector<std::string> alias = base;
  alias[std::find(alias.begin(), alias.end(), "--d5-95") - alias.begin()] = "--d595";
  alias[std::find(alias.begin(), alias.end(), "s") - alias.begin()] = "t";
  alias.push_back("--count");
  alias.push_back("1");
  ASSERT_EQ(run_cli(alias, d.path).code, 0);
  EXPECT_EQ(slurp(d.path + "/t/rezaeian_0001.AT2"), first);
}

TEST(CliMotion, LongRecordsGenerateInLinearTime) {
  // 40,000 samples with a sweeping filter frequency (the kernel runs over the filter's memory only)
  // and 200,000 with a constant one (a recursion): seconds, not the hours of a quadratic sum.
  TmpDir d("motion_long");
  EXPECT_EQ(run_cli({"motion", "generate", "--arias", "0.8", "--d5-95", "20", "--t-mid", "12", "--f-mid", "3",
                     "--f-slope", "-0.005", "--t-end", "400", "--out", "a", "--quiet"},
                    d.path)
                .code,
            0);
  EXPECT_EQ(run_cli({"motion", "generate", "--arias", "0.8", "--d5-95", "20", "--t-mid", "12", "--f-mid", "3",
                     "--t-end", "2000", "--out", "b", "--quiet"},
                    d.path)
                .code,
            0);
}
