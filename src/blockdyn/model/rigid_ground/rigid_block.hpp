// SPDX-License-Identifier: Apache-2.0
#pragma once
// The full planar rigid block on rigid ground (3 DOF, seed 001 sec. 4.2): five mechanisms (rest,
// slide, rock and slide-rock about either base corner, flight), static and kinetic Coulomb
// friction, impacts by the housner or newton law. Every switch is an event located in time; at a
// switch the next mechanism is selected by solving the contact problem (contact_problem.hpp)
// and Painleve's inconsistency or indeterminacy is reported, not resolved silently.
// State in the ground frame (SI): centre (x, y), rotation theta (counter-clockwise), their rates,
// and the works of friction, of the ground's inertial forces and of the impacts.
#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "blockdyn/excitation/ground_motion.hpp"
#include "blockdyn/excitation/rest_exit.hpp"
#include "blockdyn/integrate/hybrid_model.hpp"
#include "blockdyn/model/common/block_kinematics.hpp"
#include "blockdyn/model/rigid_ground/contact_problem.hpp"
#include "blockdyn/model/rigid_ground/mechanism.hpp"
#include "blockdyn/model/rigid_ground/rigid_params.hpp"

namespace blockdyn {

struct RigidMode {
  Mechanism mech = Mechanism::Rest;
  int side = 0;         // rock, slide-rock: the corner in contact (+1 A, -1 B)
  int slip = 0;         // slide, slide-rock: sign of the contact's tangential velocity
  double anchor = 0.0;  // rest: x of the centre; rock: x of the pivot corner
  bool beyond = false;  // |theta| > alpha
  // At the switch into this mode: the other mechanisms that were consistent too (mechanism_bit;
  // 0 almost always). Not a stick-or-slip choice on one contact set (static friction holds).
  unsigned alternatives = 0;
};

// Contact forces of the current mechanism (N), per base corner.
struct RigidReactions {
  double NA = 0, TA = 0, NB = 0, TB = 0;
  double ax = 0, ay = 0, alpha = 0;  // accelerations of the centre and angular acceleration
  double D = 1;                      // slide-rock: effective normal compliance factor (Painleve <= 0)
};

class RigidBlock {
 public:
  // Class-scoped on purpose, reusing names of the Winkler state indices (namespace scope):
  // clang's -Wshadow reports the hiding, which is what is meant here.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
  enum : std::size_t { kX, kY, kTheta, kVX, kVY, kOmega, kWorkFriction, kWorkGround, kWorkImpact, kDimR };
#pragma GCC diagnostic pop
  enum Event : int {
    kEvContact0,
    kEvContact1,
    kEvFriction,
    kEvImpact,
    kEvOverturn,
    kEvAlpha,
    kEvPainleve,
    kNumEventsR
  };
  static constexpr std::size_t kDim = kDimR;
  static constexpr std::size_t kNumEvents = kNumEventsR;
  static constexpr bool kStateJumps = true;
  // Impact accumulation ends at rest as in HousnerBlock (same thresholds).
  static constexpr double kAccumulationTime = 1e-9;
  static constexpr double kAccumulationRelative = 1e-12;
  using Mode = RigidMode;
  using State = std::array<double, kDim>;

  RigidBlock(const RigidBlockParams& p, const GroundMotion& g = {});

  void rhs(double t, const Mode& m, const State& z, State& dz) const;
  void events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const;
  void complete(const Mode& m, State& z) const;
  Transition<Mode> transition(double t, const Mode& m, State& z, int event) const;
  std::optional<Transition<Mode>> resolve_chatter(double, const Mode&, const State&) const { return std::nullopt; }
  double step_hint(const Mode&) const { return 0.1 / p_; }
  State abs_tol_scale() const;
  // At rest: where rest fails (RestExit), else the input's breakpoints.
  double next_breakpoint(double t, const Mode& m) const;
  unsigned alternatives(const Mode& m) const { return m.alternatives; }

  RigidReactions reactions(double t, const Mode& m, const State& z) const;
  // The mechanism a state starts in (nullopt: Painleve) and why a state is outside the model.
  std::optional<Mode> initial_mode(double t, State& z) const;
  std::optional<std::string> validity_problem(const State& z) const;

  double kinetic_energy(const State& z) const;
  double potential_energy(const State& z) const { return m_ * g_ * (z[kY] - hh_); }
  double energy(const Mode&, const State& z) const { return kinetic_energy(z) + potential_energy(z); }
  double work(const State& z) const { return z[kWorkFriction] + z[kWorkGround] + z[kWorkImpact]; }
  // Height of a base corner above the ground.
  double corner_gap(const State& z, int side) const;

  // What the rigid-family recorders and outputs read (shared with HousnerBlock).
  static constexpr std::size_t kThetaIndex = kTheta, kOmegaIndex = kOmega;
  Mechanism mechanism(const Mode& m) const { return m.mech; }
  int pivot(const Mode& m) const { return m.side; }
  int slip(const Mode& m) const { return m.slip; }
  // The corner that hits the ground at an impact event.
  int impact_corner(const Mode& from, int event) const {
    if (from.mech == Mechanism::Flight) return event == kEvContact0 ? 1 : -1;
    return -from.side;
  }
  std::array<double, 6> pose(const Mode&, const State& z) const { return {z[0], z[1], z[2], z[3], z[4], z[5]}; }
  std::array<double, 4> contact_forces(double t, const Mode& m, const State& z) const {
    const RigidReactions f = reactions(t, m, z);
    return {f.NA, f.TA, f.NB, f.TB};
  }
  std::array<double, 2> ground_acceleration(double t) const {
    return {forced_ ? ground_.ah(t) : 0.0, forced_ ? ground_.av(t) : 0.0};
  }
  const BlockShape& shape() const { return par_.shape; }

  const RigidBlockParams& params() const { return par_; }
  const GroundMotion& ground() const { return ground_; }
  double alpha() const { return alpha_; }
  double p() const { return p_; }

 private:
  double gh(double t) const { return forced_ ? g_ * ground_.ah(t) : 0.0; }
  double gv(double t) const { return g_ * (1.0 + (forced_ ? ground_.av(t) : 0.0)); }
  Vec2 corner(double theta, int side) const { return base_corner(BodyRotation::of(theta), bh_, hh_, side); }
  // The contact problem (force level) at a state, over the corners touching the ground.
  ContactProblem contact_problem(double t, const State& z, int sides[2]) const;
  // The next mechanism at a switch; tr.stop with kind Painleve when there is none.
  Transition<Mode> reselect(double t, const Mode& from, State& z, const SelectionHints& h_by_side, int kind) const;
  Transition<Mode> impact(double t, const Mode& from, State& z, int hit_side) const;
  // Time below which the remaining impacts of an accumulating sequence are ended (see HousnerBlock).
  double horizon(double t, double e) const;
  Mode mode_of(const ContactSolution& s, const int sides[2], const State& z, const Mode& from) const;
  // Other mechanisms consistent at a switch (see RigidMode::alternatives): those of the contact
  // problem without the event's hints, less the one left and the one chosen.
  unsigned alternatives_of(const Selection& all, const int sides[2], const State& z, const Mode& from,
                           const Mode& chosen) const;
  // At a checkpoint of rest (RestExit::checkpoint): the transition, by the test the search used.
  Transition<Mode> leave_rest_at(double t, const Mode& md, State& z) const;

  RigidBlockParams par_;
  GroundMotion ground_;
  bool forced_;
  double m_, I_, g_, bh_, hh_, alpha_, p_, R_;
  double tol_gap_, tol_v_, tol_f_, tol_a_, v_close_;
  double tan_alpha_;    // b / h: rest fails by rocking where |a_H| > tan(alpha) (1 + a_V)
  RestExit rest_exit_;  // the smaller resistance, rocking or sliding, fails first
};

}  // namespace blockdyn
