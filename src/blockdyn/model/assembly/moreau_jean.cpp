// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/assembly/moreau_jean.hpp"

#include <algorithm>
#include <cmath>

namespace blockdyn {

namespace {
// The compliance added to the Delassus matrix's diagonal, relative to its largest entry: the
// contact problem of a statically indeterminate assembly (an arch's joints, a face's two ends)
// has many impulses for one motion; the compliance picks the one of least norm and makes the
// problem positive definite, so the active-set iteration ends. It lets a resting contact creep by
// about 1e-10 of the velocity one step's gravity gives (an arch at rest: 1e-12 rad in 10 s).
constexpr double kRedundancyCompliance = 1e-10;
// An end slips when its tangential velocity after the step exceeds this fraction of the
// problem's velocity scale (the solve's own accuracy is 1e-12 of it).
constexpr double kSlipVelocity = 1e-9;

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
  solver_.reserve(np, n);
  for (auto* x : {&bn_, &bt_, &mu_, &mu_k_, &pn_warm_, &pt_warm_, &un_shift_}) x->resize(np);
  for (auto* x : {&ub_, &lb_, &active_, &face_}) x->resize(np);
  for (auto* x : {&ju_, &jl_, &mju_, &mjl_}) x->resize(np);
  ends_.resize(np);
  // The step's problem: its arrays are these (their sizes never change); n set at each step.
  problem_.W = W_.data();
  problem_.stride = std::size_t(m_cap_);
  problem_.bn = bn_.data();
  problem_.bt = bt_.data();
  problem_.mu = mu_.data();
  problem_.face = face_.data();
  problem_.pn_warm = pn_warm_.data();
  problem_.pt_warm = pt_warm_.data();
  problem_.coords = n;
  problem_.velocities = &velocities_;
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

void MoreauJean::velocity_change(int nc, const double* pn_of, const double* pt_of, double* dv) const {
  std::fill(dv, dv + 3 * nb_, 0.0);
  for (int i = 0; i < nc; ++i) {
    const double pn = pn_of[i], pt = pt_of[i];
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

void MoreauJean::StepVelocities::relative(const double* pn, const double* pt, double* un, double* ut) {
  MoreauJean& s = *self;
  const int nc = s.problem_.n;
  s.velocity_change(nc, pn, pt, s.dv_.data());
  for (int k = 0; k < 3 * s.nb_; ++k) s.vnew_[k] = s.vfree_[k] + s.dv_[k];
  for (int i = 0; i < nc; ++i) {
    double n = dot3(&s.ju_[i][0], &s.vnew_[3 * s.ub_[i]]), t = dot3(&s.ju_[i][3], &s.vnew_[3 * s.ub_[i]]);
    if (s.lb_[i] >= 0) {
      n += dot3(&s.jl_[i][0], &s.vnew_[3 * s.lb_[i]]);
      t += dot3(&s.jl_[i][3], &s.vnew_[3 * s.lb_[i]]);
    }
    n += s.un_shift_[i];  // Newton's law and the gap allowance (see step())
    un[i] = n;
    ut[i] = t;
  }
}

void MoreauJean::StepVelocities::bodies(const double* pn, const double* pt, double* dv) {
  self->velocity_change(self->problem_.n, pn, pt, dv);
}

bool MoreauJean::step(double t, std::vector<double>& q, std::vector<double>& v) {
  const double h = o_.h;
  const int n = 3 * nb_;
  const auto a = ground_acceleration(t + 0.5 * h);
  free_motion(q, v, a);
  const int nc = assemble_ends(v);
  delassus(nc);
  problem_.n = nc;
  problem_.compliance = compliance_;
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
    face_[i] = p / 2;
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
    pn_warm_[i] = e.pn_prev;
    pt_warm_[i] = e.pt_prev;
    // An end that was in contact keeps its class (one without an impulse stays separate: at a
    // hinge of a redundant assembly the free motion pushes on it, the solution does not); a new
    // one is guessed by its free motion.
    solver_.classes()[i] = was_slip > 0                                   ? ContactClass::SlipPos
                           : was_slip < 0                                 ? ContactClass::SlipNeg
                           : was_pushing || (!was_active && bn_[i] < 0.0) ? ContactClass::Stick
                                                                          : ContactClass::Separate;
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
  const auto& pn = solver_.pn();
  const auto& pt = solver_.pt();
  const auto& cls = solver_.classes();
  velocity_change(nc, pn.data(), pt.data(), dv_.data());
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
    e.pn = pn[i];
    e.pt = pt[i];
    e.un_after = row_dot(0, vnew_);
    e.ut_after = row_dot(1, vnew_);
    const double ut_before = row_dot(1, v);
    e.pushing = e.pn > 0.0;
    // A slip is the solution's class where the problem was solved exactly (unique with the
    // compliance); after Gauss-Seidel, a tangential speed above the scheme's noise.
    e.slipping =
        e.pushing && (classes_solved_ ? is_slip(cls[i])
                                      : std::fabs(e.ut_after) > solver_.slip_threshold(problem_, i, slip_velocity_));
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
    if (!solve_coulomb(v_scale)) return false;
    bool dropped = false;
    const auto& pn = solver_.pn();
    velocity_change(nc, pn.data(), solver_.pt().data(), dv_.data());
    for (int k = 0; k < 3 * nb_; ++k) vnew_[k] = vfree_[k] + dv_[k];
    for (int i = 0; i < nc; ++i) {
      if (!(mu_[i] > mu_k_[i]) || !(pn[i] > 0.0)) continue;
      double ut = dot3(&ju_[i][3], &vnew_[3 * ub_[i]]);
      if (lb_[i] >= 0) ut += dot3(&jl_[i][3], &vnew_[3 * lb_[i]]);
      if (classes_solved_ ? is_slip(solver_.classes()[i])
                          : std::fabs(ut) > solver_.slip_threshold(problem_, i, slip_velocity_)) {
        mu_[i] = mu_k_[i];
        dropped = true;
      }
    }
    if (!dropped) return true;
    ++stats_.static_drops;
  }
  return true;
}

bool MoreauJean::solve_coulomb(double v_scale) {
  const double tol = PlanarContactSolver::kSolveTolerance * v_scale;
  classes_solved_ = true;
  const long before = solver_.active_set_iterations();
  auto count = [&] { stats_.active_set_iterations += solver_.active_set_iterations() - before; };
  if (o_.direct && solver_.solve_direct(problem_, tol)) {
    count();
    ++stats_.direct;
    return true;
  }
  // Lemke's solution as the active-set guess: its classes, solved again directly, are checked
  // against every condition (and sharpened to the direct solve's accuracy).
  if (o_.direct && solver_.solve_lemke(problem_) && solver_.solve_direct(problem_, tol)) {
    count();
    ++stats_.lemke;
    return true;
  }
  count();
  ++stats_.gauss_seidel;
  classes_solved_ = false;
  const bool ok = solver_.solve_gauss_seidel(problem_, PlanarContactSolver::kSolveTolerance * v_scale, o_.max_sweeps);
  sweeps_ = solver_.sweeps();
  stats_.sweeps += sweeps_;
  return ok;
}

}  // namespace blockdyn
