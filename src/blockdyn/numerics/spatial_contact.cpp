// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/numerics/spatial_contact.hpp"

#include <cfloat>
#include <cmath>

#include "blockdyn/numerics/circle_root.hpp"
#include "blockdyn/numerics/dense_solve.hpp"

namespace blockdyn {

namespace {

constexpr int kSlipAngleSamples = 96;      // the slip's angle sampled around the circle
constexpr int kSlipAngleBisections = 200;  // to rounding
constexpr int kSpatialMaxSweeps = 400;     // Gauss-Seidel: then unsolved, the caller decides
constexpr double kSpatialSettle = 1e-14;   // relative change of the velocities between sweeps
constexpr double kSpatialConeTie = 1e-12;  // relative slack of a cone or a sign at rounding
constexpr double kSpatialPolish = 1e-9;    // a pressed point Gauss-Seidel leaves this slow (relative) sticks
constexpr int kSpatialPolishEvery = 2;     // sweeps between tries of the exact sticking solve
constexpr double kSpatialSolved = 1e-10;   // relative: the conditions a settled Gauss-Seidel meets
constexpr int kSpatialNewtonSteps = 12;    // Newton's method on Gauss-Seidel's classes

void spatial_times3(const double* w, const double* x, double* y) {
  for (int r = 0; r < 3; ++r) y[r] = w[3 * r] * x[0] + w[3 * r + 1] * x[1] + w[3 * r + 2] * x[2];
}

bool in_coulomb_cone(const double* p, double mu, double scale) {
  return p[2] >= -kSpatialConeTie * scale && std::hypot(p[0], p[1]) <= mu * p[2] + kSpatialConeTie * scale;
}

bool solve_spatial3(const double* w, const double* b, double* x) {
  const double a = w[0], bb = w[1], c = w[2], d = w[3], e = w[4], f = w[5], g = w[6], h = w[7], k = w[8];
  const double det = a * (e * k - f * h) - bb * (d * k - f * g) + c * (d * h - e * g);
  if (!(std::fabs(det) > 0)) return false;
  x[0] = (b[0] * (e * k - f * h) - bb * (b[1] * k - f * b[2]) + c * (b[1] * h - e * b[2])) / det;
  x[1] = (a * (b[1] * k - f * b[2]) - b[0] * (d * k - f * g) + c * (d * b[2] - b[1] * g)) / det;
  x[2] = (a * (e * b[2] - b[1] * h) - bb * (d * b[2] - b[1] * g) + b[0] * (d * h - e * g)) / det;
  return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

// The slip along angle phi: the impulse p = p_N (-mu cos, -mu sin, 1) that brings u_N to v_N, the
// tangential velocity it leaves, and the residual d x u_T (zero where u_T lies along d).
struct SpatialSlipTrial {
  double pn = 0, along = 0, cross = 0;
  bool valid = false;
};
SpatialSlipTrial spatial_slip_at(const double* w, const double* q, double v_normal, double mu, double phi, double* p) {
  const double d[2] = {std::cos(phi), std::sin(phi)};
  const double g[3] = {-mu * d[0], -mu * d[1], 1.0};
  double wg[3];
  spatial_times3(w, g, wg);
  SpatialSlipTrial s;
  if (!(wg[2] > 0)) return s;
  s.pn = (v_normal - q[2]) / wg[2];
  const double ut[2] = {q[0] + s.pn * wg[0], q[1] + s.pn * wg[1]};
  s.along = d[0] * ut[0] + d[1] * ut[1];
  s.cross = d[0] * ut[1] - d[1] * ut[0];
  s.valid = s.pn >= 0;
  for (int i = 0; i < 3; ++i) p[i] = s.pn * g[i];
  return s;
}

}  // namespace

bool solve_contact_3x3(const double* w, const double* q, double v_normal, double mu_s, double mu_k, double* p) {
  p[0] = p[1] = p[2] = 0;
  if (q[2] >= v_normal) return true;  // leaves (or stays) without an impulse
  const double target[3] = {-q[0], -q[1], v_normal - q[2]};
  const double scale = std::fabs(target[0]) + std::fabs(target[1]) + std::fabs(target[2]);
  double stick[3] = {0, 0, 0};
  if (solve_spatial3(w, target, stick) && in_coulomb_cone(stick, mu_s, scale / (std::fabs(w[8]) + 1e-300))) {
    for (int i = 0; i < 3; ++i) p[i] = stick[i];
    return true;
  }
  // Slip: the root of d x u_T(d) with u_T . d >= 0 nearest the sticking impulse's opposite.
  // (The scan starts half a sample before it: a root there, the usual case, falls inside an interval.)
  const double phi0 = std::atan2(-stick[1], -stick[0]) - M_PI / kSlipAngleSamples;
  double trial[3];
  auto sample = [&](double phi) {
    const SpatialSlipTrial s = spatial_slip_at(w, q, v_normal, mu_k, phi, trial);
    return CircleSample{s.cross, s.valid};
  };
  auto accept = [&](double root) {
    const SpatialSlipTrial s = spatial_slip_at(w, q, v_normal, mu_k, root, trial);
    return s.valid && s.along >= 0;
  };
  const double best =
      nearest_circle_root(phi0, CircleRootScan{kSlipAngleSamples, kSlipAngleBisections, 1e-17}, sample, accept);
  if (std::isnan(best)) return false;
  spatial_slip_at(w, q, v_normal, mu_k, best, p);
  return true;
}

namespace {

using SpatialVector = std::array<double, 3 * kMaxSpatialPoints>;

void spatial_velocities(const SpatialContactProblem& pr, const SpatialVector& p, SpatialVector& u) {
  const int m = 3 * pr.n;
  for (int r = 0; r < m; ++r) {
    u[std::size_t(r)] = pr.q[std::size_t(r)];
    for (int c = 0; c < m; ++c) u[std::size_t(r)] += pr.at(r, c) * p[std::size_t(c)];
  }
}

// The points of `stick` (a bit each) sticking at their normal velocity asked for, the others
// without impulse: the least-norm impulses, accepted where every impulse lies in its cone and the
// points left free do not sink.
bool sticking_subset(const SpatialContactProblem& pr, unsigned stick, SpatialContactSolution& sol) {
  int idx[kMaxSpatialPoints], k = 0;
  for (int i = 0; i < pr.n; ++i)
    if (stick & (1u << unsigned(i))) idx[k++] = i;
  const int m = 3 * k;
  std::array<double, 9 * kMaxSpatialPoints * kMaxSpatialPoints> a{};
  SpatialVector rhs{}, x{};
  for (int bi = 0; bi < k; ++bi)
    for (int r = 0; r < 3; ++r) {
      const int row = 3 * idx[bi] + r;
      rhs[std::size_t(3 * bi + r)] = (r == 2 ? pr.v_normal[std::size_t(idx[bi])] : 0.0) - pr.q[std::size_t(row)];
      for (int bj = 0; bj < k; ++bj)
        for (int c = 0; c < 3; ++c) a[std::size_t((3 * bi + r) * m + 3 * bj + c)] = pr.at(row, 3 * idx[bj] + c);
    }
  if (k > 0 && !solve_dense_least_norm(m, a.data(), rhs.data(), x.data())) return false;
  SpatialVector p{}, u{};
  double pscale = 0, uscale = 0;
  for (int bi = 0; bi < k; ++bi)
    for (int r = 0; r < 3; ++r) {
      p[std::size_t(3 * idx[bi] + r)] = x[std::size_t(3 * bi + r)];
      pscale = std::fmax(pscale, std::fabs(x[std::size_t(3 * bi + r)]));
    }
  spatial_velocities(pr, p, u);
  for (int r = 0; r < 3 * pr.n; ++r) uscale = std::fmax(uscale, std::fabs(pr.q[std::size_t(r)]));
  for (int i = 0; i < pr.n; ++i) uscale = std::fmax(uscale, pr.v_normal[std::size_t(i)]);
  for (int i = 0; i < pr.n; ++i) {
    if (stick & (1u << unsigned(i))) {
      if (!in_coulomb_cone(&p[std::size_t(3 * i)], pr.mu_s, pscale)) return false;
      // The least-norm impulses of a system with no exact solution (more points at rest than the
      // body's freedom allows) are no solution.
      for (int r = 0; r < 3; ++r) {
        const double want = r == 2 ? pr.v_normal[std::size_t(i)] : 0.0;
        if (std::fabs(u[std::size_t(3 * i + r)] - want) > kSpatialConeTie * std::fmax(uscale, 1e-300)) return false;
      }
    } else if (u[std::size_t(3 * i + 2)] < pr.v_normal[std::size_t(i)] - kSpatialConeTie * uscale) {
      return false;
    }
  }
  sol.solved = true;
  sol.p = p;
  sol.u = u;
  return true;
}

// Whether impulses p and velocities u solve the problem: each point pressed only at its normal
// velocity asked for (never below it), in its cone, on the cone's edge against its slip.
bool solves(const SpatialContactProblem& pr, const SpatialVector& p, const SpatialVector& u) {
  double ps = 0, us = 0;
  for (int r = 0; r < 3 * pr.n; ++r) {
    ps = std::fmax(ps, std::fabs(p[std::size_t(r)]));
    us = std::fmax(us, std::fmax(std::fabs(u[std::size_t(r)]), std::fabs(pr.q[std::size_t(r)])));
  }
  const double pt_tie = kSpatialSolved * ps, u_tie = kSpatialSolved * us;
  for (int i = 0; i < pr.n; ++i) {
    const double* pi = &p[std::size_t(3 * i)];
    const double* ui = &u[std::size_t(3 * i)];
    const double vn = pr.v_normal[std::size_t(i)];
    if (pi[2] < -pt_tie || ui[2] < vn - u_tie) return false;
    if (pi[2] > pt_tie && std::fabs(ui[2] - vn) > u_tie) return false;
    const double pt = std::hypot(pi[0], pi[1]), ut = std::hypot(ui[0], ui[1]);
    if (pt > pr.mu_s * pi[2] + pt_tie) return false;
    if (ut > u_tie && pi[2] > pt_tie) {
      if (std::fabs(pt - pr.mu_k * pi[2]) > pt_tie) return false;
      if (std::fabs(pi[0] * ut + pt * ui[0]) > pt_tie * ut || std::fabs(pi[1] * ut + pt * ui[1]) > pt_tie * ut)
        return false;
    }
  }
  return true;
}

// Gauss-Seidel's answer made exact: the points it leaves pressed keep their class (sticking, or
// slipping with a direction), and Newton's method solves their conditions together - a sticking
// point's velocity (0, 0, v_N), a slipping point's normal velocity v_N and its slip along its
// direction d(phi) (its impulse p_N (-mu_k d, 1)) - to rounding. False if it does not converge.
bool polish_classes(const SpatialContactProblem& pr, SpatialVector& p, SpatialVector& u) {
  int kind[kMaxSpatialPoints], at[kMaxSpatialPoints], m = 0;  // kind: 0 free, 1 stick, 2 slip
  double x[3 * kMaxSpatialPoints];
  double us = 0;
  for (int r = 0; r < 3 * pr.n; ++r) us = std::fmax(us, std::fabs(pr.q[std::size_t(r)]));
  for (int i = 0; i < pr.n; ++i) {
    const double* pi = &p[std::size_t(3 * i)];
    const double* ui = &u[std::size_t(3 * i)];
    kind[i] = pi[2] > 0 ? (std::hypot(ui[0], ui[1]) > kSpatialPolish * us ? 2 : 1) : 0;
    at[i] = m;
    if (kind[i] == 1) {
      x[m++] = pi[0], x[m++] = pi[1], x[m++] = pi[2];
    } else if (kind[i] == 2) {
      x[m++] = pi[2], x[m++] = std::atan2(ui[1], ui[0]);
    }
  }
  if (m == 0) return false;
  auto impulses = [&](const double* xs, SpatialVector& ps) {
    ps.fill(0);
    for (int i = 0; i < pr.n; ++i) {
      double* pi = &ps[std::size_t(3 * i)];
      if (kind[i] == 1) pi[0] = xs[at[i]], pi[1] = xs[at[i] + 1], pi[2] = xs[at[i] + 2];
      if (kind[i] == 2) {
        const double pn = xs[at[i]], phi = xs[at[i] + 1];
        pi[0] = -pr.mu_k * pn * std::cos(phi), pi[1] = -pr.mu_k * pn * std::sin(phi), pi[2] = pn;
      }
    }
  };
  auto residual = [&](const double* xs, double* f) {
    SpatialVector ps, us2;
    impulses(xs, ps);
    spatial_velocities(pr, ps, us2);
    for (int i = 0; i < pr.n; ++i) {
      const double* ui = &us2[std::size_t(3 * i)];
      const double vn = pr.v_normal[std::size_t(i)];
      if (kind[i] == 1) f[at[i]] = ui[0], f[at[i] + 1] = ui[1], f[at[i] + 2] = ui[2] - vn;
      if (kind[i] == 2) {
        const double phi = xs[at[i] + 1];
        f[at[i]] = ui[2] - vn;
        f[at[i] + 1] = std::cos(phi) * ui[1] - std::sin(phi) * ui[0];
      }
    }
  };
  double f[3 * kMaxSpatialPoints], jac[9 * kMaxSpatialPoints * kMaxSpatialPoints], dx[3 * kMaxSpatialPoints];
  for (int it = 0; it < kSpatialNewtonSteps; ++it) {
    residual(x, f);
    double size = 0;
    for (int k = 0; k < m; ++k) size = std::fmax(size, std::fabs(f[k]));
    if (size <= 4 * DBL_EPSILON * us) break;
    // The Jacobian by central differences (the residual is linear in the impulses, smooth in phi).
    for (int c = 0; c < m; ++c) {
      double xp[3 * kMaxSpatialPoints], xm[3 * kMaxSpatialPoints], fp[3 * kMaxSpatialPoints], fm[3 * kMaxSpatialPoints];
      const double h = 1e-7 * std::fmax(1.0, std::fabs(x[c]));
      for (int k = 0; k < m; ++k) xp[k] = xm[k] = x[k];
      xp[c] += h;
      xm[c] -= h;
      residual(xp, fp);
      residual(xm, fm);
      for (int r = 0; r < m; ++r) jac[r * m + c] = (fp[r] - fm[r]) / (2 * h);
    }
    for (int k = 0; k < m; ++k) f[k] = -f[k];
    if (!solve_dense_least_norm(m, jac, f, dx)) return false;
    for (int k = 0; k < m; ++k) x[k] += dx[k];
  }
  SpatialVector ps, us2;
  impulses(x, ps);
  spatial_velocities(pr, ps, us2);
  if (!solves(pr, ps, us2)) return false;
  p = ps;
  u = us2;
  return true;
}

}  // namespace

SpatialContactSolution solve_spatial_contact(const SpatialContactProblem& pr) {
  SpatialContactSolution sol;
  const int n = pr.n, m = 3 * n;
  if (n < 1 || n > kMaxSpatialPoints) return sol;
  auto velocities = [&](const SpatialVector& p, SpatialVector& u) { spatial_velocities(pr, p, u); };
  auto block = [&](int i, double* w) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) w[3 * r + c] = pr.at(3 * i + r, 3 * i + c);
  };
  double scale = 0;
  for (int r = 0; r < m; ++r) scale = std::fmax(scale, std::fabs(pr.q[std::size_t(r)]));
  for (int i = 0; i < n; ++i) scale = std::fmax(scale, pr.v_normal[std::size_t(i)]);
  if (n == 1) {
    double w[9];
    block(0, w);
    sol.solved = solve_contact_3x3(w, pr.q.data(), pr.v_normal[0], pr.mu_s, pr.mu_k, sol.p.data());
    sol.method = 1;
    velocities(sol.p, sol.u);
    return sol;
  }
  // The points that approach sticking at their normal velocity asked for, the others free (as the
  // planar block's impact has it); else every point sticking: the least-norm impulses.
  const unsigned all = (1u << unsigned(n)) - 1;
  unsigned approaching = 0;
  for (int i = 0; i < n; ++i)
    if (pr.q[std::size_t(3 * i + 2)] < pr.v_normal[std::size_t(i)]) approaching |= 1u << unsigned(i);
  if (approaching != all && approaching != 0 && sticking_subset(pr, approaching, sol)) {
    sol.method = 2;
    return sol;
  }
  if (sticking_subset(pr, all, sol)) {
    sol.method = 3;
    return sol;
  }
  // Gauss-Seidel from no impulse: each point exactly, the others held.
  SpatialVector p{}, u{}, u_prev{};
  velocities(p, u);
  for (int sweep = 1; sweep <= kSpatialMaxSweeps; ++sweep) {
    u_prev = u;
    for (int i = 0; i < n; ++i) {
      double w[9], qi[3], pi[3];
      block(i, w);
      for (int r = 0; r < 3; ++r) {
        qi[r] = pr.q[std::size_t(3 * i + r)];
        for (int c = 0; c < m; ++c)
          if (c / 3 != i) qi[r] += pr.at(3 * i + r, c) * p[std::size_t(c)];
      }
      if (!solve_contact_3x3(w, qi, pr.v_normal[std::size_t(i)], pr.mu_s, pr.mu_k, pi)) return sol;
      for (int r = 0; r < 3; ++r) p[std::size_t(3 * i + r)] = pi[r];
    }
    velocities(p, u);
    double change = 0;
    for (int r = 0; r < m; ++r) change = std::fmax(change, std::fabs(u[std::size_t(r)] - u_prev[std::size_t(r)]));
    const bool settled = change <= kSpatialSettle * scale;
    if (settled || sweep == kSpatialMaxSweeps || sweep % kSpatialPolishEvery == 0) {
      // The points Gauss-Seidel leaves pressed and at rest, solved together exactly (a corner
      // and an edge that stick, as Housner's law has them); else its own answer.
      unsigned stick = 0;
      bool slips = false;
      for (int i = 0; i < n; ++i) {
        if (!(p[std::size_t(3 * i + 2)] > 0)) continue;
        if (std::hypot(u[std::size_t(3 * i)], u[std::size_t(3 * i + 1)]) <= kSpatialPolish * scale)
          stick |= 1u << unsigned(i);
        else
          slips = true;
      }
      if (!slips && sticking_subset(pr, stick, sol)) {
        sol.sweeps = sweep;
        sol.method = 4;
        return sol;
      }
      // Some slip: Newton's method on the classes Gauss-Seidel has reached, accepted where it
      // solves the problem exactly (Gauss-Seidel alone converges linearly: hundreds of sweeps).
      if (slips && !settled && sweep < kSpatialMaxSweeps) {
        SpatialVector pn = p, un = u;
        if (polish_classes(pr, pn, un)) {
          sol.solved = true;
          sol.sweeps = sweep;
          sol.method = 6;
          sol.p = pn;
          sol.u = un;
          return sol;
        }
      }
      if (!settled && sweep < kSpatialMaxSweeps) continue;
      if (!settled || !solves(pr, p, u)) return sol;  // did not settle, or settled where it is no solution
      const bool exact = polish_classes(pr, p, u);    // exact to rounding where Newton's method converges
      sol.solved = true;
      sol.sweeps = sweep;
      sol.method = exact ? 6 : 5;
      sol.p = p;
      sol.u = u;
      return sol;
    }
  }
  return sol;
}

}  // namespace blockdyn
