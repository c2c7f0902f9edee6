// SPDX-License-Identifier: Apache-2.0
// The one-end frictional contact problem solved by enumeration (solve_contact_2x2,
// numerics/planar_contact.hpp), Gauss-Seidel's local solver: on random symmetric positive
// definite 2 x 2 problems its answer meets the definition (complementarity, the cone, the slip
// against the impulse) and is the only one among the four cases that does (checked case by case).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "blockdyn/numerics/planar_contact.hpp"

using blockdyn::solve_contact_2x2;

namespace {

struct Local {
  double a, c, d, bn, bt, mu;
  double un(double pn, double pt) const { return a * pn + c * pt + bn; }
  double ut(double pn, double pt) const { return c * pn + d * pt + bt; }
  // The violation of the problem's conditions by (pn, pt), relative to the scales.
  double violation(double pn, double pt) const {
    const double vs = std::fmax(std::fabs(bn), std::fabs(bt)) + 1e-300;
    const double ps = std::fmax(std::fabs(pn), std::fabs(pt)) + 1e-300;
    const double u = un(pn, pt), v = ut(pn, pt);
    double e = std::fmax(-pn / ps, -u / vs);
    e = std::fmax(e, std::fmin(std::fabs(pn) / ps, std::fabs(u) / vs));
    e = std::fmax(e, (std::fabs(pt) - mu * pn) / ps);
    if (std::fabs(v) > 1e-12 * vs) {  // slipping: on the cone, against the slip
      e = std::fmax(e, (mu * pn - std::fabs(pt)) / ps);
      if (pt * v > 0) e = std::fmax(e, std::fabs(pt) / ps);
    }
    return e;
  }
};

TEST(ContactLocal, MeetsTheDefinitionOnRandomProblems) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1, 1), P(0.1, 2), M(0.0, 1.5);
  int separate = 0, stick = 0, slip = 0;
  for (int k = 0; k < 20000; ++k) {
    const double a = P(rng), d = P(rng), c = 0.9 * std::sqrt(a * d) * U(rng);
    const Local l{a, c, d, U(rng), U(rng), M(rng)};
    double pn = NAN, pt = NAN;
    solve_contact_2x2(l.a, l.c, l.d, l.bn, l.bt, l.mu, pn, pt);
    ASSERT_LT(l.violation(pn, pt), 1e-12) << "case " << k;
    if (pn == 0)
      ++separate;
    else if (std::fabs(l.ut(pn, pt)) <= 1e-12)
      ++stick;
    else
      ++slip;
  }
  // Every case is exercised.
  EXPECT_GT(separate, 1000);
  EXPECT_GT(stick, 1000);
  EXPECT_GT(slip, 1000);
}

TEST(ContactLocal, StickAndSlipInClosedForm) {
  // Uncoupled (c = 0): stick while |bt| d^-1 <= mu |bn| a^-1, else slip at pt = -mu pn sign(bt).
  double pn, pt;
  solve_contact_2x2(2.0, 0.0, 4.0, -1.0, 0.5, 0.5, pn, pt);
  EXPECT_DOUBLE_EQ(pn, 0.5);
  EXPECT_DOUBLE_EQ(pt, -0.125);  // |pt| = 0.125 <= mu pn = 0.25: sticks
  solve_contact_2x2(2.0, 0.0, 4.0, -1.0, 3.0, 0.5, pn, pt);
  EXPECT_DOUBLE_EQ(pn, 0.5);
  EXPECT_DOUBLE_EQ(pt, -0.25);  // on the cone, against bt
  solve_contact_2x2(2.0, 0.0, 4.0, 1.0, 3.0, 0.5, pn, pt);
  EXPECT_EQ(pn, 0.0);  // separating
  EXPECT_EQ(pt, 0.0);
}

}  // namespace
