// SPDX-License-Identifier: Apache-2.0
#pragma once
// Housner's rocking block (1 DOF, seed 001 sec. 4.1): a rigid block on rigid ground that only
// rocks about a base corner, never slides or flies. theta > 0: rocking on the left corner A.
//   theta'' = -p^2 [ (1 + a_V/g) sin(alpha s - theta) - (a_H/g) cos(alpha s - theta) ],  s = sgn theta
// At theta = 0 the pivot changes with theta'+ = e theta'- (default Housner's e_H). At rest it
// uplifts the instant |a_H| > (g + a_V) tan(alpha). Impacts accumulate in finite time: once the
// remaining accumulation time is below a threshold the block is set at rest (the kinetic energy
// left is booked as impact loss). |theta| = alpha is reported (beyond_alpha), pi/2 is overturn.
#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "blockdyn/excitation/ground_motion.hpp"
#include "blockdyn/excitation/rest_exit.hpp"
#include "blockdyn/integrate/hybrid_model.hpp"
#include "blockdyn/model/rigid_ground/mechanism.hpp"
#include "blockdyn/model/rigid_ground/rigid_params.hpp"

namespace blockdyn {

// The rocking restitution of a run: the given one (in [0, 1]) or Housner's 1 - 1.5 sin^2(alpha),
// which is negative for b/h > sqrt(2) (the block would bounce back onto the same corner): then
// std::invalid_argument naming the restitution and the alternatives.
double housner_coefficient(const BlockShape& shape, std::optional<double> restitution);

struct HousnerMode {
  Mechanism mech = Mechanism::Rest;  // Rest or Rock
  int side = 1;                      // pivot: +1 left corner A (theta > 0), -1 right corner B
  bool beyond = false;               // |theta| > alpha
};

class HousnerBlock {
 public:
  // theta, theta', work of the ground's inertial forces, kinetic energy lost at impacts.
  // Class-scoped on purpose, reusing names of the Winkler state indices (namespace scope):
  // clang's -Wshadow reports the hiding, which is what is meant here.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
  enum : std::size_t { kTheta, kOmega, kWorkGround, kWorkImpact, kDimH };
#pragma GCC diagnostic pop
  enum Event : int { kEvImpact, kEvOverturn, kEvAlpha, kEvUplift, kEvLiftOff, kNumEventsH };
  static constexpr std::size_t kDim = kDimH;
  static constexpr std::size_t kNumEvents = kNumEventsH;
  static constexpr bool kStateJumps = true;
  using Mode = HousnerMode;
  using State = std::array<double, kDim>;

  // A sequence of impacts is ended at rest once the time its remaining impacts take is below
  // kAccumulationTime / p, or below kAccumulationRelative t / (1 - e) (so that its swings stay
  // resolvable in floating point at time t).
  static constexpr double kAccumulationTime = 1e-9;
  static constexpr double kAccumulationRelative = 1e-12;

  HousnerBlock(const BlockShape& shape, double restitution, const GroundMotion& g = {});

  void rhs(double t, const Mode& m, const State& z, State& dz) const;
  void events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const;
  void complete(const Mode&, State&) const {}
  Transition<Mode> transition(double t, const Mode& m, State& z, int event) const;
  std::optional<Transition<Mode>> resolve_chatter(double, const Mode&, const State&) const { return std::nullopt; }
  double step_hint(const Mode&) const { return 0.1 / p_; }
  State abs_tol_scale() const { return {1.0, p_, wscale_, wscale_}; }
  // At rest: where rest fails (RestExit), else the input's breakpoints.
  double next_breakpoint(double t, const Mode& m) const;

  Mode initial_mode(double t, const State& z) const;
  std::optional<std::string> validity_problem(const State& z) const;

  // Mechanical energy (J) relative to the upright block at rest, and the accumulated works.
  double kinetic_energy(const State& z) const { return 0.5 * io_ * z[kOmega] * z[kOmega]; }
  double potential_energy(const Mode& m, const State& z) const;
  double energy(const Mode& m, const State& z) const { return kinetic_energy(z) + potential_energy(m, z); }
  double work(const State& z) const { return z[kWorkGround] + z[kWorkImpact]; }
  // Vertical reaction at the pivot over m g (the Housner model assumes it stays >= 0).
  double normal_reaction(double t, const Mode& m, const State& z) const;
  double angular_acceleration(double t, const Mode& m, const State& z) const;

  // What the rigid-family recorders and outputs read (shared with RigidBlock).
  static constexpr std::size_t kThetaIndex = kTheta, kOmegaIndex = kOmega;
  Mechanism mechanism(const Mode& m) const { return m.mech; }
  int pivot(const Mode& m) const { return m.mech == Mechanism::Rock ? m.side : 0; }
  int slip(const Mode&) const { return 0; }
  unsigned alternatives(const Mode&) const { return 0; }  // rocking is its only motion
  // The corner that hits the ground at an impact event (the one opposite the pivot).
  int impact_corner(const Mode& from, int) const { return -from.side; }
  // Centre (x, y), theta and their rates (the base centre stands at x = 0).
  std::array<double, 6> pose(const Mode& m, const State& z) const;
  // Normal and tangential force at each base corner (N), ground acceleration (g).
  std::array<double, 4> contact_forces(double t, const Mode& m, const State& z) const;
  std::array<double, 2> ground_acceleration(double t) const { return {ah(t), av(t)}; }

  const BlockShape& shape() const { return shape_; }
  const GroundMotion& ground() const { return ground_; }
  double restitution() const { return e_; }
  double alpha() const { return alpha_; }
  double p() const { return p_; }

 private:
  double ah(double t) const { return forced_ ? ground_.ah(t) : 0.0; }
  double av(double t) const { return forced_ ? ground_.av(t) : 0.0; }
  bool rest_holds(double t) const;
  Transition<Mode> after_impact(double t, const Mode& m, State& z) const;

  BlockShape shape_;
  double e_;
  GroundMotion ground_;
  bool forced_;
  double alpha_, R_, p_, io_, ta_, wscale_;
  RestExit rest_exit_;
};

}  // namespace blockdyn
