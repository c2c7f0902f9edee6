// SPDX-License-Identifier: Apache-2.0
#pragma once
// Tangent dynamics of the block models (analysis/dynamics/tangent_traits.hpp): which components
// a separation is measured on and which modes are the same branch.
//   Housner block: (theta, theta'/p); the exact Jacobian of the rocking equation; no tangent
//     space at rest.
//   Rigid 3-DOF block: (y, theta, x', y', theta') in (L, 1, sqrt(g L), sqrt(g L), p) units; x is
//     left out (the dynamics is invariant under a horizontal translation, so an x offset never
//     grows and would pin the exponent at 0); no tangent space at rest.
//   Assembly: every block's (x, y, theta) and rates and the contact points' tangential spring
//     displacements, in (width, width, 1, sqrt(g width), ..., 1/p) units; the ground fixes the
//     frame (sticking contacts hold the blocks), so no direction is neutral.
// Accumulated works are never in the metric (they do not feed back).
#include <cmath>

#include "blockdyn/analysis/dynamics/tangent_traits.hpp"
#include "blockdyn/model/assembly/assembly_model.hpp"
#include "blockdyn/model/rigid_ground/housner_block.hpp"
#include "blockdyn/model/rigid_ground/rigid_block.hpp"

namespace blockdyn {

template <>
struct TangentTraits<HousnerBlock> {
  using M = HousnerBlock;
  static constexpr std::size_t N = M::kDim;
  static constexpr bool kCompleteIsIdentity = true;
  static Vec<N> scale(const M& m) { return m.abs_tol_scale(); }
  static std::array<bool, N> metric(const M&) { return {true, true, false, false}; }
  static bool same_branch(const M::Mode& a, const M::Mode& b) {
    return a.mech == b.mech && a.side == b.side && a.beyond == b.beyond;
  }
  static bool moving(const M::Mode& md) { return md.mech != Mechanism::Rest; }
  // theta'' = -p^2 [(1 + a_V) sin(phi) - a_H cos(phi)], phi = s alpha - theta.
  static bool jvp(const M& m, double t, const M::Mode& md, const Vec<N>& z, const Vec<N>& v, Vec<N>& jv) {
    if (md.mech == Mechanism::Rest) {
      jv.fill(0.0);
      return true;
    }
    const auto a = m.ground_acceleration(t);
    const double phi = md.side * m.alpha() - z[M::kTheta];
    const double sp = std::sin(phi), cp = std::cos(phi), p2 = m.p() * m.p();
    const double wscale = m.abs_tol_scale()[M::kWorkGround];
    jv[M::kTheta] = v[M::kOmega];
    jv[M::kOmega] = p2 * ((1.0 + a[1]) * cp + a[0] * sp) * v[M::kTheta];
    jv[M::kWorkGround] =
        wscale * (v[M::kOmega] * (a[0] * cp - a[1] * sp) + z[M::kOmega] * (a[0] * sp + a[1] * cp) * v[M::kTheta]);
    jv[M::kWorkImpact] = 0.0;
    return true;
  }
};

template <>
struct TangentTraits<RigidBlock> {
  using M = RigidBlock;
  static constexpr std::size_t N = M::kDim;
  static constexpr bool kCompleteIsIdentity = false;
  static Vec<N> scale(const M& m) { return m.abs_tol_scale(); }
  static std::array<bool, N> metric(const M&) { return {false, true, true, true, true, true, false, false, false}; }
  static bool same_branch(const M::Mode& a, const M::Mode& b) {
    return a.mech == b.mech && a.side == b.side && a.slip == b.slip && a.beyond == b.beyond;
  }
  static bool moving(const M::Mode& md) { return md.mech != Mechanism::Rest; }
  static bool jvp(const M&, double, const M::Mode&, const Vec<N>&, const Vec<N>&, Vec<N>&) { return false; }
};

template <int MaxBlocks>
struct TangentTraits<AssemblyModel<MaxBlocks>> {
  using M = AssemblyModel<MaxBlocks>;
  static constexpr std::size_t N = M::kDim;
  static constexpr bool kCompleteIsIdentity = false;
  static Vec<N> scale(const M& m) {
    const Assembly& a = m.assembly();
    double w = INFINITY, R = 0;
    for (const auto& b : a.blocks) {
      w = std::fmin(w, b.width);
      R = std::fmax(R, 0.5 * std::hypot(b.width, b.height));
    }
    const double v = std::sqrt(a.g * w), p = std::sqrt(0.75 * a.g / R);
    Vec<N> s;
    s.fill(1.0);
    for (int b = 0; b < MaxBlocks; ++b) {
      s[M::ix(b)] = s[M::ix(b) + 1] = w;
      s[M::ix(b) + 2] = 1.0;
      s[M::iv(b)] = s[M::iv(b) + 1] = v;
      s[M::iv(b) + 2] = p;
    }
    for (int q = 0; q < M::kPoints; ++q) s[M::iu(q)] = w;
    const double W = a.g * w;  // works per unit mass: never in the metric
    for (std::size_t i = M::kWGround; i < N; ++i) s[i] = W;
    return s;
  }
  static std::array<bool, N> metric(const M& m) {
    std::array<bool, N> a{};
    for (int b = 0; b < m.blocks(); ++b)
      for (int k = 0; k < 3; ++k) a[M::ix(b) + k] = a[M::iv(b) + k] = true;
    for (int q = 0; q < 2 * m.interfaces(); ++q) a[M::iu(q)] = true;
    return a;
  }
  static bool same_branch(const typename M::Mode& a, const typename M::Mode& b) {
    return a.point == b.point && a.owner == b.owner && a.side == b.side;
  }
  static bool moving(const typename M::Mode&) { return true; }
  static bool jvp(const M&, double, const typename M::Mode&, const Vec<N>&, const Vec<N>&, Vec<N>&) { return false; }
};

}  // namespace blockdyn
