// SPDX-License-Identifier: Apache-2.0
#pragma once
// A test model of the event machinery: x'' = a(x) with one event function, g = c - x (mode 0) then
// x - c (mode 1), so every crossing of x = c is an event and each restarts the function at zero.
// With `Rates` the model also gives the event's rate (exact), else the integrator differences.
#include <array>
#include <optional>

#include "blockdyn/integrate/hybrid_integrator.hpp"

namespace threshold_test {

using blockdyn::Transition;
using blockdyn::Vec;

template <class Accel, bool Rates = false>
struct ThresholdCrossing {
  static constexpr std::size_t kDim = 2;
  static constexpr std::size_t kNumEvents = 1;
  using Mode = int;
  using State = Vec<2>;
  double c;
  double hint = 0.5;
  void rhs(double, const Mode&, const State& z, State& dz) const {
    dz[0] = z[1];
    dz[1] = Accel{}(z[0]);
  }
  void events(double, const Mode& m, const State& z, std::array<double, 1>& g) const {
    g[0] = m == 0 ? c - z[0] : z[0] - c;  // mode 1: back below c
  }
  void event_rates(double t, const Mode& m, const State& z, const State& dz, std::array<double, 1>& g,
                   std::array<double, 1>& gd) const requires Rates {
    events(t, m, z, g);
    gd[0] = m == 0 ? -dz[0] : dz[0];
  }
  void complete(const Mode&, State&) const {}
  Transition<Mode> transition(double, const Mode& m, const State&, int) const { return {1 - m, false, m}; }
  std::optional<Transition<Mode>> resolve_chatter(double, const Mode&, const State&) const { return std::nullopt; }
  double step_hint(const Mode&) const { return hint; }
  State abs_tol_scale() const { return {1.0, 1.0}; }
};

struct Harmonic {  // x'' = -x: x = A sin t
  double operator()(double x) const { return -x; }
};
struct Gravity {  // x'' = -1: a thrown stone, a polynomial path
  double operator()(double) const { return -1.0; }
};

}  // namespace threshold_test
