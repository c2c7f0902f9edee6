// SPDX-License-Identifier: Apache-2.0
// The planar frictional contact problem as one LCP (Anitescu and Potra's form of the 2D cone,
// PlanarContactSolver::solve_lemke) solved by Lemke's method, on random problems of chains of
// bodies (planar_contact_test_problem.hpp): its impulses meet the problem's definition, and its
// classes, handed to the active-set solver, are a guess it completes (the path the Moreau-Jean
// step takes where the active set alone does not settle).
#include <gtest/gtest.h>

#include <random>

#include "numerics/planar_contact_test_problem.hpp"

using namespace blockdyn;

TEST(ContactLemkeForm, SolutionsMeetTheDefinition) {
  std::mt19937 rng(21);
  int solved = 0, total = 0;
  for (int bodies = 1; bodies <= 5; ++bodies)
    for (int k = 0; k < 60; ++k) {
      test::ContactTestProblem p;
      test::random_contact_problem(p, bodies, 0.8, 1e-10, rng);
      PlanarContactSolver s;
      s.reserve(p.ends, 3 * bodies);
      ++total;
      if (!s.solve_lemke(p.problem)) continue;
      ++solved;
      EXPECT_LT(test::contact_violation(p, s.pn(), s.pt()), 1e-7) << bodies << " bodies, problem " << k;
      // Its classes as the active set's guess: solved again exactly.
      EXPECT_TRUE(s.solve_direct(p.problem, 1e-12 * 2.0)) << bodies << " bodies, problem " << k;
      EXPECT_LT(test::contact_violation(p, s.pn(), s.pt()), 1e-8);
    }
  EXPECT_EQ(solved, total);
}
