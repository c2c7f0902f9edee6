// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/assembly/rigid_assembly_model.hpp"

#include "blockdyn/base/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "blockdyn/model/assembly/rest_limit.hpp"
#include "blockdyn/numerics/dense_solve.hpp"

namespace blockdyn {

namespace {
// Relative tolerances of the mode selection: a force, gap, velocity or acceleration this small
// (against the assembly's weight, smallest size, sqrt(g L) and g) counts as zero.
constexpr double kTol = 1e-9;
// Rounding band of the gap and slip-rate events (relative to L and sqrt(g L)): a gap computed from
// positions of order L carries rounding of order 1e-16 L, so a point that leaves its face with a
// tiny velocity (the last impacts of an accumulation) would otherwise see its gap cross zero in
// the rounding, at once and again. A point closes 1e-12 L past contact.
constexpr double kNoiseBand = 1e-12;
// Iterations of an active-set search before it is declared unsettled.
constexpr int kMaxActiveSet = 64;

// The drift of a relative velocity u . X (X rotating with body B) for the corner P of body A:
// the velocity-dependent part of its rate.
double drift(const BodyPose* A, const BodyPose* B, const Vec2& P, const Vec2& X) {
  const double wa = A ? A->omega : 0.0, wb = B ? B->omega : 0.0;
  const Vec2 ra = A ? P - Vec2{A->x, A->y} : Vec2{};
  const Vec2 va = A ? material_velocity(*A, P) : Vec2{};
  const Vec2 vb_c = B ? Vec2{B->vx, B->vy} : Vec2{};
  const Vec2 vb = B ? material_velocity(*B, P) : Vec2{};
  return -wa * wa * dot(ra, X) - wb * dot(perp(va - vb_c), X) + wb * dot(va - vb, perp(X));
}

// The assembly as the deformable model's geometry needs it: its laws' dashpots are never used
// here, but their calibration must not see the rigid law's restitution 0.
Assembly for_geometry(Assembly a) {
  for (AssemblyInterface& f : a.interfaces) f.law.damping = 0.0;
  return a;
}
}  // namespace

template <int MaxBlocks>
RigidAssemblyModel<MaxBlocks>::RigidAssemblyModel(const Assembly& a, const GroundMotion& g, double noise_band)
    : geo_(for_geometry(a), g, noise_band),
      ground_(g),
      forced_(!g.is_zero()),
      nb_(int(a.blocks.size())),
      ni_(int(a.interfaces.size())),
      g_(a.g),
      rotation_band_(noise_band) {
  len_ = INFINITY;
  f_scale_ = 0.0;
  for (int b = 0; b < nb_; ++b) {
    const AssemblyBlock& k = a.blocks[b];
    m_[b] = k.mass;
    I_[b] = k.inertia();
    inv_mass_[3 * b] = inv_mass_[3 * b + 1] = 1.0 / k.mass;
    inv_mass_[3 * b + 2] = 1.0 / k.inertia();
    y0_[b] = k.y;
    len_ = std::fmin(len_, std::fmin(k.width, k.height));
    f_scale_ += k.mass * g_;
  }
  for (int i = 0; i < ni_; ++i) {
    const AssemblyInterface& f = a.interfaces[i];
    lower_[i] = f.lower;
    upper_[i] = f.upper;
    mu_s_[i] = f.law.mu_s;
    mu_k_[i] = f.law.mu_k;
    e_[i] = f.law.restitution;
  }
  v_scale_ = std::sqrt(g_ * len_);
  settle_velocity_ = std::sqrt(2.0 * g_ * std::fmax(noise_band, 1e-12 * len_));
  step_hint_ = 1e-3 * std::sqrt(len_ / g_);
  switch_band_ = std::fmax(1e-10 * len_, noise_band);
  z0_ = geo_.initial_state();
}

template <int MaxBlocks>
void RigidAssemblyModel<MaxBlocks>::rows(const State& z, const Geometry& geo, const Mode& m,
                                         std::array<PointRows, kPoints>& r) const {
  for (int p = 0; p < 2 * ni_; ++p) {
    const int i = p / 2, owner = m.owner[p];
    const int u = upper_[i], l = lower_[i];
    PointRows& k = r[p];
    k.upper = u;
    k.lower = l;
    const BodyPose& pu = geo.pose[u];
    const BodyPose& pl = geo.of(l);
    k.c = contact_point(pl, geo.lower[i], pu, geo.upper[i], p % 2, owner);
    const Vec2 N = owner == 0 ? k.c.n : -1.0 * k.c.n, T = k.c.t;
    const Vec2 ru = k.c.P - Vec2{pu.x, pu.y};
    k.nu = {N.x, N.y, cross(ru, N)};
    k.tu = {T.x, T.y, cross(ru, T)};
    if (l >= 0) {
      const Vec2 rl = k.c.P - Vec2{pl.x, pl.y};
      k.nl = {-N.x, -N.y, -cross(rl, N)};
      k.tl = {-T.x, -T.y, -cross(rl, T)};
    } else {
      k.nl = k.tl = {0, 0, 0};
    }
    k.gap = k.c.gap;
    k.vn = k.c.gap_rate;
    k.vt = k.c.slip_rate;
    // The corner's body A and the face's body B (nullptr: the ground).
    const BodyPose* A = owner == 0 ? &pu : (l >= 0 ? &pl : nullptr);
    const BodyPose* B = owner == 0 ? (l >= 0 ? &pl : nullptr) : &pu;
    k.kn = drift(A, B, k.c.P, k.c.n);
    k.kt = (owner == 0 ? 1.0 : -1.0) * drift(A, B, k.c.P, k.c.t);
  }
}

template <int MaxBlocks>
double RigidAssemblyModel<MaxBlocks>::rate_of(const PointRows& r, const std::array<double, kCoords>& acc,
                                              bool normal) const {
  const auto& ru = normal ? r.nu : r.tu;
  const auto& rl = normal ? r.nl : r.tl;
  double v = normal ? r.kn : r.kt;
  for (int k = 0; k < 3; ++k) {
    v += ru[k] * acc[3 * r.upper + k];
    if (r.lower >= 0) v += rl[k] * acc[3 * r.lower + k];
  }
  return v;
}

namespace {
// The contact problem of a mode as a dense linear system over the unknown forces (or impulses):
// each unknown has a generalized force column, each constraint a row; A = rows M^-1 columns.
template <int NC, int MaxU>
struct ContactSystem {
  std::array<std::array<double, NC>, MaxU> col{}, row{};
  std::array<double, MaxU> rhs{};
  int n = 0;
  void clear() { n = 0; }
  int add() {
    col[n].fill(0.0);
    row[n].fill(0.0);
    return n++;
  }
  // Solve for the unknowns; the least-norm solution where the constraints are redundant.
  bool solve(const std::array<double, NC>& inv_mass, std::array<double, MaxU>& x) const {
    if (n == 0) return true;
    static_assert(MaxU <= kMaxDenseUnknowns, "the contact system exceeds the dense solver's size");
    std::array<double, MaxU * MaxU> A;
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j) {
        double s = 0.0;
        for (int c = 0; c < NC; ++c) s += row[k][c] * inv_mass[c] * col[j][c];
        A[std::size_t(k * n + j)] = s;
      }
    return solve_dense_least_norm(n, A.data(), rhs.data(), x.data());
  }
};

// A contact point's rows, scaled by s, added into a generalized vector (upper block's u, lower's l).
template <int NC, class Rows>
void place_rows(std::array<double, NC>& w, const Rows& k, const std::array<double, 3>& u,
                const std::array<double, 3>& l, double s) {
  for (int c = 0; c < 3; ++c) {
    w[3 * k.upper + c] += s * u[c];
    if (k.lower >= 0) w[3 * k.lower + c] += s * l[c];
  }
}

// The point's relative normal (or tangential) velocity for the generalized velocities w.
template <int NC, class Rows>
double relative_rate(const std::array<double, NC>& w, const Rows& k, bool normal) {
  const auto& u = normal ? k.nu : k.tu;
  const auto& l = normal ? k.nl : k.tl;
  double s = 0.0;
  for (int c = 0; c < 3; ++c) {
    s += u[c] * w[3 * k.upper + c];
    if (k.lower >= 0) s += l[c] * w[3 * k.lower + c];
  }
  return s;
}
}  // namespace

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

template <int MaxBlocks>
typename RigidAssemblyModel<MaxBlocks>::State RigidAssemblyModel<MaxBlocks>::abs_tol_scale() const {
  State s;
  s.fill(1.0);
  return s;
}

template <int MaxBlocks>
double RigidAssemblyModel<MaxBlocks>::next_breakpoint(double t, const Mode& m) const {
  if (!forced_) return INFINITY;
  if (!m.rest) return ground_.next_break(t);
  if (!(m.rest_pos == exit_pos_ && m.rest_neg == exit_neg_)) {
    rest_exit_ = RestExit(ground_, m.rest_pos, m.rest_neg);
    exit_pos_ = m.rest_pos;
    exit_neg_ = m.rest_neg;
  }
  return rest_exit_.checkpoint(t);
}

template <int MaxBlocks>
typename RigidAssemblyModel<MaxBlocks>::Mode RigidAssemblyModel<MaxBlocks>::initial_mode(const State& z) const {
  Mode m{};
  Geometry geo;
  geo_.geometry(z, geo);
  for (int p = 0; p < 2 * ni_; ++p) {
    const int i = p / 2;
    m.owner[p] = owner_margin(geo.lower[i], geo.upper[i], p % 2, 0) >= 0.0 ? 0 : 1;
    const double gap = contact_gap(geo.lower[i], geo.upper[i], p % 2, m.owner[p]);
    m.point[p] =
        std::fabs(gap) <= 1e-7 * len_ ? (mu_k_[i] == 0.0 ? PointState::SlipPos : PointState::Stick) : PointState::Open;
  }
  for (int b = 0; b < nb_; ++b) m.side[b] = z[ix(b) + 2] < 0.0 ? -1 : 1;
  State zz = z;
  if (try_rest(0.0, m, zz)) return m;
  // Resting on every face but not held by it at t = 0 (a load beyond the static limit from the
  // start): the sticking mode, whose failing conditions fire at t = 0 as events, so the run
  // reports how it left rest.
  bool touching = true, still = true;
  for (int p = 0; p < 2 * ni_; ++p) touching &= is_closed(m.point[p]);
  for (int b = 0; b < nb_; ++b)
    for (int k = 0; k < 3; ++k) still &= z[iv(b) + k] == 0.0;
  if (touching && still) return m;
  if (!select_mode(0.0, m, z)) throw std::invalid_argument("initial state: no consistent contact mode");
  return m;
}

template <int MaxBlocks>
std::optional<std::string> RigidAssemblyModel<MaxBlocks>::validity_problem(const Mode& m, const State& z) const {
  for (std::size_t k = 0; k < kDim; ++k)
    if (!std::isfinite(z[k])) return "the state is not finite";
  Geometry geo;
  geo_.geometry(z, geo);
  for (int p = 0; p < 2 * ni_; ++p) {
    const double gap = contact_gap(geo.lower[p / 2], geo.upper[p / 2], p % 2, m.owner[p]);
    if (gap < -0.02 * len_)
      return "interpenetration " + number_text(-gap, 6) + " m at interface " + std::to_string(p / 2);
  }
  return std::nullopt;
}

template <int MaxBlocks>
typename RigidAssemblyModel<MaxBlocks>::Energy RigidAssemblyModel<MaxBlocks>::energy_terms(const Mode&,
                                                                                           const State& z) const {
  Energy e;
  for (int b = 0; b < nb_; ++b) {
    const double vx = z[iv(b)], vy = z[iv(b) + 1], w = z[iv(b) + 2];
    e.kinetic += 0.5 * m_[b] * (vx * vx + vy * vy) + 0.5 * I_[b] * w * w;
    e.gravity += m_[b] * g_ * (z[ix(b) + 1] - y0_[b]);
  }
  return e;
}

template <int MaxBlocks>
typename RigidAssemblyModel<MaxBlocks>::PointForce RigidAssemblyModel<MaxBlocks>::point_force(const Mode& m,
                                                                                              const State& z, double t,
                                                                                              int p) const {
  Geometry geo;
  geo_.geometry(z, geo);
  std::array<PointRows, kPoints> r;
  Mode mm = m;
  if (m.rest) mm.rest = false;
  rows(z, geo, mm, r);
  PointForce f;
  f.c = r[p].c;
  if (!is_closed(mm.point[p])) return f;
  const Solution s = solve(t, mm, z, r);
  f.fn = s.fn[p];
  f.ft = s.ft[p];
  return f;
}

template <int MaxBlocks>
typename RigidAssemblyModel<MaxBlocks>::PointForce RigidAssemblyModel<MaxBlocks>::point_force(const Mode& m,
                                                                                              const State& z,
                                                                                              int p) const {
  return point_force(m, z, 0.0, p);
}

template class RigidAssemblyModel<1>;
template class RigidAssemblyModel<3>;
template class RigidAssemblyModel<8>;
template class RigidAssemblyModel<24>;

}  // namespace blockdyn
