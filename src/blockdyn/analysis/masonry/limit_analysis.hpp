// SPDX-License-Identifier: Apache-2.0
#pragma once
// Static limit analysis of an assembly of rigid no-tension blocks with unlimited compressive
// strength and Coulomb friction (Heyman's masonry; spec limit-analysis.md): the horizontal load
// multiplier lambda (the constant ground acceleration a_H = lambda g, in the direction asked, at
// which the assembly becomes a mechanism), the mechanism (the dual of the equilibrium equations)
// and a distribution of contact forces at the limit (its line of thrust). Contact points are the
// two ends of each interface's overlap, as in the dynamics. With associative friction the linear
// programme is exact; a mechanism that slides is an upper estimate for non-associative friction.
#include <string>
#include <vector>

#include "blockdyn/model/assembly/assembly_params.hpp"
#include "blockdyn/model/assembly/rest_limit.hpp"

namespace blockdyn {

// The statics of an assembly at its initial pose: masses, centres and the contact points.
StaticProblem static_problem_at_start(const Assembly& a);

struct InterfaceMotion {
  std::string state;        // closed | hinge | sliding | separating
  int hinge_end = -1;       // hinge: the end (0 left, 1 right along the lower face) that stays closed
  double normal_rate[2]{};  // opening rates at the two ends (> 0: opening)
  double slip_rate = 0;     // tangential rate of the upper block against the lower
};

struct InterfaceThrust {
  double normal[2]{};       // N at the two ends (N)
  double tangential = 0;    // T (N) on the upper block along the lower face
  Vec2 point[2];            // the contact points
  bool bears = false;       // N1 + N2 > 0
  Vec2 centre;              // centre of pressure (where the resultant crosses the joint)
  double eccentricity = 0;  // of the centre from the joint's middle, over half the joint
};

struct LimitAnalysis {
  // ok: lambda found; unstable: the assembly cannot stand under its own weight (nothing below
  // is meaningful); no_mechanism: no collapse up to lambda = 1e6.
  std::string status = "unstable";
  int direction = 1;
  double lambda = 0;
  std::vector<double> mechanism;  // (vx, vy, omega) per block, scaled to max |v| of a point = 1
  std::vector<InterfaceMotion> interfaces;
  std::vector<InterfaceThrust> thrust;
  bool sliding = false;  // the mechanism slides somewhere
  // Whether the value holds for non-associative friction too (no sliding in the mechanism).
  bool exact_for_non_associative = false;
};

// direction +1: a_H > 0 (the inertial load towards -x); -1: a_H < 0. exact: as max_load_multiplier.
LimitAnalysis limit_analysis(const Assembly& a, int direction, bool exact = true);

// The thinnest arch (thickness / radius) of the preset's geometry that stands under its own
// weight (lambda >= 0 both ways), bracketed to `tol` by regula falsi on the margin (the smaller
// lambda of the two directions, which rises through 0 there); throws std::invalid_argument if even
// t/R = 1.9 does not stand.
struct MinThickness {
  double ratio = 0;
  int evaluations = 0;
  LimitAnalysis at_minimum;  // the analysis of the thinnest arch found standing
  Assembly arch;             // that arch
};
MinThickness min_thickness_ratio(const PresetOptions& arch, double tol = 1e-7);

}  // namespace blockdyn
