// SPDX-License-Identifier: Apache-2.0
// `blockdyn sweep --model rigid3d` (a settings sweep, commands/settings_sweep.hpp): each row is
// `simulate --model rigid3d` with the axes' values, bit for bit; the table is the same on one and
// two threads and after a resume; its axes are the family's options, anything else a usage error.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "cli_test.hpp"

namespace rigid3d_sweep_test {

std::vector<std::string> sweep_args(const std::string& out, const std::string& threads) {
  return {"sweep",
          "--model",
          "rigid3d",
          "--width",
          "0.4",
          "--depth",
          "0.3",
          "--height",
          "1.2",
          "--mu-s",
          "0.6",
          "--ground-h-pulse",
          "one-sine",
          "--ground-h-duration",
          "0.5",
          "--axis",
          "ground_h_amplitude=0.3:0.9:4",
          "--axis",
          "ground_azimuth=0,30",
          "--t-end",
          "3",
          "--output",
          out,
          "--threads",
          threads,
          "--quiet"};
}

std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> c;
  for (std::size_t a = 0, b = 0; b != std::string::npos; a = b + 1) {
    b = line.find(',', a);
    c.push_back(line.substr(a, b == std::string::npos ? std::string::npos : b - a));
  }
  return c;
}

TEST(Rigid3dSweep, RowsAreSimulateRunsAndTheTableDoesNotDependOnThreads) {
  TmpDir d("rigid3d_sweep");
  const auto a = run_cli(sweep_args("a.csv", "1"), d.path), b = run_cli(sweep_args("b.csv", "2"), d.path);
  ASSERT_EQ(a.code, 0) << a.err;
  ASSERT_EQ(b.code, 0) << b.err;
  const std::string ta = slurp(d.path + "/a.csv");
  EXPECT_EQ(ta, slurp(d.path + "/b.csv"));
  std::vector<std::string> lines;
  for (std::size_t x = 0, y; (y = ta.find('\n', x)) != std::string::npos; x = y + 1)
    lines.push_back(ta.substr(x, y - x));
  ASSERT_EQ(lines.size(), 9u);  // header + 4 x 2 points
  const auto head = cells(lines[0]);
  EXPECT_EQ(head[1], "ground_h_amplitude");
  EXPECT_EQ(head[2], "ground_azimuth");
  EXPECT_EQ(head[3], "status");
  int overturned = 0, checked = 0;
  for (std::size_t i : {2u, 7u}) {
    const auto c = cells(lines[i]);
    const json s = cli_json({"simulate", "--model",
                             "rigid3d",  "--width",
                             "0.4",      "--depth",
                             "0.3",      "--height",
                             "1.2",      "--mu-s",
                             "0.6",      "--ground-h-pulse",
                             "one-sine", "--ground-h-duration",
                             "0.5",      "--ground-h-amplitude",
                             c[1],       "--ground-azimuth",
                             c[2],       "--t-end",
                             "3",        "--json"},
                            d.path);
    EXPECT_EQ(c[3], s["status"].get<std::string>()) << i;
    EXPECT_EQ(std::stod(c[5]), s["max_tilt"].get<double>()) << i;
    EXPECT_EQ(std::stol(c[12]), s["impacts"].get<long>()) << i;
    ++checked;
  }
  for (std::size_t i = 1; i < lines.size(); ++i) overturned += cells(lines[i])[3] == "overturned";
  EXPECT_EQ(checked, 2);
  EXPECT_GT(overturned, 0);  // the sweep sees both outcomes
  EXPECT_LT(overturned, 8);
}

TEST(Rigid3dSweep, ItsAxesAreTheFamilysOptions) {
  TmpDir d("rigid3d_sweep_bad");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"sweep", "--model", "rigid3d", "--axis", "k=1:2:2", "--output", "x.csv"}, "axis"},
      {{"sweep", "--model", "rigid3d", "--output", "x.csv"}, "axis"},
      {{"sweep", "--model", "rigid3d", "--axis", "tilt=0.1,0.2", "--axis", "tilt=0.3", "--output", "x.csv"}, "axis"},
      {{"sweep", "--model", "rigid3d", "--axis", "tilt=2:3:2", "--output", "x.csv"}, "tilt"},
      {{"sweep", "--model", "rigid3d", "--axis", "width=0.1,-1", "--output", "x.csv"}, "width"},
  };
  expect_usage_errors(cases, d.path);
}

}  // namespace rigid3d_sweep_test
