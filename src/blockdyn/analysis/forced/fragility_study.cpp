// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/fragility_study.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "blockdyn/analysis/sweep/parallel_map.hpp"
#include "blockdyn/base/number_text.hpp"
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

FragilitySuite fragility_suite_3d(const std::vector<std::string>& names,
                                  const std::vector<std::shared_ptr<const Accelerogram>>& h1,
                                  const std::vector<std::shared_ptr<const Accelerogram>>& h2,
                                  const std::vector<std::shared_ptr<const Accelerogram>>& v,
                                  const std::vector<double>& incidences, const std::vector<double>& alpha_at,
                                  const IntensityMeasure& im, double g, const std::string& field) {
  const std::size_t n = h1.size(), ni = incidences.size();
  if (names.size() != n || (!h2.empty() && h2.size() != n) || (!v.empty() && v.size() != n))
    throw std::invalid_argument(field + ": every record needs the same components");
  if (ni == 0 || alpha_at.size() != ni) throw std::invalid_argument(field + ": give the incidences");
  for (std::size_t k = 0; k < n; ++k) {
    const auto same_length = [&](const std::vector<std::shared_ptr<const Accelerogram>>& c) {
      return c.empty() || (c[k]->size() == h1[k]->size() && c[k]->t_last() == h1[k]->t_last());
    };
    if (!same_length(h2) || !same_length(v))
      throw std::invalid_argument(field + ": the components of '" + names[k] + "' differ in length (" +
                                  std::to_string(h1[k]->size()) + " samples in h1)");
  }
  FragilitySuite s;
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t j = 0; j < ni; ++j) {
      s.names.push_back(ni > 1 ? names[k] + " @ " + number_text(incidences[j]) + " deg" : names[k]);
      s.records.push_back(h1[k]);
      if (!h2.empty()) s.records_h2.push_back(h2[k]);
      if (!v.empty()) s.records_v.push_back(v[k]);
      s.incidence.push_back(incidences[j]);
      s.incidence_index.push_back(j);
      double m = intensity_of(*h1[k], im, g, alpha_at[j]);
      if (!h2.empty()) m = std::sqrt(m * intensity_of(*h2[k], im, g, alpha_at[j]));
      if (!(m > 0))
        throw std::invalid_argument(field + ": '" + names[k] + "' has " + im.text +
                                    " = 0: it cannot be scaled to a level");
      s.im.push_back(m);
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
  const double t_end = o.t_end ? *o.t_end : s.records[r.record]->t_last() + o.t_after;
  SurvivalOutcome out;
  if (s.three_dimensional()) {
    if (!m.run3) throw std::invalid_argument("suite: records in components or at incidences need a 3D body (rigid3d)");
    out =
        m.run3(record_components(s.records[r.record], s.records_h2.empty() ? nullptr : s.records_h2[r.record],
                                 s.records_v.empty() ? nullptr : s.records_v[r.record], r.scale, s.incidence[r.record]),
               t_end);
  } else {
    GroundMotion gm;
    gm.horizontal.record = s.records[r.record];
    gm.horizontal.scale = r.scale;
    out = m.run(gm, t_end);
  }
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
  if (res.fit.ok && o.bootstrap > 0) res.band = bootstrap_fragility(groups, int(o.bootstrap), o.seed, o.threads);
  const double lo = *std::min_element(o.levels.begin(), o.levels.end()),
               hi = *std::max_element(o.levels.begin(), o.levels.end());
  res.curve = fragility_curve(res.fit, res.band, lo * 0.5, hi * 1.5);
  res.runs = std::move(runs);
  return res;
}

FragilityResult fragility_result_at_incidence(const std::vector<FragilityRunOutcome>& runs, const FragilitySuite& s,
                                              const FragilityOptions& o, std::size_t j) {
  FragilitySuite sub;
  std::vector<std::size_t> entry_of(s.names.size(), std::size_t(-1));
  for (std::size_t k = 0; k < s.names.size(); ++k)
    if (s.incidence_index[k] == j) {
      entry_of[k] = sub.names.size();
      sub.names.push_back(s.names[k]);
      sub.im.push_back(s.im[k]);
    }
  std::vector<FragilityRunOutcome> mine;
  for (const FragilityRunOutcome& r : runs) {
    if (entry_of[r.record] == std::size_t(-1)) continue;
    FragilityRunOutcome one = r;
    one.record = entry_of[r.record];
    mine.push_back(one);
  }
  return fragility_result(std::move(mine), sub, o);
}

FragilityResult run_fragility(const ForcedModel& m, const FragilitySuite& s, const FragilityOptions& o) {
  validate(o);
  const std::size_t n = o.levels.size() * s.names.size();
  std::vector<FragilityRunOutcome> runs(n);
  parallel_for(n, o.threads, [&](std::size_t i) { runs[i] = fragility_run(m, s, o, i); });
  return fragility_result(std::move(runs), s, o);
}

}  // namespace blockdyn
