// SPDX-License-Identifier: Apache-2.0
#pragma once
// An assembly of rigid blocks (rectangles or convex polygons) with deformable unilateral frictional contacts (spec
// block-assemblies.md; seed 002), as a hybrid model for the generic integrator. Every block has
// all three planar degrees of freedom. Contacts sit at the two ends of each interface's overlap
// (contact_point.hpp); each point's law (deformable_contact.hpp) is smooth inside a mode, and
// every switch (open, close, stick, slip, a contact end passing to the other block's corner) is an
// event located in time. Also events: each block's passage through theta = 0, the collapse
// criteria (mode 1: a block's rotation reaches its limit; mode 2: an interface loses its
// bearing) and interpenetration beyond the model's validity.
//
// The capacity MaxBlocks (blocks) fixes the state size at compile time (no allocation in the loop);
// an assembly with fewer blocks leaves the spare slots at zero.
// State: (x, y, theta) per block, their rates, the tangential elastic displacement of each
// contact point, and the accumulated works of the ground, of the normal contacts (dashpots),
// of friction and of the contact-end switches.
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include "blockdyn/excitation/ground_motion.hpp"
#include "blockdyn/integrate/hybrid_model.hpp"
#include "blockdyn/model/assembly/assembly_event_kind.hpp"
#include "blockdyn/model/assembly/assembly_params.hpp"
#include "blockdyn/model/assembly/contact_point.hpp"
#include "blockdyn/model/assembly/deformable_contact.hpp"
#include "blockdyn/model/assembly/interface_faces.hpp"

namespace blockdyn {

template <int MaxBlocks>
struct AssemblyMode {
  static constexpr int kIfaces = MaxBlocks + 1, kPoints = 2 * kIfaces;
  std::array<PointState, kPoints> point{};
  std::array<std::uint8_t, kPoints> owner{};  // 0: the upper block's corner, 1: the lower's
  std::array<std::int8_t, MaxBlocks> side{};  // sign of each block's rotation (+1 for 0)
  std::array<std::uint8_t, kPoints> held{};   // open points held open after chatter (PointLaw::close_band)
};

template <int MaxBlocks>
class AssemblyModel {
 public:
  static constexpr int kBlocks = MaxBlocks, kIfaces = MaxBlocks + 1, kPoints = 2 * kIfaces;
  static constexpr std::size_t kDim = 6 * MaxBlocks + kPoints + 4;
  // Per point: normal, tangential, end owner, validity; per block: theta = 0 and collapse;
  // per interface: bearing.
  static constexpr std::size_t kNumEvents = 4 * kPoints + 2 * MaxBlocks + kIfaces;
  static constexpr bool kStateJumps = false;
  using Mode = AssemblyMode<MaxBlocks>;
  using State = Vec<kDim>;

  static constexpr std::size_t ix(int b) { return 3 * b; }
  static constexpr std::size_t iv(int b) { return 3 * MaxBlocks + 3 * b; }
  static constexpr std::size_t iu(int p) { return 6 * MaxBlocks + p; }
  static constexpr std::size_t kWGround = 6 * MaxBlocks + kPoints, kWNormal = kWGround + 1, kWFriction = kWGround + 2,
                               kWSwitch = kWGround + 3;
  // Event index layout.
  static constexpr int ev_normal(int p) { return p; }
  static constexpr int ev_tangent(int p) { return kPoints + p; }
  static constexpr int ev_owner(int p) { return 2 * kPoints + p; }
  static constexpr int ev_valid(int p) { return 3 * kPoints + p; }
  static constexpr int ev_wzero(int b) { return 4 * kPoints + b; }
  static constexpr int ev_collapse(int b) { return 4 * kPoints + MaxBlocks + b; }
  static constexpr int ev_bearing(int i) { return 4 * kPoints + 2 * MaxBlocks + i; }

  // Elongation (m) by which a sticking point's tangential spring may exceed the static cone
  // before it slips (PointLaw::stick_band = k_T kStickBand: 3e-4 N at seed 002's stiffness, far
  // below any force the runs resolve, above the integration noise of the spring).
  static constexpr double kStickBand = 1e-10;

  // noise_band (rad, m): a block's rotation has passed 0 once it is this far on the other side,
  // and a contact end passes to the other corner once the corners are this far apart: at rest
  // a symmetric assembly keeps these at zero only up to the integration error.
  AssemblyModel(const Assembly& a, const GroundMotion& g, double noise_band = 1e-12);

  int blocks() const { return nb_; }
  int interfaces() const { return ni_; }
  const Assembly& assembly() const { return asm_; }
  const PointLaw& law(int iface) const { return law_[iface]; }

  void rhs(double t, const Mode& m, const State& z, State& dz) const;
  void events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const;
  // The event functions and their time derivatives at (t, z), given dz = rhs(t, m, z) (an
  // integrator has it for free at a step's end: the last stage, FSAL). One geometry evaluation
  // and no dynamics: cheaper than events() alone when a point slips, about as cheap otherwise,
  // so an event scan can bracket each function with values and rates at both ends of a step
  // (cubic Hermite) instead of sampling the step. Exact in closed form, except the switch back
  // to stick of a slipping point (its rate needs F_N'', the third derivative of the gap): NaN,
  // meaning "not known, sample this one".
  void event_rates(double t, const Mode& m, const State& z, const State& dz, std::array<double, kNumEvents>& g,
                   std::array<double, kNumEvents>& g_rate) const;
  void complete(const Mode& m, State& z) const;
  Transition<Mode> transition(double t, const Mode& m, State& z, int event) const;
  // Zero-time open/close chatter of points whose force is zero to rounding: they are held open
  // until their force would push beyond the rounding (PointLaw::close_band); nullopt if no point
  // is such.
  std::optional<Transition<Mode>> resolve_chatter(double t, const Mode& m, const State& z) const;
  double step_hint(const Mode&) const { return step_hint_; }
  State abs_tol_scale() const;
  double next_breakpoint(double t) const { return forced_ ? ground_.next_break(t) : INFINITY; }

  // The initial state of the assembly's blocks and the modes its contacts start in.
  State initial_state() const;
  Mode initial_mode(const State& z) const;
  // Why a state is outside the model (nullopt: inside).
  std::optional<std::string> validity_problem(const Mode& m, const State& z) const;

  // Energy: kinetic, gravity (from the initial heights), normal and tangential springs.
  struct Energy {
    double kinetic = 0, gravity = 0, normal_spring = 0, tangential_spring = 0;
    double total() const { return kinetic + gravity + normal_spring + tangential_spring; }
  };
  Energy energy_terms(const Mode& m, const State& z) const;
  double energy(const Mode& m, const State& z) const { return energy_terms(m, z).total(); }
  double work(const State& z) const { return z[kWGround] + z[kWNormal] + z[kWFriction] + z[kWSwitch]; }

  // Contact point p (interface p / 2, end p % 2) and its forces on the upper block.
  struct PointForce {
    FaceContact c;
    double fn = 0, ft = 0;  // normal (>= 0) and tangential force on the upper block
    double d = 0, d_rate = 0;
  };
  // The poses and faces of a state, computed once per evaluation (one sincos per block).
  struct Geometry {
    std::array<BodyPose, MaxBlocks + 1> pose;  // blocks; the last slot is the ground (at rest)
    std::array<Face, kIfaces> lower, upper;
    const BodyPose& of(int b) const { return b < 0 ? pose[MaxBlocks] : pose[b]; }
  };
  void geometry(const State& z, Geometry& g) const;
  void point_force(const Mode& m, const State& z, const Geometry& g, int p, PointForce& f) const;
  PointForce point_force(const Mode& m, const State& z, const Geometry& g, int p) const {
    PointForce f;
    point_force(m, z, g, p, f);
    return f;
  }
  PointForce point_force(const Mode& m, const State& z, int p) const {
    Geometry g;
    geometry(z, g);
    return point_force(m, z, g, p);
  }
  // The same at time t (the deformable law's forces depend on the state alone; the rigid law's
  // constraint forces on the ground's acceleration too).
  PointForce point_force(const Mode& m, const State& z, double /*t*/, int p) const { return point_force(m, z, p); }
  // Every point's force at once (a trajectory row), the geometry computed once.
  void point_forces(const Mode& m, const State& z, double /*t*/, std::array<PointForce, kPoints>& out) const {
    Geometry g;
    geometry(z, g);
    for (int p = 0; p < 2 * ni_; ++p) point_force(m, z, g, p, out[p]);
  }
  // Accelerations of every block (and the normal-force rates of the slipping points), the
  // ground's accelerations and the contact points. all_points = false: the open points clear of
  // their faces get only their gap (what the right-hand side needs).
  struct Dynamics {
    double ah, av;
    std::array<double, 3 * MaxBlocks> acc;
    std::array<PointForce, kPoints> pf;
    std::array<double, kPoints> fn_rate;
  };
  void dynamics(double t, const Mode& m, const State& z, const Geometry& geo, Dynamics& d, bool need_rates,
                bool all_points = true) const;
  BodyPose pose(const State& z, int b) const;
  double overlap_of(const State& z, int iface) const;
  double rotation_limit(int b) const { return limit_[b]; }
  std::array<double, 2> ground_acceleration(double t) const {
    return {forced_ ? ground_.ah(t) : 0.0, forced_ ? ground_.av(t) : 0.0};
  }

 private:
  // The state of a point re-derived from the geometry (after an end switch).
  // Whether a point slips (then the slip rates need the normal forces' rates).
  bool any_slip(const Mode& m) const;
  PointState consistent_state(const Mode& m, const State& z, const Geometry& g, int p) const;
  // The event functions from an evaluation's geometry and points.
  void event_values(const Mode& m, const State& z, const Geometry& geo, const Dynamics& d,
                    std::array<double, kNumEvents>& g) const;
  // A point's gap acceleration for block accelerations acc, and its normal force's rate.
  double gap_acceleration(const State& z, const std::array<double, 3 * MaxBlocks>& acc, const PointForce& pf,
                          int i) const;
  double normal_force_rate(const State& z, const std::array<double, 3 * MaxBlocks>& acc, const PointForce& pf,
                           int p) const;
  // Rate of along_lower(lower, upper, side) (the upper base corner's coordinate along the lower
  // face) of interface i.
  double along_lower_rate(const Geometry& geo, int i, int side) const;

  Assembly asm_;
  GroundMotion ground_;
  bool forced_;
  int nb_, ni_;
  std::array<double, MaxBlocks> m_{}, I_{}, inv_m_{}, inv_I_{}, limit_{}, y0_{};
  std::array<PointLaw, kIfaces> law_{};
  std::array<int, kIfaces> lower_{}, upper_{};
  std::array<LocalFace, kIfaces> lface_{}, uface_{};  // in the blocks' frames (the ground's: fixed)
  double g_, step_hint_, d_max_, switch_band_, rotation_band_;
};

}  // namespace blockdyn
