// SPDX-License-Identifier: Apache-2.0
#pragma once
// The "rigid" contact law for assemblies (spec block-assemblies.md; seed 001): unilateral,
// non-penetrating contacts with Coulomb friction and Newton's impact law, integrated by Moreau and
// Jean's nonsmooth time-stepping scheme. Each step of length h:
//   q_m = q + h/2 v                        (midpoint positions)
//   the contact ends with gap(q_m) <= 0 are active (contact_point.hpp, the same ends as the
//   deformable law);
//   v+ = v + h M^-1 f(t + h/2) + M^-1 H^T P, with, per active end, the impulses (P_N, P_T) solving
//     u_N+ + e u_N- >= 0  _|_  P_N >= 0                  (Newton, u_N- < 0 only)
//     |P_T| <= mu P_N, P_T opposing u_T+ when it is not 0  (Coulomb at the impulse level)
//   solved by nonsmooth Gauss-Seidel: each end's 2 x 2 Coulomb problem exactly, the others
//   fixed, sweeps until the impulses change by less than 1e-12 of the largest;
//   q+ = q_m + h/2 v+.
// Events (contacts opening and closing, impacts, stick and slip) are known to within one step.
#include <array>
#include <utility>
#include <string>
#include <vector>

#include "blockdyn/excitation/ground_motion.hpp"
#include "blockdyn/model/assembly/assembly_params.hpp"
#include "blockdyn/model/assembly/contact_point.hpp"

namespace blockdyn {

struct MoreauJeanOptions {
  double h = 1e-4;               // time step (s)
  double max_friction = 1e3;     // friction coefficients above this (90 degrees) are capped here
  double regularisation = 0.0;   // relative compliance added to the Delassus diagonal
  int max_sweeps = 20000;        // Gauss-Seidel sweeps per step before the step is refused
};

class MoreauJean {
 public:
  struct End {
    bool active = false, pushing = false, slipping = false;
    int owner = 0;
    FaceContact c;
    double pn = 0, pt = 0;        // impulses of the last step on the upper block (N s)
    double un_before = 0, un_after = 0, ut_after = 0;  // normal and tangential relative velocities
    double pn_prev = 0, pt_prev = 0;                   // the previous step's impulses (warm start)
  };

  MoreauJean(const Assembly& a, const GroundMotion& g, const MoreauJeanOptions& o);

  int blocks() const { return nb_; }
  int interfaces() const { return ni_; }
  const Assembly& assembly() const { return asm_; }
  // One step from t: q (x, y, theta per block) and v (their rates) are advanced in place.
  // Returns false when the contact problem's iteration does not converge (reported, not
  // integrated).
  bool step(double t, std::vector<double>& q, std::vector<double>& v);
  const std::vector<End>& ends() const { return ends_; }
  double h() const { return o_.h; }
  int sweeps() const { return sweeps_; }  // of the last step's contact problem

  // Works of the last step: of the ground's inertial forces, of the normal and of the
  // tangential contact impulses (each P . (u+ + u-) / 2: exact for an impulse).
  double work_ground = 0, work_normal = 0, work_tangential = 0;

  double kinetic_energy(const std::vector<double>& v) const;
  double gravity_energy(const std::vector<double>& q) const;
  double overlap_of(const std::vector<double>& q, int iface) const;
  // The upper base centre along the lower face (its change: the interface's relative sliding).
  double base_position_of(const std::vector<double>& q, int iface) const;
  double rotation_limit(int b) const;
  std::array<double, 2> ground_acceleration(double t) const;

 private:
  BodyPose pose(const std::vector<double>& q, const std::vector<double>& v, int b) const;
  std::pair<Face, Face> faces(const std::vector<double>& q, int iface) const;  // lower, upper
  Assembly asm_;
  GroundMotion ground_;
  bool forced_;
  MoreauJeanOptions o_;
  int nb_, ni_;
  std::vector<double> minv_;  // 3 per block
  std::vector<double> qm_, vfree_, vnew_, dv_, rows_, W_, z_, bn_, bt_, mu_, pn_, pt_;
  std::vector<int> active_;
  std::vector<End> ends_;
  int sweeps_ = 0;
  double touch_ = 0;
};

}  // namespace blockdyn
