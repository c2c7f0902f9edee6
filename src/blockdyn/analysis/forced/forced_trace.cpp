// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/forced_trace.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace blockdyn {

void ForcedTrace::sample(long, double t, int blocks, const BlockState* s) {
  blocks_ = blocks;
  t_.push_back(t);
  s_.insert(s_.end(), s, s + blocks);
  track(t, blocks, s);
}

void ForcedTrace::step_end(double t, int blocks, const BlockState* s) {
  blocks_ = blocks;
  track(t, blocks, s);
}

void ForcedTrace::track(double t, int blocks, const BlockState* s) {
  if (!(period() > 0)) return;
  const double k = std::floor((t - t0()) / period());
  const std::size_t i = k > 0 ? std::size_t(k) : 0;
  if (amp_.size() < 2 * std::size_t(blocks) * (i + 1)) amp_.resize(2 * std::size_t(blocks) * (i + 1), 0.0);
  for (int b = 0; b < blocks; ++b) {
    double* a = &amp_[2 * (i * blocks + b)];
    a[0] = std::fmax(a[0], std::fabs(s[b][2]));
    a[1] = std::fmax(a[1], std::fabs(s[b][5]));
  }
}

double ForcedTrace::theta_amplitude(std::size_t k, int block) const {
  const std::size_t i = 2 * (k * blocks_ + block);
  return i < amp_.size() ? amp_[i] : 0.0;
}

double ForcedTrace::omega_amplitude(std::size_t k, int block) const {
  const std::size_t i = 2 * (k * blocks_ + block) + 1;
  return i < amp_.size() ? amp_[i] : 0.0;
}

void ForcedTrace::event(const ProbeEvent& e) {
  if (keep_ < 0 || e.block == keep_) ev_.push_back(e);
}

std::vector<Impact> impacts_of(const ForcedTrace& tr, int block, ImpactRule rule) {
  std::vector<Impact> out;
  const auto& ev = tr.events();
  if (rule == ImpactRule::VelocityJump) {
    for (const ProbeEvent& e : ev)
      if (e.block == block && e.kind == ProbeEvent::Impact) out.push_back({e.t, e.omega_before, e.omega_after});
    return out;
  }
  // Passages after a lift-off. theta' before (and, for the rigid law, after) from the closing of
  // the hitting corner nearest the passage: the last one since the previous impact, else the
  // first one after the passage (the rigid law closes it in the step after the crossing).
  // This block's events in time order (the rigid law reports a step's contact changes at its
  // end, before the passage it interpolates inside the step).
  std::vector<std::size_t> mine;
  for (std::size_t i = 0; i < ev.size(); ++i)
    if (ev[i].block == block) mine.push_back(i);
  std::stable_sort(mine.begin(), mine.end(), [&](std::size_t a, std::size_t b) { return ev[a].t < ev[b].t; });
  bool lifted = false;
  std::size_t prev = 0;  // position in `mine` just after the previous impact
  for (std::size_t q = 0; q < mine.size(); ++q) {
    const ProbeEvent& e = ev[mine[q]];
    if (e.kind == ProbeEvent::Open) lifted = true;
    if (e.kind != ProbeEvent::Passage || !lifted) continue;
    // Moving towards negative theta the right corner (+1) hits, and the other way the left one.
    const int hit = e.omega_before < 0 ? 1 : -1;
    const ProbeEvent* close = nullptr;
    for (std::size_t r = q; r-- > prev;)
      if (ev[mine[r]].kind == ProbeEvent::Close && ev[mine[r]].side == hit) {
        close = &ev[mine[r]];
        break;
      }
    for (std::size_t r = q + 1; !close && r < mine.size() && ev[mine[r]].kind != ProbeEvent::Passage; ++r)
      if (ev[mine[r]].kind == ProbeEvent::Close && ev[mine[r]].side == hit) close = &ev[mine[r]];
    Impact im{e.t, e.omega_before, e.omega_after};
    if (close) {
      im.omega_before = close->omega_before;
      if (close->omega_after != close->omega_before) im.omega_after = close->omega_after;  // a velocity jump
    }
    out.push_back(im);
    lifted = false;
    prev = q + 1;
  }
  return out;
}

StrobeSeries strobe_series(const ForcedTrace& tr, int block) {
  StrobeSeries s;
  s.t0 = tr.t0();
  s.period = tr.period();
  const std::size_t K = tr.strobes();
  for (std::size_t k = 0; k < K; ++k) {
    s.theta.push_back(tr.strobe(k, block)[2]);
    s.omega.push_back(tr.strobe(k, block)[5]);
    s.theta_amp.push_back(tr.theta_amplitude(k, block));
    s.omega_amp.push_back(tr.omega_amplitude(k, block));
  }
  return s;
}

namespace {
std::vector<double> times_of(const std::vector<Impact>& imp) {
  std::vector<double> t;
  t.reserve(imp.size());
  for (const Impact& i : imp) t.push_back(i.t);
  return t;
}
}  // namespace

CycleReport cycles_of(const ForcedTrace& tr, int block, ImpactRule rule, const CycleOptions& o,
                      std::optional<double> t_failure) {
  return detect_cycles(strobe_series(tr, block), times_of(impacts_of(tr, block, rule)), o, t_failure);
}

std::string dominant_cycle(const ForcedTrace& tr, int block, ImpactRule rule, const CycleOptions& o,
                           std::optional<double> t_failure) {
  const long periods = long(tr.strobes()) - 1;
  const CycleOptions f = fitted(o, periods);
  if (periods - f.transient < 2) return "";
  return cycles_of(tr, block, rule, f, t_failure).dominant;
}

}  // namespace blockdyn
