// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/cycle_detection.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace blockdyn {

void validate(const CycleOptions& o) {
  if (!(o.window >= 2 && o.window <= 100000))
    throw std::invalid_argument("window must be in [2, 100000] forcing periods");
  if (!(o.max_period >= 1 && 2 * o.max_period <= o.window))
    throw std::invalid_argument("max-period must be in [1, window / 2] forcing periods");
  if (!(o.tolerance > 0 && o.tolerance <= 1)) throw std::invalid_argument("tolerance must be in (0, 1]");
  if (!(o.transient >= 0 && o.transient <= 10000000))
    throw std::invalid_argument("transient must be in [0, 1e7] periods");
}

CycleOptions fitted(const CycleOptions& o, long periods) {
  CycleOptions f = o;
  const long avail = periods - o.transient;
  if (avail < o.window) {
    f.window = int(std::max(2L, avail));
    f.max_period = std::max(1, std::min(o.max_period, f.window / 2));
  }
  return f;
}

std::string CycleSegment::label() const {
  if (type != "periodic") return type;
  char buf[64];
  if (impacts_per_cycle % 2 == 0)
    std::snprintf(buf, sizeof buf, "(%d,%d)", impacts_per_cycle / 2, n);
  else
    std::snprintf(buf, sizeof buf, "(%g,%d)", m(), n);
  return buf;
}

namespace {

struct WindowLabel {
  int type = 2;  // 0 periodic, 1 no-impacts, 2 non-periodic
  int c = 0, n = 0;
  double d = 0;
  bool same(const WindowLabel& o) const { return type == o.type && c == o.c && n == o.n; }
};

long count_in(const std::vector<double>& t, double a, double b) {
  return long(std::lower_bound(t.begin(), t.end(), b) - std::lower_bound(t.begin(), t.end(), a));
}

// The label of every window of W periods from the transient on: periodic (the smallest period n
// at which theta and omega return within the tolerance, with c impacts per cycle), no-impacts, or
// non-periodic.
std::vector<WindowLabel> window_labels(const StrobeSeries& s, const std::vector<double>& impacts,
                                       const CycleOptions& o) {
  const long K = long(s.theta.size());
  const int W = o.window;
  auto tk = [&](long k) { return s.t0 + double(k) * s.period; };
  auto amp = [&](const std::vector<double>& a, const std::vector<double>& x, long k0, long k1) {
    double m = 0;
    for (long k = k0; k <= k1; ++k) {
      m = std::fmax(m, std::fabs(x[k]));
      if (k < k1 && std::size_t(k) < a.size()) m = std::fmax(m, a[k]);
    }
    return m;
  };
  auto rel = [](double d, double scale) { return d == 0 ? 0.0 : scale > 0 ? d / scale : INFINITY; };
  std::vector<WindowLabel> lab;
  const long first = o.transient, last = K - 1 - W;  // window starts
  for (long k = first; k <= last; ++k) {
    WindowLabel L;
    const long n_imp = count_in(impacts, tk(k), tk(k + W));
    if (n_imp == 0) {
      L.type = 1;
    } else {
      const double a_th = amp(s.theta_amp, s.theta, k, k + W), a_om = amp(s.omega_amp, s.omega, k, k + W);
      for (int n = 1; n <= o.max_period && L.type == 2; ++n) {
        double d = 0;
        for (long j = k; j + n <= k + W && d <= o.tolerance; ++j)
          d = std::fmax(d, std::fmax(rel(std::fabs(s.theta[j + n] - s.theta[j]), a_th),
                                     rel(std::fabs(s.omega[j + n] - s.omega[j]), a_om)));
        if (d > o.tolerance) continue;
        const long wn = (W / n) * n;
        const long c = std::lround(double(count_in(impacts, tk(k), tk(k + wn))) * n / double(wn));
        L.type = c == 0 ? 1 : 0;
        L.c = int(c);
        L.n = c == 0 ? 0 : n;
        L.d = d;
      }
    }
    lab.push_back(L);
  }
  return lab;
}

// Runs of equal labels (periodic or no-impacts) -> intervals; later runs win overlaps; a cycle
// shown for less than two of its orbits (a piece left between overlapping windows of other
// labels) is not a cycle.
std::vector<CycleSegment> labelled_segments(const StrobeSeries& s, const std::vector<WindowLabel>& lab,
                                            const CycleOptions& o) {
  auto tk = [&](long k) { return s.t0 + double(k) * s.period; };
  const long first = o.transient;
  std::vector<CycleSegment> segs;
  for (std::size_t i = 0; i < lab.size();) {
    std::size_t j = i;
    double d = lab[i].d;
    while (j + 1 < lab.size() && lab[j + 1].same(lab[i])) d = std::fmax(d, lab[++j].d);
    if (lab[i].type != 2) {
      CycleSegment c;
      c.type = lab[i].type == 0 ? "periodic" : "no-impacts";
      c.impacts_per_cycle = lab[i].c;
      c.n = lab[i].n;
      c.t_start = tk(first + long(i));
      c.t_end = tk(first + long(j) + o.window);
      c.return_distance = d;
      while (!segs.empty() && segs.back().t_end > c.t_start) {
        if (segs.back().t_start >= c.t_start)
          segs.pop_back();
        else
          segs.back().t_end = c.t_start;
      }
      if (!segs.empty() && segs.back().t_end == c.t_start && segs.back().label() == c.label()) {
        segs.back().t_end = c.t_end;
        segs.back().return_distance = std::fmax(segs.back().return_distance, d);
      } else {
        segs.push_back(c);
      }
    }
    i = j + 1;
  }
  std::erase_if(segs, [&](const CycleSegment& c) {
    return c.type == "periodic" && c.t_end - c.t_start < (2 * c.n - 0.5) * s.period;
  });
  return segs;
}

// The segments with the gaps between them (non-periodic) from t_lo to t_hi.
void fill_gaps(const std::vector<CycleSegment>& segs, double t_lo, double t_hi, std::vector<CycleSegment>& out) {
  auto gap = [&](double a, double b) {
    CycleSegment g;
    g.type = "non-periodic";
    g.t_start = a;
    g.t_end = b;
    out.push_back(g);
  };
  double t = t_lo;
  for (const CycleSegment& c : segs) {
    if (c.t_start > t) gap(t, c.t_start);
    out.push_back(c);
    t = c.t_end;
  }
  if (t < t_hi) gap(t, t_hi);
}

}  // namespace

CycleReport detect_cycles(const StrobeSeries& s, const std::vector<double>& impacts, const CycleOptions& o,
                          std::optional<double> t_failure) {
  validate(o);
  if (s.omega.size() != s.theta.size()) throw std::invalid_argument("strobe series: theta and omega differ in length");
  CycleReport rep;
  rep.options = o;
  const std::vector<WindowLabel> lab = window_labels(s, impacts, o);
  rep.windows = long(lab.size());
  const std::vector<CycleSegment> segs = labelled_segments(s, lab, o);
  if (!lab.empty())
    fill_gaps(segs, s.t0 + double(o.transient) * s.period, s.t0 + double(long(s.theta.size()) - 1) * s.period,
              rep.segments);
  for (CycleSegment& c : rep.segments) c.impacts = count_in(impacts, c.t_start, c.t_end);
  // Dominant label by total duration (the first in time on a tie).
  std::map<std::string, double> total;
  double best = -1;
  for (const CycleSegment& c : rep.segments) total[c.label()] += c.t_end - c.t_start;
  for (const CycleSegment& c : rep.segments)
    if (total[c.label()] > best) {
      best = total[c.label()];
      rep.dominant = c.label();
    }
  if (t_failure) {
    CycleSegment f;
    f.type = "collapse";
    f.t_start = f.t_end = *t_failure;
    rep.segments.push_back(f);
  }
  for (std::size_t i = 1; i < rep.segments.size(); ++i)
    if (rep.segments[i].label() != rep.segments[i - 1].label())
      rep.changes.push_back({rep.segments[i].t_start, rep.segments[i - 1].label(), rep.segments[i].label()});
  return rep;
}

}  // namespace blockdyn
