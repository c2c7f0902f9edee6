// SPDX-License-Identifier: Apache-2.0
// The rigid contact law's hybrid model (rigid_assembly_model.hpp): its construction, the
// contact points' rows, scales, initial mode, validity, energy and point forces. Its other
// concepts are in files of their own, included at the end (one translation unit, so that the
// model is instantiated once per capacity): the smooth motion of a mode
// (rigid_assembly_dynamics.ipp), impacts (rigid_assembly_impact.ipp), rest
// (rigid_assembly_rest.ipp) and the transitions (rigid_assembly_transition.ipp).
#include "blockdyn/model/assembly/rigid_assembly_model.hpp"

#include "blockdyn/base/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "blockdyn/model/assembly/rest_limit.hpp"
#include "blockdyn/model/assembly/rigid_assembly_internal.hpp"
#include "blockdyn/numerics/dense_solve.hpp"

namespace blockdyn {

using namespace rigid_assembly;

namespace {
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
void RigidAssemblyModel<MaxBlocks>::point_forces(const Mode& m, const State& z, double t,
                                                 std::array<PointForce, kPoints>& out) const {
  Geometry geo;
  geo_.geometry(z, geo);
  std::array<PointRows, kPoints> r;
  Mode mm = m;
  if (m.rest) mm.rest = false;
  rows(z, geo, mm, r);
  bool any_closed = false;
  for (int p = 0; p < 2 * ni_; ++p) any_closed = any_closed || is_closed(mm.point[p]);
  Solution s;
  if (any_closed) s = solve(t, mm, z, r);
  for (int p = 0; p < 2 * ni_; ++p) {
    out[p] = PointForce{};
    out[p].c = r[p].c;
    if (!is_closed(mm.point[p])) continue;
    out[p].fn = s.fn[p];
    out[p].ft = s.ft[p];
  }
}

}  // namespace blockdyn

// The model's other parts, one concept each.
#include "blockdyn/model/assembly/rigid_assembly_dynamics.ipp"
#include "blockdyn/model/assembly/rigid_assembly_impact.ipp"
#include "blockdyn/model/assembly/rigid_assembly_rest.ipp"
#include "blockdyn/model/assembly/rigid_assembly_transition.ipp"

namespace blockdyn {

template class RigidAssemblyModel<1>;
template class RigidAssemblyModel<3>;
template class RigidAssemblyModel<8>;
template class RigidAssemblyModel<24>;

}  // namespace blockdyn
