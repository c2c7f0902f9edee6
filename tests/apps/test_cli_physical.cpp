// SPDX-License-Identifier: Apache-2.0
// Physical-unit input and output of `blockdyn simulate`: k = k_line a b / (m g), time scale
// sqrt(a / g), the same run as its non-dimensional twin. With a physical block every time is in
// seconds (--t-end 3 is 3 s, t_end = 3 / sqrt(a / g) non-dimensional).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

#include "test_sweep_util.hpp"

using sweep_test::run_cli;
using sweep_test::TmpDir;

TEST(CliPhysical, FlagsGiveTheNonDimensionalTwin) {
  TmpDir d("phys");
  const double a = 1.8, b = 0.45, t = 0.4, rho = 2700, ks = 2e9, g = 9.81;
  const auto phys =
      run_cli({"simulate", "--height", "1.8", "--width", "0.45", "--thickness", "0.4", "--density", "2700",
               "--subgrade-modulus", "2e9", "--mu", "0.5", "--ic", "ic1", "--t-end", "3", "--json"},
              d.path);
  ASSERT_EQ(phys.code, 0) << phys.err;
  const auto jp = nlohmann::json::parse(phys.out);
  const double m = rho * a * b * t;
  const double k = ks * t * a * b / (m * g);
  EXPECT_NEAR(jp["parameters"]["r"].get<double>(), b / a, 1e-15);
  EXPECT_NEAR(jp["parameters"]["k"].get<double>(), k, 1e-9 * k);
  EXPECT_NEAR(jp["physical"]["mass_kg"].get<double>(), m, 1e-9 * m);
  EXPECT_NEAR(jp["physical"]["time_scale_s"].get<double>(), std::sqrt(a / g), 1e-14);
  EXPECT_NEAR(jp["physical"]["t_final_s"].get<double>(), 3.0, 1e-12);
  EXPECT_NEAR(jp["t_final"].get<double>(), 3.0 / std::sqrt(a / g), 1e-12);
  EXPECT_NEAR(jp["physical"]["final_state"]["x_m"].get<double>(), jp["final_state"]["x"].get<double>() * a, 1e-12);

  char kbuf[64];
  std::snprintf(kbuf, sizeof kbuf, "%.17g", k);
  char tbuf[64];
  std::snprintf(tbuf, sizeof tbuf, "%.17g", 3.0 / std::sqrt(a / g));
  const auto nd = run_cli(
      {"simulate", "--r", "0.25", "--k", kbuf, "--mu", "0.5", "--ic", "ic1", "--t-end", tbuf, "--json"}, d.path);
  ASSERT_EQ(nd.code, 0) << nd.err;
  const auto jn = nlohmann::json::parse(nd.out);
  EXPECT_EQ(jn["ihor"], jp["ihor"]);
  EXPECT_NEAR(jn["final_state"]["w"].get<double>(), jp["final_state"]["w"].get<double>(), 1e-9);
}

TEST(CliPhysical, IncompleteOrConflictingInputIsRejected) {
  TmpDir d("physbad");
  for (const std::vector<std::string>& bad :
       {std::vector<std::string>{"simulate", "--height", "1.8", "--width", "0.45"},  // no mass, no stiffness
        std::vector<std::string>{"simulate", "--height", "-1", "--width", "0.45", "--mass", "3", "--line-stiffness",
                                 "1e6"},
        std::vector<std::string>{"simulate", "--height", "1", "--width", "0.4", "--mass", "3", "--line-stiffness",
                                 "1e6", "--k", "5"},
        std::vector<std::string>{"simulate", "--units", "physical"}}) {
    const auto r = run_cli(bad, d.path);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
  }
}
