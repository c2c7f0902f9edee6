// SPDX-License-Identifier: Apache-2.0
#pragma once
// The "rigid" contact law for assemblies (spec block-assemblies.md; seed 001): unilateral,
// non-penetrating contacts with Coulomb friction (static and kinetic) and Newton's impact law,
// integrated by Moreau and Jean's nonsmooth time-stepping scheme. Each step of length h:
//   q_m = q + h/2 v                        (midpoint positions)
//   the contact ends with gap(q_m) <= g h^2 are active (contact_point.hpp, the same ends as the
//   deformable law);
//   v+ = v + h M^-1 f(t + h/2) + M^-1 H^T P, with, per active end, the impulses (P_N, P_T) solving
//     u_N+ + e u_N- >= 0  _|_  P_N >= 0                  (Newton, u_N- < 0 only)
//     Coulomb at the impulse level: stick (u_T+ = 0) with |P_T| <= mu P_N, or slip with
//     P_T = -mu P_N sign(u_T+), mu the end's static or kinetic coefficient (below);
//   q+ = q_m + h/2 v+.
// Static and kinetic friction: an end that was not slipping at the end of the previous step
// (sticking, or just coming into contact) has the static coefficient mu_s, an end that was
// slipping the kinetic one mu_k. The step's problem is solved with these; an end that slips all
// the same (static friction exceeded) gets mu_k and the problem is solved again (the
// coefficients only drop, so this ends after at most one pass per end). A face slips when the
// step's solution has it on its cone's edge with a tangential velocity (after Gauss-Seidel: a
// tangential velocity above 1e-9 of the problem's velocity scale and the compliance's creep); a
// face slides or sticks as a whole. A sliding end sticks again once the kinetic impulse can stop it, as the
// deformable law's slip ends where the slip rate vanishes; then mu_s holds it.
// The contact problem of a step is solved exactly, for the problem with a compliance of 1e-10 of
// the Delassus matrix's largest diagonal entry on its diagonal: an assembly's joints are
// redundant (a face's two ends; an arch, statically indeterminate three times), so the impulses
// of the rigid problem are not unique; the compliance picks one (near the least-norm one) and
// makes the problem positive definite; it moves the velocities by about 1e-10 of an impulse's
// effect. A face has one tangential impulse (its two ends lie on one line along its tangent) and
// its Coulomb cone is the face's (|P_T| <= sum mu P_N). The solvers, in turn:
//  1. an active-set iteration from the previous step's stick / slip / separation pattern (each
//     guess one banded Cholesky solve, checked against every complementarity and cone condition;
//     block changes while they reduce the violations, then Murty's rule, one at a time);
//  2. where it does not settle within a few guesses (a joint pattern changing at once along an
//     arch), Lemke's method on the LCP form of the problem (lemke.hpp), whose classes are solved
//     and checked again as in 1;
//  3. nonsmooth Gauss-Seidel (each end's 2 x 2 Coulomb problem exactly, sweeps until the blocks'
//     velocities change by less than 1e-12 of the problem's scale) from the same warm start.
// The run's JSON counts each (contact_solves). Events (contacts opening and closing, impacts,
// stick and slip) are known to within one step.
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "blockdyn/excitation/ground_motion.hpp"
#include "blockdyn/model/assembly/assembly_params.hpp"
#include "blockdyn/model/assembly/contact_point.hpp"
#include "blockdyn/model/assembly/interface_faces.hpp"
#include "blockdyn/numerics/planar_contact.hpp"

namespace blockdyn {

struct MoreauJeanOptions {
  double h = 1e-4;              // time step (s)
  double max_friction = 1e3;    // friction coefficients above this (90 degrees) are capped here
  double regularisation = 0.0;  // relative compliance added to the Delassus diagonal
  int max_sweeps = 20000;       // Gauss-Seidel sweeps per step before the step is refused
  bool direct = true;           // active-set direct solve first (false: Gauss-Seidel only)
};

class MoreauJean {
 public:
  struct End {
    bool active = false, pushing = false, slipping = false;
    int slip = 0;  // slip direction (+1 / -1) when slipping: sign of the tangential velocity after the step
    int owner = 0;
    FaceContact c;
    double pn = 0, pt = 0;                             // impulses of the last step on the upper block (N s)
    double un_before = 0, un_after = 0, ut_after = 0;  // normal and tangential relative velocities
    double pn_prev = 0, pt_prev = 0;                   // the previous step's impulses (warm start)
  };
  // How the contact problems were solved (counts over the run).
  struct SolveStats {
    long steps = 0, empty = 0, direct = 0, gauss_seidel = 0, sweeps = 0, active_set_iterations = 0, static_drops = 0,
         lemke = 0;
  };

  MoreauJean(const Assembly& a, const GroundMotion& g, const MoreauJeanOptions& o);
  // Its contact problem points into its own arrays: not copied or moved.
  MoreauJean(const MoreauJean&) = delete;
  MoreauJean& operator=(const MoreauJean&) = delete;

  int blocks() const { return nb_; }
  int interfaces() const { return ni_; }
  const Assembly& assembly() const { return asm_; }
  // One step from t: q (x, y, theta per block) and v (their rates) are advanced in place.
  // Returns false when the contact problem's iteration does not converge (reported, not
  // integrated).
  bool step(double t, std::vector<double>& q, std::vector<double>& v);
  const std::vector<End>& ends() const { return ends_; }
  double h() const { return o_.h; }
  int sweeps() const { return sweeps_; }  // Gauss-Seidel sweeps of the last step (0: direct solve)
  const SolveStats& solve_stats() const { return stats_; }

  // Works of the last step: of the ground's inertial forces, of the normal and of the
  // tangential contact impulses (each P . (u+ + u-) / 2: exact for an impulse).
  double work_ground = 0, work_normal = 0, work_tangential = 0;

  double kinetic_energy(const std::vector<double>& v) const;
  double gravity_energy(const std::vector<double>& q) const;
  double overlap_of(const std::vector<double>& q, int iface) const;
  // The upper base centre along the lower face (its change: the interface's relative sliding).
  double base_position_of(const std::vector<double>& q, int iface) const;
  // Both for every interface at once (one sincos per block): overlap[i], base_position[i].
  void measure_interfaces(const std::vector<double>& q, std::vector<double>& overlap,
                          std::vector<double>& base_position) const;
  double rotation_limit(int b) const;
  std::array<double, 2> ground_acceleration(double t) const;

 private:
  BodyPose pose(const std::vector<double>& q, const std::vector<double>& v, int b) const;
  std::pair<Face, Face> faces(const std::vector<double>& q, int iface) const;  // lower, upper
  // The contact problem of the nc active ends (W_, bn_, bt_, mu_*), solved by the solver (its
  // impulses and classes); an end that slips with its static coefficient gets its kinetic one.
  // False when no method solves it.
  bool solve(int nc, double v_scale);
  // One Coulomb problem: the active set, Lemke's guess for it, Gauss-Seidel as the last resort.
  bool solve_coulomb(double v_scale);
  // The steps of step(): the free velocities and the faces at the midpoint; the active ends with
  // their Jacobian rows and right-hand sides (returns their count); the Delassus matrix; the new
  // velocities, impulses, end states and works.
  void free_motion(const std::vector<double>& q, const std::vector<double>& v, const std::array<double, 2>& a);
  int assemble_ends(const std::vector<double>& v);
  void delassus(int nc);
  void conclude(int nc, const std::vector<double>& v, const std::array<double, 2>& a);
  // Velocity change of the blocks from the impulses (sparse: each end touches two blocks).
  void velocity_change(int nc, const double* pn, const double* pt, double* dv) const;
  // The ends' relative velocities and the blocks' velocity change for the solver, from the blocks.
  struct StepVelocities final : ContactVelocities {
    explicit StepVelocities(MoreauJean* s) : self(s) {}
    void relative(const double* pn, const double* pt, double* un, double* ut) override;
    void bodies(const double* pn, const double* pt, double* dv) override;
    MoreauJean* self;
  };
  Assembly asm_;
  GroundMotion ground_;
  bool forced_;
  MoreauJeanOptions o_;
  int nb_, ni_, m_cap_;
  std::vector<double> minv_;  // 3 per block
  std::vector<BodyPose> poses_;
  mutable std::vector<BodyRotation> rot_;  // measure_interfaces' scratch
  std::vector<Face> lower_face_, upper_face_;
  std::vector<InterfaceFaces> local_faces_;  // each interface's faces in its blocks' frames
  std::vector<double> limit_;                // collapse mode 1's rotation per block
  // Interface i's faces placed with the poses of its blocks.
  Face lower_face_at(int i, const BodyPose& lower) const {
    return blockdyn::lower_face_at(local_faces_[i].lower, asm_.interfaces[i].lower < 0, lower);
  }
  Face upper_face_at(int i, const BodyPose& upper) const { return face_at(upper, local_faces_[i].upper); }
  // Per active end: the blocks (upper, lower; -1 the ground), the Jacobian rows (normal x, y,
  // theta, then tangent) on each, and the same rows scaled by the inverse masses.
  std::vector<int> ub_, lb_, active_, face_;
  std::vector<std::array<double, 6>> ju_, jl_, mju_, mjl_;
  std::vector<double> qm_, vfree_, vnew_, dv_, W_, bn_, bt_, mu_, mu_k_, pn_warm_, pt_warm_, un_shift_;
  PlanarContactProblem problem_;  // the step's contact problem (numerics/planar_contact.hpp)
  PlanarContactSolver solver_;
  StepVelocities velocities_{this};
  std::vector<End> ends_;
  int sweeps_ = 0;
  bool classes_solved_ = true;  // the solver holds the last solution's classes (not after Gauss-Seidel)
  double touch_ = 0, slip_velocity_ = 0, compliance_ = 0;
  double reach_ = 0;  // the largest block's half diagonal (m)
  SolveStats stats_;
};

}  // namespace blockdyn
