// SPDX-License-Identifier: Apache-2.0
#pragma once
// The rigid3d body on rigid ground (docs/3d.md), one hybrid model over its contact modes: at
// rest on its base; sliding on it; rocking about a base edge (two corners) or, for a
// cylinder, about a rim point and its tangent; pivoting on one corner; a box's edge or corner
// sticking or slipping (Coulomb, contact_slip.hpp); in flight. Each mode's events are located on
// the dense output: a contact point's load reaching zero (a corner lifts, the body takes off), a
// base point touching the ground (an impact), the friction a sticking contact needs reaching
// mu_s (it slips; a point carrying less than 1 % of the load is not checked: it is about to lift,
// and the friction so small a load could give is not what keeps it), a slip ending (it sticks, or
// slips on the other way), no load being consistent with the slip (Painleve: the run stops), the
// base standing vertical (overturn). An impact is a velocity-level problem on the base points that
// touch (body_newton_impact.cpp: Newton's restitution and Coulomb's cone on the impulses, the
// default), or the angular momentum about the new contact conserved (Housner's law in 3D, an
// option); a sequence of impacts that accumulates ends at rest. The exit from rest
// is found on the ground motion itself (excitation/rest_exit.hpp) at its first crossing.
// State in the ground's frame: as BodyFlight's, then the ground's work and the impacts' loss (J).
#include <array>
#include <optional>
#include <string>

#include "blockdyn/excitation/ground_motion_3d.hpp"
#include "blockdyn/integrate/hybrid_model.hpp"
#include "blockdyn/model/rigid3d/base_slide.hpp"
#include "blockdyn/model/rigid3d/body_rest.hpp"
#include "blockdyn/model/rigid3d/body_shape.hpp"
#include "blockdyn/model/rigid3d/contact_slip.hpp"
#include "blockdyn/model/rigid3d/disc_slide.hpp"
#include "blockdyn/model/rigid3d/rim_rolling.hpp"
#include "blockdyn/numerics/spatial_contact.hpp"

namespace blockdyn {

enum class BodyContact : unsigned char { Rest, Flight, Line, Point, Slide, Roll };

// Which base points touch and how: Line holds two (box corners i and j, or one rim point and
// its tangent), Point one corner, Roll a cylinder's rim rolling (its contact point travelling). Body-frame points;
// world pivot and axis (fixed while in mode).
struct BodyOnGroundMode {
  BodyContact contact = BodyContact::Rest;
  int corner_a = -1, corner_b = -1;  // box corner indices (bit 0: +x, bit 1: +y); -1: a rim point
  Vec3 point_a{}, point_b{};         // body frame: the contact points (line: its two ends)
  Vec3 pivot{}, axis{};              // world: the pivot (a line's midpoint) and the line's unit axis
  double half_length = 0;            // line: half the distance between its ends (rim: 0)
  double yaw = 0;                    // rest: the body's e1 from the world's x axis (rad)
  int released = -1;                 // point: the corner that just lifted off the line, and when
  double released_t = 0;             // (its touch is first looked for a rounding's height below)
  double impact_t = -1;              // the last impact's time, and how many came within
  int rapid_impacts = 0;             // kInstant of the one before (an accumulation at an instant)
  // Line or Point: which of its points slip on the ground (bit 0: a, bit 1: b; 0: both stick).
  // A point that sticks while the other slips stays at `pivot` (world).
  unsigned char slipping = 0;
  // slide: the base corner that carries no load, the base bearing on the other three (-1: on all
  // four, the linear pressure).
  int unloaded = -1;
  // slide: the unit direction of the slip's generalised velocity (vx, vy, L omega_z) it was last
  // seen in (slip_reference.hpp): the slide ends where its component along it reaches zero. A
  // slipping point a (b): the direction of its slip velocity, likewise.
  Vec3 slip_ref{}, slip_ref_b{};
  // roll, slipping: started with its tilt below the base's landing (after a landing, or tipped
  // up from flat): the landing is looked for once the tilt has risen past twice it (kEvTouch0 +
  // 2), a fall back meanwhile, and a stick before lands the base.
  bool lifting = false;
  bool slips() const { return slipping != 0; }
};

enum class Body3dEventKind : int {
  Mode = 0,     // a mode change (a corner lifts, rest ends)
  Impact,       // a base point hits the ground
  LiftOff,      // the body leaves the ground
  Rest,         // the base comes to rest flat without an impact (an accumulation's last impact is an Impact to rest)
  Overturn,     // the base stands vertical
  NotModelled,  // rolling on the rim, a chatter it cannot resolve (the run stops)
  GroundBreak,  // a breakpoint of the ground motion
  Invalid,      // the ground pulls down faster than g
  Painleve,     // at a new contact neither sticking nor lifting is consistent (the run stops)
  Stick,        // a slide ends: the base sticks (at rest, or sliding on in another direction)
  SlipTurn,     // a slide's direction turned by 60 degrees from its reference: a new reference (no event)
  Slip,         // a box's edge or corner starts slipping (or slips on the other way)
};
const char* to_string(Body3dEventKind k);

// Newton: the touching base points' velocity-level problem (normal restitution e, Coulomb's cone
// on the impulses); Housner: the angular momentum about the new contact conserved (it sticks).
enum class Body3dImpactLaw : unsigned char { Newton, Housner };
const char* to_string(Body3dImpactLaw l);  // "newton", "housner" (the planar block's names)

struct BodyOnGroundOptions {
  double mu_s = 1e6;  // static friction coefficient (large: sticking throughout)
  double mu_k = -1;   // kinetic friction coefficient of a sliding base (< 0: mu_s)
  Body3dImpactLaw impact = Body3dImpactLaw::Newton;
  double restitution = 0;  // Newton's e in [0, 1] (the box; a cylinder's rim impact is Housner's)
  double rest_yaw = 0;     // rad: the yaw the body rests at (its exit from rest under a record is
                           // prepared for it; at another yaw it is searched from scratch)
};

class BodyOnGround {
 public:
  // Class-scoped on purpose, reusing names of the Winkler state indices (namespace scope):
  // clang's -Wshadow reports the hiding, which is what is meant here.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
  enum : std::size_t {
    kX,
    kY,
    kZ,
    kQw,
    kQx,
    kQy,
    kQz,
    kVx,
    kVy,
    kVz,
    kWx,
    kWy,
    kWz,
    kWorkGround,
    kWorkImpact,
    kWorkFriction,
    kDimB
  };
#pragma GCC diagnostic pop
  enum Event : int {
    kEvLiftOff,  // the total normal load (contact modes)
    kEvLoadA,    // a line's end loads (box edge), or the moment a rim point cannot carry
    kEvLoadB,
    kEvTouch0,                  // the heights of the base points not in contact (box: 4; rim: the opposite point);
    kEvTouch3 = kEvTouch0 + 3,  // slide: the four corners' loads (a cylinder: 1 - the rim point's share)
    kEvOverturn,                // R33: the base vertical
    kEvSlipA,                   // mu_s N - |T| at each sticking contact point (a, b); a slipping point: its
    kEvSlipB,                   // slip along its reference; slide: the slip along its reference, its turn
    kEvTouchdown,               // flight: the lowest base point's height
    kEvPainleve,                // slipping edge or corner: the loads' consistency (Painleve where it is zero)
    kEvTurnA,                   // a slipping point's turn from its reference (60 degrees): a, b
    kEvTurnB,
    kNumEventsB
  };
  static constexpr std::size_t kDim = kDimB;
  static constexpr std::size_t kNumEvents = kNumEventsB;
  static constexpr bool kStateJumps = true;
  using Mode = BodyOnGroundMode;
  using State = std::array<double, kDim>;

  // The accumulation of impacts ends at rest once the time its remaining impacts take is below
  // kAccumulationTime sqrt(size / g) (as Housner's model's).
  static constexpr double kAccumulationTime = 1e-9;
  // ... or, under Newton's law, once the edge it leaves would rise less than this (in size)
  // before landing again; a corner's bounce (e > 0) that would rise less is plastic.
  static constexpr double kUnresolvedRise = 1e-12;
  // Impacts this close in time (relative to t, at least 1 s: a few hundred ulps) count as one
  // instant; more than kMaxRapid of them in a row stop the run (a corner sequence that does not
  // end) instead of looping. An accumulation's impacts stay farther apart (kAccumulationTime).
  static constexpr double kInstant = 1e-13;
  // Base points this close to the ground (in body sizes) touch it at an impact (a base landing
  // flat brings its far corners down at one instant up to rounding), and a contact point leaving
  // slower than kImpactLeaving (relative to the impact's velocity scale) stays in contact: both
  // impact laws.
  static constexpr double kImpactTouch = 1e-12;
  // A corner this close to the ground (in size) touches it where a flat base tips.
  static constexpr double kFlatTouch = 1e-12;
  // Loads, friction margins (in m g) and a lifted corner's acceleration (in g) this far below zero
  // still count as consistent (the rounding of a switch).
  static constexpr double kLoadTie = 1e-9;
  static constexpr double kImpactLeaving = 1e-9;
  static constexpr int kMaxRapid = 64;
  // A cylinder's rim landing again this soon after its last landing (in sqrt(size / g)): the
  // landings accumulate, the base lands flat (body_impact.cpp).
  static constexpr double kRimAccumulation = 1e-9;

  BodyOnGround(const Body3d& body, const GroundMotion3d& ground = {}, const BodyOnGroundOptions& opt = {});

  void rhs(double t, const Mode& m, const State& z, State& dz) const;
  void events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const;
  // events()[index] alone, bit for bit: cheaper for a pivot's corner heights and the overturn.
  double event_value(double t, const Mode& m, const State& z, int index) const;
  void complete(const Mode& m, State& z) const;
  Transition<Mode> transition(double t, const Mode& m, State& z, int event) const;
  // Mode changes repeating at one instant (an edge and a corner taking turns: the contact would
  // slide, or needs the contact problem of both at once): the run stops, with the reason.
  std::optional<Transition<Mode>> resolve_chatter(double, const Mode& m, const State&) const {
    return Transition<Mode>{m, true, int(Body3dEventKind::NotModelled)};
  }
  double step_hint(const Mode&) const { return step_; }
  double next_breakpoint(double t, const Mode& m) const;
  State abs_tol_scale() const { return scale_; }

  // Kinetic + m g z (J), and the closed balance: energy - ground work - impact and friction work
  // (constant).
  double energy(const State& z) const;
  double balance(const State& z) const { return energy(z) - z[kWorkGround] - z[kWorkImpact] - z[kWorkFriction]; }
  // A slip's predicted time to its stick (where it would reverse: the friction jumps there), for
  // the integrator's step control; infinity in the other modes.
  double kink_ahead(double t, const Mode& m, const State& z, const State& dz) const;
  // The ground's reaction (N) at the contact points of m (a and b), world frame.
  std::array<Vec3, 2> contact_forces(double t, const Mode& m, const State& z) const;
  // Where the body touches the ground (world; a line's midpoint), NaN off it or on its base.
  Vec3 contact_point(const Mode& m, const State& z) const;
  double tilt(const State& z) const;  // rad: e3 from Z

  // The mode of a body at state z touching the ground where it does (rest, a line, a corner or
  // flight; a tilted body's lowest points decide; `slipping`: contact points moving along the
  // ground slip, else the contact takes the velocities it allows). Throws std::invalid_argument
  // for a body below the ground.
  Mode mode_of(double t, const State& z, bool slipping = false) const;
  // A box's edge or corner contact at z: its points moving along the ground slipping (`slipping`,
  // unless friction would stop them at once), else sticking or slipping as friction decides; a
  // stop where no state of the contact is consistent (Painleve).
  Transition<Mode> contact_motion(double t, const Mode& contact, const State& z, bool slipping) const;
  // The start: the mode of z; where a box starts on an edge or a corner with a corner moving into
  // the ground (Newton's law, `slipping`: a velocity given), an impact at t first
  // (body_newton_impact.cpp: z jumps).
  Transition<Mode> start(double t, State& z, bool slipping = false) const;

  // A Moreau-Jean step of the body from t to t + h (body_time_step.cpp): the stepping strategy
  // across a span where no contact state is consistent (Painleve). `loaded`: the base points
  // (base_points) whose normal impulse is positive; `solved` false where not even the normal
  // impulses solve the problem; `frictionless` where only they did.
  struct TimeStep {
    unsigned loaded = 0;
    bool solved = false, frictionless = false;
  };
  TimeStep time_step(double t, double h, State& z) const;
  // Where the events can take over after a step that left the corners `loaded` carrying the body:
  // the contact they make, consistent at the acceleration level, its state completed onto it
  // (what that changes booked as impact work); none where it is not consistent, or the base flat.
  std::optional<Transition<Mode>> resume_contact(double t, State& z, unsigned loaded) const;
  // The events taking over on `contact` (stick or slip as its points move) where that is
  // consistent: z completed onto it.
  std::optional<Transition<Mode>> resume_on(double t, State& z, const Mode& contact) const;
  // The base's points a time step's contact problem takes (body frame, at orientation r): a box's
  // four corners; a cylinder's rim at its lowest point and a quarter, a half and three quarters
  // of a turn from it (the support of the base when flat). Returns their count.
  int base_points(const Mat3& r, Vec3* points) const;
  // A cylinder's rim point p (body frame) taking over from the steps: put on the ground, rocking
  // or rolling on it (sticking, or slipping the way it moves), where that is consistent.
  std::optional<Transition<Mode>> resume_on_rim(double t, State& z, const Vec3& p) const;

  const Body3d& body() const { return body_; }
  const GroundMotion3d& ground() const { return ground_; }
  const BodyOnGroundOptions& options() const { return opt_; }
  double size() const { return size_; }
  // Why the run stopped at a NotModelled or Invalid event (empty otherwise).
  static std::string stop_reason(const Mode& from, int event, Body3dEventKind kind);

 private:
  Vec3 specific_force(double t) const;  // gravity and the ground's acceleration reversed (m/s^2)
  // The rates every moving mode shares: position, orientation and the ground's work on the centroid.
  void set_kinematic_rates(double t, const State& z, State& dz) const;
  Vec3 corner(int i) const;  // body frame
  // Corner i's height above the pivot's contact point m.point_a (a released corner's allowance
  // added inside its window), the base's up `up`.
  double corner_height(double t, const Mode& m, const Vec3& up, int i) const;
  bool rest_holds(double t, double yaw) const;
  Mode line_mode(const Mat3& r, const Vec3& x, const Vec3& pa, const Vec3& pb, int ca, int cb) const;
  Mode point_mode(const Mat3& r, const Vec3& x, const Vec3& p, int c) const;
  Mode rim_mode(const Mat3& r, const Vec3& x, const Vec3& p) const;
  Transition<Mode> leave_rest(double t, const State& z) const;
  Transition<Mode> mode_change(double t, const Mode& m, State& z, int event) const;
  Transition<Mode> impact(double t, const Mode& from, State& z, int event) const;
  Transition<Mode> contact_after_impact(double t, const Mode& from, State& z, int event) const;
  // Newton's and Coulomb's impact of a box (body_newton_impact.cpp): the impulses at the base
  // points that touch, then the contact they leave (its points sticking or slipping).
  Transition<Mode> newton_impact(double t, const Mode& from, State& z) const;
  // The same for a cylinder's rim landing on a rim point: one point's impulse in Coulomb's cone
  // (numerics/spatial_contact.hpp), then the rim point at rest, slipping, or bouncing off.
  Transition<Mode> newton_rim_impact(double t, const Mode& from, State& z) const;
  // The velocity-level contact problem of the base corners `corners` (n of them) at orientation r
  // and velocities (v, w): W, q and the friction; their arms (world) in `arm`; v_normal left zero.
  SpatialContactProblem point_problem(const Mat3& r, const Vec3& v, const Vec3& w, const Vec3* points, int n,
                                      Vec3* arm) const;
  SpatialContactProblem corner_problem(const Mat3& r, const Vec3& v, const Vec3& w, const int* corners, int n,
                                       Vec3* arm) const;
  // J^-1 in the world's axes, R diag(1/I) R^T.
  Mat3 world_inverse_inertia(const Mat3& r) const;
  // Housner's law in 3D: the new contact sticks, the angular momentum about it conserved.
  Transition<Mode> housner_impact(double t, const Mode& from, State& z) const;
  // After an impact: the contact's consistency (a pull: flight or a slip, else Painleve), the
  // accumulation of impacts, then sticking or slipping as friction decides.
  Transition<Mode> after_impact(double t, const Mode& from, const Mode& next, State& z, double w_before) const;
  // The last impact of an accumulation: the base at rest after it (settle), reported as an impact.
  Transition<Mode> impact_at_rest(double t, State& z) const;
  // Whether the edge the impact left (from's, not next's) rises too slowly to resolve
  // (kUnresolvedRise).
  bool old_edge_rise_unresolved(const Mode& from, const Mode& next, const State& z) const;
  Transition<Mode> after_load_zero(double t, const Mode& m, State& z, int event) const;
  Transition<Mode> settle(double t, State& z) const;
  Transition<Mode> landed_flat(double t, State& z) const;
  // The sliding base (base_slide.hpp): its mode, its motion, its mode changes.
  Mode slide_mode(const State& z, const Vec3& slip_ref) const;
  Vec3 slip_of(const State& z) const;  // the slip's generalised velocity (vx, vy, L omega_z)
  struct SlideState {
    BaseSlide motion;
    Vec3 f;  // the specific force (m/s^2)
  };
  SlideState slide_state(double t, const Mode& m, const State& z) const;
  void slide_rhs(double t, const Mode& m, const State& z, State& dz) const;
  void slide_events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const;
  Transition<Mode> slide_change(double t, const Mode& m, State& z, int event) const;
  // The slide's slip ends (a stick: rest, or sliding on the other way) or turns (a new reference).
  Transition<Mode> slide_ends_or_turns(double t, const Mode& m, State& z, int event) const;
  // The rates of position and yaw of the base sliding flat.
  void set_slide_kinematics(const State& z, State& dz) const;
  // The cylinder's base sliding flat (disc_slide.hpp, body_disc_slide.cpp): its motion, its events
  // (the load, the resultant reaching the rim, the slip's stick and turn), and the tip onto the
  // rim point the resultant reaches, slipping (or held) as the rim does.
  DiscSlide disc_slide_state(double t, const Mode& m, const State& z) const;
  void disc_slide_rhs(double t, const Mode& m, const State& z, State& dz) const;
  void disc_slide_events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const;
  Transition<Mode> tip_disc_from_slide(double t, const Mode& m, const State& z) const;
  Transition<Mode> start_slide(double t, const State& z, const Vec3& towards) const;
  // The base sliding flat, corner k's load reaches zero: it bears on the other three, or tips onto
  // the edge or corner still loaded, its points slipping as they move.
  Transition<Mode> unload_in_slide(double t, const Mode& m, const State& z, int k) const;
  Transition<Mode> tip_from_slide(double t, const Mode& m, const State& z, const int* support, int n) const;
  // A cylinder rolling on its rim (rim_rolling.hpp): motion, events, completion, mode changes.
  RimRolling rolling(double t, const State& z) const;
  void roll_rhs(double t, const State& z, State& dz) const;
  void roll_events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const;
  void roll_complete(State& z) const;
  Transition<Mode> roll_change(double t, const Mode& m, State& z, int event) const;
  // The changes every moving contact (rolling, a slipping rim, edge or corner) makes alike: a
  // breakpoint of the ground (no change), take-off, overturn, Painleve; none for other events.
  std::optional<Transition<Mode>> moving_contact_ends(const Mode& m, int event) const;
  // A cylinder on its rim, rolling or slipping: the mode, its contact point (body frame) kept in
  // point_a as the reference side. The base lands where the tilt passes through zero: the height
  // of the rim point opposite the reference (signed: it changes sign there, where 2 a sin(tilt)
  // only touches zero); the reference is renewed where the contact has travelled 60 degrees
  // along the rim from it (kEvTouch0 + 1; not at a tilt below 1e-8 rad, where the base lands). The rim point that
  // touched just before the landing.
  Mode roll_mode(const State& z, bool slipping) const;
  // A rim contact at rest at z on the rim point `point` (body frame): rocking on it, or rolling if
  // the body turns about more than its tangent (above kRollStart sqrt(g / size)).
  Mode rim_or_roll(const State& z, const Vec3& point) const;
  // The time the rim's tilt towards m's reference side, extrapolated linearly, takes to reach half
  // the landing's tilt (just before the base passes flat, where the contact jumps sides: a kink),
  // or infinity.
  double rim_flat_ahead(const Mode& m, const State& z) const;
  static constexpr double kRollStart = 1e-12;
  void rim_side_events(const Mode& m, const Mat3& r, std::array<double, kNumEvents>& g) const;
  Transition<Mode> rim_side_change(double t, const Mode& m, State& z, int event) const;
  Vec3 rim_point_before_landing(const State& z) const;
  bool rim_below_landing(const Mode& m, const State& z) const;
  void lower_onto_rim(const Mode& m, State& z) const;
  // A cylinder slipping on its rim (rim_rolling.hpp, body_rim_slip.cpp): a Roll mode with
  // `slipping` set, its slip followed against slip_ref; the motion under the friction along -d, or
  // as the state's slip gives it.
  RimSlip rim_slipping(double t, const Vec3& d, const State& z, const Vec3& side) const;
  RimSlip rim_slipping(double t, const Mode& m, const State& z) const;
  void rim_slip_rhs(double t, const Mode& m, const State& z, State& dz) const;
  void rim_slip_events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const;
  void rim_slip_complete(const Mode& m, State& z) const;
  double rim_slip_kink_ahead(double t, const Mode& m, const State& z) const;
  Transition<Mode> rim_slip_change(double t, const Mode& m, State& z, int event) const;
  // The rim's contact at rest on the ground starting to slip, first against `ref` (flight where
  // no slip is consistent and the contact rises, else Painleve).
  Transition<Mode> start_rim_slip(double t, const State& z, const Vec3& ref, const Vec3& side, int kind) const;
  // A rim contact at rest (rocking on a rim point, or rolling): held if mu_s holds it (and
  // may_stick), else slipping.
  Transition<Mode> rim_contact_holds_or_slips(double t, const Mode& stick, const State& z, int kind,
                                              bool may_stick) const;
  // Contact c with its points slipping the way they move (those at rest: as c has them).
  Mode moving_contact(const Mode& c, const State& z) const;
  // A box's edge or corner with a point slipping (contact_slip.hpp, body_contact_slip.cpp): the
  // points' arms and horizontal velocities, the motion, its events and mode changes.
  struct ContactSlip {
    ContactPoints points;
    std::array<Vec3, 2> slip{};  // each point's horizontal velocity
  };
  ContactSlip contact_slip_of(const Mode& m, const State& z) const;
  // The motion and the points' horizontal accelerations, from the points as contact_slip_of gives
  // them (computed once per evaluation), or from the mode.
  SlipContactMotion contact_slip_motion(double t, const ContactSlip& c, const State& z) const;
  SlipContactMotion contact_slip_motion(double t, const Mode& m, const State& z) const {
    return contact_slip_motion(t, contact_slip_of(m, z), z);
  }
  std::array<Vec3, 2> contact_slip_rates(double t, const ContactSlip& c, const State& z) const;
  std::array<Vec3, 2> contact_slip_rates(double t, const Mode& m, const State& z) const {
    return contact_slip_rates(t, contact_slip_of(m, z), z);
  }
  void contact_slip_rhs(double t, const Mode& m, const State& z, State& dz) const;
  void contact_slip_events(double t, const Mode& m, const State& z, std::array<double, kNumEvents>& g) const;
  void contact_slip_complete(const Mode& m, State& z) const;
  Transition<Mode> contact_slip_change(double t, const Mode& m, State& z, int event) const;
  // The contact `stick` at z (its points at rest) sticking if friction holds it (and may_stick),
  // else with the points that friction cannot hold slipping the way the motion takes them
  // (reported as `kind`, or as Slip where it was Mode).
  Transition<Mode> stick_or_slip(double t, const Mode& stick, const State& z, int kind, bool may_stick = true) const;
  // The contact m (from `stick`, its points at rest) with the points of `mask` slipping, their
  // directions the fixed point of the slip's acceleration.
  Mode slipping_contact(double t, const Mode& stick, const State& z, unsigned mask) const;
  // The direction point i of m starts slipping in, at rest at z: the one its slip accelerates in.
  Vec3 slip_start_direction(double t, const Mode& m, const State& z, int i) const;
  // Both ends of an edge starting to slip together: their directions, solved together.
  void joint_start_directions(double t, Mode& m, const State& z) const;
  // Whether contact m is consistent at z (loads, friction, the slip's directions; `lifted` a
  // corner that leaves the ground, rising).
  bool consistent_contact(double t, const Mode& m, const State& z, int lifted) const;
  // The corners off m's contact at the ground (within `touch` sizes: a flat base tipping, or a
  // time step's drift) do not accelerate into it.
  bool other_corners_rise(double t, const Mode& m, const State& z, double touch) const;
  // The events handed `next` on state `on` (completed onto it) from z: what the completion changed
  // booked with the impacts.
  Transition<Mode> hand_back(State& z, const State& on, const Mode& next) const;
  // m's sticking points' friction margins (mu_s N - |T|, in m g): a and b (1 where none).
  std::array<double, 2> stick_margins(double t, const Mode& m, const State& z) const;
  // Housner's law in 3D: the angular momentum about the new contact m conserved.
  void conserve_momentum_about(const Mode& m, State& z) const;
  void set_contact_velocity(const Mode& m, State& z) const;
  bool pulls_away(double t, const Mode& m, const State& z) const;
  // Whether a corner of the contact m would move into the ground in flight (its acceleration
  // without the contact's forces pointing down).
  bool sinks_in_flight(double t, const Mode& m, const State& z) const;
  // The acceleration of the body point at `arm` (world, from the centroid) given z and its rates dz.
  Vec3 point_acceleration(const State& z, const State& dz, const Vec3& arm) const;
  // The rate of the world's up seen in the body frame, d(R^T Z)/dt = -(R^T omega) x R^T Z.
  Vec3 up_rate(const Mat3& r, const State& z) const;
  // A start's slip below this (m/s) friction would stop at once (kInstantSlip sqrt(size / g) at mu_k g).
  double instant_slip() const;
  // Flat and moving along the ground: sliding that way (its slip's generalised velocity nonzero).
  Mode sliding(const State& z) const;
  // Whether friction would stop a start's slipping contact m at once (a sticking contact's limit).
  bool slip_stops_at_once(const Mode& m, const State& z) const;
  // A start on the rim with its rim point moving along the ground: the rim slipping that way, if
  // that is consistent and friction would not stop it at once.
  std::optional<Mode> moving_rim(double t, const State& z) const;
  // A start's slip that friction would stop within this time (in sqrt(size / g)) stops at once.
  static constexpr double kInstantSlip = 1e-6;

  Body3d body_;
  GroundMotion3d ground_;
  BodyOnGroundOptions opt_;
  Vec3 inertia_;
  double size_, step_, window_;
  double v_unresolved_;                       // the speed that rises kUnresolvedRise of the size
  double mu_k_ = 0, reach_ = 0;               // the kinetic friction; the base's half diagonal (box) or radius
  double azimuth_cos_ = 1, azimuth_sin_ = 0;  // the ground's h direction, computed once
  State scale_;
  bool forced_ = false;
  BodyRestSearch rest_search_;
};

// The initial state of the rigid3d body (docs/3d.md): standing turned by yaw (rad), tilted by
// `tilt` (rad) about the base point or edge on the side of tilt_azimuth (rad, world), resting on
// it; or lifted by `lift` (m) with the given velocity and angular velocity (world).
struct Body3dStart {
  double yaw = 0, tilt = 0, tilt_azimuth = 0, lift = 0;
  Vec3 velocity{}, angular_velocity{};
};
BodyOnGround::State initial_state(const Body3d& b, const Body3dStart& s);

}  // namespace blockdyn
