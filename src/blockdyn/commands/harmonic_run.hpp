// SPDX-License-Identifier: Apache-2.0
#pragma once
// One traced run of a forced model under seed 002's harmonic motion a_H = beta alpha g cos(Omega t
// + phase), omega = Omega / p: the options the cycle and impact-map studies share (the model's and
// the run's), the run with its ForcedTrace, the CSV of sampled states, the summary's common part.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "blockdyn/analysis/forced/forced_model.hpp"
#include "blockdyn/analysis/forced/forced_trace.hpp"
#include "blockdyn/commands/study_command.hpp"

namespace blockdyn {

// --model --width --height --mass --g --mu-s --mu-k --impact --restitution --preset --contact
// --slenderness --block-width --drums --phi-s --phi-l --columns-rock-only (api/forced_model_settings);
// extra_models: further --model values the study handles itself.
std::vector<StudyOption> forced_model_options(const std::vector<std::string>& extra_models = {});
// The model the options given describe.
ForcedModel forced_model_of(const StudyOptions& o);
// The model's name and preset ("assembly trilith").
std::string forced_model_label(const StudyOptions& o);

// --excitation --beta --omega --phase --t-end --periods --block --trace-per-period and the model's;
// without --t-end or --periods a run lasts default_periods forcing periods.
std::vector<StudyOption> harmonic_run_options(double default_periods);

struct HarmonicSetup {
  ForcedModel fm;
  GroundMotion g;
  double beta = 0, omega = 0, phase = 0;
  double Omega = 0, period = 0, t_end = 0;
  int block = 0, trace_per_period = 32;
  std::string title;  // for figures: model (preset), beta, omega, phase, the block
};
// Throws std::invalid_argument naming the option.
HarmonicSetup harmonic_setup(const StudyOptions& o);

// The run from rest to t_end, sampled at t0 + T j / per_period.
struct HarmonicRun {
  SurvivalOutcome outcome;
  std::unique_ptr<ForcedTrace> trace;
};
HarmonicRun run_harmonic(const HarmonicSetup& h, double t0, int per_period);

// The sampled states as a table: `k,t` (strobe_only: every per_period-th sample, k its period
// index) then x,y,theta,vx,vy,omega per block (suffix _b), then a label column `extra_column`
// with extra(t); samples before t_from are left out.
CellTable samples_table(const ForcedTrace& tr, bool strobe_only, const std::string& extra_column = "",
                        const std::function<Cell(double)>& extra = {}, double t_from = -1.0);

// The opening of a forced analysis's summary: run (program, version), model, alpha, p.
nlohmann::ordered_json forced_summary_head(const ForcedModel& fm);
// The fields every harmonic-run summary carries: run, model, alpha, p, excitation, the block, the
// impact definition and the outcome (status, collapse_mode, t_failure, t_final).
void describe_run(nlohmann::ordered_json& j, const HarmonicSetup& h, const HarmonicRun& r);
std::string short_num(double v);  // %.6g

}  // namespace blockdyn
