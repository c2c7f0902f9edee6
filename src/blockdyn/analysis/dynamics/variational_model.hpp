// SPDX-License-Identifier: Apache-2.0
#pragma once
// A hybrid model together with K tangent vectors (its variational equation), as one hybrid model
// for the generic integrator: state (z, v_1, ..., v_K), the base model's events and modes.
//
// Between events each tangent follows v' = Df(t, mode, z) v (the model's analytic
// Jacobian-vector product if TangentTraits provides one, else central differences of the
// right-hand side). At an event (index i, time t_e) the base transition maps z- to z+ =
// J(t_e, z-) and each tangent is mapped by the saltation matrix. Derivation: a perturbation v of
// z- moves the event time by dt = -(grad g . v) / (grad g . f- + dg/dt) (first order in
// g(t_e + dt, z- + v + f- dt) = 0); the perturbed trajectory jumps at t_e + dt from
// z- + v + f- dt to J(t_e + dt, z- + w), w = v + f- dt, and, carried back to t_e with f+, lies at
//     z+ + DJ.(dt, w) - f+ dt,
// so
//     v+ = DJ.(dt, w) - f+ dt = [DJ + (f+ - DJ f- - J_t) (grad g)^T / (grad g . f- + g_t)] v
// (S = DJ + (f+ - DJ f-) (grad g)^T / (grad g . f-) for an autonomous surface and map). Only the
// derivative of J along the event surface enters (w is tangent to it in (t, z)), so a
// transition that writes the surface value (theta = 0 at an impact) is differentiated exactly.
// DJ.(dt, w) is a central difference of the model's own transition (followed by complete()) at
// (t_e +- h dt, z- +- h w); where one side lands in another mode branch (a decision boundary)
// the other side is used alone (counted). At a breakpoint of the input (a fixed time) dt = 0.
// complete() (projection onto the mode's constraints) projects the tangents by its own
// derivative, so a tangent stays in the mode's tangent space (a block at rest has none).
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "blockdyn/analysis/dynamics/tangent_traits.hpp"
#include "blockdyn/integrate/hybrid_model.hpp"

namespace blockdyn {

struct VariationalStats {
  long saltations = 0;  // tangents mapped across an event
  long one_sided = 0;   // ... of which by a one-sided difference (a branch boundary nearby)
  long unmatched = 0;   // ... where no perturbed transition stayed on the branch (identity used)
  long grazing = 0;     // events crossed tangentially (dg/dt = 0): the saltation is unbounded
  double max_gain = 0;  // largest |v+| / |v-| over the saltations (metric norm)
};

template <HybridModel M, int K = 1, class Traits = TangentTraits<M>>
class VariationalModel {
 public:
  static constexpr std::size_t N = M::kDim;
  static constexpr std::size_t kDim = N * (1 + K);
  static constexpr std::size_t kNumEvents = M::kNumEvents;
  static constexpr bool kStateJumps = true;
  static constexpr int kTangents = K;
  using Mode = typename M::Mode;
  using State = Vec<kDim>;
  using Base = Vec<N>;
  // Central-difference step in scaled units (each component moves by at most kFd * scale).
  static constexpr double kFd = 1e-6;

  explicit VariationalModel(const M& m) : m_(m), scale_(Traits::scale(m)), metric_(Traits::metric(m)) {}

  const M& model() const { return m_; }
  const VariationalStats& stats() const { return stats_; }
  const Base& scale() const { return scale_; }

  static Base base(const State& Z) {
    Base z;
    std::copy_n(Z.begin(), N, z.begin());
    return z;
  }
  static Base tangent(const State& Z, int k) {
    Base v;
    std::copy_n(Z.begin() + N * (1 + k), N, v.begin());
    return v;
  }
  static void set_base(State& Z, const Base& z) { std::copy_n(z.begin(), N, Z.begin()); }
  static void set_tangent(State& Z, int k, const Base& v) { std::copy_n(v.begin(), N, Z.begin() + N * (1 + k)); }

  // The separation a tangent measures: Euclidean over the metric components, each in its scale.
  double norm(const Base& v) const {
    double s = 0;
    for (std::size_t i = 0; i < N; ++i)
      if (metric_[i]) s += (v[i] / scale_[i]) * (v[i] / scale_[i]);
    return std::sqrt(s);
  }

  void rhs(double t, const Mode& md, const State& Z, State& dZ) const {
    const Base z = base(Z);
    Base f;
    m_.rhs(t, md, z, f);
    set_base(dZ, f);
    for (int k = 0; k < K; ++k) {
      Base jv;
      jvp(t, md, z, tangent(Z, k), jv);
      set_tangent(dZ, k, jv);
    }
  }

  void events(double t, const Mode& md, const State& Z, std::array<double, kNumEvents>& g) const {
    m_.events(t, md, base(Z), g);
  }

  void complete(const Mode& md, State& Z) const {
    Base z = base(Z);
    m_.complete(md, z);
    set_base(Z, z);
    if constexpr (!Traits::kCompleteIsIdentity) {
      for (int k = 0; k < K; ++k) {
        const Base v = tangent(Z, k);
        const double n = full_norm(v);
        if (n == 0.0) continue;
        const double h = kFd / n;
        Base zp = z, zm = z, out;
        for (std::size_t i = 0; i < N; ++i) {
          zp[i] += h * v[i];
          zm[i] -= h * v[i];
        }
        m_.complete(md, zp);
        m_.complete(md, zm);
        for (std::size_t i = 0; i < N; ++i) out[i] = (zp[i] - zm[i]) / (2.0 * h);
        set_tangent(Z, k, out);
      }
    }
  }

  Transition<Mode> transition(double t, const Mode& md, State& Z, int e) const {
    Base z = base(Z);
    const Base z_minus = z;
    const Transition<Mode> tr = m_.transition(t, md, z, e);
    set_base(Z, z);
    if (tr.stop) return tr;
    Base z_plus = z;
    m_.complete(tr.next, z_plus);
    Base f_minus, f_plus;
    m_.rhs(t, md, z_minus, f_minus);
    m_.rhs(t, tr.next, z_plus, f_plus);
    for (int k = 0; k < K; ++k) {
      const Base v = tangent(Z, k);
      const Base vp = saltation(t, md, tr.next, z_minus, z_plus, f_minus, f_plus, e, v);
      const double n0 = norm(v);
      if (n0 > 0.0) stats_.max_gain = std::fmax(stats_.max_gain, norm(vp) / n0);
      set_tangent(Z, k, vp);
    }
    return tr;
  }

  std::optional<Transition<Mode>> resolve_chatter(double t, const Mode& md, const State& Z) const {
    return m_.resolve_chatter(t, md, base(Z));
  }
  double step_hint(const Mode& md) const { return m_.step_hint(md); }
  double next_breakpoint(double t, const Mode& md) const { return next_breakpoint_of(m_, t, md); }
  State abs_tol_scale() const {
    State s;
    for (int k = 0; k <= K; ++k) std::copy_n(scale_.begin(), N, s.begin() + N * k);
    return s;
  }

  // The tangent image of v across event e (public for tests).
  Base saltation(double t, const Mode& from, const Mode& to, const Base& z_minus, const Base& z_plus,
                 const Base& f_minus, const Base& f_plus, int e, const Base& v) const {
    ++stats_.saltations;
    const double T = time_scale(from);
    double dt = 0.0;
    if (e != kBreakpoint) {
      auto g = [&](double tt, const Base& y) {
        std::array<double, kNumEvents> ge;
        m_.events(tt, from, y, ge);
        return ge[std::size_t(e)];
      };
      const double g_v = directional(g, t, z_minus, v);
      const double g_f = directional(g, t, z_minus, f_minus);
      const double ht = kFd * T;
      const double g_t = (g(t + ht, z_minus) - g(t - ht, z_minus)) / (2.0 * ht);
      const double g_dot = g_f + g_t;
      if (g_v != 0.0) {
        if (!(std::fabs(g_dot) > 0.0)) {
          ++stats_.grazing;
          dt = 0.0;
        } else {
          dt = -g_v / g_dot;
        }
      }
    }
    Base w;
    for (std::size_t i = 0; i < N; ++i) w[i] = v[i] + f_minus[i] * dt;
    const double n = std::hypot(full_norm(w), dt / T);
    Base out{};
    if (n > 0.0) {
      const double h = kFd / n;
      Base jp, jm;
      const bool ok_p = jump(t + h * dt, from, to, z_minus, w, h, e, jp);
      const bool ok_m = jump(t - h * dt, from, to, z_minus, w, -h, e, jm);
      for (std::size_t i = 0; i < N; ++i) {
        if (ok_p && ok_m)
          out[i] = (jp[i] - jm[i]) / (2.0 * h);
        else if (ok_p)
          out[i] = (jp[i] - z_plus[i]) / h;
        else if (ok_m)
          out[i] = (z_plus[i] - jm[i]) / h;
        else
          out[i] = w[i];
      }
      if (!(ok_p && ok_m)) ++(ok_p || ok_m ? stats_.one_sided : stats_.unmatched);
    }
    for (std::size_t i = 0; i < N; ++i) out[i] -= f_plus[i] * dt;
    return out;
  }

 private:
  double full_norm(const Base& v) const {
    double s = 0;
    for (std::size_t i = 0; i < N; ++i) s += (v[i] / scale_[i]) * (v[i] / scale_[i]);
    return std::sqrt(s);
  }

  double time_scale(const Mode& md) const {
    const double h = m_.step_hint(md);
    return std::isfinite(h) && h > 0.0 ? 10.0 * h : 1.0;
  }

  template <class G>
  double directional(G& g, double t, const Base& z, const Base& v) const {
    const double n = full_norm(v);
    if (n == 0.0) return 0.0;
    const double h = kFd / n;
    Base zp = z, zm = z;
    for (std::size_t i = 0; i < N; ++i) {
      zp[i] += h * v[i];
      zm[i] -= h * v[i];
    }
    return (g(t, zp) - g(t, zm)) / (2.0 * h);
  }

  // The base transition of event e at (t, z- + h w), completed in its next mode; false when it
  // stops or lands in another branch than `to`.
  bool jump(double t, const Mode& from, const Mode& to, const Base& z_minus, const Base& w, double h, int e,
            Base& out) const {
    for (std::size_t i = 0; i < N; ++i) out[i] = z_minus[i] + h * w[i];
    const Transition<Mode> tr = m_.transition(t, from, out, e);
    if (tr.stop || !Traits::same_branch(tr.next, to)) return false;
    m_.complete(tr.next, out);
    return true;
  }

  void jvp(double t, const Mode& md, const Base& z, const Base& v, Base& jv) const {
    if (Traits::jvp(m_, t, md, z, v, jv)) return;
    const double n = full_norm(v);
    if (n == 0.0) {
      jv.fill(0.0);
      return;
    }
    const double h = kFd / n;
    Base zp = z, zm = z, fp, fm;
    for (std::size_t i = 0; i < N; ++i) {
      zp[i] += h * v[i];
      zm[i] -= h * v[i];
    }
    m_.rhs(t, md, zp, fp);
    m_.rhs(t, md, zm, fm);
    for (std::size_t i = 0; i < N; ++i) jv[i] = (fp[i] - fm[i]) / (2.0 * h);
  }

  const M& m_;
  Base scale_;
  std::array<bool, N> metric_;
  mutable VariationalStats stats_;  // per run: each run owns its VariationalModel
};

}  // namespace blockdyn
