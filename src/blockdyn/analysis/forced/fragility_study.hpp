// SPDX-License-Identifier: Apache-2.0
#pragma once
// A fragility study as a typed C++ call: every record of a suite scaled to every intensity level,
// one run of a forced model each (overturned or not), the fractions per level and the lognormal
// curve fitted by maximum likelihood with a bootstrap band over the records (fragility_fit.hpp).
//   FragilitySuite suite = fragility_suite(names, records, IntensityMeasure::pga(), g, alpha);
//   FragilityResult r = run_fragility(model, suite, {.levels = {0.1, 0.2, 0.3}});
// `blockdyn fragility` runs the same runs (fragility_run) on the sweep runner (threads, MPI,
// resume) and reduces them with fragility_result.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "blockdyn/analysis/forced/forced_model.hpp"
#include "blockdyn/analysis/forced/fragility_fit.hpp"
#include "blockdyn/excitation/accelerogram.hpp"

namespace blockdyn {

// What scales a record: its pga (g), pgv (m/s), Sa at a period (g) or its pga over the block's
// uplift acceleration g tan(alpha). Each scales linearly with the record.
struct IntensityMeasure {
  enum class Kind { Pga, Pgv, Sa, PgaOverUplift };
  Kind kind = Kind::Pga;
  double period = 0;      // Sa: T (s)
  double damping = 0.05;  // Sa: damping ratio
  std::string text;       // as given: "pga", "pgv", "sa:0.5", "pga-over-uplift"

  static IntensityMeasure pga() { return {Kind::Pga, 0, 0.05, "pga"}; }
};
// The record's measure at scale 1 (alpha: the block's slenderness, for pga-over-uplift).
double intensity_of(const Accelerogram& r, const IntensityMeasure& im, double g, double alpha);

// A suite's entries: records, or records of two or three components (h1 along the incidence, h2
// across it, v vertical), each at one or more incidences (a 3D body's: the angle of h1 from the
// body's e1). An entry's measure is its record's, or the geometric mean of its two horizontal
// components' (pga-over-uplift: with the entry's incidence's alpha).
struct FragilitySuite {
  std::vector<std::string> names;
  std::vector<std::shared_ptr<const Accelerogram>> records;
  std::vector<double> im;  // of each entry at scale 1
  // Components and incidences (empty: single records along the model's own direction).
  std::vector<std::shared_ptr<const Accelerogram>> records_h2, records_v;
  std::vector<double> incidence;             // deg, one per entry
  std::vector<std::size_t> incidence_index;  // the entry's incidence among the study's (0, 1, ...)
  bool three_dimensional() const { return !records_h2.empty() || !records_v.empty() || !incidence.empty(); }
};
// The suite with each record's measure; throws std::invalid_argument naming `field` and the
// record for a record whose measure is zero (it cannot be scaled to a level).
FragilitySuite fragility_suite(const std::vector<std::string>& names,
                               const std::vector<std::shared_ptr<const Accelerogram>>& records,
                               const IntensityMeasure& im, double g, double alpha,
                               const std::string& field = "records");

// The suite of records (h1, and h2 and v where given: the same length or empty) at every
// incidence (record fastest is not the order: entry = record * incidences + incidence index),
// `alpha_at` each incidence's slenderness angle (for pga-over-uplift). Throws
// std::invalid_argument naming `field`.
FragilitySuite fragility_suite_3d(const std::vector<std::string>& names,
                                  const std::vector<std::shared_ptr<const Accelerogram>>& h1,
                                  const std::vector<std::shared_ptr<const Accelerogram>>& h2,
                                  const std::vector<std::shared_ptr<const Accelerogram>>& v,
                                  const std::vector<double>& incidences, const std::vector<double>& alpha_at,
                                  const IntensityMeasure& im, double g, const std::string& field = "suite");

struct FragilityOptions {
  std::vector<double> levels;   // intensity levels (> 0)
  std::optional<double> t_end;  // every run's duration (s); else each record's end + t_after
  double t_after = 5;
  long bootstrap = 200;  // resamples of the records for the 90 % band (0: none)
  std::uint64_t seed = 1;
  int threads = 1;  // run_fragility's worker threads (0: all cores)
};
// Throws std::invalid_argument naming the option, its value and the allowed range.
void validate(const FragilityOptions& o);

// One run of the study, index i: level i % L of record i / L (level fastest).
struct FragilityRunOutcome {
  std::size_t record = 0;
  double level = 0, record_im = 0, scale = 0;
  bool overturned = false;
  bool invalid = false;  // the run left the model (it stopped where the model cannot go on)
  double max_abs_rotation = 0;
  std::optional<double> t_failure;
};
FragilityRunOutcome fragility_run(const ForcedModel& m, const FragilitySuite& s, const FragilityOptions& o,
                                  std::size_t i);

struct FragilityLevel {
  double im = 0;
  std::size_t n = 0, n_overturned = 0;  // the runs that stayed in the model, and of them overturned
  std::size_t n_outside_model = 0;      // the runs that left it: not in n, nor in the fit
};
// The fitted curve on 80 levels from lo / 2 to 1.5 hi (lo, hi: the study's levels), with the
// bootstrap's pointwise 90 % band where there is one.
struct FragilityCurvePoint {
  double im = 0, p = 0;
  std::optional<double> p05, p95;
};
struct FragilityResult {
  std::vector<FragilityRunOutcome> runs;  // in the order of their index
  std::vector<FragilityLevel> levels;
  FragilityFit fit;
  FragilityBand band;
  std::vector<FragilityCurvePoint> curve;
};
// The study's result from its runs (any order of computation; `runs` indexed as fragility_run).
FragilityResult fragility_result(std::vector<FragilityRunOutcome> runs, const FragilitySuite& s,
                                 const FragilityOptions& o);
// The study's result restricted to the entries at incidence index j (their runs, re-indexed).
FragilityResult fragility_result_at_incidence(const std::vector<FragilityRunOutcome>& runs, const FragilitySuite& s,
                                              const FragilityOptions& o, std::size_t j);
// Every run in memory (o.threads), then fragility_result: the same numbers as the command.
FragilityResult run_fragility(const ForcedModel& m, const FragilitySuite& s, const FragilityOptions& o);

}  // namespace blockdyn
