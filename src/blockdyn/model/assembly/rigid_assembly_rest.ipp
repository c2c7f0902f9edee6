// SPDX-License-Identifier: Apache-2.0
// Rest of the rigid law: the static limits of a configuration (a linear programme), settling
// into rest, and leaving it along the collapse mechanism when the ground motion exceeds a limit.
// Part of RigidAssemblyModel's definition, included only by rigid_assembly_model.cpp (which
// instantiates the model once per capacity).

namespace blockdyn {

using namespace rigid_assembly;

template <int MaxBlocks>
StaticProblem RigidAssemblyModel<MaxBlocks>::static_problem(const State& z,
                                                            const std::array<PointRows, kPoints>& r) const {
  StaticProblem sp;
  sp.g = g_;
  for (int b = 0; b < nb_; ++b) {
    sp.mass.push_back(m_[b]);
    sp.centre.push_back({z[ix(b)], z[ix(b) + 1]});
  }
  for (int i = 0; i < ni_; ++i) sp.mu.push_back(mu_s_[i]);
  for (int p = 0; p < 2 * ni_; ++p) {
    StaticContact k;
    k.upper = upper_[p / 2];
    k.lower = lower_[p / 2];
    k.iface = p / 2;
    k.P = r[p].c.P;
    k.n = {r[p].nu[0], r[p].nu[1]};
    k.t = {r[p].tu[0], r[p].tu[1]};
    sp.contacts.push_back(k);
  }
  return sp;
}

template <int MaxBlocks>
std::optional<typename RigidAssemblyModel<MaxBlocks>::RestLimits> RigidAssemblyModel<MaxBlocks>::rest_limits(
    const State& z) const {
  Geometry geo;
  geo_.geometry(z, geo);
  Mode m{};
  for (int p = 0; p < 2 * ni_; ++p)
    m.owner[p] = owner_margin(geo.lower[p / 2], geo.upper[p / 2], p % 2, 0) >= 0.0 ? 0 : 1;
  std::array<PointRows, kPoints> r;
  rows(z, geo, m, r);
  const StaticProblem sp = static_problem(z, r);
  const LoadMultiplier pos = max_load_multiplier(sp, +1), neg = max_load_multiplier(sp, -1);
  if (!pos.feasible || !neg.feasible || pos.lambda < 0 || neg.lambda < 0) return std::nullopt;
  return RestLimits{pos.lambda, neg.lambda};
}

template <int MaxBlocks>
bool RigidAssemblyModel<MaxBlocks>::try_rest(double t, Mode& m, State& z) const {
  Geometry geo;
  geo_.geometry(z, geo);
  std::array<PointRows, kPoints> r;
  rows(z, geo, m, r);
  for (int p = 0; p < 2 * ni_; ++p)
    if (std::fabs(r[p].gap) > 1e-7 * len_) return false;
  for (int b = 0; b < nb_; ++b) {
    const double w =
        std::fabs(z[iv(b) + 2]) * std::fmax(geo_.assembly().blocks[b].width, geo_.assembly().blocks[b].height);
    if (std::fabs(z[iv(b)]) > settle_velocity_ || std::fabs(z[iv(b) + 1]) > settle_velocity_ || w > settle_velocity_)
      return false;
  }
  std::optional<RestLimits> lim;
  double dz = 0.0;
  for (int b = 0; b < nb_; ++b)
    for (int k = 0; k < 3; ++k) dz = std::fmax(dz, std::fabs(z[ix(b) + k] - z0_[ix(b) + k]));
  // The assembly's own configuration recurs (a rocking block returning upright): its limits once.
  if (dz == 0.0) {
    if (!limits0_) limits0_ = rest_limits(z);
    lim = limits0_;
  } else {
    lim = rest_limits(z);
  }
  if (!lim) return false;
  const auto a = ground_acceleration(t);
  if (!(1.0 + a[1] > 0.0) || lim->pos * (1.0 + a[1]) - a[0] < 0.0 || lim->neg * (1.0 + a[1]) + a[0] < 0.0) return false;
  // Rest is exactly rest: the residual motion (an accumulation of impacts) is booked as their loss.
  double ke = 0.0;
  for (int b = 0; b < nb_; ++b) {
    ke += 0.5 * m_[b] * (z[iv(b)] * z[iv(b)] + z[iv(b) + 1] * z[iv(b) + 1]) + 0.5 * I_[b] * z[iv(b) + 2] * z[iv(b) + 2];
    for (int k = 0; k < 3; ++k) z[iv(b) + k] = 0.0;
  }
  z[kWNormal] -= ke;
  m.rest = true;
  m.rest_pos = lim->pos;
  m.rest_neg = lim->neg;
  for (int p = 0; p < 2 * ni_; ++p) m.point[p] = PointState::Stick;
  return true;
}

template <int MaxBlocks>
typename RigidAssemblyModel<MaxBlocks>::Mode RigidAssemblyModel<MaxBlocks>::mechanism_mode(const Mode& m,
                                                                                           const State& z,
                                                                                           int direction) const {
  Geometry geo;
  geo_.geometry(z, geo);
  std::array<PointRows, kPoints> r;
  rows(z, geo, m, r);
  const StaticProblem sp = static_problem(z, r);
  Mode out = m;
  out.rest = false;
  const LoadMultiplier lm = max_load_multiplier(sp, direction);
  std::array<double, kCoords> u{};
  for (int c = 0; c < 3 * nb_ && c < int(lm.mechanism.size()); ++c) u[c] = lm.mechanism[c];
  std::array<double, kPoints> vn{}, vt{};
  double scale = 0.0;
  for (int p = 0; p < 2 * ni_; ++p) {
    vn[p] = rate_of(r[p], u, true) - r[p].kn;
    vt[p] = rate_of(r[p], u, false) - r[p].kt;
    scale = std::fmax(scale, std::fmax(std::fabs(vn[p]), std::fabs(vt[p])));
  }
  for (int p = 0; p < 2 * ni_; ++p) {
    if (!(scale > 0)) break;
    if (vn[p] > 1e-6 * scale)
      out.point[p] = PointState::Open;
    else if (std::fabs(vt[p]) > 1e-6 * scale)
      out.point[p] = vt[p] > 0 ? PointState::SlipPos : PointState::SlipNeg;
    else
      out.point[p] = PointState::Stick;
  }
  return out;
}

template <int MaxBlocks>
void RigidAssemblyModel<MaxBlocks>::leave_rest(double t, const Mode& m, State& z, Transition<Mode>& tr) const {
  Mode& n = tr.next;
  const auto a = ground_acceleration(t);
  const bool pos_fails = m.rest_pos * (1.0 + a[1]) - a[0] < 0.0;
  const bool neg_fails = m.rest_neg * (1.0 + a[1]) + a[0] < 0.0;
  tr.kind = kAssemblyInputBreakpoint;
  if (!pos_fails && !neg_fails && 1.0 + a[1] > 0.0) return;
  if (!(1.0 + a[1] > 0.0)) {
    n.rest = false;
    for (int p = 0; p < 2 * ni_; ++p) n.point[p] = PointState::Open;
  } else {
    n = mechanism_mode(m, z, pos_fails ? +1 : -1);
  }
  tr.kind = kAssemblySlipStarts;
  for (int p = 0; p < 2 * ni_; ++p)
    if (n.point[p] == PointState::Open) tr.kind = kAssemblyContactOpens;
  reselect(t, tr, z);
}

}  // namespace blockdyn
