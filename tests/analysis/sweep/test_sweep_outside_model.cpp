// SPDX-License-Identifier: Apache-2.0
// A sweep point whose initial state lies outside the model (three corners below the surface on a
// very soft foundation) is reported in its row, not integrated, and does not stop the sweep.
#include <gtest/gtest.h>

#include "test_sweep_util.hpp"

using sweep_test::run_cli;
using sweep_test::slurp;
using sweep_test::TmpDir;

TEST(SweepOutsideModel, PointIsReportedAndTheSweepGoesOn) {
  TmpDir d("outside");
  const auto r = run_cli(
      {"sweep", "--k", "1,1e4", "--r", "1", "--mu", "0.3", "--ic", "ic1", "--t-end", "2", "-o", "o.csv", "--quiet"},
      d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string csv = slurp(d.path + "/o.csv");
  std::istringstream in(csv);
  std::string header, row1, row2;
  std::getline(in, header);
  std::getline(in, row1);
  std::getline(in, row2);
  // Columns: index,k,r,inv_r,mu,ic,status,...
  EXPECT_NE(row1.find(",ic1,outside_model,"), std::string::npos) << row1;
  EXPECT_NE(row2.find(",ic1,t_end,"), std::string::npos) << row2;
  EXPECT_NE(r.err.find("outside the model"), std::string::npos) << r.err;
}
