// SPDX-License-Identifier: Apache-2.0
// The smooth motion of a mode of the rigid law: its contact problem (the forces that keep the
// closed points closed and the sticking interfaces stuck), the right-hand side, the event
// functions, and the choice of the mode consistent with a state.
// Part of RigidAssemblyModel's definition, included only by rigid_assembly_model.cpp (which
// instantiates the model once per capacity).

namespace blockdyn {

using namespace rigid_assembly;

template <int MaxBlocks>
typename RigidAssemblyModel<MaxBlocks>::Solution RigidAssemblyModel<MaxBlocks>::solve(
    double t, const Mode& m, const State& z, const std::array<PointRows, kPoints>& r) const {
  Solution s;
  const double ah = forced_ ? ground_.ah(t) : 0.0, av = forced_ ? ground_.av(t) : 0.0;
  const std::array<double, kCoords>& inv_mass = inv_mass_;
  std::array<double, kCoords> f{};
  for (int b = 0; b < nb_; ++b) {
    f[3 * b] = -m_[b] * g_ * ah;
    f[3 * b + 1] = -m_[b] * g_ * (1.0 + av);
  }
  constexpr int kMaxU = kPoints + kIfaces;
  ContactSystem<kCoords, kMaxU> sys;
  std::array<int, kPoints> normal_of{};
  std::array<int, kIfaces> tangent_of{}, ref_of{};
  auto place = [](std::array<double, kCoords>& v, const PointRows& k, const std::array<double, 3>& u,
                  const std::array<double, 3>& l, double w) { place_rows<kCoords>(v, k, u, l, w); };
  tangent_of.fill(-1);
  ref_of.fill(-1);
  for (int p = 0; p < 2 * ni_; ++p) {
    normal_of[p] = -1;
    const PointState st = m.point[p];
    if (!is_closed(st)) continue;
    const int j = sys.add();
    normal_of[p] = j;
    const PointRows& k = r[p];
    place(sys.col[j], k, k.nu, k.nl, 1.0);
    if (const int sg = slip_sign(st); sg != 0) place(sys.col[j], k, k.tu, k.tl, -mu_k_[p / 2] * sg);
    place(sys.row[j], k, k.nu, k.nl, 1.0);
    sys.rhs[j] = -k.kn;
    const int i = p / 2;
    if (st == PointState::Stick && ref_of[i] < 0) {
      ref_of[i] = p;
      const int jt = sys.add();
      tangent_of[i] = jt;
      place(sys.col[jt], k, k.tu, k.tl, 1.0);
      place(sys.row[jt], k, k.tu, k.tl, 1.0);
      sys.rhs[jt] = -k.kt;
    }
  }
  // Right-hand sides: minus the drifts and the free motion's rates.
  for (int j = 0; j < sys.n; ++j) {
    double free = 0.0;
    for (int c = 0; c < kCoords; ++c) free += sys.row[j][c] * inv_mass[c] * f[c];
    sys.rhs[j] -= free;
  }
  std::array<double, kMaxU> x{};
  s.ok = sys.solve(inv_mass, x);
  std::array<double, kCoords> F = f;
  for (int j = 0; j < sys.n; ++j)
    for (int c = 0; c < kCoords; ++c) F[c] += sys.col[j][c] * x[j];
  for (int c = 0; c < kCoords; ++c) s.acc[c] = F[c] * inv_mass[c];
  for (int p = 0; p < 2 * ni_; ++p) {
    if (normal_of[p] < 0) continue;
    s.fn[p] = x[normal_of[p]];
    if (const int sg = slip_sign(m.point[p]); sg != 0) s.ft[p] = -mu_k_[p / 2] * sg * s.fn[p];
  }
  // A sticking interface's tangential force, shared by its closed points as their normal forces.
  for (int i = 0; i < ni_; ++i) {
    if (tangent_of[i] < 0) continue;
    const double T = x[tangent_of[i]];
    double sum = 0.0;
    int closed = 0;
    for (int p = 2 * i; p < 2 * i + 2; ++p)
      if (m.point[p] == PointState::Stick) sum += s.fn[p], ++closed;
    for (int p = 2 * i; p < 2 * i + 2; ++p)
      if (m.point[p] == PointState::Stick) s.ft[p] = sum > 0.0 ? T * s.fn[p] / sum : T / closed;
  }
  (void)z;
  return s;
}

template <int MaxBlocks>
void RigidAssemblyModel<MaxBlocks>::rhs(double t, const Mode& m, const State& z, State& dz) const {
  dz.fill(0.0);
  if (m.rest) return;
  Geometry geo;
  geo_.geometry(z, geo);
  std::array<PointRows, kPoints> r;
  rows(z, geo, m, r);
  const Solution s = solve(t, m, z, r);
  for (int b = 0; b < nb_; ++b)
    for (int k = 0; k < 3; ++k) {
      dz[ix(b) + k] = z[iv(b) + k];
      dz[iv(b) + k] = s.acc[3 * b + k];
    }
  const auto a = ground_acceleration(t);
  double w_ground = 0.0, w_friction = 0.0;
  for (int b = 0; b < nb_; ++b) w_ground -= m_[b] * g_ * (a[0] * z[iv(b)] + a[1] * z[iv(b) + 1]);
  for (int p = 0; p < 2 * ni_; ++p)
    if (slip_sign(m.point[p]) != 0) w_friction += s.ft[p] * r[p].vt;
  dz[kWGround] = w_ground;
  dz[kWFriction] = w_friction;
}

template <int MaxBlocks>
void RigidAssemblyModel<MaxBlocks>::events(double t, const Mode& m, const State& z,
                                           std::array<double, kNumEvents>& g) const {
  g.fill(1.0);
  if (m.rest) {
    const auto a = ground_acceleration(t);
    g[ev_rest(+1)] = m.rest_pos * (1.0 + a[1]) - a[0];
    g[ev_rest(-1)] = m.rest_neg * (1.0 + a[1]) + a[0];
    return;
  }
  Geometry geo;
  geo_.geometry(z, geo);
  std::array<PointRows, kPoints> r;
  rows(z, geo, m, r);
  const Solution s = solve(t, m, z, r);
  std::array<bool, kIfaces> done{};
  for (int p = 0; p < 2 * ni_; ++p) {
    const int i = p / 2;
    const PointState st = m.point[p];
    if (!is_closed(st)) {
      g[ev_normal(p)] = r[p].gap / len_ + kNoiseBand;
      // A guard armed at any start: an opened point whose gap turned negative at once.
      g[ev_valid(p)] = r[p].gap / len_ + kTol;
    } else {
      g[ev_normal(p)] = s.fn[p] / f_scale_;
      if (st == PointState::Stick) {
        if (!done[i] && mu_s_[i] < kNoSlipFriction) {
          double fn = 0.0, ft = 0.0;
          for (int q = 2 * i; q < 2 * i + 2; ++q)
            if (m.point[q] == PointState::Stick) fn += s.fn[q], ft += s.ft[q];
          g[ev_tangent(p)] = (mu_s_[i] * fn - std::fabs(ft)) / f_scale_;
        }
        done[i] = true;
      } else if (mu_k_[i] > 0.0) {
        g[ev_tangent(p)] = slip_sign(st) * r[p].vt / v_scale_ + kNoiseBand;
      }
    }
    g[ev_owner(p)] = owner_margin(geo.lower[i], geo.upper[i], p % 2, m.owner[p]) + switch_band_;
  }
  for (int b = 0; b < nb_; ++b) {
    const double th = z[ix(b) + 2];
    g[ev_wzero(b)] = m.side[b] * th + rotation_band_;
    g[ev_collapse(b)] = geo_.rotation_limit(b) - std::fabs(th);
  }
  for (int i = 0; i < ni_; ++i)
    if (lower_[i] >= 0) g[ev_bearing(i)] = overlap(geo.lower[i], geo.upper[i]) - geo_.assembly().min_bearing;
}

template <int MaxBlocks>
bool RigidAssemblyModel<MaxBlocks>::select_mode(double t, Mode& m, const State& z) const {
  Geometry geo;
  geo_.geometry(z, geo);
  std::array<PointRows, kPoints> r;
  rows(z, geo, m, r);
  const double tol_f = kTol * f_scale_, tol_g = kTol * len_, tol_v = kTol * v_scale_, tol_a = kTol * g_;
  for (int it = 0; it < kMaxActiveSet; ++it) {
    const Solution s = solve(t, m, z, r);
    if (!s.ok) return false;
    double worst = 0.0;
    int wp = -1;
    PointState to = PointState::Open;
    bool whole_interface = false;
    auto consider = [&](double v, int p, PointState st, bool iface) {
      if (v > worst) worst = v, wp = p, to = st, whole_interface = iface;
    };
    for (int p = 0; p < 2 * ni_; ++p) {
      const int i = p / 2;
      const PointState st = m.point[p];
      if (is_closed(st)) {
        consider(-s.fn[p] / tol_f, p, PointState::Open, false);
        if (st == PointState::Stick && mu_s_[i] < kNoSlipFriction) {
          double fn = 0.0, ft = 0.0;
          for (int q = 2 * i; q < 2 * i + 2; ++q)
            if (m.point[q] == PointState::Stick) fn += s.fn[q], ft += s.ft[q];
          consider((std::fabs(ft) - mu_s_[i] * fn) / tol_f, p, ft > 0 ? PointState::SlipNeg : PointState::SlipPos,
                   true);
        } else if (slip_sign(st) != 0 && std::fabs(r[p].vt) <= tol_v) {
          consider(-slip_sign(st) * rate_of(r[p], s.acc, false) / tol_a, p, PointState::Stick, true);
        }
      } else if (std::fabs(r[p].gap) <= tol_g && std::fabs(r[p].vn) <= tol_v) {
        // A touching point that would penetrate closes, sliding with its interface if it slides.
        PointState closed = PointState::Stick;
        const int other = p ^ 1;
        if (is_closed(m.point[other]))
          closed = m.point[other];
        else if (std::fabs(r[p].vt) > tol_v)
          closed = r[p].vt > 0 ? PointState::SlipPos : PointState::SlipNeg;
        if (mu_k_[i] == 0.0 && closed == PointState::Stick) closed = PointState::SlipPos;
        consider(-rate_of(r[p], s.acc, true) / tol_a, p, closed, false);
      }
    }
    if (wp < 0 || worst <= 1.0) return true;
    if (whole_interface) {
      for (int q = 2 * (wp / 2); q < 2 * (wp / 2) + 2; ++q)
        if (is_closed(m.point[q])) m.point[q] = to;
    } else {
      m.point[wp] = to;
    }
  }
  return false;
}

}  // namespace blockdyn
