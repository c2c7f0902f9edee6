// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/assembly/moreau_jean.hpp"

#include <algorithm>
#include <cmath>

namespace blockdyn {

namespace {
constexpr double kSolveTolerance = 1e-12;

// The 2 x 2 frictional contact problem of one end: u = [a c; c d] [pn; pt] + [bn; bt],
// 0 <= pn _|_ u_N >= 0, |pt| <= mu pn, pt = -mu pn sign(u_T) when u_T != 0. Exact: separation,
// stick, or slip in the direction consistent with the resulting u_T.
void solve_local(double a, double c, double d, double bn, double bt, double mu, double& pn, double& pt) {
  if (bn >= 0.0) {
    pn = pt = 0.0;
    return;
  }
  const double det = a * d - c * c;
  if (det > 0.0) {
    pn = (-bn * d + bt * c) / det;
    pt = (-bt * a + bn * c) / det;
    if (pn >= 0.0 && std::fabs(pt) <= mu * pn) return;
  }
  double best_pn = -1.0;
  for (int s : {1, -1}) {
    const double denom = a - s * mu * c;
    if (!(denom > 0.0)) continue;
    const double n = -bn / denom, t = -s * mu * n;
    const double ut = c * n + d * t + bt;
    if (s * ut >= 0.0) {
      pn = n;
      pt = t;
      return;
    }
    if (n > best_pn) {
      best_pn = n;
      pn = n;
      pt = t;
    }
  }
  if (best_pn < 0.0) pn = pt = 0.0;
}
}  // namespace

MoreauJean::MoreauJean(const Assembly& a, const GroundMotion& g, const MoreauJeanOptions& o)
    : asm_(a), ground_(g), forced_(!g.is_zero()), o_(o), nb_(int(a.blocks.size())), ni_(int(a.interfaces.size())),
      sweeps_(0) {
  double min_size = INFINITY;
  for (const AssemblyBlock& k : a.blocks) min_size = std::fmin(min_size, std::fmin(k.width, k.height));
  // Ends this close to a face are active: blocks placed on each other touch only up to
  // rounding, and a rocking corner rises by O(h^2) per step off its pivot through the midpoint
  // positions; g h^2 is the fall of a free end in one step.
  touch_ = std::fmax(1e-9 * min_size, a.g * o.h * o.h);
  minv_.resize(3 * nb_);
  for (int b = 0; b < nb_; ++b) {
    minv_[3 * b] = minv_[3 * b + 1] = 1.0 / a.blocks[b].mass;
    minv_[3 * b + 2] = 1.0 / a.blocks[b].inertia();
  }
  const int np = 2 * ni_, n = 3 * nb_;
  qm_.resize(n);
  vfree_.resize(n);
  vnew_.resize(n);
  dv_.resize(n);
  rows_.resize(std::size_t(2 * np) * n);
  W_.resize(std::size_t(2 * np) * (2 * np));
  z_.resize(4 * np);
  bn_.resize(np);
  bt_.resize(np);
  mu_.resize(np);
  pn_.resize(np);
  pt_.resize(np);
  active_.resize(np);
  ends_.resize(np);
}

BodyPose MoreauJean::pose(const std::vector<double>& q, const std::vector<double>& v, int b) const {
  BodyPose p;
  if (b < 0) return p;
  p.x = q[3 * b];
  p.y = q[3 * b + 1];
  p.theta = q[3 * b + 2];
  p.vx = v[3 * b];
  p.vy = v[3 * b + 1];
  p.omega = v[3 * b + 2];
  p.q = BodyRotation::of(p.theta);
  return p;
}

std::array<double, 2> MoreauJean::ground_acceleration(double t) const {
  return {forced_ ? ground_.ah(t) : 0.0, forced_ ? ground_.av(t) : 0.0};
}

double MoreauJean::rotation_limit(int b) const {
  return asm_.collapse_rotation * std::atan2(asm_.blocks[b].width, asm_.blocks[b].height);
}

double MoreauJean::kinetic_energy(const std::vector<double>& v) const {
  double e = 0;
  for (int b = 0; b < nb_; ++b)
    e += 0.5 * (v[3 * b] * v[3 * b] + v[3 * b + 1] * v[3 * b + 1]) / minv_[3 * b] +
         0.5 * v[3 * b + 2] * v[3 * b + 2] / minv_[3 * b + 2];
  return e;
}

double MoreauJean::gravity_energy(const std::vector<double>& q) const {
  double e = 0;
  for (int b = 0; b < nb_; ++b) e += asm_.blocks[b].mass * asm_.g * (q[3 * b + 1] - asm_.blocks[b].y);
  return e;
}

std::pair<Face, Face> MoreauJean::faces(const std::vector<double>& q, int i) const {
  const AssemblyInterface& f = asm_.interfaces[i];
  const BodyPose up = pose(q, q, f.upper), lp = pose(q, q, f.lower);  // rates unused
  const Face uf = base_face(up, asm_.blocks[f.upper].width, asm_.blocks[f.upper].height);
  const Face lf = f.lower < 0 ? ground_face() : top_face(lp, asm_.blocks[f.lower].width, asm_.blocks[f.lower].height);
  return {lf, uf};
}

double MoreauJean::overlap_of(const std::vector<double>& q, int i) const {
  const auto [lf, uf] = faces(q, i);
  return overlap(lf, uf);
}

double MoreauJean::base_position_of(const std::vector<double>& q, int i) const {
  const auto [lf, uf] = faces(q, i);
  return base_position(lf, uf);
}

bool MoreauJean::step(double t, std::vector<double>& q, std::vector<double>& v) {
  const double h = o_.h;
  const int n = 3 * nb_, np = 2 * ni_;
  for (int k = 0; k < n; ++k) qm_[k] = q[k] + 0.5 * h * v[k];
  // Free motion: gravity and the ground's inertial forces at the midpoint in time.
  const auto a = ground_acceleration(t + 0.5 * h);
  for (int b = 0; b < nb_; ++b) {
    vfree_[3 * b] = v[3 * b] - h * asm_.g * a[0];
    vfree_[3 * b + 1] = v[3 * b + 1] - h * asm_.g * (1.0 + a[1]);
    vfree_[3 * b + 2] = v[3 * b + 2];
  }
  // Active contact ends at the midpoint positions and their Jacobian rows (normal, tangent) of
  // the relative velocity of the upper block's side against the lower's.
  int nc = 0;
  for (int p = 0; p < np; ++p) {
    const AssemblyInterface& f = asm_.interfaces[p / 2];
    const BodyPose up = pose(qm_, v, f.upper), lp = pose(qm_, v, f.lower);
    const Face uf = base_face(up, asm_.blocks[f.upper].width, asm_.blocks[f.upper].height);
    const Face lf = f.lower < 0 ? ground_face() : top_face(lp, asm_.blocks[f.lower].width, asm_.blocks[f.lower].height);
    End& e = ends_[p];
    e.owner = owner_margin(lf, uf, p % 2, 0) >= 0.0 ? 0 : 1;
    e.c = contact_point(lp, lf, up, uf, p % 2, e.owner);
    e.active = e.c.gap <= touch_;
    e.pushing = e.slipping = false;
    e.pn = e.pt = 0;
    if (!e.active) continue;
    active_[nc] = p;
    // Direction of the normal impulse on the upper block (away from the lower one).
    const Vec2 nu = e.c.corner_of_upper ? e.c.n : -1.0 * e.c.n;
    double* rn = &rows_[std::size_t(2 * nc) * n];
    double* rt = &rows_[std::size_t(2 * nc + 1) * n];
    std::fill(rn, rn + 2 * n, 0.0);
    auto add = [&](int b, double s) {
      if (b < 0) return;
      const Vec2 r = e.c.P - Vec2{qm_[3 * b], qm_[3 * b + 1]};
      rn[3 * b] += s * nu.x;
      rn[3 * b + 1] += s * nu.y;
      rn[3 * b + 2] += s * cross(r, nu);
      rt[3 * b] += s * e.c.t.x;
      rt[3 * b + 1] += s * e.c.t.y;
      rt[3 * b + 2] += s * cross(r, e.c.t);
    };
    add(f.upper, 1.0);
    add(f.lower, -1.0);
    ++nc;
  }
  auto dotrow = [&](int r, const std::vector<double>& x) {
    const double* row = &rows_[std::size_t(r) * n];
    double s = 0;
    for (int k = 0; k < n; ++k) s += row[k] * x[k];
    return s;
  };
  std::vector<double>& z = z_;
  if (nc > 0) {
    const int m = 2 * nc;
    double diag_max = 0;
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) {
        double s = 0;
        const double* ri = &rows_[std::size_t(i) * n];
        const double* rj = &rows_[std::size_t(j) * n];
        for (int k = 0; k < n; ++k) s += ri[k] * minv_[k] * rj[k];
        W_[std::size_t(i) * m + j] = s;
        if (i == j) diag_max = std::fmax(diag_max, s);
      }
    // An optional compliance on the Delassus diagonal (0 by default).
    for (int i = 0; i < m; ++i) W_[std::size_t(i) * m + i] += o_.regularisation * diag_max;
    // Nonsmooth Gauss-Seidel (Moreau; Jean): each end's 2 x 2 Coulomb problem solved exactly
    // with the others' impulses fixed, sweeps repeated until no end's relative velocity changes
    // by more than kSolveTolerance of the problem's velocity scale. The velocities are what is
    // unique: the impulses of redundant contacts (two ends per face of a resting assembly,
    // statically indeterminate) are not, and pivoting methods lose accuracy on them.
    for (int i = 0; i < nc; ++i) {
      End& e = ends_[active_[i]];
      const ContactLaw& law = asm_.interfaces[active_[i] / 2].law;
      e.un_before = dotrow(2 * i, v);
      // u_N+ + e u_N- >= 0, relaxed by the gap an end still has above its face (see below).
      bn_[i] = dotrow(2 * i, vfree_) + law.restitution * std::fmin(e.un_before, 0.0) + 2.0 * std::fmax(e.c.gap, 0.0) / h;
      bt_[i] = dotrow(2 * i + 1, vfree_);
      mu_[i] = std::fmin(law.mu_k, o_.max_friction);
      // Warm start from the end's impulses of the previous step.
      pn_[i] = e.pn_prev;
      pt_[i] = e.pt_prev;
    }
    auto Wx = [&](int i, int j) { return W_[std::size_t(i) * m + j]; };
    double v_scale = asm_.g * h;
    for (int i = 0; i < nc; ++i) v_scale = std::fmax(v_scale, std::fmax(std::fabs(bn_[i]), std::fabs(bt_[i])));
    std::fill(dv_.begin(), dv_.end(), 0.0);
    bool converged = false;
    for (int sweep = 0; sweep < o_.max_sweeps && !converged; ++sweep) {
      double change = 0;
      for (int i = 0; i < nc; ++i) {
        double bn = bn_[i], bt = bt_[i];
        for (int j = 0; j < nc; ++j) {
          if (j == i) continue;
          bn += Wx(2 * i, 2 * j) * pn_[j] + Wx(2 * i, 2 * j + 1) * pt_[j];
          bt += Wx(2 * i + 1, 2 * j) * pn_[j] + Wx(2 * i + 1, 2 * j + 1) * pt_[j];
        }
        double pn, pt;
        solve_local(Wx(2 * i, 2 * i), Wx(2 * i, 2 * i + 1), Wx(2 * i + 1, 2 * i + 1), bn, bt, mu_[i], pn, pt);
        pn_[i] = pn;
        pt_[i] = pt;
      }
      // The blocks' velocity change due to the impulses: unique even where the impulses are not.
      for (int k = 0; k < n; ++k) {
        double dv = 0;
        for (int i = 0; i < nc; ++i)
          dv += minv_[k] * (rows_[std::size_t(2 * i) * n + k] * pn_[i] + rows_[std::size_t(2 * i + 1) * n + k] * pt_[i]);
        change = std::fmax(change, std::fabs(dv - dv_[k]));
        dv_[k] = dv;
      }
      converged = sweep > 0 && change <= kSolveTolerance * v_scale;
      sweeps_ = sweep + 1;
    }
    if (!converged) return false;
    for (int i = 0; i < nc; ++i) {
      z[i] = pn_[i];
      z[nc + i] = pt_[i];
    }
  }
  // v+ = v_free + M^-1 H^T P.
  std::vector<double>& vnew = vnew_;
  for (int k = 0; k < n; ++k) vnew[k] = vfree_[k];
  for (int i = 0; i < nc; ++i) {
    const double pn = z[i], pt = z[nc + i];
    const double* rn = &rows_[std::size_t(2 * i) * n];
    const double* rt = &rows_[std::size_t(2 * i + 1) * n];
    for (int k = 0; k < n; ++k) vnew[k] += minv_[k] * (rn[k] * pn + rt[k] * pt);
  }
  // Works of the step (each impulse's P (u+ + u-)/2) and of the ground's inertial forces.
  work_normal = work_tangential = 0;
  for (int i = 0; i < nc; ++i) {
    End& e = ends_[active_[i]];
    e.pn = z[i];
    e.pt = z[nc + i];
    e.un_after = dotrow(2 * i, vnew);
    e.ut_after = dotrow(2 * i + 1, vnew);
    const double ut_before = dotrow(2 * i + 1, v);
    e.pushing = e.pn > 0.0;
    e.slipping = e.pushing && std::fabs(e.pt) >= (1.0 - 1e-9) * mu_[i] * e.pn && std::fabs(e.ut_after) > 0.0;
    work_normal += e.pn * 0.5 * (e.un_after + e.un_before);
    work_tangential += e.pt * 0.5 * (e.ut_after + ut_before);
  }
  for (End& e : ends_) {
    e.pn_prev = e.active ? e.pn : 0.0;
    e.pt_prev = e.active ? e.pt : 0.0;
  }
  work_ground = 0;
  for (int b = 0; b < nb_; ++b)
    work_ground -= asm_.blocks[b].mass * asm_.g * h *
                   (a[0] * 0.5 * (v[3 * b] + vnew[3 * b]) + a[1] * 0.5 * (v[3 * b + 1] + vnew[3 * b + 1]));
  for (int k = 0; k < n; ++k) {
    q[k] = qm_[k] + 0.5 * h * vnew[k];
    v[k] = vnew[k];
  }
  return true;
}

}  // namespace blockdyn
