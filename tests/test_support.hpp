// SPDX-License-Identifier: Apache-2.0
#pragma once
// Helpers shared by the validation tests: recording measured numbers in the test report,
// simulation options, simple initial states, and sampling the completed state along the dense
// output of an accepted step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>

#include "blockdyn/simulation/winkler_simulation.hpp"

namespace blockdyn::test {

// The message of the std::invalid_argument that f throws ("(no error)" if it throws none).
inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

// Measured numbers go to the test report (--gtest_output=json) for docs/validation.md.
inline void record(const char* key, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  ::testing::Test::RecordProperty(key, buf);
}

// "8" for rtol = 1e-8: the suffix of report keys measured at that tolerance.
inline std::string rtol_tag(double rtol) { return std::to_string(int(std::lround(-std::log10(rtol)))); }

// Default integrator settings, run up to t_end.
inline WinklerRunOptions sim_options(double t_end) {
  WinklerRunOptions o;
  o.t_end = t_end;
  return o;
}

// Run up to t_end at relative tolerance rtol (absolute tolerance rtol / 100).
inline WinklerRunOptions sim_options(double t_end, double rtol) {
  WinklerRunOptions o = sim_options(t_end);
  o.integrator.rtol = rtol;
  o.integrator.atol = rtol * 1e-2;
  return o;
}

// The upright block at rest with its base at height h (h < 0: submerged).
inline WinklerState upright_at_rest(double h) {
  WinklerState z{};
  z[kH] = h;
  return z;
}

// The completed state of a dense-output segment at time t.
inline WinklerState completed_state(const WinklerBlock& m, const DenseSegment<kStateDim>& seg, const WinklerMode& mode,
                                    double t) {
  WinklerState z;
  seg.eval(t, z);
  m.complete(mode, z);
  return z;
}

// Calls f(t, z) with the completed state z at t = t0 + (t1 - t0) j / n, j = first, ..., n.
template <class F>
void sample_segment(const WinklerBlock& m, const DenseSegment<kStateDim>& seg, double t0, double t1,
                    const WinklerMode& mode, int first, int n, F&& f) {
  for (int j = first; j <= n; ++j) {
    const double t = t0 + (t1 - t0) * j / double(n);
    f(t, completed_state(m, seg, mode, t));
  }
}

}  // namespace blockdyn::test
