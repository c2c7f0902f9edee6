// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/fragility_study.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "blockdyn/analysis/sweep/parallel_map.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/excitation/intensity_measures.hpp"
#include "blockdyn/excitation/response_spectrum.hpp"

namespace blockdyn {

double intensity_of(const Accelerogram& r, const IntensityMeasure& im, double g, double alpha) {
  switch (im.kind) {
    case IntensityMeasure::Kind::Pga:
      return r.peak();
    case IntensityMeasure::Kind::PgaOverUplift:
      return r.peak() / std::tan(alpha);
    case IntensityMeasure::Kind::Pgv:
      return intensity_measures(r, g).pgv;
    case IntensityMeasure::Kind::Sa:
      break;
  }
  return spectral_ordinate(r, im.period, im.damping, g).sa;
}

FragilitySuite fragility_suite(const std::vector<std::string>& names,
                               const std::vector<std::shared_ptr<const Accelerogram>>& records,
                               const IntensityMeasure& im, double g, double alpha, const std::string& field) {
  if (names.size() != records.size()) throw std::invalid_argument(field + ": a name for every record");
  FragilitySuite s;
  s.names = names;
  s.records = records;
  for (std::size_t k = 0; k < records.size(); ++k) {
    s.im.push_back(intensity_of(*records[k], im, g, alpha));
    if (!(s.im.back() > 0))
      throw std::invalid_argument(field + ": '" + names[k] + "' has " + im.text +
                                  " = 0: it cannot be scaled to a level");
  }
  return s;
}

void validate(const FragilityOptions& o) {
  if (o.levels.empty()) throw std::invalid_argument("levels: give the intensity levels A:B:N or A,B,C");
  for (double l : o.levels) require_in_range("levels", l, 0, 1e6, false);
  if (o.bootstrap < 0 || o.bootstrap > 100000) throw std::invalid_argument("bootstrap: must be in [0, 100000]");
  require_in_range("t-after", o.t_after, 0, 1e4);
  if (o.t_end) require_in_range("t-end", *o.t_end, 0, 1e5, false);
}

FragilityRunOutcome fragility_run(const ForcedModel& m, const FragilitySuite& s, const FragilityOptions& o,
                                  std::size_t i) {
  FragilityRunOutcome r;
  const std::size_t nl = o.levels.size();
  r.record = i / nl;
  r.level = o.levels[i % nl];
  r.record_im = s.im[r.record];
  r.scale = r.level / r.record_im;
  GroundMotion gm;
  gm.horizontal.record = s.records[r.record];
  gm.horizontal.scale = r.scale;
  const SurvivalOutcome out = m.run(gm, o.t_end ? *o.t_end : s.records[r.record]->t_last() + o.t_after);
  r.overturned = out.collapse_mode.has_value();
  r.invalid = out.invalid && !r.overturned;
  r.max_abs_rotation = out.max_abs_rotation;
  r.t_failure = out.t_failure;
  return r;
}

namespace {

// The fitted curve and the bootstrap's pointwise 90 % band on 80 levels across [lo, hi].
std::vector<FragilityCurvePoint> fragility_curve(const FragilityFit& f, const FragilityBand& b, double lo, double hi) {
  std::vector<FragilityCurvePoint> c;
  if (!f.ok) return c;
  for (int i = 0; i < 80; ++i) {
    const double x = lo * std::pow(hi / lo, double(i) / 79.0);
    std::vector<double> ps;
    for (const auto& [m, beta] : b.fits) ps.push_back(normal_cdf(std::log(x / m) / beta));
    std::sort(ps.begin(), ps.end());
    FragilityCurvePoint pt{x, normal_cdf(std::log(x / f.median) / f.beta), std::nullopt, std::nullopt};
    if (!ps.empty()) {
      pt.p05 = ps[std::size_t(0.05 * double(ps.size() - 1))];
      pt.p95 = ps[std::size_t(std::ceil(0.95 * double(ps.size() - 1)))];
    }
    c.push_back(pt);
  }
  return c;
}

}  // namespace

FragilityResult fragility_result(std::vector<FragilityRunOutcome> runs, const FragilitySuite& s,
                                 const FragilityOptions& o) {
  FragilityResult res;
  const std::size_t nl = o.levels.size();
  std::vector<FragilityRun> all;
  std::vector<std::vector<FragilityRun>> groups(s.names.size());
  res.levels.resize(nl);
  for (std::size_t i = 0; i < nl; ++i) res.levels[i].im = o.levels[i];
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const FragilityRunOutcome& r = runs[i];
    if (r.invalid) {
      ++res.levels[i % nl].n_outside_model;
      continue;
    }
    all.push_back({r.level, r.overturned});
    groups[r.record].push_back({r.level, r.overturned});
    ++res.levels[i % nl].n;
    res.levels[i % nl].n_overturned += r.overturned;
  }
  res.fit = fit_fragility(all);
  if (res.fit.ok && o.bootstrap > 0) res.band = bootstrap_fragility(groups, int(o.bootstrap), o.seed);
  const double lo = *std::min_element(o.levels.begin(), o.levels.end()),
               hi = *std::max_element(o.levels.begin(), o.levels.end());
  res.curve = fragility_curve(res.fit, res.band, lo * 0.5, hi * 1.5);
  res.runs = std::move(runs);
  return res;
}

FragilityResult run_fragility(const ForcedModel& m, const FragilitySuite& s, const FragilityOptions& o) {
  validate(o);
  const std::size_t n = o.levels.size() * s.names.size();
  std::vector<FragilityRunOutcome> runs(n);
  parallel_for(n, o.threads, [&](std::size_t i) { runs[i] = fragility_run(m, s, o, i); });
  return fragility_result(std::move(runs), s, o);
}

}  // namespace blockdyn
