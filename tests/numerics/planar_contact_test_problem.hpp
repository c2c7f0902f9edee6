// SPDX-License-Identifier: Apache-2.0
#pragma once
// Random planar frictional contact problems with the structure the solvers rely on, built from
// mechanics independent of the library's: rigid bodies (3 velocities each, diagonal inverse
// masses), faces between two bodies or a body and the ground, each with two ends on one line
// along its tangent (so their tangential rows coincide). W = J M^-1 J^T (+ a compliance c on the
// diagonal), b = J v_free. And the check of a solution against the definition of the problem:
// u = (W - cI) p + b from the bodies' velocities, 0 <= p_N _|_ u_N + c p_N >= 0, each face's
// cone sum |p_T| <= sum mu p_N, slipping faces' impulses against their slip.
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "blockdyn/numerics/planar_contact.hpp"

namespace blockdyn::test {

struct ContactTestProblem final : ContactVelocities {
  int nbodies = 0, ends = 0;
  ContactTestProblem() = default;
  ContactTestProblem(const ContactTestProblem&) = delete;  // the problem points into its arrays
  std::vector<double> minv, vfree;                         // 3 per body
  std::vector<std::array<double, 6>> jn;                   // per end: normal row on (upper, lower) bodies
  std::vector<std::array<double, 6>> jt;                   // tangential row
  std::vector<int> upper, lower, face;                     // lower -1: the ground
  std::vector<double> W, bn, bt, mu, pn0, pt0;
  double compliance = 0;
  PlanarContactProblem problem;

  void relative(const double* pn, const double* pt, double* un, double* ut) override {
    std::vector<double> dv(3 * std::size_t(nbodies));
    bodies_change(pn, pt, dv.data());
    for (int i = 0; i < ends; ++i) {
      un[i] = row(jn[i], i, dv.data(), true);
      ut[i] = row(jt[i], i, dv.data(), true);
    }
  }
  void bodies(const double* pn, const double* pt, double* dv) override { bodies_change(pn, pt, dv); }

  void bodies_change(const double* pn, const double* pt, double* dv) const {
    std::fill(dv, dv + 3 * nbodies, 0.0);
    for (int i = 0; i < ends; ++i)
      for (int k = 0; k < 3; ++k) {
        dv[3 * upper[i] + k] += minv[3 * upper[i] + k] * (jn[i][k] * pn[i] + jt[i][k] * pt[i]);
        if (lower[i] >= 0)
          dv[3 * lower[i] + k] += minv[3 * lower[i] + k] * (jn[i][3 + k] * pn[i] + jt[i][3 + k] * pt[i]);
      }
  }
  // The row's relative velocity for the bodies' velocities v_free + dv (with_free) or dv alone.
  double row(const std::array<double, 6>& r, int i, const double* dv, bool with_free) const {
    double s = 0;
    for (int k = 0; k < 3; ++k) {
      s += r[k] * ((with_free ? vfree[3 * upper[i] + k] : 0.0) + dv[3 * upper[i] + k]);
      if (lower[i] >= 0) s += r[3 + k] * ((with_free ? vfree[3 * lower[i] + k] : 0.0) + dv[3 * lower[i] + k]);
    }
    return s;
  }
};

// `faces` faces on a chain of `bodies` bodies (face f between body f-1 and f; the first on the
// ground), two ends each; free velocities pushing into the contacts with probability `push`.
inline void random_contact_problem(ContactTestProblem& p, int bodies, double mu_max, double compliance,
                                   std::mt19937& rng, double push = 0.7) {
  std::uniform_real_distribution<double> U(-1, 1), pos(0.2, 1.0), mu_d(0.05, mu_max);
  p.nbodies = bodies;
  p.minv.resize(3 * std::size_t(bodies));
  p.vfree.resize(3 * std::size_t(bodies));
  std::vector<std::array<double, 2>> centre{std::size_t(bodies)};
  for (int b = 0; b < bodies; ++b) {
    const double m = pos(rng), I = 0.1 * pos(rng);
    p.minv[3 * b] = p.minv[3 * b + 1] = 1.0 / m;
    p.minv[3 * b + 2] = 1.0 / I;
    centre[b] = {0.3 * U(rng), 1.0 * b + 0.5};
    for (int k = 0; k < 3; ++k) p.vfree[3 * b + k] = U(rng);
    if (std::bernoulli_distribution(push)(rng)) p.vfree[3 * b + 1] = -std::fabs(p.vfree[3 * b + 1]) - 0.5;
  }
  for (int f = 0; f < bodies; ++f) {
    const double tilt = 0.2 * U(rng);
    const std::array<double, 2> n{-std::sin(tilt), std::cos(tilt)}, t{std::cos(tilt), std::sin(tilt)};
    const std::array<double, 2> c{0.3 * U(rng), 1.0 * f};
    const double half = 0.2 + 0.1 * pos(rng), mu = mu_d(rng);
    for (int e = 0; e < 2; ++e) {
      const double s = e == 0 ? -half : half;
      const std::array<double, 2> P{c[0] + s * t[0], c[1] + s * t[1]};
      auto rows = [&](int body, double sign, std::array<double, 6>& rn, std::array<double, 6>& rt, int off) {
        const double rx = P[0] - centre[body][0], ry = P[1] - centre[body][1];
        rn[off] = sign * n[0];
        rn[off + 1] = sign * n[1];
        rn[off + 2] = sign * (rx * n[1] - ry * n[0]);
        rt[off] = sign * t[0];
        rt[off + 1] = sign * t[1];
        rt[off + 2] = sign * (rx * t[1] - ry * t[0]);
      };
      std::array<double, 6> rn{}, rt{};
      rows(f, 1.0, rn, rt, 0);
      if (f > 0) rows(f - 1, -1.0, rn, rt, 3);
      p.jn.push_back(rn);
      p.jt.push_back(rt);
      p.upper.push_back(f);
      p.lower.push_back(f - 1);
      p.face.push_back(f);
      p.mu.push_back(mu);
    }
  }
  p.ends = int(p.jn.size());
  const int n = p.ends;
  p.compliance = compliance;
  p.W.assign(std::size_t(4 * n * n), 0.0);
  auto dot_minv = [&](const std::array<double, 6>& a, int i, const std::array<double, 6>& b, int j) {
    double s = 0;
    for (int k = 0; k < 3; ++k) {
      if (p.upper[i] == p.upper[j]) s += a[k] * p.minv[3 * p.upper[i] + k] * b[k];
      if (p.lower[j] >= 0 && p.upper[i] == p.lower[j]) s += a[k] * p.minv[3 * p.upper[i] + k] * b[3 + k];
      if (p.lower[i] >= 0 && p.lower[i] == p.upper[j]) s += a[3 + k] * p.minv[3 * p.lower[i] + k] * b[k];
      if (p.lower[i] >= 0 && p.lower[i] == p.lower[j]) s += a[3 + k] * p.minv[3 * p.lower[i] + k] * b[3 + k];
    }
    return s;
  };
  double diag_max = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const std::size_t S = std::size_t(2 * n);
      p.W[(2 * i) * S + 2 * j] = dot_minv(p.jn[i], i, p.jn[j], j);
      p.W[(2 * i) * S + 2 * j + 1] = dot_minv(p.jn[i], i, p.jt[j], j);
      p.W[(2 * i + 1) * S + 2 * j] = dot_minv(p.jt[i], i, p.jn[j], j);
      p.W[(2 * i + 1) * S + 2 * j + 1] = dot_minv(p.jt[i], i, p.jt[j], j);
      if (i == j) diag_max = std::max({diag_max, p.W[(2 * i) * S + 2 * i], p.W[(2 * i + 1) * S + 2 * i + 1]});
    }
  p.compliance = compliance * diag_max;
  for (int k = 0; k < 2 * n; ++k) p.W[std::size_t(k) * std::size_t(2 * n + 1)] += p.compliance;
  std::vector<double> zero(3 * std::size_t(bodies), 0.0);
  for (int i = 0; i < n; ++i) {
    p.bn.push_back(p.row(p.jn[i], i, zero.data(), true));
    p.bt.push_back(p.row(p.jt[i], i, zero.data(), true));
  }
  p.pn0.assign(std::size_t(n), 0.0);
  p.pt0.assign(std::size_t(n), 0.0);
  PlanarContactProblem& q = p.problem;
  q.n = n;
  q.W = p.W.data();
  q.stride = std::size_t(2 * n);
  q.bn = p.bn.data();
  q.bt = p.bt.data();
  q.mu = p.mu.data();
  q.face = p.face.data();
  q.pn_warm = p.pn0.data();
  q.pt_warm = p.pt0.data();
  q.compliance = p.compliance;
  q.coords = 3 * bodies;
  q.velocities = &p;
}

// The largest violation of the problem's conditions by impulses (pn, pt), relative to the
// problem's velocity scale (velocities) and impulse scale (impulses).
inline double contact_violation(ContactTestProblem& p, const std::vector<double>& pn, const std::vector<double>& pt) {
  const int n = p.ends;
  std::vector<double> un(static_cast<std::size_t>(n)), ut(static_cast<std::size_t>(n));
  p.relative(pn.data(), pt.data(), un.data(), ut.data());
  double v_scale = 1e-300, p_scale = 1e-300;
  for (int i = 0; i < n; ++i) v_scale = std::max({v_scale, std::fabs(p.bn[i]), std::fabs(p.bt[i])});
  // Impulses are measured against the largest of the solution's and those the free velocities
  // call for (v / W_ii): a problem whose solution is zero has rounding-sized impulses.
  double w_max = 1e-300;
  for (int k = 0; k < 2 * n; ++k) w_max = std::max(w_max, p.W[std::size_t(k) * std::size_t(2 * n + 1)]);
  p_scale = v_scale / w_max;
  for (int i = 0; i < n; ++i) p_scale = std::max({p_scale, std::fabs(pn[i]), std::fabs(pt[i])});
  double err = 0;
  for (int i = 0; i < n; ++i) {
    const double cn = un[i] + p.compliance * pn[i];
    err = std::max(err, -pn[i] / p_scale);
    err = std::max(err, -cn / v_scale);
    err = std::max(err, std::min(std::fabs(pn[i]) / p_scale, std::fabs(cn) / v_scale));
  }
  for (int i = 0; i + 1 < n; i += 2) {  // a face: ends i, i + 1
    const double sum_pt = pt[i] + pt[i + 1], cap = p.mu[i] * pn[i] + p.mu[i + 1] * pn[i + 1];
    err = std::max(err, (std::fabs(sum_pt) - cap) / p_scale);
    // The tangential velocity of the face (with the compliance) against its impulse: a face that
    // slips has its impulse on the cone, opposite to the slip.
    const double ct = ut[i] + p.compliance * sum_pt;
    if (std::fabs(ct) > 1e-9 * v_scale) {
      err = std::max(err, (cap - std::fabs(sum_pt)) / p_scale);
      if (sum_pt * ct > 0) err = std::max(err, std::fabs(sum_pt) / p_scale);
    }
  }
  return err;
}

}  // namespace blockdyn::test
