// SPDX-License-Identifier: Apache-2.0
#pragma once
// One run of the rigid3d body (model/rigid3d/body_on_ground.hpp) from its initial state: the
// contact it starts in, the event-driven integration, every event as a typed record, trajectory
// rows at an output interval and at events, and the run's result (status, times, counts, the
// energy balance's largest error). The `simulate --model rigid3d` command and the tests run here.
#include <functional>
#include <string>
#include <vector>

#include "blockdyn/integrate/integrator_options.hpp"
#include "blockdyn/model/rigid3d/body_on_ground.hpp"
#include "blockdyn/simulation/run_result.hpp"

namespace blockdyn {

struct Body3dEventRecord : EventRecordCore<Body3dEventKind> {
  BodyContact from, to;
  unsigned char from_slipping = 0, to_slipping = 0;  // the contact's slipping points (BodyOnGroundMode)
  BodyOnGround::State z{};                           // after the event (after an impact's jump)
};

// A trajectory row: time, mode and state; at an event its kind (after the event's transition).
struct Body3dSample {
  double t;
  BodyOnGroundMode mode;
  BodyOnGround::State z;
  const char* event = nullptr;
};

struct Body3dRunOptions {
  double t_end = 10;             // s
  double output_interval = 0;    // s between trajectory rows (0: events only)
  bool rows_every_step = false;  // a row at every step's end as well (the CLI's output-interval 0)
  IntegratorOptions integ{};
  bool track_energy = true;  // the balance at every step end; false: at events only
  bool track_tilt = true;    // the largest tilt inside every step; false: at events only
  // In contact, contact points that the start's velocities move along the ground slip from t = 0
  // (a velocity given); false: the contact takes the velocities it allows (a rotation given).
  bool slip_start = false;
  std::function<void(const Body3dSample&)> on_sample;  // rows (null: none)
  EventSink<Body3dEventRecord>* events = nullptr;      // as they happen (null: kept in the result)
  long max_events = 1'000'000;  // kept in the result's list (a run's memory bounded); further ones counted only
  // Where no contact state is consistent at the acceleration level (Painleve; or an edge and a
  // corner taking turns at one instant, impacts that do not end, a cylinder's flat base tipping
  // onto a roll) or the events' steps underflow in a stiff slip, the run goes on by Moreau-Jean
  // steps of this length (s; 0: kPainleveStep sqrt(size / g)) until the contact the steps leave
  // is consistent (BodyOnGround::time_step); false: the run stops there (invalid).
  bool painleve_steps = true;
  double painleve_step = 0;
};

// The default Moreau-Jean step across a Painleve span, and the longest span (in sqrt(size / g)).
inline constexpr double kPainleveStep = 1e-6;
inline constexpr double kPainleveSpan = 0.5;

// status: t_end, overturned or invalid (note: why an invalid run stopped).
struct Body3dResult : RunResult {
  BodyOnGround::State z{};
  BodyOnGroundMode mode{};
  double overturn_time = -1, first_uplift_time = -1, first_slide_time = -1, max_tilt = 0;
  // m: the largest length of the slip so far, the slipping point's displacements on the ground (the
  // base's centre sliding flat, the corner or the edge's midpoint slipping) summed over the slips
  double max_slide = 0;
  double max_tilt_azimuth = 0, overturn_azimuth = 0;  // deg: where the body leans, from x towards y
  double initial_energy = 0;                          // of the closed balance (J)
  std::vector<Body3dEventRecord> events;              // when no sink is given (at most max_events)
  long event_count = 0;                               // all of them, kept or not
  // The Painleve spans crossed by Moreau-Jean steps: how many, their time (s) and steps.
  long painleve_spans = 0, painleve_steps = 0;
  double painleve_time = 0;
};

// The direction the body leans to (deg from the world's x axis towards y): the azimuth of e3.
double tilt_azimuth_deg(const BodyOnGround::State& z);

// Throws std::invalid_argument for an initial state below the ground or a bad option.
Body3dResult simulate_body3d(const BodyOnGround& model, BodyOnGround::State z, const Body3dRunOptions& o);

}  // namespace blockdyn
