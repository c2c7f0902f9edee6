// SPDX-License-Identifier: Apache-2.0
// Impacts of the rigid law: the velocity-level problem of the points that close (restitution
// targets, Coulomb's cone on the impulses), solved by an active set, and the jump applied.
// Part of RigidAssemblyModel's definition, included only by rigid_assembly_model.cpp (which
// instantiates the model once per capacity).

namespace blockdyn {

using namespace rigid_assembly;

// The velocity-level problem of one impact: the points in the impact set, which of them are
// active (an impulse, the restitution target reached), each interface's slip, and the solution.
template <int MaxBlocks>
struct RigidAssemblyModel<MaxBlocks>::ImpactWork {
  static constexpr int kMaxU = kPoints + kIfaces;
  std::array<PointRows, kPoints> r;
  std::array<double, kCoords> v{}, vp{};  // velocities before and after
  std::array<bool, kPoints> in{}, active{};
  std::array<int, kIfaces> slip{};  // per interface: 0 stick, +-1 slipping that way
  std::array<double, kPoints> target{}, pn{}, pt{};
  std::array<double, kIfaces> tsum{};  // a sticking interface's tangential impulse
  ContactSystem<kCoords, kMaxU> sys;
  std::array<double, kMaxU> x{};
  double tol_v = 0, p_scale = 0;
};

template <int MaxBlocks>
bool RigidAssemblyModel<MaxBlocks>::solve_impact(ImpactWork& w) const {
  auto& sys = w.sys;
  sys.clear();
  std::array<int, kPoints> jn{};
  std::array<int, kIfaces> jt{};
  jn.fill(-1);
  jt.fill(-1);
  for (int p = 0; p < 2 * ni_; ++p) {
    if (!w.active[p]) continue;
    const PointRows& k = w.r[p];
    const int i = p / 2, j = sys.add();
    jn[p] = j;
    place_rows<kCoords>(sys.col[j], k, k.nu, k.nl, 1.0);
    if (w.slip[i] != 0) place_rows<kCoords>(sys.col[j], k, k.tu, k.tl, -mu_k_[i] * w.slip[i]);
    place_rows<kCoords>(sys.row[j], k, k.nu, k.nl, 1.0);
    sys.rhs[j] = w.target[p] - relative_rate<kCoords>(w.v, k, true);
    if (w.slip[i] == 0 && jt[i] < 0) {
      const int q = sys.add();
      jt[i] = q;
      place_rows<kCoords>(sys.col[q], k, k.tu, k.tl, 1.0);
      place_rows<kCoords>(sys.row[q], k, k.tu, k.tl, 1.0);
      sys.rhs[q] = -relative_rate<kCoords>(w.v, k, false);
    }
  }
  if (!sys.solve(inv_mass_, w.x)) return false;
  w.vp = w.v;
  for (int j = 0; j < sys.n; ++j)
    for (int c = 0; c < kCoords; ++c) w.vp[c] += inv_mass_[c] * sys.col[j][c] * w.x[j];
  w.pn.fill(0.0);
  w.pt.fill(0.0);
  for (int p = 0; p < 2 * ni_; ++p) {
    if (jn[p] < 0) continue;
    w.pn[p] = w.x[jn[p]];
    if (w.slip[p / 2] != 0) w.pt[p] = -mu_k_[p / 2] * w.slip[p / 2] * w.pn[p];
  }
  for (int i = 0; i < ni_; ++i) w.tsum[i] = jt[i] >= 0 ? w.x[jt[i]] : 0.0;
  return true;
}

template <int MaxBlocks>
bool RigidAssemblyModel<MaxBlocks>::change_impact_set(ImpactWork& w) const {
  // The most violated condition, if any: a pulling impulse, a point approaching, friction
  // beyond the cone, a slip reversing.
  double worst = 1.0;
  int kind = 0, at = -1;
  for (int p = 0; p < 2 * ni_; ++p) {
    if (!w.in[p]) continue;
    const double un = relative_rate<kCoords>(w.vp, w.r[p], true);
    if (w.active[p] && -w.pn[p] / (kTol * w.p_scale) > worst) worst = -w.pn[p] / (kTol * w.p_scale), kind = 1, at = p;
    if (!w.active[p] && (w.target[p] - un) / w.tol_v > worst) worst = (w.target[p] - un) / w.tol_v, kind = 2, at = p;
  }
  for (int i = 0; i < ni_; ++i) {
    double sn = 0.0;
    int p0 = -1;
    for (int p = 2 * i; p < 2 * i + 2; ++p)
      if (w.active[p]) sn += w.pn[p], p0 = p0 < 0 ? p : p0;
    if (p0 < 0) continue;
    if (w.slip[i] == 0 && mu_s_[i] < kNoSlipFriction) {
      const double v_ex = (std::fabs(w.tsum[i]) - mu_s_[i] * sn) / (kTol * w.p_scale);
      if (v_ex > worst) worst = v_ex, kind = 3, at = p0;
    } else if (w.slip[i] != 0 && mu_s_[i] > 0.0) {
      const double back = -w.slip[i] * relative_rate<kCoords>(w.vp, w.r[p0], false) / w.tol_v;
      if (back > worst) worst = back, kind = 4, at = p0;
    }
  }
  if (kind == 1) w.active[at] = false;
  if (kind == 2) w.active[at] = true;
  if (kind == 3) w.slip[at / 2] = w.tsum[at / 2] > 0 ? -1 : 1;
  if (kind == 4) w.slip[at / 2] = 0;
  return kind != 0;
}

template <int MaxBlocks>
void RigidAssemblyModel<MaxBlocks>::apply_impact(const ImpactWork& w, Mode& m, State& z) const {
  // The impulses' works (exact: P (u+ + u-) / 2), and the new velocities.
  double w_n = 0.0, w_t = 0.0;
  std::array<bool, kIfaces> booked{};
  for (int p = 0; p < 2 * ni_; ++p) {
    if (!w.active[p]) continue;
    const PointRows& k = w.r[p];
    w_n += w.pn[p] * 0.5 * (relative_rate<kCoords>(w.vp, k, true) + k.vn);
    w_t += w.pt[p] * 0.5 * (relative_rate<kCoords>(w.vp, k, false) + k.vt);
    // A sticking interface's impulse, at the point its constraint was written for.
    if (w.slip[p / 2] == 0 && !booked[p / 2]) {
      booked[p / 2] = true;
      w_t += w.tsum[p / 2] * 0.5 * (relative_rate<kCoords>(w.vp, k, false) + k.vt);
    }
  }
  z[kWNormal] += w_n;
  z[kWFriction] += w_t;
  for (int b = 0; b < nb_; ++b)
    for (int k = 0; k < 3; ++k) z[iv(b) + k] = w.vp[3 * b + k];
  // The points that stay in contact: those whose normal velocity after is zero.
  Geometry geo;
  geo_.geometry(z, geo);
  std::array<PointRows, kPoints> r;
  rows(z, geo, m, r);
  const double tol_v = w.tol_v;
  for (int p = 0; p < 2 * ni_; ++p) {
    if (!w.in[p] || r[p].vn > tol_v) {
      m.point[p] = PointState::Open;
      continue;
    }
    if (std::fabs(r[p].vt) > tol_v)
      m.point[p] = r[p].vt > 0 ? PointState::SlipPos : PointState::SlipNeg;
    else
      m.point[p] = mu_k_[p / 2] == 0.0 ? PointState::SlipPos : PointState::Stick;
  }
}

template <int MaxBlocks>
bool RigidAssemblyModel<MaxBlocks>::impact(double t, Mode& m, State& z) const {
  ImpactWork w;
  Geometry geo;
  geo_.geometry(z, geo);
  rows(z, geo, m, w.r);
  const double tol_g = 1e-7 * len_;
  w.tol_v = kTol * v_scale_;
  w.p_scale = f_scale_ / g_ * v_scale_;  // momentum scale
  for (int b = 0; b < nb_; ++b)
    for (int k = 0; k < 3; ++k) w.v[3 * b + k] = z[iv(b) + k];
  // The impact set: closed points and the open ones touching.
  for (int p = 0; p < 2 * ni_; ++p) {
    const PointRows& k = w.r[p];
    w.in[p] = is_closed(m.point[p]) || (k.gap <= tol_g && k.vn < w.tol_v);
    w.active[p] = w.in[p] && (is_closed(m.point[p]) || k.vn < -w.tol_v);
    w.target[p] = -e_[p / 2] * std::fmin(k.vn, 0.0);
  }
  for (int i = 0; i < ni_; ++i) w.slip[i] = mu_s_[i] <= 0.0 ? (w.r[2 * i].vt >= 0 ? 1 : -1) : 0;
  bool settled = false;
  for (int it = 0; it < kMaxActiveSet && !settled; ++it) {
    if (!solve_impact(w)) return false;
    settled = !change_impact_set(w);
  }
  if (!settled) return false;
  // The end of an accumulation of impacts: a point that leaves its face slower than
  // settle_velocity() (it would fly no higher than the noise band) stays on it: its normal
  // velocity is set to zero by one more solve with it held (the impulse this takes is of that order).
  bool held = false;
  for (int p = 0; p < 2 * ni_; ++p) {
    if (!w.in[p] || w.active[p]) continue;
    const double un = relative_rate<kCoords>(w.vp, w.r[p], true);
    if (un > 0.0 && un < settle_velocity_ && w.target[p] < settle_velocity_) {
      w.active[p] = true;
      w.target[p] = 0.0;
      held = true;
    }
  }
  if (held && !solve_impact(w)) return false;
  apply_impact(w, m, z);
  (void)t;
  return true;
}

}  // namespace blockdyn
