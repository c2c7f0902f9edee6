// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/numerics/planar_contact.hpp"

#include <algorithm>
#include <cmath>

#include "blockdyn/numerics/redundant_solve.hpp"

namespace blockdyn {

namespace {
// A pivot this small against the Delassus diagonal: the guessed active set is degenerate (the
// impulses of redundant ends are not unique) and another solver takes over.
constexpr double kSingularPivot = 1e-13;
// Guesses of the active-set iteration before it gives up (one or two in practice).
constexpr int kMaxActiveSetIterations = 12;
// Block pivoting steps without fewer violated conditions before single changes take over.
constexpr int kBlockPivotStalls = 2;
}  // namespace

void solve_contact_2x2(double a, double c, double d, double bn, double bt, double mu, double& pn, double& pt) {
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

void PlanarContactSolver::reserve(int max_ends, int max_coords) {
  const int np = max_ends;
  m_cap_ = 2 * np;
  A_.resize(std::size_t(m_cap_) * std::size_t(m_cap_));
  rhs_.resize(std::size_t(m_cap_));
  pivots_.resize(std::size_t(m_cap_));
  lcp_m_.resize(std::size_t(4 * np) * std::size_t(4 * np));
  lcp_q_.resize(std::size_t(4 * np));
  lcp_z_.resize(std::size_t(4 * np));
  lemke_.reserve(4 * np);
  for (auto* x : {&face_end_, &face_of_, &flips_, &col_n_, &col_t_}) x->resize(std::size_t(np));
  for (auto* x : {&pn_, &pt_, &un_, &ut_}) x->resize(std::size_t(np));
  cls_.resize(std::size_t(np));
  next_.resize(std::size_t(np));
  dv_.resize(std::size_t(max_coords));
  dv_new_.resize(std::size_t(max_coords));
}

bool PlanarContactSolver::solve_lemke(const PlanarContactProblem& p) {
  const int nc = p.n;
  int nf = 0;
  for (int i = 0; i < nc; ++i) {
    if (i == 0 || p.face[i - 1] != p.face[i]) face_end_[nf++] = i;
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
  for (int k = 0; k < 2 * nc; ++k) d = std::max(d, W(p, k, k));
  const double inv_d = 1.0 / d;
  for (int i = 0; i < nc; ++i) {
    for (int j = 0; j < nc; ++j) M(i, j) = W(p, 2 * i, 2 * j) * inv_d;
    for (int f = 0; f < nf; ++f) {
      const double nt = W(p, 2 * i, 2 * face_end_[f] + 1) * inv_d;
      M(i, bp + f) = nt;
      M(i, bm + f) = -nt;
    }
    lcp_q_[std::size_t(i)] = p.bn[i] * inv_d;
  }
  for (int f = 0; f < nf; ++f) {
    const int r = face_end_[f];
    for (int j = 0; j < nc; ++j) {
      const double tn = W(p, 2 * r + 1, 2 * j) * inv_d;
      M(bp + f, j) = tn;
      M(bm + f, j) = -tn;
    }
    for (int g = 0; g < nf; ++g) {
      const double tt = W(p, 2 * r + 1, 2 * face_end_[g] + 1) * inv_d;
      M(bp + f, bp + g) = tt;
      M(bp + f, bm + g) = -tt;
      M(bm + f, bp + g) = -tt;
      M(bm + f, bm + g) = tt;
    }
    M(bp + f, lm + f) = 1.0;
    M(bm + f, lm + f) = 1.0;
    // The face's cone, scaled by its largest coefficient.
    double mu_max = 0.0;
    for (int i = r; i < nc && face_of_[i] == f; ++i) mu_max = std::max(mu_max, p.mu[i]);
    const double cs = mu_max > 0.0 ? 1.0 / mu_max : 1.0;
    for (int i = r; i < nc && face_of_[i] == f; ++i) M(lm + f, i) = p.mu[i] * cs;
    M(lm + f, bp + f) = -cs;
    M(lm + f, bm + f) = -cs;
    lcp_q_[std::size_t(bp + f)] = p.bt[r] * inv_d;
    lcp_q_[std::size_t(bm + f)] = -p.bt[r] * inv_d;
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
    cls_[i] = !(pn_[i] > 0.0) ? ContactClass::Separate
              : slip > 0.0    ? (pt_[r] > 0.0 ? ContactClass::SlipNeg : ContactClass::SlipPos)
                              : ContactClass::Stick;
  }
  // The face's tangential impulse shared by its ends as their normal impulses (slipping ends:
  // each -s mu P_N, as the active-set solution has them).
  for (int f = 0; f < nf; ++f) {
    const int r = face_end_[f];
    double T = pt_[r], N_sum = 0.0;
    for (int i = r; i < nc && face_of_[i] == f; ++i) N_sum += pn_[i];
    for (int i = r; i < nc && face_of_[i] == f; ++i) {
      if (is_slip(cls_[i]))
        pt_[i] = (cls_[i] == ContactClass::SlipPos ? -1.0 : 1.0) * p.mu[i] * pn_[i];
      else
        pt_[i] = N_sum > 0.0 ? T * pn_[i] / N_sum : (i == r ? T : 0.0);
    }
  }
  return true;
}

// The linear system of the guessed pattern (separate, stick, slip +/-) into A_ and rhs_: u_N = 0
// for every end in contact, u_T = 0 for every sticking end, P_T = -s mu P_N for every slipping
// one. Returns its size.
int PlanarContactSolver::assemble_guess(const PlanarContactProblem& p) {
  const int nc = p.n;
  const std::size_t S = std::size_t(m_cap_);
  int m = 0;
  // One tangential unknown per sticking face, on its first sticking end: the two ends of a face
  // lie on one line along its tangent, so only the sum of their tangential impulses acts (the
  // split, a redundancy, is shared out once solved). The unknowns go end by end, so that a
  // chain of blocks (a column, an arch) gives a banded matrix.
  for (int i = 0; i < nc; ++i) {
    col_n_[i] = cls_[i] != ContactClass::Separate ? m++ : -1;
    const int j = cls_[i] == ContactClass::Stick ? sticking_partner(p, i) : 0;
    col_t_[i] = cls_[i] == ContactClass::Stick && (j < 0 || j > i) ? m++ : -1;
  }
  // Equation rows in the same order as the unknowns: u_N of ends in contact, u_T of sticking ones.
  auto coeff_row = [&](int wrow, double* out) {
    for (int j = 0; j < nc; ++j) {
      if (col_n_[j] < 0) continue;
      double c = W(p, wrow, 2 * j);
      if (is_slip(cls_[j])) c -= (cls_[j] == ContactClass::SlipPos ? 1.0 : -1.0) * p.mu[j] * W(p, wrow, 2 * j + 1);
      out[col_n_[j]] = c;
      if (col_t_[j] >= 0) out[col_t_[j]] = W(p, wrow, 2 * j + 1);
    }
  };
  for (int i = 0; i < nc; ++i) {
    if (col_n_[i] >= 0) {
      coeff_row(2 * i, &A_[std::size_t(col_n_[i]) * S]);
      rhs_[col_n_[i]] = -p.bn[i];
    }
    if (col_t_[i] >= 0) {
      coeff_row(2 * i + 1, &A_[std::size_t(col_t_[i]) * S]);
      rhs_[col_t_[i]] = -p.bt[i];
    }
  }
  return m;
}

// The impulses of the guessed pattern from the assembled system of size m.
void PlanarContactSolver::solve_guess(const PlanarContactProblem& p, int m, double diag_max) {
  const int nc = p.n;
  // Without slipping ends the system is the Delassus matrix's restriction (symmetric positive
  // definite unless degenerate).
  bool any_slip = false;
  for (int i = 0; i < nc; ++i) any_slip = any_slip || is_slip(cls_[i]);
  if (any_slip)
    gauss_solve(A_.data(), rhs_.data(), m, m_cap_, kSingularPivot * diag_max, pivots_.data());
  else
    cholesky_solve(A_.data(), rhs_.data(), m, m_cap_, kSingularPivot * diag_max, pivots_.data());
  for (int i = 0; i < nc; ++i) {
    pn_[i] = col_n_[i] >= 0 ? rhs_[col_n_[i]] : 0.0;
    pt_[i] = col_t_[i] >= 0                     ? rhs_[col_t_[i]]
             : cls_[i] == ContactClass::SlipPos ? -p.mu[i] * pn_[i]
             : cls_[i] == ContactClass::SlipNeg ? p.mu[i] * pn_[i]
                                                : 0.0;
  }
}

// Checks every condition of the guess (P_N >= 0, the cone, the slip direction, u_N >= 0 where
// separate); each violated one proposes a new guess for its end in next_. Returns how many are
// violated, the first in `first`; `accurate`: the holding ends' equations are met to tol.
int PlanarContactSolver::check_guess(const PlanarContactProblem& p, double tol, double diag_max, int& first,
                                     bool& accurate) {
  const int nc = p.n;
  // The relative velocities after the step, from the bodies' (sparse: two bodies per end).
  p.velocities->relative(pn_.data(), pt_.data(), un_.data(), ut_.data());
  // The conditions of the regularised problem (u + c P = 0 where an end holds); each violated
  // one proposes a new guess for its end (for the face's cone: for both its ends).
  const double p_tol = tol / diag_max;
  int violations = 0;
  first = -1;
  accurate = true;
  for (int i = 0; i < nc; ++i) next_[i] = cls_[i];
  for (int i = 0; i < nc; ++i) {
    const double un = un_[i], ut = ut_[i];
    const double cn = un + p.compliance * pn_[i], ct = ut + p.compliance * pt_[i];
    bool violated = false;
    switch (cls_[i]) {
      case ContactClass::Separate:
        if (un < -tol) next_[i] = ContactClass::Stick, violated = true;
        break;
      case ContactClass::Stick: {
        accurate = accurate && std::fabs(cn) <= tol && (col_t_[i] < 0 || std::fabs(ct) <= tol);
        // The face's two ends lie on one line along its tangent, so only their tangential
        // impulses' sum is defined (a redundant pair may put it all on one end): the cone is
        // the face's, sum |P_T| <= sum mu P_N.
        const int j = sticking_partner(p, i);
        const double pt = pt_[i] + (j >= 0 ? pt_[j] : 0.0);
        const double cap = p.mu[i] * pn_[i] + (j >= 0 ? p.mu[j] * pn_[j] : 0.0);
        if (pn_[i] < -p_tol) {
          // Sticking pulls and separating penetrates (the end has gone back and forth): what
          // remains is sliding at a vanishing normal impulse, against the tangential one.
          next_[i] = flips_[i] >= 2 && j < 0 ? (pt > 0 ? ContactClass::SlipNeg : ContactClass::SlipPos)
                                             : ContactClass::Separate;
          violated = true;
        } else if (std::fabs(pt) > cap + p_tol && (j < 0 || pn_[j] >= -p_tol)) {
          // Outside the cone: the face slips against the impulse's tendency.
          next_[i] = pt > 0 ? ContactClass::SlipNeg : ContactClass::SlipPos;
          if (j >= 0) next_[j] = next_[i];
          violated = true;
        }
        break;
      }
      case ContactClass::SlipPos:
      case ContactClass::SlipNeg: {
        accurate = accurate && std::fabs(cn) <= tol;
        const double sg = cls_[i] == ContactClass::SlipPos ? 1.0 : -1.0;
        if (pn_[i] < -p_tol) {
          next_[i] = ContactClass::Separate, violated = true;
        } else if (sg * ut < -tol) {
          next_[i] = ContactClass::Stick, violated = true;
        }
        break;
      }
    }
    if (violated && first < 0) first = i;
    violations += violated;
  }
  return violations;
}

bool PlanarContactSolver::solve_direct(const PlanarContactProblem& p, double tol) {
  const int nc = p.n;
  double diag_max = 0;
  for (int k = 0; k < 2 * nc; ++k) diag_max = std::max(diag_max, p.W[std::size_t(k) * (p.stride + 1)]);
  int best = nc + 1, stalls = 0;
  for (int i = 0; i < nc; ++i) flips_[i] = 0;
  for (int iter = 0; iter < kMaxActiveSetIterations; ++iter) {
    ++active_set_iterations_;
    solve_guess(p, assemble_guess(p), diag_max);
    int first = -1;
    bool accurate = true;
    const int violations = check_guess(p, tol, diag_max, first, accurate);
    if (violations == 0) {
      if (!accurate) return false;
      share_sticking_friction(p);
      return true;
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
      const int j = sticking_partner(p, first);
      cls_[first] = next_[first];
      if (j >= 0 && next_[j] == next_[first] && is_slip(next_[first])) cls_[j] = next_[j];
    }
  }
  return false;
}

double PlanarContactSolver::slip_threshold(const PlanarContactProblem& p, int i, double slip_velocity) const {
  double pt = std::fabs(pt_[i]);
  for (int j : {i - 1, i + 1})
    if (j >= 0 && j < p.n && p.face[j] == p.face[i]) pt += std::fabs(pt_[j]);
  return slip_velocity + 2.0 * p.compliance * pt;
}

int PlanarContactSolver::sticking_partner(const PlanarContactProblem& p, int i) const {
  for (int j : {i - 1, i + 1})
    if (j >= 0 && j < p.n && p.face[j] == p.face[i] && cls_[j] == ContactClass::Stick) return j;
  return -1;
}

void PlanarContactSolver::share_sticking_friction(const PlanarContactProblem& p) {
  // A sticking face's tangential impulse shared by its two ends as their normal impulses (the
  // split is not unique; this one keeps each end inside its own cone and warm-starts the next
  // step's Gauss-Seidel well).
  for (int i = 0; i + 1 < p.n; ++i) {
    const int j = i + 1;
    if (cls_[i] != ContactClass::Stick || sticking_partner(p, i) != j) continue;
    const double T = pt_[i] + pt_[j], N = pn_[i] + pn_[j];
    if (N > 0.0) {
      pt_[i] = T * pn_[i] / N;
      pt_[j] = T * pn_[j] / N;
    }
    ++i;
  }
}

// Each end's 2 x 2 Coulomb problem solved exactly with the others' impulses fixed, sweeps repeated
// until no body's velocity change from the impulses moves by more than tol. The velocities are
// what is unique: the impulses of redundant contacts (two ends per face of a resting assembly,
// statically indeterminate) are not, and pivoting methods lose accuracy on them.
bool PlanarContactSolver::solve_gauss_seidel(const PlanarContactProblem& p, double tol, int max_sweeps) {
  const int nc = p.n, n = p.coords;
  for (int i = 0; i < nc; ++i) {
    pn_[i] = p.pn_warm[i];
    pt_[i] = p.pt_warm[i];
  }
  std::fill(dv_.begin(), dv_.begin() + n, 0.0);
  bool converged = false;
  sweeps_ = 0;
  for (int sweep = 0; sweep < max_sweeps && !converged; ++sweep) {
    for (int i = 0; i < nc; ++i) {
      double bn = p.bn[i], bt = p.bt[i];
      for (int j = 0; j < nc; ++j) {
        if (j == i) continue;
        bn += W(p, 2 * i, 2 * j) * pn_[j] + W(p, 2 * i, 2 * j + 1) * pt_[j];
        bt += W(p, 2 * i + 1, 2 * j) * pn_[j] + W(p, 2 * i + 1, 2 * j + 1) * pt_[j];
      }
      solve_contact_2x2(W(p, 2 * i, 2 * i), W(p, 2 * i, 2 * i + 1), W(p, 2 * i + 1, 2 * i + 1), bn, bt, p.mu[i], pn_[i],
                        pt_[i]);
    }
    // The bodies' velocity change due to the impulses: unique even where the impulses are not.
    p.velocities->bodies(pn_.data(), pt_.data(), dv_new_.data());
    double change = 0;
    for (int k = 0; k < n; ++k) {
      change = std::max(change, std::fabs(dv_new_[k] - dv_[k]));
      dv_[k] = dv_new_[k];
    }
    converged = sweep > 0 && change <= tol;
    sweeps_ = sweep + 1;
  }
  return converged;
}

}  // namespace blockdyn
