// SPDX-License-Identifier: Apache-2.0
// The transitions of the rigid law's modes: a point opening or closing, sticking or slipping,
// switching ends, the projection back onto the constraints, and the hand-over to time-stepping
// and back.
// Part of RigidAssemblyModel's definition, included only by rigid_assembly_model.cpp (which
// instantiates the model once per capacity).

namespace blockdyn {

using namespace rigid_assembly;

template <int MaxBlocks>
void RigidAssemblyModel<MaxBlocks>::project(const Mode& m, State& z, bool velocities) const {
  // Positions: the closed points' gaps back to zero (they drift by the integration error and the
  // events' noise band, and a point that reopens must start on its face for its gap event to mean
  // what it says), by Newton steps until they are zero to rounding (one linearised step leaves a
  // start turned by 0.05 rad 1e-5 m off). Velocities: the closed points' normal and the sticking
  // interfaces' slip velocities to zero (time-stepping leaves them at its own tolerance, and a
  // constraint kept at a nonzero rate would do work); the constraint is linear in them: one step.
  // The smallest mass-weighted change, its energy booked with the contacts' work.
  const Energy before = energy_terms(m, z);
  for (int it = 0; it < (velocities ? 1 : 8); ++it)
    if (!project_step(m, z, velocities)) break;
  z[kWNormal] += energy_terms(m, z).total() - before.total();
}

template <int MaxBlocks>
bool RigidAssemblyModel<MaxBlocks>::project_step(const Mode& m, State& z, bool velocities) const {
  Geometry geo;
  geo_.geometry(z, geo);
  std::array<PointRows, kPoints> r;
  rows(z, geo, m, r);
  constexpr int kMaxU = kPoints + kIfaces;
  ContactSystem<kCoords, kMaxU> sys;
  auto add = [&](const PointRows& k, const std::array<double, 3>& u, const std::array<double, 3>& l, double value) {
    const int j = sys.add();
    for (int c = 0; c < 3; ++c) {
      sys.col[j][3 * k.upper + c] = sys.row[j][3 * k.upper + c] = u[c];
      if (k.lower >= 0) sys.col[j][3 * k.lower + c] = sys.row[j][3 * k.lower + c] = l[c];
    }
    sys.rhs[j] = -value;
  };
  std::array<bool, kIfaces> stuck{};
  double residual = 0.0;
  for (int p = 0; p < 2 * ni_; ++p) {
    if (!is_closed(m.point[p])) continue;
    add(r[p], r[p].nu, r[p].nl, velocities ? r[p].vn : r[p].gap);
    residual = std::fmax(residual, std::fabs(velocities ? r[p].vn : r[p].gap));
    if (velocities && m.point[p] == PointState::Stick && !stuck[p / 2]) {
      stuck[p / 2] = true;
      add(r[p], r[p].tu, r[p].tl, r[p].vt);
      residual = 1.0;
    }
  }
  if (!velocities && residual <= 1e-15 * len_) return false;  // the gaps are zero to rounding
  std::array<double, kMaxU> x{};
  if (sys.n == 0 || !sys.solve(inv_mass_, x)) return false;
  for (int j = 0; j < sys.n; ++j)
    for (int b = 0; b < nb_; ++b)
      for (int k = 0; k < 3; ++k)
        z[(velocities ? iv(b) : ix(b)) + k] += inv_mass_[3 * b + k] * sys.col[j][3 * b + k] * x[j];
  return true;
}

template <int MaxBlocks>
void RigidAssemblyModel<MaxBlocks>::hand_over(Transition<Mode>& tr, const std::string& why) const {
  tr.stop = true;
  tr.kind = kAssemblyToTimeStepping;
  handover_ = true;
  problem_ = why;
}

template <int MaxBlocks>
void RigidAssemblyModel<MaxBlocks>::reselect(double t, Transition<Mode>& tr, State& z) const {
  project(tr.next, z, false);
  if (!select_mode(t, tr.next, z))
    hand_over(tr, "no contact mode consistent (the acceleration-level contact problem has no solution)");
}

template <int MaxBlocks>
void RigidAssemblyModel<MaxBlocks>::open_or_close(double t, const Mode& m, State& z, int p,
                                                  Transition<Mode>& tr) const {
  Mode& n = tr.next;
  if (is_closed(m.point[p])) {
    n.point[p] = PointState::Open;
    tr.kind = kAssemblyContactOpens;
  } else {
    n.point[p] = PointState::Stick;
    const State before = z;
    if (!impact(t, n, z)) return hand_over(tr, "an impact problem without a settled solution");
    // An accumulation of impacts that does not settle (a chattering contact).
    const std::size_t slot = std::size_t(impacts_++ % kAccumulationImpacts);
    const double oldest = impact_times_[slot];
    impact_times_[slot] = t;
    if (impacts_ > kAccumulationImpacts && t - oldest < kAccumulationWindow * std::sqrt(len_ / g_))
      return hand_over(tr, "impacts accumulating without settling (a chattering contact)");
    // An impact when the velocities jumped; a contact closing without approach (grazing) otherwise.
    tr.kind = kAssemblyContactCloses;
    for (int b = 0; b < nb_; ++b)
      for (int k = 0; k < 3; ++k)
        if (z[iv(b) + k] != before[iv(b) + k]) tr.kind = kAssemblyImpact;
  }
  reselect(t, tr, z);
  if (!tr.stop) try_rest(t, n, z);
}

template <int MaxBlocks>
void RigidAssemblyModel<MaxBlocks>::stick_or_slip(double t, const Mode& m, State& z, int p,
                                                  Transition<Mode>& tr) const {
  Mode& n = tr.next;
  const int i = p / 2;
  if (m.point[p] == PointState::Stick) {
    Geometry geo;
    geo_.geometry(z, geo);
    std::array<PointRows, kPoints> r;
    rows(z, geo, m, r);
    const Solution s = solve(t, m, z, r);
    double ft = 0.0;
    for (int q = 2 * i; q < 2 * i + 2; ++q) ft += s.ft[q];
    for (int q = 2 * i; q < 2 * i + 2; ++q)
      if (is_closed(n.point[q])) n.point[q] = ft > 0 ? PointState::SlipNeg : PointState::SlipPos;
    tr.kind = kAssemblySlipStarts;
  } else {
    for (int q = 2 * i; q < 2 * i + 2; ++q)
      if (is_closed(n.point[q])) n.point[q] = PointState::Stick;
    tr.kind = kAssemblyStickStarts;
  }
  reselect(t, tr, z);
  if (!tr.stop) try_rest(t, n, z);
}

template <int MaxBlocks>
void RigidAssemblyModel<MaxBlocks>::switch_end(double t, State& z, int p, Transition<Mode>& tr) const {
  Mode& n = tr.next;
  n.owner[p] ^= 1;
  tr.kind = kAssemblyEndSwitch;
  if (is_closed(n.point[p])) {
    // The other block's corner takes the contact with its own normal velocity (a rotating face
    // passing a corner): approaching, it strikes (an impact); leaving, the end opens.
    Geometry geo;
    geo_.geometry(z, geo);
    std::array<PointRows, kPoints> r;
    rows(z, geo, n, r);
    if (r[p].vn > kTol * v_scale_) {
      n.point[p] = PointState::Open;
    } else if (r[p].vn < -kTol * v_scale_ && !impact(t, n, z)) {
      return hand_over(tr, "an impact problem without a settled solution");
    }
  }
  reselect(t, tr, z);
}

template <int MaxBlocks>
Transition<typename RigidAssemblyModel<MaxBlocks>::Mode> RigidAssemblyModel<MaxBlocks>::transition(double t,
                                                                                                   const Mode& m,
                                                                                                   State& z,
                                                                                                   int event) const {
  Transition<Mode> tr;
  tr.next = m;
  if (m.rest) {
    leave_rest(t, m, z, tr);
  } else if (event == kBreakpoint) {
    tr.kind = kAssemblyInputBreakpoint;
    reselect(t, tr, z);
    if (!tr.stop) try_rest(t, tr.next, z);
  } else if (event < ev_tangent(0) || (event >= ev_valid(0) && event < ev_wzero(0))) {
    open_or_close(t, m, z, event < ev_tangent(0) ? event : event - ev_valid(0), tr);
  } else if (event < ev_owner(0)) {
    stick_or_slip(t, m, z, event - ev_tangent(0), tr);
  } else if (event < ev_valid(0)) {
    switch_end(t, z, event - ev_owner(0), tr);
  } else if (event < ev_collapse(0)) {
    const int b = event - ev_wzero(0);
    tr.next.side[b] = std::int8_t(-m.side[b]);
    tr.kind = kAssemblyUprightPassage;
  } else {
    tr.stop = true;
    tr.kind = event < ev_bearing(0) ? kAssemblyRotationCollapse : kAssemblyBearingCollapse;
  }
  return tr;
}

template <int MaxBlocks>
std::optional<typename RigidAssemblyModel<MaxBlocks>::Mode> RigidAssemblyModel<MaxBlocks>::resume(double t, State& z,
                                                                                                  Mode guess) const {
  handover_ = false;
  problem_.clear();
  impacts_ = 0;
  guess.rest = false;
  for (int b = 0; b < nb_; ++b) guess.side[b] = z[ix(b) + 2] < 0.0 ? -1 : 1;
  State trial = z;
  project(guess, trial, false);
  project(guess, trial, true);
  if (!select_mode(t, guess, trial)) return std::nullopt;
  z = trial;
  try_rest(t, guess, z);
  return guess;
}

}  // namespace blockdyn
