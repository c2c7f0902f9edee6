// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/simulation/rigid_simulation.hpp"

#include "blockdyn/base/number_text.hpp"

#include <cmath>
#include <stdexcept>

#include "blockdyn/base/checks.hpp"
#include "blockdyn/simulation/rigid_recorder.hpp"
#include "blockdyn/simulation/run.hpp"

namespace blockdyn {

HousnerBlock::State housner_initial_state(const HousnerBlock& m, const RigidInitial& in) {
  const char* extra = in.x0 ? "x0" : in.y0 ? "y0" : in.vx0 ? "vx0" : in.vy0 ? "vy0" : nullptr;
  if (extra)
    throw std::invalid_argument(std::string(extra) +
                                " is not a state of the housner model (only w0, vw0; use `model` rigid)");
  require(std::isfinite(in.w0), "w0", "finite", in.w0);
  require(std::isfinite(in.vw0), "vw0", "finite", in.vw0);
  HousnerBlock::State z{in.w0, in.vw0, 0.0, 0.0};
  if (auto why = m.validity_problem(z)) throw std::invalid_argument("initial state: " + *why);
  return z;
}

RigidBlock::State rigid_initial_state(const RigidBlock& m, const RigidInitial& in) {
  for (auto [name, v] : {std::pair{"x0", in.x0}, {"y0", in.y0}, {"vx0", in.vx0}, {"vy0", in.vy0}})
    if (v) require(std::isfinite(*v), name, "finite", *v);
  require(std::isfinite(in.w0), "w0", "finite", in.w0);
  require(std::isfinite(in.vw0), "vw0", "finite", in.vw0);
  const BlockShape& s = m.shape();
  const double bh = 0.5 * s.width, hh = 0.5 * s.height, th = in.w0;
  RigidBlock::State z{};
  z[RigidBlock::kTheta] = th;
  z[RigidBlock::kOmega] = in.vw0;
  z[RigidBlock::kX] = in.x0.value_or(0.0);
  // Standing on its lowest base corner unless y0 says otherwise.
  const double stand = hh * std::cos(th) + bh * std::fabs(std::sin(th));
  z[RigidBlock::kY] = in.y0.value_or(stand);
  if (!in.vx0 && !in.vy0 && std::fabs(z[RigidBlock::kY] - stand) <= 1e-12 * s.height) {
    // Rotating about the corner on the ground (at theta = 0: the one it turns onto).
    int side = th > 0 ? 1 : th < 0 ? -1 : (in.vw0 >= 0 ? 1 : -1);
    const Vec2 r = base_corner(BodyRotation::of(th), bh, hh, side);
    z[RigidBlock::kVX] = in.vw0 * r.y;
    z[RigidBlock::kVY] = -in.vw0 * r.x;
  } else {
    z[RigidBlock::kVX] = in.vx0.value_or(0.0);
    z[RigidBlock::kVY] = in.vy0.value_or(0.0);
  }
  if (auto why = m.validity_problem(z)) throw std::invalid_argument("initial state: " + *why);
  return z;
}

namespace {

template <class Model>
void finish(const Model& m, const RunOutcome<Model>& out, const EnergyBalance<Model>& bal, bool tracked,
            RigidResult& res) {
  using M = Model;
  res.run_status = out.status;
  res.t_final = out.t;
  res.final_mode = m.mechanism(out.mode);
  res.final_state = m.pose(out.mode, out.z);
  res.stats = out.stats;
  res.kinetic_final = m.kinetic_energy(out.z);
  res.potential_final = m.energy(out.mode, out.z) - res.kinetic_final;
  res.work_ground = out.z[M::kWorkGround];
  res.work_impact = out.z[M::kWorkImpact];
  if constexpr (requires { M::kWorkFriction; }) res.work_friction = out.z[M::kWorkFriction];
  if (tracked) {
    res.max_abs_energy_error = bal.max_abs_error();
    res.max_abs_energy_change = bal.max_abs_change();
  }
  res.status = sim_status(out.status, res.overturn_time.has_value());
  if (res.event_counts[int(RigidEventKind::Painleve)] > 0 || (out.status == RunStatus::ModelStop && !res.overturn_time))
    res.status = SimStatus::Invalid;
  if (res.event_counts[int(RigidEventKind::Painleve)] > 0)
    res.note = "Painleve: no unique consistent mechanism (or impulse) at t = " + number_text(out.t, 6) +
               " s; the rigid model with this friction and slenderness has no unique motion";
  else if (res.status == SimStatus::Invalid)
    res.note =
        "the state left the model at t = " + number_text(out.t, 6) + " s (e.g. vertical ground acceleration above g)";
}

template <class Model>
RigidResult run_rigid_family(const Model& m, typename Model::Mode mode, typename Model::State z,
                             const RigidRunOptions& opt, Observer<Model>* extra, RigidEventSink* events,
                             const char* name) {
  RigidResult res;
  res.model = name;
  res.t_start = opt.t_start;
  m.complete(mode, z);
  res.initial_mode = m.mechanism(mode);
  res.initial_state = m.pose(mode, z);
  res.energy_initial = m.energy(mode, z);
  RigidRecorder<Model> rec(opt.record_events, res, events);
  EnergyBalance<Model> bal;
  FanOut<Model> obs;
  obs.add(&rec);
  if (opt.track_energy) obs.add(&bal);
  obs.add(extra);
  const RunClock clock;
  const RunOutcome<Model> out = run_model(m, mode, z, opt.t_start, opt.t_end, opt.integrator, obs);
  res.timing = clock.elapsed();
  finish(m, out, bal, opt.track_energy, res);
  return res;
}

}  // namespace

RigidResult simulate_housner(const BlockShape& shape, std::optional<double> restitution, const GroundMotion& g,
                             const RigidInitial& init, const RigidRunOptions& opt, Observer<HousnerBlock>* extra,
                             RigidEventSink* events) {
  validate(shape);
  const double e = housner_coefficient(shape, restitution);
  validate(g);
  validate(opt);
  const HousnerBlock m(shape, e, g);
  const HousnerBlock::State z = housner_initial_state(m, init);
  return run_rigid_family(m, m.initial_mode(opt.t_start, z), z, opt, extra, events, "housner");
}

RigidResult simulate_rigid(const RigidBlockParams& p, const GroundMotion& g, const RigidInitial& init,
                           const RigidRunOptions& opt, Observer<RigidBlock>* extra, RigidEventSink* events) {
  validate(p);
  validate(g);
  validate(opt);
  const RigidBlock m(p, g);
  RigidBlock::State z = rigid_initial_state(m, init);
  const auto mode = m.initial_mode(opt.t_start, z);
  if (!mode)
    throw std::invalid_argument("initial state: no unique consistent mechanism (Painleve's paradox for mu-k = " +
                                number_text(p.interface.mu_k, 6) + " and this slenderness)");
  return run_rigid_family(m, *mode, z, opt, extra, events, "rigid");
}

}  // namespace blockdyn
