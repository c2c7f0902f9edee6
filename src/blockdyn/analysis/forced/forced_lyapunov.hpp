// SPDX-License-Identifier: Apache-2.0
#pragma once
// Largest Lyapunov exponent of a forced block or assembly (issue 9, item 6): the orbit from its
// initial state through a transient, then the variational equation with saltation matrices at
// every impact and mode switch, renormalised every `interval` (analysis/dynamics/tangent_lyapunov.hpp).
// Optionally two nearby orbits as well (sensitive dependence): the reference and a copy whose
// rotation rate differs by twin_d0 (metric units) at the start of the measurement, both
// integrated together (PairModel), their separation sampled every interval.
//
// Supported: the Housner block, the rigid 3-DOF block (both impact laws) and assemblies with the
// deformable contact law. Not supported: assemblies with rigid contacts (Moreau-Jean
// time-stepping: no event-located orbit, hence no variational equation).
#include <optional>
#include <string>
#include <vector>

#include "blockdyn/analysis/dynamics/tangent_lyapunov.hpp"
#include "blockdyn/excitation/ground_motion.hpp"
#include "blockdyn/model/assembly/assembly_params.hpp"
#include "blockdyn/model/rigid_ground/rigid_params.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"

namespace blockdyn {

struct ForcedLyapunovOptions {
  double t_end = 100;      // s
  double t_transient = 0;  // s: the tangent starts here, or at the first motion after it
  double interval = 1;     // s: renormalisation (and twin sampling) interval
  IntegratorOptions integrator{1e-10, 1e-12};
  double twin_d0 = 0;  // > 0: also the two nearby orbits, this far apart (metric units)
  bool keep_history = true;
};
void validate(const ForcedLyapunovOptions& o);

struct TwinSample {
  double t = 0, separation = 0;  // metric units (rad, rate / p, ...)
};

struct ForcedLyapunovOutcome {
  TangentLyapunovResult tangent;      // exponent (1/s), status, history, saltation statistics
  double exponent_second_half = NAN;  // growth after the middle of the measured window only
  long impacts = 0;                   // rigid family: impacts from t = 0 (assembly: contact closings)
  bool moved = false;                 // the orbit left rest at some time
  std::optional<int> collapse_mode;   // 1: overturn / rotation limit, 2: loss of bearing
  std::optional<double> t_failure;
  std::string metric;            // what the separation is measured on
  std::vector<TwinSample> twin;  // (t, separation), from the tangent's start
  std::string twin_note;         // why the twin run stopped early, if it did
};

ForcedLyapunovOutcome housner_lyapunov(const BlockShape& shape, std::optional<double> restitution,
                                       const GroundMotion& g, const RigidInitial& init, const ForcedLyapunovOptions& o);
ForcedLyapunovOutcome rigid_lyapunov(const RigidBlockParams& p, const GroundMotion& g, const RigidInitial& init,
                                     const ForcedLyapunovOptions& o);
// Assemblies start from their own initial state (at rest, as built); deformable contacts only.
ForcedLyapunovOutcome assembly_lyapunov(const Assembly& a, const GroundMotion& g, const ForcedLyapunovOptions& o);

}  // namespace blockdyn
