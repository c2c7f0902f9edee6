// SPDX-License-Identifier: Apache-2.0
#pragma once
// Long-term response classification (thesis sec. 4.4): steady rocking, settle down, zero-friction
// rock-flight, rock to vertical, plus overturned and settled (at rest). The decision uses
// measurable quantities only (see classify() and docs/response.md):
//   1. the run overturned                                         -> overturned
//   2. settled (at rest): the total energy stays below 0 over the late window, so the block can
//      never fly again (flight needs E >= 0), and above rest it keeps at most settled_energy of
//      the energy it had available, E - E_rest <= settled_energy (E0 - E_rest). What remains is
//      a vibration on the springs (undamped: it never dies out completely)   -> settled
//   3. mu > 0, the block flew, friction dissipated most of the available energy E0 - E_rest,
//      and the rocking has died out (late rotational share of kinetic energy small; the
//      remaining heave may or may not still lift it off)          -> settle down
//   4. the block (almost) never flies in the late window [late_start, t_end]:
//      flight fraction of that window < steady_flight_fraction   -> steady rocking
//   5. the swing-averaged rotational share of the kinetic energy, rotation / (rotation + y'),
//      fell from the first swings to the late window by a large factor (energy flows from
//      rocking into heave)                                        -> rock to vertical
//   6. mu == 0 (energy conserved, flying, no such trend)          -> zero-friction rock-flight
//   7. mu > 0, flying, and energy almost conserved over the late window (the thesis's table:
//      rock to vertical = flight, no steady state, energy almost conserved; the trend of 5 can
//      take longer than t_end to show)                            -> rock to vertical
//   otherwise                                                     -> unclassified
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "blockdyn/analysis/winkler/swings.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"

namespace blockdyn {

enum class ResponseType {
  SteadyRocking,
  Settled,
  SettleDown,
  ZeroFrictionRockFlight,
  RockToVertical,
  Overturned,
  Unclassified,
  Failed
};
const char* to_string(ResponseType t);

struct ResponseCriteria {
  // Steady rocking: the thesis's "almost never flies" - late flight fraction below this.
  double steady_flight_fraction = 0.05;
  // Settled: E < 0 over the late window and E - E_rest <= settled_energy (E0 - E_rest). In the
  // thesis's maps the blocks that came to rest keep <= 4e-3 of it, steady rocking >= 3e-2 (the
  // soft blocks next to the stability boundary, which slide under ic2), so 1e-2 sits in the gap.
  double settled_energy = 1e-2;
  // Settle down: fraction of the available energy E0 - E_rest lost to friction (the thesis: the
  // swing-averaged total energy drops by at least an order of magnitude) ...
  double settle_dissipation = 0.5;
  // ... and late rotational share of the kinetic energy below this (rocking eliminated).
  double settle_rotation_share = 0.1;
  // Rock to vertical: late rotational share <= this factor times the early share.
  double vertical_trend = 0.7;
  int early_swings = 2;  // swings averaged for the early shares
  // Rock to vertical with mu > 0: friction work in the late window below this fraction of the
  // energy available there.
  double conserved_dissipation = 0.1;
};

struct ResponseMetrics {
  SimStatus status = SimStatus::TEnd;
  double t_final = 0, late_start = 0;
  std::optional<double> overturn_time, first_flight_time;
  double e0 = 0, e_final = 0, e_rest = 0;  // e_rest = -1/(2k): the block at rest upright
  double work_friction = 0;
  double dissipated_fraction = 0;       // -W_friction / (E0 - E_rest)
  double late_dissipated_fraction = 0;  // the same over the late window, relative to E(late_start)
  // Largest total energy in the late window (at its start or end: friction only removes energy;
  // the two-corner non-potential part is far smaller), absolute and as (E - E_rest) / (E0 - E_rest);
  // NaN and 1 if the run did not reach the late window.
  double late_energy_max = std::numeric_limits<double>::quiet_NaN();
  double late_energy_fraction = 1;
  double max_abs_energy_error = 0;
  long upright_passages = 0, takeoffs = 0, late_takeoffs = 0;
  double flight_fraction = 0, late_flight_fraction = 0;  // of the run / of the late window
  long swings = 0, late_swings = 0;
  double early_swing_length = 0, late_swing_length = 0;      // means
  double late_swing_length_cv = 0;                           // std / mean in the late window
  Energy early_average, late_average;                        // means of swing averages
  double early_rotation_share = 0, late_rotation_share = 0;  // rotation / (rotation + kinetic_y)
};

struct ResponseReport {
  ResponseType type = ResponseType::Unclassified;
  std::string reason;  // which criterion decided, with the numbers
  ResponseMetrics metrics;
};

ResponseMetrics compute_metrics(const WinklerParams& p, const WinklerResult& r, const SwingAccumulator& acc,
                                const ResponseCriteria& c);
ResponseReport classify(const WinklerParams& p, const ResponseMetrics& m, const ResponseCriteria& c = {});

struct ResponseOptions {
  double t_end = 1000;
  IntegratorOptions integrator;
  double late_fraction = 0.5;   // late window: [late_fraction * t_end, t_end]
  double quadrature_dt = 1e-3;  // swing-average sampling
  double phase_dt = 0.0;        // phase-portrait sampling (0: none; the sweep does not need it)
  ResponseCriteria criteria;
};

void validate(const ResponseOptions& o);

struct ResponseRun {
  ResponseReport report;
  WinklerResult result;
  std::vector<SwingRecord> swings;
  std::vector<PhaseSample> phase;
};

// One run from z0 with the swing accumulator attached, classified. Thread-safe (no shared state),
// so a sweep can call it from parallel_map.
ResponseRun run_response(const WinklerParams& p, const GroundMotion& g, const WinklerState& z0,
                         const ResponseOptions& o);

// The sweep entry point: type and metrics only.
inline ResponseReport classify_response(const WinklerParams& p, const GroundMotion& g, const WinklerState& z0,
                                        const ResponseOptions& o) {
  ResponseOptions q = o;
  q.phase_dt = 0.0;
  return run_response(p, g, z0, q).report;
}

}  // namespace blockdyn
