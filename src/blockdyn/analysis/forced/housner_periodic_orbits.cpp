// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/housner_periodic_orbits.hpp"

#include "blockdyn/base/angles.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "blockdyn/analysis/dynamics/tangent_lyapunov.hpp"
#include "blockdyn/analysis/forced/block_tangent_traits.hpp"
#include "blockdyn/analysis/forced/linear_rocking_orbits.hpp"
#include "blockdyn/model/rigid_ground/housner_block.hpp"
#include "blockdyn/simulation/simulation.hpp"

namespace blockdyn {

double RockingForcing::e() const { return restitution >= 0 ? restitution : shape.housner_restitution(); }

void validate(const RockingForcing& f) {
  validate(f.shape);
  if (!(f.restitution < 0 || f.restitution <= 1)) throw std::invalid_argument("restitution must be in [0, 1]");
  if (f.restitution < 0) housner_coefficient(f.shape, std::nullopt);  // Housner's own must be >= 0
  if (!(f.ks > 0 && f.ks <= kMaxGroundAcceleration)) throw std::invalid_argument("ks must be in (0, 1000] (g)");
  if (!(f.omega > 0 && f.omega * f.p() / (2 * M_PI) <= kMaxGroundFrequency))
    throw std::invalid_argument("omega must be > 0 (and Omega / 2 pi <= 1e4 Hz)");
}

void validate(const OrbitType& t) {
  if (t.m < 1 || t.m > 50 || t.n < 1 || t.n > 50)
    throw std::invalid_argument("cycle (m, n): m and n must be in [1, 50]");
  if (t.symmetric && (t.m % 2 == 0 || t.n % 2 == 0))
    throw std::invalid_argument("cycle (m, n): a symmetric orbit needs m and n odd");
}

namespace {

HousnerBlock make_block(const RockingForcing& f) {
  GroundMotion g;
  g.horizontal.amplitude = f.ks;
  g.horizontal.frequency = f.Omega() / kTwoPi;
  g.horizontal.phase = 0.0;
  return HousnerBlock(f.shape, f.e(), g);
}

struct PassObserver final : Observer<HousnerBlock> {
  PassObserver(int n, double start, std::vector<OrbitImpact>* out) : wanted(n), t0(start), impacts(out) {}
  int wanted;
  double t0;
  std::vector<OrbitImpact>* impacts;
  double max_abs = 0;
  std::string failure;
  bool on_segment(const HousnerBlock&, const Segment& seg, double a, double b, const HousnerMode&) override {
    HousnerBlock::State y;
    for (int k = 1; k <= 8; ++k) {
      seg.eval(a + (b - a) * k / 8.0, y);
      max_abs = std::fmax(max_abs, std::fabs(y[HousnerBlock::kTheta]));
    }
    return true;
  }
  bool on_event(const HousnerBlock&, const Event& e) override {
    if (e.stop) {
      failure = e.kind == int(RigidEventKind::Overturn) ? "overturn" : "outside the model";
      return false;
    }
    if (e.index != HousnerBlock::kEvImpact) return true;
    if (e.to.mech == Mechanism::Rest) {
      failure = "the block comes to rest";
      return false;
    }
    impacts->push_back({e.t - t0, 0.0, e.z_before[HousnerBlock::kOmega], e.z[HousnerBlock::kOmega]});
    return int(impacts->size()) < wanted;
  }
};

std::array<std::complex<double>, 2> eig_of(const std::array<double, 4>& a) {
  return eigenvalues2(a[0], a[1], a[2], a[3]);
}

double max_modulus(const std::array<std::complex<double>, 2>& mu) {
  return std::fmax(std::abs(mu[0]), std::abs(mu[1]));
}

}  // namespace

ImpactMapPass impact_map_pass(const RockingForcing& f, const OrbitType& type, double psi, double u,
                              const IntegratorOptions& integ) {
  ImpactMapPass out;
  if (!(u > 0) || !std::isfinite(u) || !std::isfinite(psi)) {
    out.failure = "the rate after the impact must be > 0";
    return out;
  }
  const HousnerBlock model = make_block(f);
  const double Om = f.Omega(), ap = f.alpha() * f.p();
  const double t0 = wrap_angle(psi) / Om;
  HousnerBlock::State z{0.0, u * ap, 0.0, 0.0};
  HousnerMode md{Mechanism::Rock, 1, false};
  const int wanted = type.symmetric ? type.m : 2 * type.m;
  PassObserver obs(wanted, t0, &out.impacts);
  Simulation<HousnerBlock> sim(model, integ, t0, md, z);
  const double t_limit = t0 + (type.n + 2) * kTwoPi / Om;
  const RunStatus st = sim.advance(t_limit, obs);
  out.max_abs_rotation = obs.max_abs;
  if (int(out.impacts.size()) < wanted) {
    out.failure = !obs.failure.empty()          ? obs.failure
                  : st == RunStatus::ReachedEnd ? "fewer impacts than the cycle needs within n + 2 periods"
                                                : std::string("integration stopped: ") + to_string(st);
    return out;
  }
  for (auto& i : out.impacts) i.phase = wrap_angle(psi + Om * i.t);
  const OrbitImpact& last = out.impacts.back();
  const double dpsi = Om * last.t;
  if (type.symmetric) {
    out.image = {psi + dpsi - M_PI * type.n, -last.rate_after / ap};
  } else {
    out.image = {psi + dpsi - kTwoPi * type.n, last.rate_after / ap};
  }
  out.residual = {out.image[0] - psi, out.image[1] - u};
  out.ok = true;
  return out;
}

namespace {

// Central-difference Jacobian of the residual; false when a pass fails.
bool shooting_jacobian(const RockingForcing& f, const OrbitType& type, double psi, double u, const ShootingOptions& o,
                       std::array<double, 4>& J) {
  const double h = o.fd_step;
  for (int j = 0; j < 2; ++j) {
    const double dp = j == 0 ? h : 0.0, du = j == 1 ? h : 0.0;
    const ImpactMapPass a = impact_map_pass(f, type, psi + dp, u + du, o.integrator);
    const ImpactMapPass b = impact_map_pass(f, type, psi - dp, u - du, o.integrator);
    if (!a.ok || !b.ok || a.impacts.size() != b.impacts.size()) return false;
    J[0 + j] = (a.residual[0] - b.residual[0]) / (2 * h);
    J[2 + j] = (a.residual[1] - b.residual[1]) / (2 * h);
  }
  return true;
}

}  // namespace

void orbit_monodromy(const RockingForcing& f, const OrbitType& type, PeriodicOrbit& orbit,
                     const IntegratorOptions& integ) {
  const HousnerBlock model = make_block(f);
  const double Om = f.Omega(), p = f.p();
  const double t0 = orbit.phase / Om;
  HousnerBlock::State z{0.0, orbit.velocity * f.alpha() * p, 0.0, 0.0};
  HousnerMode md{Mechanism::Rock, 1, false};
  // Base point half-way to the first impact (the stroboscopic map is smooth there).
  const double t_mid = t0 + 0.5 * orbit.impacts.front().t;
  Observer<HousnerBlock> quiet;
  Simulation<HousnerBlock> sim(model, integ, t0, md, z);
  if (sim.advance(t_mid, quiet) != RunStatus::ReachedEnd) return;
  md = sim.mode();
  z = sim.state();
  std::array<HousnerBlock::State, 2> dirs{};
  dirs[0][HousnerBlock::kTheta] = 1.0;
  dirs[1][HousnerBlock::kOmega] = p;
  const auto tm = tangent_map<HousnerBlock, 2>(model, md, z, t_mid, t_mid + orbit.period, dirs, integ);
  if (tm.status != RunStatus::ReachedEnd) return;
  orbit.monodromy = {tm.v[0][HousnerBlock::kTheta], tm.v[1][HousnerBlock::kTheta], tm.v[0][HousnerBlock::kOmega] / p,
                     tm.v[1][HousnerBlock::kOmega] / p};
  orbit.multipliers = eig_of(orbit.monodromy);
}

PeriodicOrbit find_periodic_orbit(const RockingForcing& f, const OrbitType& type, double psi0, double u0,
                                  const ShootingOptions& o) {
  validate(f);
  validate(type);
  PeriodicOrbit orb;
  orb.period = type.n * kTwoPi / f.Omega();
  double psi = psi0, u = u0;
  ImpactMapPass pass = impact_map_pass(f, type, psi, u, o.integrator);
  if (!pass.ok) {
    orb.failure = "at the guess: " + pass.failure;
    return orb;
  }
  auto norm = [](const std::array<double, 2>& r) { return std::hypot(r[0], r[1]); };
  double rn = norm(pass.residual);
  std::array<double, 4> J{};
  for (orb.iterations = 0; orb.iterations < o.max_iterations && rn > o.tol; ++orb.iterations) {
    if (!shooting_jacobian(f, type, psi, u, o, J)) {
      orb.failure = "the impact sequence changes next to the iterate (grazing)";
      return orb;
    }
    const double det = J[0] * J[3] - J[1] * J[2];
    if (!(std::fabs(det) > 0) || !std::isfinite(det)) {
      orb.failure = "singular shooting Jacobian";
      return orb;
    }
    const double dpsi = -(J[3] * pass.residual[0] - J[1] * pass.residual[1]) / det;
    const double du = -(-J[2] * pass.residual[0] + J[0] * pass.residual[1]) / det;
    bool accepted = false;
    for (double lam = 1.0; lam > 1e-3; lam *= 0.5) {
      // Keep the step modest and u positive.
      const double s = std::fmin(
          lam, std::fmin(1.0 / std::fmax(1e-300, std::fabs(dpsi)), 0.5 * u / std::fmax(1e-300, std::fabs(du))));
      const ImpactMapPass trial = impact_map_pass(f, type, psi + s * dpsi, u + s * du, o.integrator);
      if (trial.ok && norm(trial.residual) < rn) {
        psi += s * dpsi;
        u += s * du;
        pass = trial;
        rn = norm(trial.residual);
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      orb.failure = "Newton made no progress";
      orb.residual = rn;
      return orb;
    }
  }
  orb.residual = rn;
  if (rn > o.tol) {
    orb.failure = "no convergence in " + std::to_string(o.max_iterations) + " iterations";
    return orb;
  }
  if (!shooting_jacobian(f, type, psi, u, o, J)) {
    orb.failure = "the impact sequence changes next to the orbit (grazing)";
    return orb;
  }
  orb.converged = true;
  orb.phase = wrap_angle(psi);
  orb.velocity = u;
  orb.max_abs_rotation = pass.max_abs_rotation;
  orb.impacts = pass.impacts;
  if (type.symmetric) {
    // The second half: the mirror image, n / 2 periods later.
    const std::size_t half = orb.impacts.size();
    for (std::size_t k = 0; k < half; ++k) {
      OrbitImpact i = orb.impacts[k];
      i.t += 0.5 * orb.period;
      i.phase = wrap_angle(i.phase + M_PI * type.n);
      i.rate_before = -i.rate_before;
      i.rate_after = -i.rate_after;
      orb.impacts.push_back(i);
    }
  }
  orb.jacobian = {J[0] + 1, J[1], J[2], J[3] + 1};
  const auto mu = eig_of(orb.jacobian);
  if (type.symmetric) {
    orb.half_multipliers = mu;
    for (int k = 0; k < 2; ++k) orb.multipliers_fd[k] = mu[k] * mu[k];
  } else {
    orb.multipliers_fd = mu;
  }
  orbit_monodromy(f, type, orb, o.integrator);
  if (orb.multipliers[0] == std::complex<double>() && orb.multipliers[1] == std::complex<double>())
    orb.multipliers = orb.multipliers_fd;
  const double mx = max_modulus(orb.multipliers);
  orb.stable = mx < 1.0;
  orb.lyapunov_exponent = std::log(mx) / orb.period;
  return orb;
}

std::vector<std::array<double, 2>> orbit_guesses(const RockingForcing& f, const OrbitType& type,
                                                 const IntegratorOptions& integ, double settle_periods) {
  validate(f);
  validate(type);
  std::vector<std::array<double, 2>> g;
  if (type.symmetric && type.m == 1) {
    for (const auto& l : linear_symmetric_orbits(f.ks / f.alpha(), f.omega, f.e(), type.n))
      if (l.velocity > 0) g.push_back({l.phase, l.velocity});
    return g;
  }
  // Runs from rest, started at four phases of the forcing: the impact onto theta > 0 after the
  // transient.
  const HousnerBlock model = make_block(f);
  const double Om = f.Omega(), T = kTwoPi / Om, ap = f.alpha() * f.p();
  for (int k = 0; k < 4; ++k) {
    const double t0 = 0.25 * k * T;
    HousnerBlock::State z{0.0, 0.0, 0.0, 0.0};
    HousnerMode md = model.initial_mode(t0, z);
    if (md.mech == Mechanism::Rest) {
      z[HousnerBlock::kOmega] = 0.5 * ap;
      md = model.initial_mode(t0, z);
    }
    struct Last final : Observer<HousnerBlock> {
      explicit Last(double from) : t_from(from) {}
      double t_from;
      double t = -1, rate = 0;
      bool on_event(const HousnerBlock&, const Event& e) override {
        if (e.stop) return false;
        if (e.index == HousnerBlock::kEvImpact && e.t >= t_from && e.z[HousnerBlock::kOmega] > 0) {
          t = e.t;
          rate = e.z[HousnerBlock::kOmega];
          return false;
        }
        return true;
      }
    } last(t0 + settle_periods * T);
    Simulation<HousnerBlock> sim(model, integ, t0, md, z);
    sim.advance(t0 + (settle_periods + 2.0 * type.n + 2) * T, last);
    if (last.t >= 0) g.push_back({wrap_angle(Om * last.t), last.rate / ap});
  }
  return g;
}

std::vector<PeriodicOrbit> find_periodic_orbits(const RockingForcing& f, const OrbitType& type,
                                                const std::vector<std::array<double, 2>>& guesses,
                                                const ShootingOptions& o) {
  std::vector<PeriodicOrbit> out;
  auto same = [&](const PeriodicOrbit& a, const PeriodicOrbit& b) {
    // The same orbit may be found from any of its impacts onto theta > 0.
    for (const auto& i : b.impacts) {
      if (!(i.rate_after > 0)) continue;
      const double u = i.rate_after / (f.alpha() * f.p());
      double d = std::fabs(wrap_angle(i.phase) - a.phase);
      d = std::fmin(d, kTwoPi - d);
      if (d < 1e-6 && std::fabs(u - a.velocity) < 1e-6 * std::fmax(1.0, a.velocity)) return true;
    }
    return false;
  };
  for (const auto& g : guesses) {
    PeriodicOrbit orb = find_periodic_orbit(f, type, g[0], g[1], o);
    if (!orb.converged) continue;
    bool dup = false;
    for (const auto& x : out) dup = dup || same(orb, x) || same(x, orb);
    if (!dup) out.push_back(orb);
  }
  std::sort(out.begin(), out.end(),
            [](const PeriodicOrbit& a, const PeriodicOrbit& b) { return a.velocity < b.velocity; });
  return out;
}

}  // namespace blockdyn
