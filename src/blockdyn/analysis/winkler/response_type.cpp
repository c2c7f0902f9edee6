// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/winkler/response_type.hpp"

#include "blockdyn/base/number_text.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace blockdyn {

const char* to_string(ResponseType t) {
  switch (t) {
    case ResponseType::SteadyRocking:
      return "steady_rocking";
    case ResponseType::Settled:
      return "settled";
    case ResponseType::SettleDown:
      return "settle_down";
    case ResponseType::ZeroFrictionRockFlight:
      return "zero_friction_rock_flight";
    case ResponseType::RockToVertical:
      return "rock_to_vertical";
    case ResponseType::Overturned:
      return "overturned";
    case ResponseType::Unclassified:
      return "unclassified";
    case ResponseType::Failed:
      return "failed";
  }
  return "?";
}

void validate(const ResponseOptions& o) {
  auto bad = [](const std::string& f, const std::string& range, double v) {
    throw std::invalid_argument(f + " = " + number_text(v) + " is out of range: must be " + range);
  };
  if (!std::isfinite(o.t_end) || o.t_end <= 0) bad("t-end", "finite and > 0", o.t_end);
  if (!(o.late_fraction >= 0 && o.late_fraction < 1)) bad("late-fraction", "in [0, 1)", o.late_fraction);
  if (!std::isfinite(o.quadrature_dt) || o.quadrature_dt <= 0) bad("quadrature-dt", "finite and > 0", o.quadrature_dt);
  if (!std::isfinite(o.phase_dt) || o.phase_dt < 0) bad("phase-dt", "finite and >= 0", o.phase_dt);
  const auto& c = o.criteria;
  if (!(c.steady_flight_fraction > 0 && c.steady_flight_fraction < 1))
    bad("steady-flight-fraction", "in (0, 1)", c.steady_flight_fraction);
  if (!(c.settled_energy > 0 && c.settled_energy < 1)) bad("settled-energy", "in (0, 1)", c.settled_energy);
  if (!(c.settle_dissipation > 0 && c.settle_dissipation < 1))
    bad("settle-dissipation", "in (0, 1)", c.settle_dissipation);
  if (!(c.settle_rotation_share > 0 && c.settle_rotation_share < 1))
    bad("settle-rotation-share", "in (0, 1)", c.settle_rotation_share);
  if (!(c.vertical_trend > 0 && c.vertical_trend < 1)) bad("vertical-trend", "in (0, 1)", c.vertical_trend);
  if (c.early_swings < 1) bad("early-swings", ">= 1", c.early_swings);
  if (!(c.conserved_dissipation > 0 && c.conserved_dissipation < 1))
    bad("conserved-dissipation", "in (0, 1)", c.conserved_dissipation);
}

namespace {

double rotation_share(const Energy& e) {
  const double s = e.rotation + e.kinetic_y;
  return s > 0 ? e.rotation / s : 0.0;
}

void accumulate(Energy& a, const Energy& b) {
  a.kinetic_x += b.kinetic_x;
  a.kinetic_y += b.kinetic_y;
  a.rotation += b.rotation;
  a.gravity += b.gravity;
  a.springs += b.springs;
}

Energy scaled(Energy e, double f) {
  e.kinetic_x *= f;
  e.kinetic_y *= f;
  e.rotation *= f;
  e.gravity *= f;
  e.springs *= f;
  return e;
}

std::string fmt(const char* f, double a, double b = 0, double c = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, a, b, c);
  return buf;
}

}  // namespace

ResponseMetrics compute_metrics(const WinklerParams& p, const WinklerResult& r, const SwingAccumulator& acc,
                                const ResponseCriteria& c) {
  ResponseMetrics m;
  m.status = r.status;
  m.t_final = r.t_final;
  m.late_start = acc.options().late_start;
  m.overturn_time = r.overturn_time;
  m.first_flight_time = r.first_flight_time;
  m.e0 = r.initial_energy.total();
  m.e_final = r.final_energy.total();
  m.e_rest = -0.5 / p.k;
  m.work_friction = r.work_friction();
  const double avail = m.e0 - m.e_rest;
  m.dissipated_fraction = avail > 0 ? (0.0 - m.work_friction) / avail : 0.0;  // 0 - w: no "-0"
  if (acc.reached_late()) {
    const double avail_late = acc.late_energy() - m.e_rest;
    m.late_dissipated_fraction = avail_late > 0 ? -(m.work_friction - acc.late_work_friction()) / avail_late : 0.0;
    m.late_energy_max = std::fmax(acc.late_energy(), m.e_final);
    if (avail > 0) m.late_energy_fraction = (m.late_energy_max - m.e_rest) / avail;
  }
  m.max_abs_energy_error = r.max_abs_energy_error;
  m.upright_passages = r.upright_passages;
  m.takeoffs = acc.takeoffs();
  m.late_takeoffs = acc.late_takeoffs();
  m.flight_fraction = r.t_final > 0 ? acc.flight_time() / r.t_final : 0.0;
  const double late_len = r.t_final - m.late_start;
  m.late_flight_fraction = late_len > 0 ? acc.late_flight_time() / late_len : 0.0;

  const auto& sw = acc.swings();
  m.swings = long(sw.size());
  const int ne = std::min<int>(c.early_swings, int(sw.size()));
  double len_e = 0;
  for (int i = 0; i < ne; ++i) {
    accumulate(m.early_average, sw[i].average);
    len_e += sw[i].length();
  }
  if (ne > 0) {
    m.early_average = scaled(m.early_average, 1.0 / ne);
    m.early_swing_length = len_e / ne;
  }
  double len_l = 0, len_l2 = 0;
  for (const auto& s : sw) {
    if (s.t_end < m.late_start) continue;
    ++m.late_swings;
    accumulate(m.late_average, s.average);
    len_l += s.length();
    len_l2 += s.length() * s.length();
  }
  if (m.late_swings > 0) {
    const double n = double(m.late_swings);
    m.late_average = scaled(m.late_average, 1.0 / n);
    m.late_swing_length = len_l / n;
    const double var = std::max(0.0, len_l2 / n - m.late_swing_length * m.late_swing_length);
    m.late_swing_length_cv = m.late_swing_length > 0 ? std::sqrt(var) / m.late_swing_length : 0.0;
  }
  m.early_rotation_share = rotation_share(m.early_average);
  m.late_rotation_share = rotation_share(m.late_average);
  return m;
}

ResponseReport classify(const WinklerParams& p, const ResponseMetrics& m, const ResponseCriteria& c) {
  ResponseReport rep;
  rep.metrics = m;
  auto set = [&](ResponseType t, std::string why) {
    rep.type = t;
    rep.reason = std::move(why);
    return rep;
  };
  if (m.status == SimStatus::Overturned)
    return set(ResponseType::Overturned, fmt("overturned at t = %.6g", *m.overturn_time));
  if (m.status != SimStatus::TEnd && m.status != SimStatus::EarlyStop)
    return set(ResponseType::Failed, std::string("run ended with status ") + to_string(m.status));
  // At rest: flight impossible from the late window on (E < 0) and almost all of the energy gone.
  // Tested before settle down, which keeps the blocks that still hop (E >= 0).
  if (m.late_energy_max < 0 && m.late_energy_fraction <= c.settled_energy)
    return set(ResponseType::Settled,
               fmt("E <= %.3g < 0 late (no flight possible); energy above rest %.3g of E0 - E_rest <= %.3g",
                   m.late_energy_max, m.late_energy_fraction, c.settled_energy));
  // Settle down is tested next: a block that flew, lost most of its energy to friction and
  // stopped rocking has settled whether or not its remaining heave still lifts it off.
  if (p.mu > 0 && m.takeoffs > 0 && m.dissipated_fraction >= c.settle_dissipation &&
      m.late_rotation_share < c.settle_rotation_share)
    return set(ResponseType::SettleDown,
               fmt("flew (%.0f take-offs); friction dissipated %.3g of the available energy, late rotational "
                   "share %.3g",
                   double(m.takeoffs), m.dissipated_fraction, m.late_rotation_share));
  if (m.late_flight_fraction < c.steady_flight_fraction)
    return set(ResponseType::SteadyRocking,
               fmt("late flight fraction %.3g < %.3g; energy above rest %.3g of E0 - E_rest", m.late_flight_fraction,
                   c.steady_flight_fraction, m.late_energy_fraction));
  if (m.early_rotation_share > 0 && m.late_rotation_share <= c.vertical_trend * m.early_rotation_share)
    return set(ResponseType::RockToVertical,
               fmt("flies late; rotational share of kinetic energy fell from %.3g to %.3g", m.early_rotation_share,
                   m.late_rotation_share));
  if (p.mu == 0)
    return set(ResponseType::ZeroFrictionRockFlight,
               fmt("mu = 0, flies late, rotational share %.3g -> %.3g (no trend to vertical)", m.early_rotation_share,
                   m.late_rotation_share));
  if (m.late_dissipated_fraction < c.conserved_dissipation)
    return set(ResponseType::RockToVertical,
               fmt("mu > 0, flies late, energy almost conserved late (dissipated %.3g of it); rotational share "
                   "ratio %.3g",
                   m.late_dissipated_fraction,
                   m.early_rotation_share > 0 ? m.late_rotation_share / m.early_rotation_share : 0.0));
  return set(ResponseType::Unclassified,
             fmt("mu > 0, flies late, dissipated %.3g, rotational share ratio %.3g", m.dissipated_fraction,
                 m.early_rotation_share > 0 ? m.late_rotation_share / m.early_rotation_share : 0.0));
}

ResponseRun run_response(const WinklerParams& p, const GroundMotion& g, const WinklerState& z0,
                         const ResponseOptions& o) {
  validate(o);
  SwingOptions so;
  so.quadrature_dt = o.quadrature_dt;
  so.phase_dt = o.phase_dt;
  so.late_start = o.late_fraction * o.t_end;
  SwingAccumulator acc(p, so);
  WinklerRunOptions sim;
  sim.t_end = o.t_end;
  sim.integrator = o.integrator;
  sim.record_events = false;
  ResponseRun run;
  run.result = simulate(p, g, z0, sim, &acc);
  run.report = classify(p, compute_metrics(p, run.result, acc, o.criteria), o.criteria);
  run.swings = acc.swings();
  run.phase = acc.phase();
  return run;
}

}  // namespace blockdyn
