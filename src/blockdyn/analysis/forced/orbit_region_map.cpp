// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/orbit_region_map.hpp"

#include <cmath>
#include <stdexcept>

#include "blockdyn/analysis/forced/linear_rocking_orbits.hpp"
#include "blockdyn/analysis/sweep/parallel_map.hpp"
#include "blockdyn/model/rigid_ground/housner_block.hpp"
#include "blockdyn/simulation/simulation.hpp"

namespace blockdyn {

void validate(const OrbitRegionOptions& o) {
  if (!(o.ks_min > 0 && o.ks_max >= o.ks_min && o.ks_max <= kMaxGroundAcceleration))
    throw std::invalid_argument("ks-min, ks-max: need 0 < min <= max <= 1000 (g)");
  if (!(o.omega_min > 0 && o.omega_max >= o.omega_min && o.omega_max <= 1e4))
    throw std::invalid_argument("omega-min, omega-max: need 0 < min <= max <= 1e4");
  if (!(o.ks_points >= 1 && o.omega_points >= 1 && double(o.ks_points) * o.omega_points <= 1e6))
    throw std::invalid_argument("ks-points, omega-points: at least 1 each, at most 1e6 points");
}

std::vector<OrbitRegionPoint> orbit_region_map(const RockingForcing& base, const OrbitType& type,
                                               const OrbitRegionOptions& o,
                                               const std::function<void(std::size_t)>& progress) {
  validate(o);
  validate(type);
  auto axis = [](double lo, double hi, int n, int i) { return n == 1 ? lo : lo + (hi - lo) * i / (n - 1); };
  std::vector<OrbitRegionPoint> pts(std::size_t(o.ks_points) * o.omega_points);
  std::size_t done = 0;
  parallel_for(
      std::size_t(o.omega_points), o.threads,
      [&](std::size_t wi) {
        std::vector<std::array<double, 2>> carried;
        for (int ki = 0; ki < o.ks_points; ++ki) {
          OrbitRegionPoint& pt = pts[std::size_t(ki) * o.omega_points + wi];
          RockingForcing f = base;
          f.ks = pt.ks = axis(o.ks_min, o.ks_max, o.ks_points, ki);
          f.omega = pt.omega = axis(o.omega_min, o.omega_max, o.omega_points, int(wi));
          std::vector<std::array<double, 2>> guesses = orbit_guesses(f, type, o.shooting.integrator);
          guesses.insert(guesses.end(), carried.begin(), carried.end());
          const auto found = find_periodic_orbits(f, type, guesses, o.shooting);
          carried.clear();
          pt.orbits = int(found.size());
          for (const auto& orb : found) {
            carried.push_back({orb.phase, orb.velocity});
            const double mx = std::fmax(std::abs(orb.multipliers[0]), std::abs(orb.multipliers[1]));
            pt.stable += orb.stable;
            if (!(mx >= pt.max_multiplier)) {
              pt.max_multiplier = mx;
              pt.phase = orb.phase;
              pt.velocity = orb.velocity;
            }
          }
          if (type.symmetric && type.m == 1) {
            pt.linear_orbits = pt.linear_stable = 0;
            for (const auto& l : linear_symmetric_orbits(f.ks / f.alpha(), f.omega, f.e(), type.n)) {
              if (!l.valid) continue;
              ++pt.linear_orbits;
              pt.linear_stable += std::abs(l.multipliers[0]) < 1 && std::abs(l.multipliers[1]) < 1;
            }
          }
        }
      },
      [&](std::size_t) {
        done += std::size_t(o.ks_points);
        if (progress) progress(done);
      });
  return pts;
}

OrbitSamples orbit_trajectory(const RockingForcing& f, const PeriodicOrbit& orbit, const IntegratorOptions& integ,
                              int samples) {
  OrbitSamples out;
  if (!orbit.converged || samples < 2) return out;
  GroundMotion g;
  g.horizontal.amplitude = f.ks;
  g.horizontal.frequency = f.Omega() / (2 * M_PI);
  const HousnerBlock m(f.shape, f.e(), g);
  const double t0 = orbit.phase / f.Omega();
  HousnerBlock::State z{0.0, orbit.velocity * f.alpha() * f.p(), 0.0, 0.0};
  HousnerMode md{Mechanism::Rock, 1, false};
  struct Sampler final : Observer<HousnerBlock> {
    Sampler(double start, double step, int count, OrbitSamples* o) : t0(start), dt(step), n(count), out(o) {}
    double t0, dt;
    int n;
    OrbitSamples* out;
    int next = 0;
    bool on_segment(const HousnerBlock&, const Segment& seg, double a, double b, const HousnerMode&) override {
      HousnerBlock::State y;
      while (next < n && t0 + next * dt <= b) {
        const double t = t0 + next * dt;
        if (t >= a) {
          seg.eval(t, y);
          out->t.push_back(t - t0);
          out->theta.push_back(y[HousnerBlock::kTheta]);
          out->rate.push_back(y[HousnerBlock::kOmega]);
        }
        ++next;
      }
      return true;
    }
  } s(t0, orbit.period / (samples - 1), samples, &out);
  Simulation<HousnerBlock> sim(m, integ, t0, md, z);
  sim.advance(t0 + orbit.period * (1 + 1e-12), s);
  return out;
}

}  // namespace blockdyn
