// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/assembly/assembly_model.hpp"

#include "blockdyn/base/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace blockdyn {

const char* assembly_event_name(int kind) {
  switch (kind) {
    case kAssemblyContactOpens:
      return "open";
    case kAssemblyContactCloses:
      return "close";
    case kAssemblySlipStarts:
      return "slip";
    case kAssemblyStickStarts:
      return "stick";
    case kAssemblyEndSwitch:
      return "end_switch";
    case kAssemblyUprightPassage:
      return "w_zero";
    case kAssemblyRotationCollapse:
      return "failure";
    case kAssemblyBearingCollapse:
      return "failure";
    case kAssemblyOutsideModel:
      return "invalid";
    case kAssemblyInputBreakpoint:
      return "breakpoint";
    case kAssemblyImpact:
      return "impact";
    case kAssemblyToTimeStepping:
      return "time_stepping";
    case kAssemblyToEventDriven:
      return "event_driven";
  }
  return "?";
}

namespace {
// A contact end passes to the other block's corner once the corners are this far apart
// (relative to the smallest block size, or the noise band if larger): flush faces (seed 002's
// lintel) keep their corners level only up to the integration error, which must not count as
// switches.
constexpr double kEndSwitchBand = 1e-10;
// The first step after a restart (an event): a fraction of the contacts' time scale
// sqrt(m / 2 k_N). Larger fractions cost rejected steps, smaller ones extra steps; 0.5 had the
// fewest instructions for seed 002's harmonic trilith (valgrind: -8% against 0.05).
constexpr double kStepHintFactor = 0.5;
}  // namespace

template <int MaxBlocks>
AssemblyModel<MaxBlocks>::AssemblyModel(const Assembly& a, const GroundMotion& g, double noise_band)
    : asm_(a),
      ground_(g),
      forced_(!g.is_zero()),
      nb_(int(a.blocks.size())),
      ni_(int(a.interfaces.size())),
      g_(a.g),
      rotation_band_(noise_band) {
  if (nb_ < 1 || nb_ > MaxBlocks || ni_ < 1 || ni_ > kIfaces)
    throw std::invalid_argument("assembly: " + std::to_string(nb_) + " blocks and " + std::to_string(ni_) +
                                " interfaces do not fit this model's capacity");
  double min_size = INFINITY, reach = 0.0;
  for (int b = 0; b < nb_; ++b) {
    const AssemblyBlock& k = a.blocks[b];
    reach = std::fmax(reach, std::fabs(k.x) + std::fabs(k.y) + std::hypot(k.width, k.height));
    m_[b] = k.mass;
    I_[b] = k.inertia();
    inv_m_[b] = 1.0 / m_[b];
    inv_I_[b] = 1.0 / I_[b];
    limit_[b] = a.collapse_rotation * tipping_angle(a, b);
    y0_[b] = k.y;
    min_size = std::fmin(min_size, std::fmin(k.width, k.height));
  }
  std::array<int, MaxBlocks> supports{};
  for (const AssemblyInterface& f : a.interfaces) ++supports[f.upper];
  step_hint_ = INFINITY;
  for (int i = 0; i < ni_; ++i) {
    const AssemblyInterface& f = a.interfaces[i];
    lower_[i] = f.lower;
    upper_[i] = f.upper;
    const InterfaceFaces faces = interface_faces(a, i);
    lface_[i] = faces.lower;
    uface_[i] = faces.upper;
    PointLaw& l = law_[i];
    l.kn = f.law.k_normal;
    l.kt = f.law.k_tangential > 0 ? f.law.k_tangential : f.law.k_normal / 3.0;
    l.mu_s = f.law.mu_s;
    l.mu_k = f.law.mu_k;
    l.no_slip = f.law.mu_s >= kNoSlipFriction;
    l.stick_band = l.kt * kStickBand;
    // 64 ulps of the coordinates' magnitude as a penetration: below what the geometry resolves.
    l.close_band = l.kn * 64.0 * std::numeric_limits<double>::epsilon() * reach;
    // Calibration mass: the upper block's share on this interface, dropped flat on its two points.
    const double m_share = m_[f.upper] / std::max(1, supports[f.upper]);
    l.cn = f.law.damping >= 0 ? f.law.damping : damping_for_restitution(f.law.restitution, m_share, l.kn);
    step_hint_ = std::fmin(step_hint_, kStepHintFactor * std::sqrt(m_share / (2.0 * l.kn)));
  }
  d_max_ = 0.02 * min_size;
  switch_band_ = std::fmax(kEndSwitchBand * min_size, noise_band);
}

template <int MaxBlocks>
BodyPose AssemblyModel<MaxBlocks>::pose(const State& z, int b) const {
  BodyPose p;
  p.x = z[ix(b)];
  p.y = z[ix(b) + 1];
  p.theta = z[ix(b) + 2];
  p.vx = z[iv(b)];
  p.vy = z[iv(b) + 1];
  p.omega = z[iv(b) + 2];
  p.q = BodyRotation::of(p.theta);
  return p;
}

template <int MaxBlocks>
bool AssemblyModel<MaxBlocks>::any_slip(const Mode& m) const {
  for (int p = 0; p < 2 * ni_; ++p)
    if (slip_sign(m.point[p]) != 0) return true;
  return false;
}

template <int MaxBlocks>
void AssemblyModel<MaxBlocks>::geometry(const State& z, Geometry& g) const {
  for (int b = 0; b < nb_; ++b) g.pose[b] = pose(z, b);
  for (int i = 0; i < ni_; ++i) {
    const int l = lower_[i], u = upper_[i];
    const LocalFace& lf = lface_[i];
    g.lower[i] = lower_face_at(lf, l < 0, l < 0 ? BodyPose{} : g.pose[l]);
    g.upper[i] = face_at(g.pose[u], uface_[i]);
  }
}

template <int MaxBlocks>
double AssemblyModel<MaxBlocks>::overlap_of(const State& z, int i) const {
  Geometry g;
  geometry(z, g);
  return overlap(g.lower[i], g.upper[i]);
}

template <int MaxBlocks>
void AssemblyModel<MaxBlocks>::point_force(const Mode& m, const State& z, const Geometry& g, int p,
                                           PointForce& f) const {
  const int i = p / 2, end = p % 2;
  f.c = contact_point(g.of(lower_[i]), g.lower[i], g.of(upper_[i]), g.upper[i], end, m.owner[p]);
  f.d = -f.c.gap;
  f.d_rate = -f.c.gap_rate;
  const PointState s = m.point[p];
  if (is_closed(s)) {
    const PointLaw& l = law_[i];
    f.fn = normal_force(l, f.d, f.d_rate);
    f.ft = s == PointState::Stick ? -l.kt * z[iu(p)] : -slip_sign(s) * l.mu_k * f.fn;
  } else {
    f.fn = f.ft = 0.0;
  }
}

template <int MaxBlocks>
void AssemblyModel<MaxBlocks>::dynamics(double t, const Mode& m, const State& z, const Geometry& geo, Dynamics& d,
                                        bool need_rates, bool all_points) const {
  d.ah = forced_ ? ground_.ah(t) : 0.0;
  d.av = forced_ ? ground_.av(t) : 0.0;
  std::array<double, 3 * MaxBlocks> F;
  for (int b = 0; b < nb_; ++b) {
    F[3 * b] = -m_[b] * g_ * d.ah;
    F[3 * b + 1] = -m_[b] * g_ * (1.0 + d.av);
    F[3 * b + 2] = 0.0;
  }
  for (int p = 0; p < 2 * ni_; ++p) {
    PointForce& pf = d.pf[p];
    const int i = p / 2;
    if (!is_closed(m.point[p])) {
      // An open point exerts no force and stores no energy: the right-hand side does not need
      // it, the event functions do.
      if (all_points) point_force(m, z, geo, p, pf);
      continue;
    }
    point_force(m, z, geo, p, pf);
    // Force on the upper block: the normal pushes it away from the lower one.
    const Vec2 n_up = pf.c.corner_of_upper ? pf.c.n : -1.0 * pf.c.n;
    const Vec2 Fu = pf.fn * n_up + pf.ft * pf.c.t;
    const int u = upper_[i], l = lower_[i];
    F[3 * u] += Fu.x;
    F[3 * u + 1] += Fu.y;
    F[3 * u + 2] += cross(pf.c.P - Vec2{z[ix(u)], z[ix(u) + 1]}, Fu);
    if (l >= 0) {
      F[3 * l] -= Fu.x;
      F[3 * l + 1] -= Fu.y;
      F[3 * l + 2] -= cross(pf.c.P - Vec2{z[ix(l)], z[ix(l) + 1]}, Fu);
    }
  }
  for (int b = 0; b < nb_; ++b) {
    d.acc[3 * b] = F[3 * b] / m_[b];
    d.acc[3 * b + 1] = F[3 * b + 1] / m_[b];
    d.acc[3 * b + 2] = F[3 * b + 2] / I_[b];
  }
  if (!need_rates) return;
  for (int p = 0; p < 2 * ni_; ++p)
    if (slip_sign(m.point[p]) != 0) d.fn_rate[p] = normal_force_rate(z, d.acc, d.pf[p], p);
}

// Normal-force rate of a point: F_N' = k_N d' + c_N d'', with
// gap'' = (a_A - a_B) . n + 2 omega_B v_AB . perp(n) for the corner of A on B's face.
template <int MaxBlocks>
double AssemblyModel<MaxBlocks>::normal_force_rate(const State& z, const std::array<double, 3 * MaxBlocks>& acc,
                                                   const PointForce& pf, int p) const {
  const int i = p / 2;
  return law_[i].kn * pf.d_rate - law_[i].cn * gap_acceleration(z, acc, pf, i);
}

template <int MaxBlocks>
double AssemblyModel<MaxBlocks>::gap_acceleration(const State& z, const std::array<double, 3 * MaxBlocks>& acc,
                                                  const PointForce& pf, int i) const {
  auto material_acc = [&](int b, const Vec2& P) {
    if (b < 0) return Vec2{};
    return point_acceleration(acc[3 * b], acc[3 * b + 1], acc[3 * b + 2], z[iv(b) + 2],
                              P - Vec2{z[ix(b)], z[ix(b) + 1]});
  };
  const int A = pf.c.corner_of_upper ? upper_[i] : lower_[i];
  const int B = pf.c.corner_of_upper ? lower_[i] : upper_[i];
  const Vec2 v_ab = pf.c.corner_of_upper ? pf.c.v_rel : -1.0 * pf.c.v_rel;
  const double omega_b = B >= 0 ? z[iv(B) + 2] : 0.0;
  return dot(material_acc(A, pf.c.P) - material_acc(B, pf.c.P), pf.c.n) + 2.0 * omega_b * dot(v_ab, perp(pf.c.n));
}

template <int MaxBlocks>
void AssemblyModel<MaxBlocks>::rhs(double t, const Mode& m, const State& z, State& dz) const {
  Geometry geo;
  geometry(z, geo);
  Dynamics d;
  dynamics(t, m, z, geo, d, any_slip(m), false);
  for (int b = 0; b < nb_; ++b)
    for (int k = 0; k < 3; ++k) {
      dz[ix(b) + k] = z[iv(b) + k];
      dz[iv(b) + k] = d.acc[3 * b + k];
    }
  for (int b = nb_; b < MaxBlocks; ++b)
    for (int k = 0; k < 3; ++k) dz[ix(b) + k] = dz[iv(b) + k] = 0.0;
  double w_ground = 0.0;
  for (int b = 0; b < nb_; ++b) w_ground -= m_[b] * g_ * (d.ah * z[iv(b)] + d.av * z[iv(b) + 1]);
  dz[kWGround] = w_ground;
  double w_normal = 0.0, w_friction = 0.0;
  for (int p = 0; p < kPoints; ++p) dz[iu(p)] = 0.0;
  for (int p = 0; p < 2 * ni_; ++p) {
    const PointState s = m.point[p];
    if (!is_closed(s)) continue;
    const PointForce& pf = d.pf[p];
    const PointLaw& l = law_[p / 2];
    // Power of the normal pair plus the rate of the spring energy k_N max(d, 0)^2 / 2.
    w_normal += -pf.fn * pf.d_rate + l.kn * std::max(pf.d, 0.0) * pf.d_rate;
    if (s == PointState::Stick) {
      dz[iu(p)] = pf.c.slip_rate;
    } else if (slip_sign(s) != 0) {
      const double rate = slipping_rate(l, slip_sign(s), pf.c.slip_rate, d.fn_rate[p]);
      w_friction -= l.mu_k * pf.fn * rate;
    }
  }
  dz[kWNormal] = w_normal;
  dz[kWFriction] = w_friction;
  dz[kWSwitch] = 0.0;
}

template <int MaxBlocks>
void AssemblyModel<MaxBlocks>::events(double t, const Mode& m, const State& z,
                                      std::array<double, kNumEvents>& g) const {
  Geometry geo;
  geometry(z, geo);
  Dynamics d;
  // The accelerations only for the slipping points' switch back to stick (F_N').
  const bool slip = any_slip(m);
  if (slip)
    dynamics(t, m, z, geo, d, true, true);
  else
    for (int p = 0; p < 2 * ni_; ++p) point_force(m, z, geo, p, d.pf[p]);
  event_values(m, z, geo, d, g);
}

template <int MaxBlocks>
double AssemblyModel<MaxBlocks>::along_lower_rate(const Geometry& geo, int i, int side) const {
  // d/dt [(Q - c_L) . t_L] with Q the upper corner (a material point of the upper block), c_L the
  // lower face's centre (one of the lower block's) and t_L turning at omega_L: t_L' = omega_L n_L.
  const Face& lf = geo.lower[i];
  const BodyPose& up = geo.of(upper_[i]);
  const BodyPose& lp = geo.of(lower_[i]);
  const Vec2 Q = face_corner(geo.upper[i], side);
  const Vec2 vq = material_velocity(up, Q);
  const Vec2 vc = lower_[i] < 0 ? Vec2{} : material_velocity(lp, lf.c);
  return dot(vq - vc, lf.t) + lp.omega * dot(Q - lf.c, perp(lf.t));
}

template <int MaxBlocks>
void AssemblyModel<MaxBlocks>::event_rates(double, const Mode& m, const State& z, const State& dz,
                                           std::array<double, kNumEvents>& g,
                                           std::array<double, kNumEvents>& g_rate) const {
  Geometry geo;
  geometry(z, geo);
  Dynamics d;
  for (int b = 0; b < nb_; ++b)
    for (int k = 0; k < 3; ++k) d.acc[3 * b + k] = dz[iv(b) + k];
  g_rate.fill(0.0);
  for (int p = 0; p < 2 * ni_; ++p) {
    const int i = p / 2;
    PointForce& pf = d.pf[p];
    point_force(m, z, geo, p, pf);
    const PointLaw& l = law_[i];
    const double d_acc = -gap_acceleration(z, d.acc, pf, i);
    const double fn_rate = l.kn * pf.d_rate + l.cn * d_acc;
    if (slip_sign(m.point[p]) != 0) d.fn_rate[p] = fn_rate;
    const PointState s = m.point[p];
    if (!is_closed(s)) {
      // max(-k d, -F): the derivative of the larger branch (of the larger derivative on a tie).
      const double a = -l.kn * pf.d, b = -(l.kn * pf.d + l.cn * pf.d_rate);
      const double ra = -l.kn * pf.d_rate, rb = -fn_rate;
      g_rate[ev_normal(p)] = a > b ? ra : b > a ? rb : std::max(ra, rb);
    } else {
      g_rate[ev_normal(p)] = fn_rate;
      if (s == PointState::Stick) {
        const double u = z[iu(p)];
        const double sign_u = u > 0 ? 1.0 : u < 0 ? -1.0 : 0.0;
        g_rate[ev_tangent(p)] = l.no_slip ? 0.0 : l.mu_s * fn_rate - l.kt * sign_u * dz[iu(p)];
      } else {
        g_rate[ev_tangent(p)] = l.frictionless() ? 0.0 : NAN;
      }
    }
    if (std::isfinite(geo.lower[i].half)) {
      const int end = p % 2;
      const double r = end == 0 ? along_lower_rate(geo, i, -1) : -along_lower_rate(geo, i, +1);
      g_rate[ev_owner(p)] = m.owner[p] == 0 ? r : -r;
    }
    g_rate[ev_valid(p)] = -pf.d_rate;
  }
  event_values(m, z, geo, d, g);
  for (int b = 0; b < nb_; ++b) {
    const double th = z[ix(b) + 2], w = z[iv(b) + 2];
    g_rate[ev_wzero(b)] = m.side[b] * w;
    // The right derivative of limit - |theta| (at theta = 0: -|omega|).
    g_rate[ev_collapse(b)] = th > 0 ? -w : th < 0 ? w : -std::fabs(w);
  }
  for (int i = 0; i < ni_; ++i) {
    if (lower_[i] < 0) continue;
    const double half = geo.lower[i].half;
    const double right = along_lower(geo.lower[i], geo.upper[i], +1),
                 left = along_lower(geo.lower[i], geo.upper[i], -1);
    g_rate[ev_bearing(i)] =
        (right < half ? along_lower_rate(geo, i, +1) : 0.0) - (left > -half ? along_lower_rate(geo, i, -1) : 0.0);
  }
}

template <int MaxBlocks>
void AssemblyModel<MaxBlocks>::event_values(const Mode& m, const State& z, const Geometry& geo, const Dynamics& d,
                                            std::array<double, kNumEvents>& g) const {
  g.fill(1.0);
  for (int p = 0; p < 2 * ni_; ++p) {
    const int i = p / 2;
    const PointForce& pf = d.pf[p];
    const PointLaw& l = law_[i];
    const PointState s = m.point[p];
    if (!is_closed(s)) {
      g[ev_normal(p)] = closing_margin(l, pf.d, pf.d_rate, m.held[p]);
    } else {
      g[ev_normal(p)] = pf.fn;
      g[ev_tangent(p)] = s == PointState::Stick ? sticking_margin(l, pf.fn, z[iu(p)])
                                                : slipping_rate(l, slip_sign(s), pf.c.slip_rate, d.fn_rate[p]);
    }
    g[ev_owner(p)] = owner_margin(geo.lower[i], geo.upper[i], p % 2, m.owner[p]) + switch_band_;
    g[ev_valid(p)] = d_max_ - pf.d;
  }
  for (int b = 0; b < nb_; ++b) {
    const double th = z[ix(b) + 2];
    g[ev_wzero(b)] = m.side[b] * th + rotation_band_;
    g[ev_collapse(b)] = limit_[b] - std::fabs(th);
  }
  for (int i = 0; i < ni_; ++i)
    if (lower_[i] >= 0) g[ev_bearing(i)] = overlap(geo.lower[i], geo.upper[i]) - asm_.min_bearing;
}

template <int MaxBlocks>
void AssemblyModel<MaxBlocks>::complete(const Mode& m, State& z) const {
  for (int p = 0; p < 2 * ni_; ++p)
    if (!is_closed(m.point[p])) z[iu(p)] = 0.0;  // an open point has no tangential spring
  if (!any_slip(m)) return;
  Geometry geo;
  geometry(z, geo);
  for (int p = 0; p < 2 * ni_; ++p) {
    const int s = slip_sign(m.point[p]);
    if (s == 0) continue;
    const PointForce pf = point_force(m, z, geo, p);
    z[iu(p)] = s * law_[p / 2].mu_k * pf.fn / law_[p / 2].kt;
  }
}

template <int MaxBlocks>
std::optional<Transition<typename AssemblyModel<MaxBlocks>::Mode>> AssemblyModel<MaxBlocks>::resolve_chatter(
    double, const Mode& m, const State& z) const {
  Geometry geo;
  geometry(z, geo);
  Transition<Mode> tr;
  tr.next = m;
  tr.kind = kAssemblyContactOpens;
  bool any = false;
  for (int p = 0; p < 2 * ni_; ++p) {
    if (m.held[p]) continue;
    Mode probe = m;
    probe.point[p] = PointState::Stick;
    const PointForce pf = point_force(probe, z, geo, p);
    if (std::fabs(normal_force(law_[p / 2], pf.d, pf.d_rate)) > law_[p / 2].close_band) continue;
    tr.next.point[p] = PointState::Open;
    tr.next.held[p] = 1;
    any = true;
  }
  if (!any) return std::nullopt;
  return tr;  // complete() releases the opened points' tangential springs
}

template <int MaxBlocks>
PointState AssemblyModel<MaxBlocks>::consistent_state(const Mode& m, const State& z, const Geometry& g, int p) const {
  const PointLaw& l = law_[p / 2];
  Mode probe = m;
  probe.point[p] = PointState::Stick;
  const PointForce pf = point_force(probe, z, g, p);
  const PointState closed = l.frictionless() ? PointState::SlipPos : PointState::Stick;
  if (!is_closed(m.point[p])) return closing_margin(l, pf.d, pf.d_rate, m.held[p]) < 0.0 ? closed : PointState::Open;
  if (pf.fn <= 0.0) return PointState::Open;
  if (m.point[p] == PointState::Stick && sticking_margin(l, pf.fn, z[iu(p)]) < 0.0)
    return z[iu(p)] > 0 ? PointState::SlipPos : PointState::SlipNeg;
  return m.point[p];
}

template <int MaxBlocks>
Transition<typename AssemblyModel<MaxBlocks>::Mode> AssemblyModel<MaxBlocks>::transition(double, const Mode& m,
                                                                                         State& z, int event) const {
  Transition<Mode> tr;
  tr.next = m;
  if (event == kBreakpoint) {
    tr.kind = kAssemblyInputBreakpoint;
    return tr;
  }
  const Energy e_before = energy_terms(m, z);
  std::size_t work_slot = kWFriction;
  if (event < ev_tangent(0)) {
    const int p = event;
    if (is_closed(m.point[p])) {
      tr.next.point[p] = PointState::Open;
      tr.kind = kAssemblyContactOpens;
    } else {
      tr.next.point[p] = law_[p / 2].frictionless() ? PointState::SlipPos : PointState::Stick;
      tr.next.held[p] = 0;
      tr.kind = kAssemblyContactCloses;
    }
    z[iu(p)] = 0.0;
  } else if (event < ev_owner(0)) {
    const int p = event - ev_tangent(0);
    if (m.point[p] == PointState::Stick) {
      const PointForce pf = point_force(m, z, p);
      const double u = z[iu(p)];
      const int s = u != 0.0 ? (u > 0 ? 1 : -1) : (pf.c.slip_rate >= 0 ? 1 : -1);
      tr.next.point[p] = s > 0 ? PointState::SlipPos : PointState::SlipNeg;
      tr.kind = kAssemblySlipStarts;
    } else {
      tr.next.point[p] = PointState::Stick;
      tr.kind = kAssemblyStickStarts;
    }
  } else if (event < ev_valid(0)) {
    const int p = event - ev_owner(0);
    tr.next.owner[p] ^= 1;
    Geometry geo;
    geometry(z, geo);
    tr.next.point[p] = consistent_state(tr.next, z, geo, p);
    if (!is_closed(tr.next.point[p])) z[iu(p)] = 0.0;
    tr.kind = kAssemblyEndSwitch;
    work_slot = kWSwitch;
  } else if (event < ev_wzero(0)) {
    tr.stop = true;
    tr.kind = kAssemblyOutsideModel;
    return tr;
  } else if (event < ev_collapse(0)) {
    const int b = event - ev_wzero(0);
    tr.next.side[b] = std::int8_t(-m.side[b]);
    tr.kind = kAssemblyUprightPassage;
    return tr;
  } else if (event < ev_bearing(0)) {
    tr.stop = true;
    tr.kind = kAssemblyRotationCollapse;
    return tr;
  } else {
    tr.stop = true;
    tr.kind = kAssemblyBearingCollapse;
    return tr;
  }
  // The spring energy that a switch releases or stores (the static-to-kinetic drop of the
  // friction force, an end passing to the other corner) is booked as work, so the balance stays
  // closed and the losses are reported where they occur.
  complete(tr.next, z);
  const Energy after = energy_terms(tr.next, z);
  if (work_slot == kWSwitch) {
    z[kWSwitch] += after.total() - e_before.total();
  } else {
    // An opening point's spring is released (its energy k_N d^2 / 2 left with the dashpot force
    // at zero, d >= 0) and booked with the normal contacts' work; the tangential spring's energy
    // released or dropped (opening, slip onset) with friction's.
    z[kWNormal] += after.normal_spring - e_before.normal_spring;
    z[work_slot] += after.total() - after.normal_spring - (e_before.total() - e_before.normal_spring);
  }
  return tr;
}

template <int MaxBlocks>
typename AssemblyModel<MaxBlocks>::State AssemblyModel<MaxBlocks>::abs_tol_scale() const {
  State s;
  s.fill(1.0);
  return s;
}

template <int MaxBlocks>
typename AssemblyModel<MaxBlocks>::State AssemblyModel<MaxBlocks>::initial_state() const {
  State z{};
  for (int b = 0; b < nb_; ++b) {
    const AssemblyBlock& k = asm_.blocks[b];
    z[ix(b)] = k.x;
    z[ix(b) + 1] = k.y;
    z[ix(b) + 2] = k.theta;
    z[iv(b)] = k.vx;
    z[iv(b) + 1] = k.vy;
    z[iv(b) + 2] = k.omega;
  }
  return z;
}

template <int MaxBlocks>
typename AssemblyModel<MaxBlocks>::Mode AssemblyModel<MaxBlocks>::initial_mode(const State& z) const {
  Mode m{};
  Geometry geo;
  geometry(z, geo);
  for (int p = 0; p < 2 * ni_; ++p) {
    m.owner[p] = owner_margin(geo.lower[p / 2], geo.upper[p / 2], p % 2, 0) >= 0.0 ? 0 : 1;
    m.point[p] = PointState::Open;
    m.point[p] = consistent_state(m, z, geo, p);
  }
  for (int b = 0; b < nb_; ++b) m.side[b] = z[ix(b) + 2] < 0.0 ? -1 : 1;
  return m;
}

template <int MaxBlocks>
std::optional<std::string> AssemblyModel<MaxBlocks>::validity_problem(const Mode& m, const State& z) const {
  for (std::size_t k = 0; k < kDim; ++k)
    if (!std::isfinite(z[k])) return "the state is not finite";
  for (int p = 0; p < 2 * ni_; ++p) {
    const PointForce pf = point_force(m, z, p);
    if (pf.d > d_max_)
      return "interpenetration " + number_text(pf.d, 6) + " m at interface " + std::to_string(p / 2) +
             " exceeds the model's limit " + number_text(d_max_, 6) + " m (2% of the smallest block size)";
  }
  return std::nullopt;
}

template <int MaxBlocks>
typename AssemblyModel<MaxBlocks>::Energy AssemblyModel<MaxBlocks>::energy_terms(const Mode& m, const State& z) const {
  Energy e;
  for (int b = 0; b < nb_; ++b) {
    const double vx = z[iv(b)], vy = z[iv(b) + 1], w = z[iv(b) + 2];
    e.kinetic += 0.5 * m_[b] * (vx * vx + vy * vy) + 0.5 * I_[b] * w * w;
    e.gravity += m_[b] * g_ * (z[ix(b) + 1] - y0_[b]);
  }
  Geometry geo;
  geometry(z, geo);
  for (int p = 0; p < 2 * ni_; ++p) {
    if (!is_closed(m.point[p])) continue;  // an open point's spring is released
    const PointLaw& l = law_[p / 2];
    const double d = std::fmax(-contact_gap(geo.lower[p / 2], geo.upper[p / 2], p % 2, m.owner[p]), 0.0);
    e.normal_spring += 0.5 * l.kn * d * d;
    if (is_closed(m.point[p])) e.tangential_spring += 0.5 * l.kt * z[iu(p)] * z[iu(p)];
  }
  return e;
}

template class AssemblyModel<1>;
template class AssemblyModel<3>;
template class AssemblyModel<8>;
template class AssemblyModel<24>;

}  // namespace blockdyn
