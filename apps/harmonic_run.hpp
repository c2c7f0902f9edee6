// SPDX-License-Identifier: Apache-2.0
#pragma once
// One traced run of a forced model (apps/forced_model) under seed 002's harmonic motion
// a_H = beta alpha g cos(Omega t + phase), omega = Omega / p: the flags and validation shared by
// `cycles` and `impact-map`, the run with its ForcedTrace, and the CSV of sampled states.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <functional>
#include <memory>
#include <ostream>
#include <string>

#include "blockdyn/analysis/forced/forced_trace.hpp"
#include "forced_model.hpp"

namespace blockdyn::cli {

struct HarmonicRunFlags {
  ForcedModelFlags m;
  std::string excitation = "harmonic";
  double beta = 0, omega = 0, phase = 0;
  double t_end = 0, periods = 0;
  int block = 0;
  int trace_per_period = 32;
};

// --beta --omega --phase --excitation --t-end --periods --block --trace-per-period and the model
// flags; without --t-end or --periods a run lasts default_periods forcing periods.
void add_harmonic_run_flags(CLI::App& s, HarmonicRunFlags& f, double default_periods);

// The checked flags (UsageError naming the field), the model and the motion.
struct HarmonicSetup {
  ForcedModel fm;
  GroundMotion g;
  double beta = 0, omega = 0, phase = 0;
  double Omega = 0, period = 0, t_end = 0;
  int block = 0;
};
HarmonicSetup setup_harmonic(const CLI::App& s, const HarmonicRunFlags& f);

// The run from rest to t_end, sampled at t0 + T j / per_period.
struct HarmonicRun {
  SurvivalOutcome outcome;
  std::unique_ptr<ForcedTrace> trace;
};
HarmonicRun run_harmonic(const HarmonicSetup& h, double t0, int per_period);

// The sampled states as CSV: `k,t` (strobe_only: every per_period-th sample, k its period index)
// then x,y,theta,vx,vy,omega per block (suffix _b), then the columns of `extra_header` with
// extra(t) (may be empty); samples before t_from are left out.
void write_samples_csv(std::ostream& os, const ForcedTrace& tr, bool strobe_only, const std::string& extra_header = "",
                       const std::function<std::string(double)>& extra = {}, double t_from = -1.0);

// The fields every harmonic-run JSON carries: run, model, alpha, p, excitation, the block, the
// impact definition and the outcome (status, collapse_mode, t_failure, t_final).
void describe_run(nlohmann::ordered_json& j, const HarmonicSetup& h, const HarmonicRun& r);
// A figure title: model (preset), beta, omega, the block.
std::string run_title(const HarmonicSetup& h, const HarmonicRunFlags& f);
// %.6g
std::string short_num(double v);

}  // namespace blockdyn::cli
