// SPDX-License-Identifier: Apache-2.0
#pragma once
// An assembly of rigid blocks with rigid unilateral frictional contacts, event-driven (spec
// block-assemblies.md; Pfeiffer & Glocker's formulation of multibody systems with unilateral
// contacts). The contacts are the same points as the deformable law's (contact_point.hpp): the
// two ends of each interface's overlap. In a mode every point is open, sticking or slipping
// (+/-); between events the blocks move smoothly, the closed points' constraint forces solving
// the acceleration-level contact problem of the mode:
//   M a = f(t) + sum_closed W_N^T lambda_N + sum_slipping W_T^T (-mu_k s lambda_N) + sum_sticking W_T^T lambda_T
//   closed point: gap'' = W_N a + kappa_N = 0;  sticking interface: slip' = W_T a + kappa_T = 0.
// Events, each located where its function crosses zero: a closed point's normal force reaching
// zero (it opens), an open point's gap reaching zero (an impact), a sticking interface's friction
// reaching mu_s N (it slips), a slipping point's slip rate reaching zero (it sticks or reverses),
// a contact end passing to the other block's corner, the passages of theta through 0 and the
// collapse criteria. After each event the next mode is chosen by an active-set iteration on the
// same contact problem (every normal force >= 0, every gap acceleration of a touching open point
// >= 0, every sticking force within the cone, every slip kept); an impact is resolved by the
// velocity-level problem with Newton's restitution at the impacting points and Coulomb's law for
// the impulses.
// Rest: a mode of its own in which every point is closed and sticking and nothing moves. Where the
// assembly is statically indeterminate the forces at rest are not unique: rest holds while some
// distribution holds the blocks, i.e. while the ground acceleration lies inside the static limits
// (rest_limit.hpp: c_neg (1 + a_V) >= -a_H, c_pos (1 + a_V) >= a_H), found on the ground motion
// itself (RestExit) and left into the limit's mechanism. Impacts that accumulate (a block settling
// in ever shorter rocking cycles) end in rest once the velocities after an impact are below
// settle_velocity() and rest holds: sqrt(2 g delta), the speed of a bounce delta high, delta the
// noise band (10 atol: 1e-9 m by default), below which the integration does not resolve a motion.
//
// The state and mode layouts are those of AssemblyModel (the tangential spring slots stay zero),
// so the observers of assembly runs serve both laws.
#include <array>
#include <optional>
#include <string>

#include "blockdyn/excitation/ground_motion.hpp"
#include "blockdyn/excitation/rest_exit.hpp"
#include "blockdyn/model/assembly/assembly_model.hpp"
#include "blockdyn/model/assembly/rest_limit.hpp"

namespace blockdyn {

template <int MaxBlocks>
struct RigidAssemblyMode : AssemblyMode<MaxBlocks> {
  bool rest = false;
  double rest_pos = 0, rest_neg = 0;  // at rest: the configuration's static limits
};

template <int MaxBlocks>
class RigidAssemblyModel {
 public:
  using Base = AssemblyModel<MaxBlocks>;
  static constexpr int kBlocks = MaxBlocks, kIfaces = MaxBlocks + 1, kPoints = 2 * kIfaces;
  static constexpr std::size_t kDim = Base::kDim;
  static constexpr std::size_t kNumEvents = Base::kNumEvents;
  static constexpr bool kStateJumps = true;
  static constexpr int kCoords = 3 * MaxBlocks;
  using Mode = RigidAssemblyMode<MaxBlocks>;
  using State = Vec<kDim>;
  using Geometry = typename Base::Geometry;
  using PointForce = typename Base::PointForce;
  using Energy = typename Base::Energy;

  static constexpr std::size_t ix(int b) { return Base::ix(b); }
  static constexpr std::size_t iv(int b) { return Base::iv(b); }
  static constexpr std::size_t kWGround = Base::kWGround, kWNormal = Base::kWNormal, kWFriction = Base::kWFriction,
                               kWSwitch = Base::kWSwitch;
  static constexpr int ev_normal(int p) { return Base::ev_normal(p); }
  static constexpr int ev_tangent(int p) { return Base::ev_tangent(p); }
  static constexpr int ev_owner(int p) { return Base::ev_owner(p); }
  static constexpr int ev_valid(int p) { return Base::ev_valid(p); }
  static constexpr int ev_wzero(int b) { return Base::ev_wzero(b); }
  static constexpr int ev_collapse(int b) { return Base::ev_collapse(b); }
  static constexpr int ev_bearing(int i) { return Base::ev_bearing(i); }
  // Rest's events (in the validity slots, unused by this law): the two static limits.
  static constexpr int ev_rest(int dir) { return Base::ev_valid(dir > 0 ? 0 : 1); }

  // Velocities after an impact below this end in rest where rest holds (the accumulation point
  // of a settling block's impacts); a point leaving its face slower stays on it.
  double settle_velocity() const { return settle_velocity_; }

  RigidAssemblyModel(const Assembly& a, const GroundMotion& g, double noise_band = 1e-12);

  int blocks() const { return geo_.blocks(); }
  int interfaces() const { return geo_.interfaces(); }
  const Assembly& assembly() const { return geo_.assembly(); }
  const GroundMotion& ground() const { return ground_; }
  double rotation_limit(int b) const { return geo_.rotation_limit(b); }
  std::array<double, 2> ground_acceleration(double t) const { return geo_.ground_acceleration(t); }
  void geometry(const State& z, Geometry& g) const { geo_.geometry(z, g); }
  double overlap_of(const State& z, int iface) const { return geo_.overlap_of(z, iface); }

  void rhs(double t, const Mode& m, const State& z, State& dz) const;
  void events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const;
  void complete(const Mode&, State&) const {}
  Transition<Mode> transition(double t, const Mode& m, State& z, int event) const;
  std::optional<Transition<Mode>> resolve_chatter(double, const Mode&, const State&) const { return std::nullopt; }
  double step_hint(const Mode&) const { return step_hint_; }
  State abs_tol_scale() const;
  double next_breakpoint(double t, const Mode& m) const;

  State initial_state() const { return geo_.initial_state(); }
  Mode initial_mode(const State& z) const;
  std::optional<std::string> validity_problem(const Mode& m, const State& z) const;

  // Why the last transition stopped the run; empty otherwise.
  const std::string& problem() const { return problem_; }
  // A problem found outside the model's own transitions (a time-stepping window): the run's note.
  void report(std::string why) const { problem_ = std::move(why); }
  // Whether the run stopped to hand a window to time-stepping (an accumulation of impacts that
  // does not settle, a contact problem without a consistent mode), and why.
  bool wants_time_stepping() const { return handover_; }
  // Back from time-stepping at (t, z): the mode that the contact states `guess` (from the
  // time-stepping's last step) settle into, the closed points put on their faces; nullopt if no
  // mode is consistent there yet.
  std::optional<Mode> resume(double t, State& z, Mode guess) const;
  // Impacts this many within kAccumulationWindow sqrt(L / g) that do not settle stop the run.
  static constexpr int kAccumulationImpacts = 256;
  static constexpr double kAccumulationWindow = 1e-2;

  Energy energy_terms(const Mode& m, const State& z) const;
  double energy(const Mode& m, const State& z) const { return energy_terms(m, z).total(); }
  double work(const State& z) const { return z[kWGround] + z[kWNormal] + z[kWFriction] + z[kWSwitch]; }
  // Every point's contact force in a mode from one solve of its contact problem (the
  // acceleration-level solution at t; at rest the least-norm distribution that holds the blocks).
  void point_forces(const Mode& m, const State& z, double t, std::array<PointForce, kPoints>& out) const;

  // The static limits of the configuration z (every contact closed): a_H / (g + a_V) at which rest
  // fails in each direction; nullopt where no distribution holds the blocks at all.
  struct RestLimits {
    double pos = 0, neg = 0;
  };
  std::optional<RestLimits> rest_limits(const State& z) const;

  // One point's kinematics: generalized rows of its normal and tangential relative velocities
  // (upper against lower) and their drifts (the velocity-dependent part of their rates).
  struct PointRows {
    FaceContact c;
    int upper = 0, lower = -1;
    std::array<double, 3> nu{}, nl{}, tu{}, tl{};  // rows on the upper and the lower block
    double gap = 0, vn = 0, vt = 0, kn = 0, kt = 0;
  };
  // A mode's contact problem at time t: accelerations, normal and tangential forces per point.
  struct Solution {
    std::array<double, kCoords> acc{};
    std::array<double, kPoints> fn{}, ft{};
    bool ok = true;
  };

 private:
  void rows(const State& z, const Geometry& geo, const Mode& m, std::array<PointRows, kPoints>& r) const;
  Solution solve(double t, const Mode& m, const State& z, const std::array<PointRows, kPoints>& r) const;
  // The next mode from `m` at (t, z) by the active-set iteration; false if it does not settle.
  bool select_mode(double t, Mode& m, const State& z) const;
  // The impact at (t, z): new velocities in z, work booked; the mode's closed set updated.
  bool impact(double t, Mode& m, State& z) const;
  struct ImpactWork;  // the velocity-level problem of one impact (rigid_assembly_impact.ipp)
  // Solves the impact set as it stands; false if the system is singular.
  bool solve_impact(ImpactWork& w) const;
  // Applies the most violated change to the set; false when none is violated (settled).
  bool change_impact_set(ImpactWork& w) const;
  // The solution into z (velocities, works) and the new mode of every point.
  void apply_impact(const ImpactWork& w, Mode& m, State& z) const;
  // The closed points back on their constraints: gaps (velocities = false) or rates.
  void project(const Mode& m, State& z, bool velocities) const;
  // One Newton step of it; false when there is nothing left to correct.
  bool project_step(const Mode& m, State& z, bool velocities) const;
  // Enter rest if every point touches, nothing moves and rest holds at t.
  bool try_rest(double t, Mode& m, State& z) const;
  // The transitions by kind of event (transition()): leaving rest, a contact point opening or
  // closing (an impact), stick to slip and back, the contact passing to the other block's end.
  void leave_rest(double t, const Mode& m, State& z, Transition<Mode>& tr) const;
  void open_or_close(double t, const Mode& m, State& z, int point, Transition<Mode>& tr) const;
  void stick_or_slip(double t, const Mode& m, State& z, int point, Transition<Mode>& tr) const;
  void switch_end(double t, State& z, int point, Transition<Mode>& tr) const;
  // Stops the event-driven run for time-stepping, saying why.
  void hand_over(Transition<Mode>& tr, const std::string& why) const;
  // The next mode consistent with the contact problem, after projecting z onto tr.next's constraints.
  void reselect(double t, Transition<Mode>& tr, State& z) const;
  Mode mechanism_mode(const Mode& m, const State& z, int direction) const;
  // The static programme of the configuration z with the contact points of `r`.
  StaticProblem static_problem(const State& z, const std::array<PointRows, kPoints>& r) const;
  double rate_of(const PointRows& r, const std::array<double, kCoords>& acc, bool normal) const;

  Base geo_;
  GroundMotion ground_;
  bool forced_;
  int nb_, ni_;
  std::array<double, MaxBlocks> m_{}, I_{}, y0_{};
  std::array<double, kCoords> inv_mass_{};
  std::array<double, kIfaces> mu_s_{}, mu_k_{}, e_{};
  std::array<int, kIfaces> lower_{}, upper_{};
  double g_, step_hint_, len_, v_scale_, f_scale_, rotation_band_, switch_band_, settle_velocity_;
  // The static limits of the initial configuration (the assembly returns to it after rocking).
  mutable std::optional<RestLimits> limits0_;
  State z0_{};
  // The search for rest's failure, for the limits of the rest it was built for.
  mutable RestExit rest_exit_;
  // Why the run stopped outside the scheme's reach (empty: it did not), and the recent impacts'
  // times (an accumulation that does not settle).
  mutable std::string problem_;
  mutable bool handover_ = false;
  mutable std::array<double, 256> impact_times_{};
  mutable long impacts_ = 0;
  mutable double exit_pos_ = NAN, exit_neg_ = NAN;
};

}  // namespace blockdyn
