// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/rigid_ground/contact_problem.hpp"

#include <cmath>

namespace blockdyn {

namespace {

// Small dense solve (n <= 3) by Gaussian elimination with partial pivoting.
bool solve_small(int n, double A[3][3], double x[3]) {
  double scale = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) scale = std::fmax(scale, std::fabs(A[i][j]));
  if (!(scale > 0)) return n == 0;
  for (int k = 0; k < n; ++k) {
    int piv = k;
    for (int i = k + 1; i < n; ++i)
      if (std::fabs(A[i][k]) > std::fabs(A[piv][k])) piv = i;
    if (std::fabs(A[piv][k]) <= 1e-13 * scale) return false;
    if (piv != k) {
      for (int j = 0; j < n; ++j) std::swap(A[k][j], A[piv][j]);
      std::swap(x[k], x[piv]);
    }
    for (int i = k + 1; i < n; ++i) {
      const double f = A[i][k] / A[k][k];
      for (int j = k; j < n; ++j) A[i][j] -= f * A[k][j];
      x[i] -= f * x[k];
    }
  }
  for (int k = n - 1; k >= 0; --k) {
    double s = x[k];
    for (int j = k + 1; j < n; ++j) s -= A[k][j] * x[j];
    x[k] = s / A[k][k];
  }
  return true;
}

// The shared tangential row's r_y: both corners have the same at theta = 0.
double tangent_ry(const ContactProblem& p) { return p.n == 2 ? 0.5 * (p.c[0].r.y + p.c[1].r.y) : p.c[0].r.y; }

// Rates (normal j, tangential) of a generalised vector w.
double normal_rate(const ContactPoint& c, const std::array<double, 3>& w) { return w[1] + c.r.x * w[2]; }
double tangential_rate(double ry, const std::array<double, 3>& w) { return w[0] - ry * w[2]; }

}  // namespace

std::optional<ContactSolution> solve_candidate(const ContactProblem& p, const bool closed[2], Tangential tang) {
  ContactSolution s;
  s.tang = tang;
  const double ry = tangent_ry(p);
  const double im = 1.0 / p.m, iI = 1.0 / p.I;
  // Free rates (no contact force).
  const std::array<double, 3> uf{p.b[0] * im, p.b[1] * im, p.b[2] * iI};
  int idx[2] = {-1, -1};
  int nu = 0;
  for (int j = 0; j < p.n; ++j) {
    s.closed[j] = closed[j];
    if (closed[j]) idx[j] = nu++;
  }
  const bool stick = tang == Tangential::Stick;
  const int sigma = s.sigma();
  const int iT = (stick && nu > 0) ? nu++ : -1;
  double A[3][3] = {}, x[3] = {};
  // Delassus entries: n_j.M^-1.n_k, n_j.M^-1.t, t.M^-1.t
  auto dnn = [&](int j, int k) { return im + p.c[j].r.x * p.c[k].r.x * iI; };
  auto dnt = [&](int j) { return -p.c[j].r.x * ry * iI; };
  const double dtt = im + ry * ry * iI;
  for (int j = 0; j < p.n; ++j) {
    if (!closed[j]) continue;
    const int row = idx[j];
    x[row] = p.c[j].target - normal_rate(p.c[j], uf) - p.cn[j];
    for (int k = 0; k < p.n; ++k) {
      if (!closed[k]) continue;
      A[row][idx[k]] += dnn(j, k);
      if (!stick) A[row][idx[k]] += dnt(j) * (-sigma * p.mu.mu_k);
    }
    if (iT >= 0) A[row][iT] = dnt(j);
  }
  if (iT >= 0) {
    x[iT] = -tangential_rate(ry, uf) - p.ct;
    for (int k = 0; k < p.n; ++k)
      if (closed[k]) A[iT][idx[k]] = dnt(k);
    A[iT][iT] = dtt;
  }
  // Effective normal compliance of the slip system (Painleve: not positive).
  if (!stick && nu == 1) s.effective_mass_inv = A[0][0];
  if (!stick && nu == 2) s.effective_mass_inv = std::fmin(A[0][0], A[0][0] * A[1][1] - A[0][1] * A[1][0]);
  if (stick) s.effective_mass_inv = 1.0;
  if (!solve_small(nu, A, x)) return std::nullopt;
  double sumN = 0;
  for (int j = 0; j < p.n; ++j) {
    s.N[j] = closed[j] ? x[idx[j]] : 0.0;
    sumN += s.N[j];
  }
  s.T = iT >= 0 ? x[iT] : -sigma * p.mu.mu_k * sumN;
  if (nu == 0) s.T = 0.0;
  // Resulting generalised rates.
  double F[3] = {p.b[0] + s.T, p.b[1], p.b[2] - ry * s.T};
  for (int j = 0; j < p.n; ++j) {
    F[1] += s.N[j];
    F[2] += p.c[j].r.x * s.N[j];
  }
  s.u = {F[0] * im, F[1] * im, F[2] * iI};
  return s;
}

bool consistent(const ContactProblem& p, const ContactSolution& s, double tf, double tr) {
  const double ry = tangent_ry(p);
  double sumN = 0;
  for (int j = 0; j < p.n; ++j) {
    if (s.closed[j]) {
      if (s.N[j] < -tf) return false;
      sumN += s.N[j];
    } else if (normal_rate(p.c[j], s.u) + p.cn[j] < p.c[j].target - tr) {
      return false;
    }
  }
  if (s.closed_count() == 0) return true;
  if (s.tang == Tangential::Stick) return std::fabs(s.T) <= p.mu.mu_s * sumN + tf;
  if (p.slip_sign != 0) return s.sigma() == p.slip_sign;
  // Slip onset: the contact must accelerate (or move) in the slip direction.
  return s.sigma() * (tangential_rate(ry, s.u) + p.ct) >= -tr;
}

Selection select_contacts(const ContactProblem& p, const SelectionHints& h, double tf, double tr) {
  Selection sel;
  // Candidate closed sets, most contacts first.
  const bool sets[4][2] = {{true, true}, {true, false}, {false, true}, {false, false}};
  const Tangential tangs[3] = {Tangential::Stick, Tangential::SlipPos, Tangential::SlipNeg};
  std::array<ContactSolution, 12>& found = sel.consistent;
  std::array<int, 12> rank{};
  int nf = 0;
  for (const auto& cl : sets) {
    if (p.n == 1 && cl[1]) continue;
    bool skip = false;
    for (int j = 0; j < p.n; ++j) skip |= cl[j] && h.must_open[j];
    if (skip) continue;
    const bool any = cl[0] || (p.n == 2 && cl[1]);
    for (const Tangential tg : tangs) {
      if (!any && tg != Tangential::Stick) break;  // no contact: the tangential status is moot
      const int sg = tg == Tangential::SlipPos ? 1 : tg == Tangential::SlipNeg ? -1 : 0;
      if (any && sg == 0 && (h.no_stick || p.slip_sign != 0)) continue;
      if (any && sg != 0 && p.slip_sign != 0 && sg != p.slip_sign) continue;
      const auto s = solve_candidate(p, cl, tg);
      if (!s || !consistent(p, *s, tf, tr)) continue;
      // Static friction holds if it can (stick first); then more closed contacts.
      rank[nf] = (any && sg != 0 ? 10 : 0) + (2 - s->closed_count());
      found[nf++] = *s;
    }
  }
  sel.consistent_count = nf;
  int best = -1;
  for (int i = 0; i < nf; ++i)
    if (best < 0 || rank[i] < rank[best]) best = i;
  if (best < 0) {
    sel.painleve = true;
    return sel;
  }
  sel.chosen = found[best];
  const ContactSolution& c = found[best];
  const bool stuck = c.closed_count() > 0 && c.tang == Tangential::Stick;
  if (c.closed_count() > 0 && !stuck && c.effective_mass_inv <= 0.0) sel.painleve = true;
  // Without sticking no rule orders slip and separation: two consistent candidates that move the
  // block differently are Painleve's non-uniqueness (candidates equal to tolerance are one).
  if (!stuck) {
    const double lever = std::hypot(p.c[0].r.x, p.c[0].r.y);
    auto norm = [&](double a, double b, double w) { return std::fabs(a) + std::fabs(b) + lever * std::fabs(w); };
    const double scale = norm(p.b[0] / p.m, p.b[1] / p.m, p.b[2] / p.I) + norm(c.u[0], c.u[1], c.u[2]);
    for (int i = 0; i < nf; ++i) {
      if (i == best || (found[i].closed_count() > 0 && found[i].tang == Tangential::Stick)) continue;
      const auto& o = found[i].u;
      if (norm(o[0] - c.u[0], o[1] - c.u[1], o[2] - c.u[2]) > 1e-6 * scale) sel.painleve = true;
    }
  }
  return sel;
}

}  // namespace blockdyn
