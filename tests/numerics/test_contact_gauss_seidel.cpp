// SPDX-License-Identifier: Apache-2.0
// Nonsmooth Gauss-Seidel on the planar frictional contact problem
// (PlanarContactSolver::solve_gauss_seidel) on random problems of chains of bodies
// (planar_contact_test_problem.hpp): it converges, its answer meets the problem's definition, and
// the bodies' velocities it gives do not depend on where it starts (they are unique where the
// impulses of a face's two ends are not).
#include <gtest/gtest.h>

#include <random>

#include "numerics/planar_contact_test_problem.hpp"

using namespace blockdyn;

TEST(ContactGaussSeidel, ConvergesToTheDefinition) {
  std::mt19937 rng(31);
  for (int bodies = 1; bodies <= 4; ++bodies)
    for (int k = 0; k < 40; ++k) {
      test::ContactTestProblem p;
      test::random_contact_problem(p, bodies, 0.5, 1e-10, rng);
      PlanarContactSolver s;
      s.reserve(p.ends, 3 * bodies);
      ASSERT_TRUE(s.solve_gauss_seidel(p.problem, 1e-13, 500000)) << bodies << " bodies, problem " << k;
      EXPECT_GT(s.sweeps(), 1);
      EXPECT_LT(test::contact_violation(p, s.pn(), s.pt()), 1e-6) << bodies << " bodies, problem " << k;
    }
}

TEST(ContactGaussSeidel, VelocitiesDoNotDependOnTheStart) {
  std::mt19937 rng(32);
  std::uniform_real_distribution<double> U(0, 2);
  for (int k = 0; k < 40; ++k) {
    test::ContactTestProblem p;
    test::random_contact_problem(p, 3, 0.3, 1e-10, rng);
    PlanarContactSolver a, b;
    a.reserve(p.ends, 9);
    b.reserve(p.ends, 9);
    ASSERT_TRUE(a.solve_gauss_seidel(p.problem, 1e-13, 500000));
    for (int i = 0; i < p.ends; ++i) p.pn0[i] = U(rng), p.pt0[i] = 0.1 * U(rng);  // another start
    ASSERT_TRUE(b.solve_gauss_seidel(p.problem, 1e-13, 500000));
    std::vector<double> dva(9), dvb(9);
    p.bodies_change(a.pn().data(), a.pt().data(), dva.data());
    p.bodies_change(b.pn().data(), b.pt().data(), dvb.data());
    double scale = 1e-300;
    for (double v : p.vfree) scale = std::fmax(scale, std::fabs(v));
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(dva[i], dvb[i], 1e-8 * scale) << "problem " << k;
  }
}
