// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the tangent (variational) dynamics of a hybrid model needs beyond HybridModel, with
// defaults that work for any model; a family specialises TangentTraits<Model> where it knows
// better (analysis/forced/block_tangent_traits.hpp):
//   scale(m)           size of a unit perturbation of each state component (default: the
//                      model's abs_tol_scale): finite-difference steps and the metric use it;
//   metric(m)          which components the separation is measured on: the dynamical
//                      coordinates, without accumulated works and without neutral directions
//                      such as a horizontal translation that never feeds back (default: all);
//   same_branch(a, b)  whether two modes are the same discrete branch (a transition taken at a
//                      perturbed state must land in the same mode to be differentiated);
//   moving(mode)       whether a perturbation can live in this mode (a block at rest has no
//                      tangent space: rest is reached in finite time and annihilates perturbations);
//   jvp(...)           optional analytic Jacobian-vector product of the right-hand side
//                      (returns false to use central differences);
//   kCompleteIsIdentity  complete() never changes a state (no projection of tangents needed).
#include <array>

#include "blockdyn/integrate/hybrid_model.hpp"

namespace blockdyn {

template <class M>
struct TangentTraits {
  static constexpr std::size_t N = M::kDim;
  static constexpr bool kCompleteIsIdentity = false;
  static Vec<N> scale(const M& m) { return m.abs_tol_scale(); }
  static std::array<bool, N> metric(const M&) {
    std::array<bool, N> a;
    a.fill(true);
    return a;
  }
  static bool same_branch(const typename M::Mode& a, const typename M::Mode& b) {
    if constexpr (requires { a == b; })
      return a == b;
    else
      return true;  // no comparison known: every transition is taken as the same branch
  }
  static bool moving(const typename M::Mode&) { return true; }
  static bool jvp(const M&, double, const typename M::Mode&, const Vec<N>&, const Vec<N>&, Vec<N>&) { return false; }
};

}  // namespace blockdyn
