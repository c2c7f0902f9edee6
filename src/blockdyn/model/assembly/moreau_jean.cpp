// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/assembly/moreau_jean.hpp"

#include "blockdyn/numerics/redundant_solve.hpp"

#include <algorithm>
#include <cmath>

namespace blockdyn {

namespace {
// The contact problem is solved when no end's relative velocity is off by more than this
// fraction of the problem's velocity scale.
constexpr double kSolveTolerance = 1e-12;
// A pivot this small against the Delassus diagonal: the guessed active set is degenerate (the
// impulses of redundant ends are not unique) and Gauss-Seidel takes over.
constexpr double kSingularPivot = 1e-13;
// Guesses of the active-set iteration before Gauss-Seidel takes over, besides 4 per end (one or
// two in practice).
constexpr int kMaxActiveSetIterations = 12;
// Block pivoting steps without fewer violated conditions before single changes take over.
constexpr int kBlockPivotStalls = 2;
// The compliance added to the Delassus matrix's diagonal, relative to its largest entry: the
// contact problem of a statically indeterminate assembly (an arch's joints, a face's two ends)
// has many impulses for one motion; the compliance picks the one of least norm and makes the
// problem positive definite, so the active-set iteration ends. It lets a resting contact creep by
// about 1e-10 of the velocity one step's gravity gives (an arch at rest: 1e-12 rad in 10 s).
constexpr double kRedundancyCompliance = 1e-10;
// An end slips when its tangential velocity after the step exceeds this fraction of the
// problem's velocity scale (the solve's own accuracy is 1e-12 of it).
constexpr double kSlipVelocity = 1e-9;

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

inline double dot3(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
}  // namespace

MoreauJean::MoreauJean(const Assembly& a, const GroundMotion& g, const MoreauJeanOptions& o)
    : asm_(a),
      ground_(g),
      forced_(!g.is_zero()),
      o_(o),
      nb_(int(a.blocks.size())),
      ni_(int(a.interfaces.size())),
      m_cap_(4 * int(a.interfaces.size())),
      sweeps_(0) {
  double min_size = INFINITY;
  for (const AssemblyBlock& k : a.blocks) min_size = std::fmin(min_size, std::fmin(k.width, k.height));
  // Ends this close to a face are active: blocks placed on each other touch only up to
  // rounding, and a rocking corner rises by O(h^2) per step off its pivot through the midpoint
  // positions; g h^2 is the fall of a free end in one step.
  touch_ = std::fmax(1e-9 * min_size, a.g * o.h * o.h);
  for (const AssemblyBlock& k : a.blocks) reach_ = std::fmax(reach_, 0.5 * std::hypot(k.width, k.height));
  minv_.resize(3 * nb_);
  for (int b = 0; b < nb_; ++b) {
    minv_[3 * b] = minv_[3 * b + 1] = 1.0 / a.blocks[b].mass;
    minv_[3 * b + 2] = 1.0 / a.blocks[b].inertia();
  }
  const int np = 2 * ni_, n = 3 * nb_;
  poses_.resize(nb_);
  rot_.resize(nb_);
  lower_face_.resize(ni_);
  upper_face_.resize(ni_);
  for (int i = 0; i < ni_; ++i) local_faces_.push_back(interface_faces(a, i));
  for (int b = 0; b < nb_; ++b) limit_.push_back(a.collapse_rotation * tipping_angle(a, b));
  qm_.resize(n);
  vfree_.resize(n);
  vnew_.resize(n);
  dv_.resize(n);
  W_.resize(std::size_t(m_cap_) * std::size_t(m_cap_));
  A_.resize(std::size_t(m_cap_) * std::size_t(m_cap_));
  rhs_.resize(m_cap_);
  pivots_.resize(m_cap_);
  lcp_m_.resize(std::size_t(4 * np) * std::size_t(4 * np));
  lcp_q_.resize(std::size_t(4 * np));
  lcp_z_.resize(std::size_t(4 * np));
  lemke_.reserve(4 * np);
  face_end_.resize(np);
  face_of_.resize(np);
  next_.resize(np);
  flips_.resize(np);
  for (auto* x : {&bn_, &bt_, &mu_, &mu_k_, &pn_, &pt_, &un_shift_}) x->resize(np);
  for (auto* x : {&ub_, &lb_, &active_, &col_n_, &col_t_}) x->resize(np);
  for (auto* x : {&ju_, &jl_, &mju_, &mjl_}) x->resize(np);
  cls_.resize(np);
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

double MoreauJean::rotation_limit(int b) const { return limit_[std::size_t(b)]; }

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
  return {lower_face_at(i, lp), upper_face_at(i, up)};
}

double MoreauJean::overlap_of(const std::vector<double>& q, int i) const {
  const auto [lf, uf] = faces(q, i);
  return overlap(lf, uf);
}

double MoreauJean::base_position_of(const std::vector<double>& q, int i) const {
  const auto [lf, uf] = faces(q, i);
  return base_position(lf, uf);
}

void MoreauJean::measure_interfaces(const std::vector<double>& q, std::vector<double>& ov,
                                    std::vector<double>& base) const {
  std::vector<BodyRotation>& rot = rot_;
  for (int b = 0; b < nb_; ++b) rot[b] = BodyRotation::of(q[3 * b + 2]);
  auto pose_of = [&](int b) {
    BodyPose p;
    if (b < 0) return p;
    p.x = q[3 * b];
    p.y = q[3 * b + 1];
    p.theta = q[3 * b + 2];
    p.q = rot[b];
    return p;
  };
  for (int i = 0; i < ni_; ++i) {
    const AssemblyInterface& f = asm_.interfaces[i];
    const Face uf = upper_face_at(i, pose_of(f.upper));
    const Face lf = lower_face_at(i, pose_of(f.lower));
    ov[i] = overlap(lf, uf);
    base[i] = base_position(lf, uf);
  }
}

void MoreauJean::velocity_change(int nc, std::vector<double>& dv) const {
  std::fill(dv.begin(), dv.end(), 0.0);
  for (int i = 0; i < nc; ++i) {
    const double pn = pn_[i], pt = pt_[i];
    double* du = &dv[3 * ub_[i]];
    const auto& a = mju_[i];
    for (int k = 0; k < 3; ++k) du[k] += a[k] * pn + a[3 + k] * pt;
    if (lb_[i] >= 0) {
      double* dl = &dv[3 * lb_[i]];
      const auto& l = mjl_[i];
      for (int k = 0; k < 3; ++k) dl[k] += l[k] * pn + l[3 + k] * pt;
    }
  }
}

bool MoreauJean::step(double t, std::vector<double>& q, std::vector<double>& v) {
  const double h = o_.h;
  const int n = 3 * nb_;
  const auto a = ground_acceleration(t + 0.5 * h);
  free_motion(q, v, a);
  const int nc = assemble_ends(v);
  delassus(nc);
  ++stats_.steps;
  sweeps_ = 0;
  if (nc > 0) {
    // The velocity scale of the problem's tolerances: the contacts' free velocities and the
    // blocks' own (a whole arch swinging on its hinges: the rounding of its blocks' velocities
    // reaches the contacts' small relative ones).
    double v_scale = asm_.g * h;
    for (int i = 0; i < nc; ++i) v_scale = std::max({v_scale, std::fabs(bn_[i]), std::fabs(bt_[i])});
    for (int b = 0; b < nb_; ++b)
      v_scale = std::max(
          {v_scale, std::fabs(vfree_[3 * b]), std::fabs(vfree_[3 * b + 1]), std::fabs(vfree_[3 * b + 2]) * reach_});
    slip_velocity_ = kSlipVelocity * v_scale;
    if (!solve(nc, v_scale)) return false;
  } else {
    ++stats_.empty;
  }
  conclude(nc, v, a);
  for (int k = 0; k < n; ++k) {
    q[k] = qm_[k] + 0.5 * h * vnew_[k];
    v[k] = vnew_[k];
  }
  return true;
}

void MoreauJean::free_motion(const std::vector<double>& q, const std::vector<double>& v,
                             const std::array<double, 2>& a) {
  const double h = o_.h;
  const int n = 3 * nb_;
  for (int k = 0; k < n; ++k) qm_[k] = q[k] + 0.5 * h * v[k];
  // Free motion: gravity and the ground's inertial forces at the midpoint in time.
  for (int b = 0; b < nb_; ++b) {
    vfree_[3 * b] = v[3 * b] - h * asm_.g * a[0];
    vfree_[3 * b + 1] = v[3 * b + 1] - h * asm_.g * (1.0 + a[1]);
    vfree_[3 * b + 2] = v[3 * b + 2];
  }
  // Poses and faces at the midpoint positions: one sincos per block.
  for (int b = 0; b < nb_; ++b) poses_[b] = pose(qm_, v, b);
  for (int i = 0; i < ni_; ++i) {
    const AssemblyInterface& f = asm_.interfaces[i];
    upper_face_[i] = upper_face_at(i, poses_[f.upper]);
    lower_face_[i] = f.lower < 0 ? lower_face_at(i, BodyPose{}) : lower_face_at(i, poses_[f.lower]);
  }
}

int MoreauJean::assemble_ends(const std::vector<double>& v) {
  const double h = o_.h;
  const int np = 2 * ni_;
  const BodyPose ground{};
  auto pose_of = [&](int b) -> const BodyPose& { return b < 0 ? ground : poses_[b]; };
  // Active contact ends and their Jacobian rows (normal, tangent) of the relative velocity of the
  // upper block's side against the lower's, per block.
  int nc = 0;
  for (int p = 0; p < np; ++p) {
    const AssemblyInterface& f = asm_.interfaces[p / 2];
    const Face& uf = upper_face_[p / 2];
    const Face& lf = lower_face_[p / 2];
    End& e = ends_[p];
    // What the end did in the previous step: its friction cone and the first guess.
    const bool was_pushing = e.active && e.pushing;
    const int was_slip = was_pushing && e.slipping ? e.slip : 0;
    const bool was_active = e.active;
    e.owner = owner_margin(lf, uf, p % 2, 0) >= 0.0 ? 0 : 1;
    e.c = contact_point(pose_of(f.lower), lf, pose_of(f.upper), uf, p % 2, e.owner);
    e.active = e.c.gap <= touch_;
    e.pushing = e.slipping = false;
    e.slip = 0;
    e.pn = e.pt = 0;
    if (!e.active) continue;
    const int i = nc++;
    active_[i] = p;
    ub_[i] = f.upper;
    lb_[i] = f.lower;
    // Direction of the normal impulse on the upper block (away from the lower one).
    const Vec2 nu = e.c.corner_of_upper ? e.c.n : -1.0 * e.c.n;
    const Vec2 ru = e.c.P - Vec2{qm_[3 * f.upper], qm_[3 * f.upper + 1]};
    ju_[i] = {nu.x, nu.y, cross(ru, nu), e.c.t.x, e.c.t.y, cross(ru, e.c.t)};
    const double* mu = &minv_[3 * f.upper];
    for (int k = 0; k < 6; ++k) mju_[i][k] = mu[k % 3] * ju_[i][k];
    if (f.lower >= 0) {
      const Vec2 rl = e.c.P - Vec2{qm_[3 * f.lower], qm_[3 * f.lower + 1]};
      jl_[i] = {-nu.x, -nu.y, -cross(rl, nu), -e.c.t.x, -e.c.t.y, -cross(rl, e.c.t)};
      const double* ml = &minv_[3 * f.lower];
      for (int k = 0; k < 6; ++k) mjl_[i][k] = ml[k % 3] * jl_[i][k];
    }
    auto row_dot = [&](int w, const std::vector<double>& x) {
      double s = dot3(&ju_[i][3 * w], &x[3 * f.upper]);
      if (f.lower >= 0) s += dot3(&jl_[i][3 * w], &x[3 * f.lower]);
      return s;
    };
    const ContactLaw& law = f.law;
    e.un_before = row_dot(0, v);
    // u_N+ + e u_N- >= 0, relaxed by the gap an end still has above its face (see below).
    un_shift_[i] = law.restitution * std::min(e.un_before, 0.0) + 2.0 * std::max(e.c.gap, 0.0) / h;
    bn_[i] = row_dot(0, vfree_) + un_shift_[i];
    bt_[i] = row_dot(1, vfree_);
    // Static friction for an end that was not slipping, kinetic for one that was (the static
    // coefficient drops to the kinetic one in solve() if the end slips all the same).
    mu_k_[i] = std::min(law.mu_k, o_.max_friction);
    mu_[i] = was_slip != 0 ? mu_k_[i] : std::max(mu_k_[i], std::min(law.mu_s, o_.max_friction));
    // Warm start from the end's impulses and pattern of the previous step.
    pn_[i] = e.pn_prev;
    pt_[i] = e.pt_prev;
    // An end that was in contact keeps its class (one without an impulse stays separate: at a
    // hinge of a redundant assembly the free motion pushes on it, the solution does not); a new
    // one is guessed by its free motion.
    cls_[i] = was_slip > 0                                   ? kSlipPos
              : was_slip < 0                                 ? kSlipNeg
              : was_pushing || (!was_active && bn_[i] < 0.0) ? kStick
                                                             : kSeparate;
  }
  return nc;
}

void MoreauJean::delassus(int nc) {
  // The Delassus matrix W = H M^-1 H^T in closed form: 2 x 2 blocks of the ends sharing a block.
  const std::size_t S = std::size_t(m_cap_);
  double diag_max = 0;
  for (int i = 0; i < nc; ++i)
    for (int j = i; j < nc; ++j) {
      double w[4] = {0, 0, 0, 0};  // nn, nt, tn, tt
      auto acc = [&](const std::array<double, 6>& A, const std::array<double, 6>& B) {
        w[0] += dot3(&A[0], &B[0]);
        w[1] += dot3(&A[0], &B[3]);
        w[2] += dot3(&A[3], &B[0]);
        w[3] += dot3(&A[3], &B[3]);
      };
      if (ub_[i] == ub_[j]) acc(mju_[i], ju_[j]);
      if (lb_[j] >= 0 && ub_[i] == lb_[j]) acc(mju_[i], jl_[j]);
      if (lb_[i] >= 0) {
        if (lb_[i] == ub_[j]) acc(mjl_[i], ju_[j]);
        if (lb_[j] >= 0 && lb_[i] == lb_[j]) acc(mjl_[i], jl_[j]);
      }
      const std::size_t ni = 2 * std::size_t(i), nj = 2 * std::size_t(j);
      W_[ni * S + nj] = W_[nj * S + ni] = w[0];
      W_[ni * S + nj + 1] = W_[(nj + 1) * S + ni] = w[1];
      W_[(ni + 1) * S + nj] = W_[nj * S + ni + 1] = w[2];
      W_[(ni + 1) * S + nj + 1] = W_[(nj + 1) * S + ni + 1] = w[3];
      if (i == j) diag_max = std::max({diag_max, w[0], w[3]});
    }
  // An optional compliance on the Delassus diagonal (0 by default).
  compliance_ = std::max(o_.regularisation, kRedundancyCompliance) * diag_max;
  for (int k = 0; k < 2 * nc; ++k) W_[std::size_t(k) * (S + 1)] += compliance_;
}

void MoreauJean::conclude(int nc, const std::vector<double>& v, const std::array<double, 2>& a) {
  const double h = o_.h;
  const int n = 3 * nb_;
  // v+ = v_free + M^-1 H^T P.
  velocity_change(nc, dv_);
  for (int k = 0; k < n; ++k) vnew_[k] = vfree_[k] + dv_[k];
  // Works of the step (each impulse's P (u+ + u-)/2) and of the ground's inertial forces.
  work_normal = work_tangential = 0;
  for (int i = 0; i < nc; ++i) {
    End& e = ends_[active_[i]];
    auto row_dot = [&](int w, const std::vector<double>& x) {
      double s = dot3(&ju_[i][3 * w], &x[3 * ub_[i]]);
      if (lb_[i] >= 0) s += dot3(&jl_[i][3 * w], &x[3 * lb_[i]]);
      return s;
    };
    e.pn = pn_[i];
    e.pt = pt_[i];
    e.un_after = row_dot(0, vnew_);
    e.ut_after = row_dot(1, vnew_);
    const double ut_before = row_dot(1, v);
    e.pushing = e.pn > 0.0;
    // A slip is the solution's class where the problem was solved exactly (unique with the
    // compliance); after Gauss-Seidel, a tangential speed above the scheme's noise.
    e.slipping = e.pushing && (classes_solved_ ? cls_[i] == kSlipPos || cls_[i] == kSlipNeg
                                               : std::fabs(e.ut_after) > slip_threshold(nc, i));
    e.slip = !e.slipping ? 0 : e.ut_after > 0 ? 1 : -1;
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
                   (a[0] * 0.5 * (v[3 * b] + vnew_[3 * b]) + a[1] * 0.5 * (v[3 * b + 1] + vnew_[3 * b + 1]));
}

bool MoreauJean::solve(int nc, double v_scale) {
  // Each pass solves a Coulomb problem with one coefficient per end; an end that slips with its
  // static coefficient gets the kinetic one and the problem is solved again (at most once per
  // end: the coefficients only drop).
  for (int pass = 0; pass <= nc; ++pass) {
    if (!solve_coulomb(nc, v_scale)) return false;
    bool dropped = false;
    velocity_change(nc, dv_);
    for (int k = 0; k < 3 * nb_; ++k) vnew_[k] = vfree_[k] + dv_[k];
    for (int i = 0; i < nc; ++i) {
      if (!(mu_[i] > mu_k_[i]) || !(pn_[i] > 0.0)) continue;
      double ut = dot3(&ju_[i][3], &vnew_[3 * ub_[i]]);
      if (lb_[i] >= 0) ut += dot3(&jl_[i][3], &vnew_[3 * lb_[i]]);
      if (classes_solved_ ? cls_[i] == kSlipPos || cls_[i] == kSlipNeg : std::fabs(ut) > slip_threshold(nc, i)) {
        mu_[i] = mu_k_[i];
        dropped = true;
      }
    }
    if (!dropped) return true;
    ++stats_.static_drops;
  }
  return true;
}

bool MoreauJean::solve_coulomb(int nc, double v_scale) {
  classes_solved_ = true;
  if (o_.direct && solve_direct(nc, v_scale) == kSolved) {
    ++stats_.direct;
    return true;
  }
  // Lemke's solution as the active-set guess: its classes, solved again directly, are checked
  // against every condition (and sharpened to the direct solve's accuracy).
  if (o_.direct && solve_lemke(nc) && solve_direct(nc, v_scale) == kSolved) {
    ++stats_.lemke;
    return true;
  }
  ++stats_.gauss_seidel;
  classes_solved_ = false;
  return solve_gauss_seidel(nc, v_scale);
}

// The step's contact problem as one LCP (Anitescu and Potra's form of the 2D Coulomb cone, exact
// in the plane): per end in contact the normal impulse P_N, per face the tangential impulse's two
// parts beta+ and beta- (P_T = beta+ - beta-, on the face's first end: a face's two ends lie on
// one line along its tangent, so one tangential impulse stands for both) and the slip speed
// lambda,
//   u_N = W_NN P_N + W_NT P_T + b_N >= 0  _|_ P_N >= 0
//   u_T + lambda >= 0 _|_ beta+ >= 0,  -u_T + lambda >= 0 _|_ beta- >= 0
//   sum mu P_N - beta+ - beta- >= 0 _|_ lambda >= 0.
// Lemke's method solves it whatever the redundancy of the contacts; the classes of its solution
// warm-start the next step's active-set guess.
bool MoreauJean::solve_lemke(int nc) {
  int nf = 0;
  for (int i = 0; i < nc; ++i) {
    if (i == 0 || active_[i - 1] / 2 != active_[i] / 2) face_end_[nf++] = i;
    face_of_[i] = nf - 1;
  }
  const int N = nc + 3 * nf, bp = nc, bm = nc + nf, lm = nc + 2 * nf;
  const std::size_t S = std::size_t(N);
  std::fill(lcp_m_.begin(), lcp_m_.begin() + std::ptrdiff_t(S * S), 0.0);
  auto M = [&](int i, int j) -> double& { return lcp_m_[std::size_t(i) * S + std::size_t(j)]; };
  // Scaled so that every unknown is an impulse and the entries are of order one: the velocity
  // rows by 1 / d (d the Delassus matrix's largest diagonal entry), the slip speed as d times an
  // impulse (a row's positive scale keeps its complementarity).
  double d = 0.0;
  for (int k = 0; k < 2 * nc; ++k) d = std::max(d, W(k, k));
  const double inv_d = 1.0 / d;
  for (int i = 0; i < nc; ++i) {
    for (int j = 0; j < nc; ++j) M(i, j) = W(2 * i, 2 * j) * inv_d;
    for (int f = 0; f < nf; ++f) {
      const double nt = W(2 * i, 2 * face_end_[f] + 1) * inv_d;
      M(i, bp + f) = nt;
      M(i, bm + f) = -nt;
    }
    lcp_q_[std::size_t(i)] = bn_[i] * inv_d;
  }
  for (int f = 0; f < nf; ++f) {
    const int r = face_end_[f];
    for (int j = 0; j < nc; ++j) {
      const double tn = W(2 * r + 1, 2 * j) * inv_d;
      M(bp + f, j) = tn;
      M(bm + f, j) = -tn;
    }
    for (int g = 0; g < nf; ++g) {
      const double tt = W(2 * r + 1, 2 * face_end_[g] + 1) * inv_d;
      M(bp + f, bp + g) = tt;
      M(bp + f, bm + g) = -tt;
      M(bm + f, bp + g) = -tt;
      M(bm + f, bm + g) = tt;
    }
    M(bp + f, lm + f) = 1.0;
    M(bm + f, lm + f) = 1.0;
    // The face's cone, scaled by its largest coefficient.
    double mu_max = 0.0;
    for (int i = r; i < nc && face_of_[i] == f; ++i) mu_max = std::max(mu_max, mu_[i]);
    const double cs = mu_max > 0.0 ? 1.0 / mu_max : 1.0;
    for (int i = r; i < nc && face_of_[i] == f; ++i) M(lm + f, i) = mu_[i] * cs;
    M(lm + f, bp + f) = -cs;
    M(lm + f, bm + f) = -cs;
    lcp_q_[std::size_t(bp + f)] = bt_[r] * inv_d;
    lcp_q_[std::size_t(bm + f)] = -bt_[r] * inv_d;
    lcp_q_[std::size_t(lm + f)] = 0.0;
  }
  if (!lemke_.solve(N, lcp_m_.data(), N, lcp_q_.data(), lcp_z_.data())) return false;
  for (int i = 0; i < nc; ++i) {
    const int f = face_of_[i];
    pn_[i] = lcp_z_[std::size_t(i)];
    pt_[i] = face_end_[f] == i ? lcp_z_[std::size_t(bp + f)] - lcp_z_[std::size_t(bm + f)] : 0.0;
  }
  for (int i = 0; i < nc; ++i) {
    const int f = face_of_[i], r = face_end_[f];
    const double slip = lcp_z_[std::size_t(lm + f)];
    cls_[i] = !(pn_[i] > 0.0) ? kSeparate : slip > 0.0 ? (pt_[r] > 0.0 ? kSlipNeg : kSlipPos) : kStick;
  }
  // The face's tangential impulse shared by its ends as their normal impulses (slipping ends:
  // each -s mu P_N, as the active-set solution has them).
  for (int f = 0; f < nf; ++f) {
    const int r = face_end_[f];
    double T = pt_[r], N_sum = 0.0;
    for (int i = r; i < nc && face_of_[i] == f; ++i) N_sum += pn_[i];
    for (int i = r; i < nc && face_of_[i] == f; ++i) {
      if (cls_[i] == kSlipPos || cls_[i] == kSlipNeg)
        pt_[i] = (cls_[i] == kSlipPos ? -1.0 : 1.0) * mu_[i] * pn_[i];
      else
        pt_[i] = N_sum > 0.0 ? T * pn_[i] / N_sum : (i == r ? T : 0.0);
    }
  }
  return true;
}

// The linear system of the guessed pattern (separate, stick, slip +/-) into A_ and rhs_: u_N = 0
// for every end in contact, u_T = 0 for every sticking end, P_T = -s mu_k P_N for every slipping
// one. Returns its size.
int MoreauJean::assemble_guess(int nc) {
  const std::size_t S = std::size_t(m_cap_);
  int m = 0;
  // One tangential unknown per sticking face, on its first sticking end: the two ends of a face
  // lie on one line along its tangent, so only the sum of their tangential impulses acts (the
  // split, a redundancy, is shared out once solved). The unknowns go end by end, so that a
  // chain of blocks (a column, an arch) gives a banded matrix.
  for (int i = 0; i < nc; ++i) {
    col_n_[i] = cls_[i] != kSeparate ? m++ : -1;
    const int j = cls_[i] == kStick ? sticking_partner(nc, i) : 0;
    col_t_[i] = cls_[i] == kStick && (j < 0 || j > i) ? m++ : -1;
  }
  // Equation rows in the same order as the unknowns: u_N of ends in contact, u_T of sticking ones.
  auto coeff_row = [&](int wrow, double* out) {
    for (int j = 0; j < nc; ++j) {
      if (col_n_[j] < 0) continue;
      double c = W(wrow, 2 * j);
      if (cls_[j] == kSlipPos || cls_[j] == kSlipNeg)
        c -= (cls_[j] == kSlipPos ? 1.0 : -1.0) * mu_[j] * W(wrow, 2 * j + 1);
      out[col_n_[j]] = c;
      if (col_t_[j] >= 0) out[col_t_[j]] = W(wrow, 2 * j + 1);
    }
  };
  for (int i = 0; i < nc; ++i) {
    if (col_n_[i] >= 0) {
      coeff_row(2 * i, &A_[std::size_t(col_n_[i]) * S]);
      rhs_[col_n_[i]] = -bn_[i];
    }
    if (col_t_[i] >= 0) {
      coeff_row(2 * i + 1, &A_[std::size_t(col_t_[i]) * S]);
      rhs_[col_t_[i]] = -bt_[i];
    }
  }
  return m;
}

// The impulses of the guessed pattern from the assembled system of size m.
void MoreauJean::solve_guess(int nc, int m, double diag_max) {
  // Without slipping ends the system is the Delassus matrix's restriction (symmetric positive
  // definite unless degenerate).
  bool any_slip = false;
  for (int i = 0; i < nc; ++i) any_slip = any_slip || cls_[i] == kSlipPos || cls_[i] == kSlipNeg;
  if (any_slip)
    gauss_solve(A_.data(), rhs_.data(), m, m_cap_, kSingularPivot * diag_max, pivots_.data());
  else
    cholesky_solve(A_.data(), rhs_.data(), m, m_cap_, kSingularPivot * diag_max, pivots_.data());
  for (int i = 0; i < nc; ++i) {
    pn_[i] = col_n_[i] >= 0 ? rhs_[col_n_[i]] : 0.0;
    pt_[i] = col_t_[i] >= 0        ? rhs_[col_t_[i]]
             : cls_[i] == kSlipPos ? -mu_[i] * pn_[i]
             : cls_[i] == kSlipNeg ? mu_[i] * pn_[i]
                                   : 0.0;
  }
}

// Checks every condition of the guess (P_N >= 0, the cone, the slip direction, u_N >= 0 where
// separate); each violated one proposes a new guess for its end in next_. Returns how many are
// violated, the first in `first`; `accurate`: the holding ends' equations are met to tol.
int MoreauJean::check_guess(int nc, double tol, double diag_max, int& first, bool& accurate) {
  // Check every condition; the violated ones change their end's guess. The relative
  // velocities after the step from the blocks' (sparse: two blocks per end).
  velocity_change(nc, dv_);
  for (int k = 0; k < 3 * nb_; ++k) vnew_[k] = vfree_[k] + dv_[k];
  // The conditions of the regularised problem (u + c P = 0 where an end holds); each violated
  // one proposes a new guess for its end (for the face's cone: for both its ends).
  const double p_tol = tol / diag_max;
  int violations = 0;
  first = -1;
  accurate = true;
  for (int i = 0; i < nc; ++i) next_[i] = cls_[i];
  for (int i = 0; i < nc; ++i) {
    double un = dot3(&ju_[i][0], &vnew_[3 * ub_[i]]), ut = dot3(&ju_[i][3], &vnew_[3 * ub_[i]]);
    if (lb_[i] >= 0) {
      un += dot3(&jl_[i][0], &vnew_[3 * lb_[i]]);
      ut += dot3(&jl_[i][3], &vnew_[3 * lb_[i]]);
    }
    un += un_shift_[i];  // Newton's law and the gap allowance (see step())
    const double cn = un + compliance_ * pn_[i], ct = ut + compliance_ * pt_[i];
    bool violated = false;
    switch (cls_[i]) {
      case kSeparate:
        if (un < -tol) next_[i] = kStick, violated = true;
        break;
      case kStick: {
        accurate = accurate && std::fabs(cn) <= tol && (col_t_[i] < 0 || std::fabs(ct) <= tol);
        // The face's two ends lie on one line along its tangent, so only their tangential
        // impulses' sum is defined (a redundant pair may put it all on one end): the cone is
        // the face's, sum |P_T| <= sum mu P_N.
        const int j = sticking_partner(nc, i);
        const double pt = pt_[i] + (j >= 0 ? pt_[j] : 0.0);
        const double cap = mu_[i] * pn_[i] + (j >= 0 ? mu_[j] * pn_[j] : 0.0);
        if (pn_[i] < -p_tol) {
          // Sticking pulls and separating penetrates (the end has gone back and forth): what
          // remains is sliding at a vanishing normal impulse, against the tangential one.
          next_[i] = flips_[i] >= 2 && j < 0 ? (pt > 0 ? kSlipNeg : kSlipPos) : kSeparate;
          violated = true;
        } else if (std::fabs(pt) > cap + p_tol && (j < 0 || pn_[j] >= -p_tol)) {
          // Outside the cone: the face slips against the impulse's tendency.
          next_[i] = pt > 0 ? kSlipNeg : kSlipPos;
          if (j >= 0) next_[j] = next_[i];
          violated = true;
        }
        break;
      }
      case kSlipPos:
      case kSlipNeg: {
        accurate = accurate && std::fabs(cn) <= tol;
        const double sg = cls_[i] == kSlipPos ? 1.0 : -1.0;
        if (pn_[i] < -p_tol) {
          next_[i] = kSeparate, violated = true;
        } else if (sg * ut < -tol) {
          next_[i] = kStick, violated = true;
        }
        break;
      }
    }
    if (violated && first < 0) first = i;
    violations += violated;
  }
  return violations;
}

// Active-set iteration: for the guessed pattern the impulses solve one linear system; the
// violated conditions change their end's guess.
MoreauJean::DirectOutcome MoreauJean::solve_direct(int nc, double v_scale) {
  const double tol = kSolveTolerance * v_scale;
  const std::size_t S = std::size_t(m_cap_);
  double diag_max = 0;
  for (int k = 0; k < 2 * nc; ++k) diag_max = std::max(diag_max, W_[std::size_t(k) * (S + 1)]);
  int best = nc + 1, stalls = 0;
  for (int i = 0; i < nc; ++i) flips_[i] = 0;
  for (int iter = 0; iter < kMaxActiveSetIterations; ++iter) {
    ++stats_.active_set_iterations;
    solve_guess(nc, assemble_guess(nc), diag_max);
    int first = -1;
    bool accurate = true;
    const int violations = check_guess(nc, tol, diag_max, first, accurate);
    if (violations == 0) {
      if (!accurate) return kFailed;
      share_sticking_friction(nc);
      return kSolved;
    }
    // Block pivoting (every violated guess changed at once) while it makes progress; then
    // Murty's rule, one change at a time at the lowest violated index, which ends for the
    // positive definite (regularised) problem.
    if (violations < best)
      best = violations, stalls = 0;
    else
      ++stalls;
    for (int i = 0; i < nc; ++i) flips_[i] += next_[i] != cls_[i];
    if (stalls <= kBlockPivotStalls) {
      for (int i = 0; i < nc; ++i) cls_[i] = next_[i];
    } else {
      const int j = sticking_partner(nc, first);
      cls_[first] = next_[first];
      if (j >= 0 && next_[j] == next_[first] && (next_[first] == kSlipPos || next_[first] == kSlipNeg))
        cls_[j] = next_[j];
    }
  }
  return kFailed;
}

double MoreauJean::slip_threshold(int nc, int i) const {
  // The compliance lets a sticking face creep by c |P_T| (c the compliance, P_T its tangential
  // impulse): not a slip.
  double pt = std::fabs(pt_[i]);
  for (int j : {i - 1, i + 1})
    if (j >= 0 && j < nc && active_[j] / 2 == active_[i] / 2) pt += std::fabs(pt_[j]);
  return slip_velocity_ + 2.0 * compliance_ * pt;
}

int MoreauJean::sticking_partner(int nc, int i) const {
  for (int j : {i - 1, i + 1})
    if (j >= 0 && j < nc && active_[j] / 2 == active_[i] / 2 && cls_[j] == kStick) return j;
  return -1;
}

void MoreauJean::share_sticking_friction(int nc) {
  // A sticking face's tangential impulse shared by its two ends as their normal impulses (the
  // split is not unique; this one keeps each end inside its own cone and warm-starts the next
  // step's Gauss-Seidel well).
  for (int i = 0; i + 1 < nc; ++i) {
    const int j = i + 1;
    if (cls_[i] != kStick || sticking_partner(nc, i) != j) continue;
    const double T = pt_[i] + pt_[j], N = pn_[i] + pn_[j];
    if (N > 0.0) {
      pt_[i] = T * pn_[i] / N;
      pt_[j] = T * pn_[j] / N;
    }
    ++i;
  }
}

// Nonsmooth Gauss-Seidel (Moreau; Jean): each end's 2 x 2 Coulomb problem solved exactly with
// the others' impulses fixed, sweeps repeated until no block's velocity change from the
// impulses moves by more than kSolveTolerance of the problem's velocity scale. The velocities
// are what is unique: the impulses of redundant contacts (two ends per face of a resting
// assembly, statically indeterminate) are not, and pivoting methods lose accuracy on them.
bool MoreauJean::solve_gauss_seidel(int nc, double v_scale) {
  const int n = 3 * nb_;
  for (int i = 0; i < nc; ++i) {
    pn_[i] = ends_[active_[i]].pn_prev;
    pt_[i] = ends_[active_[i]].pt_prev;
  }
  std::fill(dv_.begin(), dv_.end(), 0.0);
  std::vector<double>& dv_new = vnew_;  // scratch until the step's end
  bool converged = false;
  for (int sweep = 0; sweep < o_.max_sweeps && !converged; ++sweep) {
    for (int i = 0; i < nc; ++i) {
      double bn = bn_[i], bt = bt_[i];
      for (int j = 0; j < nc; ++j) {
        if (j == i) continue;
        bn += W(2 * i, 2 * j) * pn_[j] + W(2 * i, 2 * j + 1) * pt_[j];
        bt += W(2 * i + 1, 2 * j) * pn_[j] + W(2 * i + 1, 2 * j + 1) * pt_[j];
      }
      solve_local(W(2 * i, 2 * i), W(2 * i, 2 * i + 1), W(2 * i + 1, 2 * i + 1), bn, bt, mu_[i], pn_[i], pt_[i]);
    }
    // The blocks' velocity change due to the impulses: unique even where the impulses are not.
    velocity_change(nc, dv_new);
    double change = 0;
    for (int k = 0; k < n; ++k) {
      change = std::max(change, std::fabs(dv_new[k] - dv_[k]));
      dv_[k] = dv_new[k];
    }
    converged = sweep > 0 && change <= kSolveTolerance * v_scale;
    sweeps_ = sweep + 1;
  }
  stats_.sweeps += sweeps_;
  return converged;
}

}  // namespace blockdyn
