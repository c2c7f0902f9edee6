// SPDX-License-Identifier: Apache-2.0
#pragma once
// The thesis's model: a rigid block on a Winkler foundation with Coulomb friction at the
// lowest corner, moving in contact (pivot fixed), slide or flight. Provides right-hand sides,
// event functions and transition maps for HybridIntegrator.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "blockdyn/excitation/ground_motion.hpp"
#include "blockdyn/integrate/hybrid_model.hpp"
#include "blockdyn/model/winkler/energy.hpp"
#include "blockdyn/model/winkler/foundation_force.hpp"
#include "blockdyn/model/winkler/winkler_params.hpp"
#include "blockdyn/model/winkler/winkler_state.hpp"

namespace blockdyn {

enum class WinklerEventKind : int {
  ContactToSlide,
  SlideToContact,
  SlideReversal,
  Takeoff,
  Landing,
  WZero,
  Overturn,
  Invalid,
  GroundBreak,
  GrazingHold
};
const char* to_string(WinklerEventKind k);

// Everything the equations of motion compute at one state (also used for output).
struct BlockForces {
  double Rx = 0, Ry = 0, torque = 0, torque_nonpot = 0;
  double ax = 0, ay = 0, aw = 0;  // x'', y'', w''
  double v_corner = 0;            // horizontal velocity of the lowest corner
  double margin = 0;              // mu Ry - |Rx| in contact
  double vx = 0;                  // x' implied by the contact constraint (contact only)
  int corners_below = 0;
};

class WinklerBlock {
 public:
  // Event functions; each stays >= 0 while the current mode is valid.
  enum Event : int { kEvOverturn, kEvInvalid, kEvSurface, kEvWZero, kEvFriction, kNumBlockEvents };
  static constexpr std::size_t kDim = kStateDim;
  static constexpr std::size_t kNumEvents = kNumBlockEvents;
  using Mode = WinklerMode;
  using State = WinklerState;

  explicit WinklerBlock(const WinklerParams& p, const GroundMotion& g = {});

  const WinklerParams& params() const { return p_; }
  const GroundMotion& ground() const { return ground_; }

  void rhs(double t, const Mode& m, const State& z, State& dz) const;
  void events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const;
  // The event functions and their time derivatives along dz = f(t, z), with one tilt evaluation
  // (closed forms; in contact the friction margin's rate is left NaN for the integrator).
  void event_rates(double t, const Mode& m, const State& z, const State& dz, std::array<double, kNumEvents>& g,
                   std::array<double, kNumEvents>& gdot) const;
  void complete(const Mode& m, State& z) const;
  // complete() then events() with one tilt evaluation (the integrator's event scan).
  void complete_and_events(double t, const Mode& m, State& z, std::array<double, kNumEvents>& g) const;
  // event kBreakpoint: the ground motion kinks or jumps at t (contact re-checks friction).
  Transition<Mode> transition(double t, const Mode& m, State& z, int event) const;
  double next_breakpoint(double t) const { return forced_ ? ground_.next_break(t) : INFINITY; }
  std::optional<Transition<Mode>> resolve_chatter(double t, const Mode& m, const State& z) const;
  double step_hint(const Mode& m) const;
  // The first step after an event, given h: after a take-off without ground motion the flight's
  // predicted length (a step integrates a free flight exactly) if longer.
  double restart_step(double t, const Mode& m, const State& z, const State& dz, double h) const;
  // In contact or slide: the predicted time (second order) to the next kink of the foundation
  // force, where the far bottom corner crosses the surface or the lowest one leaves it.
  double kink_ahead(double t, const Mode& m, const State& z, const State& dz) const;
  State abs_tol_scale() const;

  BlockForces forces(double t, const Mode& m, const State& z) const;
  BlockForces forces(double t, const Mode& m, const State& z, const Tilt& tilt) const;
  // Total mechanical energy and the accumulated works (friction, non-potential torque, ground),
  // for the closed energy balance.
  double energy(const Mode&, const State& z) const { return blockdyn::energy(p_, z).total(); }
  double work(const State& z) const { return z[kWorkFriction] + z[kWorkNonPotential] + z[kWorkGround]; }
  // The time derivatives of the five energy components at (t, z) (z completed) in mode m: the
  // kinetic ones from the accelerations, gravity y', the springs -Ry y' + (torque_nonpot - torque) w'.
  Energy energy_rates(double t, const Mode& m, const State& z) const;
  // The mode a state starts in (regime, lowest corner, friction direction).
  Mode initial_mode(double t, const State& z) const;
  // Empty if the state is inside the model; otherwise a description of why not.
  std::optional<std::string> validity_problem(const State& z) const;

 private:
  void complete(const Mode& m, State& z, const Tilt& tilt) const;
  void events(double t, const Mode& m, const State& z, const Tilt& tilt, std::array<double, kNumEvents>& g) const;
  Mode submerged_mode(double t, const State& z, int side) const;
  Mode stick_or_slip(double t, const State& z, int side, int slip_sign_if_stuck_fails) const;
  double ah(double t) const { return forced_ ? ground_.horizontal.at(t) : 0.0; }
  double av(double t) const { return forced_ ? ground_.vertical.at(t) : 0.0; }

  static constexpr double kFlightStepMargin = 1.25;  // first flight step / predicted flight

  WinklerParams p_;
  GroundMotion ground_;
  bool forced_;
  double inertia_, alpha_;
  FoundationStiffness stiffness_;
};

}  // namespace blockdyn
