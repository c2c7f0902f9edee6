// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/assembly/rest_limit.hpp"

#include <glpk.h>

#include <cmath>
#include <memory>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include "blockdyn/model/assembly/assembly_params.hpp"

namespace blockdyn {

namespace {
constexpr double kLambdaCap = 1e6;

struct LpDeleter {
  void operator()(glp_prob* p) const { glp_delete_prob(p); }
};

// The value of a non-basic variable: the bound its status names.
double at_bound(int stat, double lo, double up) { return stat == GLP_NU ? up : stat == GLP_NF ? 0.0 : lo; }

// The optimal basis's primal (structural values x) and dual (row prices pi) solutions, solved
// again in double precision: GLPK's exact simplex turns the data into nearby rationals (to about
// 1e-11 relative), so its solution satisfies the equations only to that; one sparse LU solve and
// a step of refinement satisfy them to the rounding. Rows: sum_j a_ij x_j - r_i = 0, with the
// non-basic columns and rows' auxiliaries at their bounds.
bool polish(glp_prob* lp, const std::vector<int>& ia, const std::vector<int>& ja, const std::vector<double>& ar,
            std::vector<double>& x, std::vector<double>& pi) {
  const int m = glp_get_num_rows(lp), n = glp_get_num_cols(lp);
  std::vector<int> slot(std::size_t(n + m), -1);  // the basic variables' positions in the LU
  int k = 0;
  for (int j = 1; j <= n; ++j)
    if (glp_get_col_stat(lp, j) == GLP_BS) slot[j - 1] = k++;
  for (int i = 1; i <= m; ++i)
    if (glp_get_row_stat(lp, i) == GLP_BS) slot[n + i - 1] = k++;
  if (k != m) return false;
  x.assign(std::size_t(n), 0.0);
  for (int j = 1; j <= n; ++j)
    if (slot[j - 1] < 0) x[j - 1] = at_bound(glp_get_col_stat(lp, j), glp_get_col_lb(lp, j), glp_get_col_ub(lp, j));
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m), cost = Eigen::VectorXd::Zero(m);
  for (int i = 1; i <= m; ++i)
    if (slot[n + i - 1] < 0)
      rhs[i - 1] = at_bound(glp_get_row_stat(lp, i), glp_get_row_lb(lp, i), glp_get_row_ub(lp, i));
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t e = 1; e < ar.size(); ++e) {
    const int i = ia[e] - 1, j = ja[e] - 1;
    if (slot[j] >= 0)
      entries.emplace_back(i, slot[j], ar[e]);
    else
      rhs[i] -= ar[e] * x[j];
  }
  for (int i = 0; i < m; ++i)
    if (slot[n + i] >= 0) entries.emplace_back(i, slot[n + i], -1.0);
  for (int j = 1; j <= n; ++j)
    if (slot[j - 1] >= 0) cost[slot[j - 1]] = glp_get_obj_coef(lp, j);
  Eigen::SparseMatrix<double> B(m, m);
  B.setFromTriplets(entries.begin(), entries.end());
  B.makeCompressed();
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(B);
  if (lu.info() != Eigen::Success) return false;
  Eigen::VectorXd v = lu.solve(rhs);
  v += lu.solve(rhs - B * v);
  const Eigen::SparseMatrix<double> Bt = B.transpose();
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lut(Bt);
  if (lut.info() != Eigen::Success) return false;
  Eigen::VectorXd y = lut.solve(cost);
  y += lut.solve(cost - Bt * y);
  if (!v.allFinite() || !y.allFinite()) return false;
  for (int j = 0; j < n; ++j)
    if (slot[j] >= 0) x[j] = v[slot[j]];
  pi.assign(y.data(), y.data() + m);
  return true;
}
// Whether the polished basic solution is optimal, checked in double precision: the primal values
// within their bounds and the reduced costs of the non-basic variables of the sign that says no
// move improves the objective (a maximum), each to a tolerance of 1e-9 of its scale. Certified,
// the floating-point simplex's basis is the optimum and the exact (rational) simplex is not needed.
bool certified(glp_prob* lp, const std::vector<int>& ia, const std::vector<int>& ja, const std::vector<double>& ar,
               const std::vector<double>& x, const std::vector<double>& pi) {
  const int m = glp_get_num_rows(lp), n = glp_get_num_cols(lp);
  double xs = 1.0, ps = 1.0;
  for (double v : x) xs = std::fmax(xs, std::fabs(v));
  for (double v : pi) ps = std::fmax(ps, std::fabs(v));
  const double tol_x = 1e-9 * xs, tol_d = 1e-9 * ps;
  std::vector<double> row(std::size_t(m), 0.0), reduced(std::size_t(n), 0.0);
  for (int j = 1; j <= n; ++j) reduced[j - 1] = glp_get_obj_coef(lp, j);
  for (std::size_t e = 1; e < ar.size(); ++e) {
    row[ia[e] - 1] += ar[e] * x[ja[e] - 1];
    reduced[ja[e] - 1] -= ar[e] * pi[ia[e] - 1];
  }
  auto inside = [](int type, double v, double lo, double up, double tol) {
    const bool lo_ok = type == GLP_FR || type == GLP_UP || v >= lo - tol;
    const bool up_ok = type == GLP_FR || type == GLP_LO || v <= up + tol;
    return lo_ok && up_ok;
  };
  for (int j = 1; j <= n; ++j) {
    if (!inside(glp_get_col_type(lp, j), x[j - 1], glp_get_col_lb(lp, j), glp_get_col_ub(lp, j), tol_x)) return false;
    const int stat = glp_get_col_stat(lp, j);
    const double d = reduced[j - 1];
    if ((stat == GLP_NL && d > tol_d) || (stat == GLP_NU && d < -tol_d) || (stat == GLP_NF && std::fabs(d) > tol_d))
      return false;
  }
  for (int i = 1; i <= m; ++i) {
    if (!inside(glp_get_row_type(lp, i), row[i - 1], glp_get_row_lb(lp, i), glp_get_row_ub(lp, i), tol_x)) return false;
    // A row's auxiliary r_i = sum a_ij x_j has the reduced cost pi_i (its column in -r_i is -1).
    const int stat = glp_get_row_stat(lp, i);
    const double d = pi[i - 1];
    if ((stat == GLP_NL && d > tol_d) || (stat == GLP_NU && d < -tol_d) || (stat == GLP_NF && std::fabs(d) > tol_d))
      return false;
  }
  return true;
}

// The constraint matrix as GLPK's triplets (1-based, entry 0 unused).
struct Triplets {
  std::vector<int> ia{0}, ja{0};
  std::vector<double> ar{0.0};
  double zero = 0.0;  // entries at most this large are left out
  void put(int row, int col, double v) {
    if (std::fabs(v) <= zero) return;
    ia.push_back(row);
    ja.push_back(col);
    ar.push_back(v);
  }
};

// Columns: N per contact (>= 0), T per interface (free), lambda (free). Rows: the three
// equilibrium equations per block, then |T| <= mu (N_1 + N_2) as two rows per interface.
void build_equilibrium_lp(glp_prob* lp, const StaticProblem& p, int direction, Triplets& m) {
  const int nb = int(p.mass.size()), nc = int(p.contacts.size()), ni = int(p.mu.size());
  glp_set_obj_dir(lp, GLP_MAX);
  const int col_t = nc + 1, col_lambda = nc + ni + 1;
  glp_add_cols(lp, nc + ni + 1);
  for (int c = 1; c <= nc; ++c) glp_set_col_bnds(lp, c, GLP_LO, 0.0, 0.0);
  for (int i = 0; i < ni; ++i) glp_set_col_bnds(lp, col_t + i, GLP_FR, 0.0, 0.0);
  glp_set_col_bnds(lp, col_lambda, GLP_DB, -kLambdaCap, kLambdaCap);
  glp_set_obj_coef(lp, col_lambda, 1.0);
  glp_add_rows(lp, 3 * nb);
  for (int b = 0; b < nb; ++b) {
    const double w = p.mass[b] * p.g;
    // Contact forces + (-w lambda direction, -w, 0) = 0.
    glp_set_row_bnds(lp, 3 * b + 1, GLP_FX, 0.0, 0.0);
    glp_set_row_bnds(lp, 3 * b + 2, GLP_FX, w, w);
    glp_set_row_bnds(lp, 3 * b + 3, GLP_FX, 0.0, 0.0);
    m.put(3 * b + 1, col_lambda, -w * direction);
  }
  std::vector<char> has_t(static_cast<std::size_t>(ni), 0);
  for (int c = 0; c < nc; ++c) {
    const StaticContact& k = p.contacts[c];
    const bool first = !has_t[k.iface];
    has_t[k.iface] = 1;
    for (int side : {+1, -1}) {
      const int b = side > 0 ? k.upper : k.lower;
      if (b < 0) continue;
      const Vec2 r = k.P - p.centre[b];
      m.put(3 * b + 1, c + 1, side * k.n.x);
      m.put(3 * b + 2, c + 1, side * k.n.y);
      m.put(3 * b + 3, c + 1, side * cross(r, k.n));
      // A tangential force along the face has the same moment wherever on the face it acts:
      // one T per interface, applied at any of its points.
      if (first) {
        m.put(3 * b + 1, col_t + k.iface, side * k.t.x);
        m.put(3 * b + 2, col_t + k.iface, side * k.t.y);
        m.put(3 * b + 3, col_t + k.iface, side * cross(r, k.t));
      }
    }
  }
  std::vector<std::vector<int>> of_iface(static_cast<std::size_t>(ni));
  for (int c = 0; c < nc; ++c) of_iface[p.contacts[c].iface].push_back(c);
  for (int i = 0; i < ni; ++i) {
    if (!(p.mu[i] < kNoSlipFriction)) continue;
    const int r0 = glp_add_rows(lp, 2);
    for (int s = 0; s < 2; ++s) {
      glp_set_row_bnds(lp, r0 + s, GLP_UP, 0.0, 0.0);
      m.put(r0 + s, col_t + i, s == 0 ? 1.0 : -1.0);
      for (int c : of_iface[i]) m.put(r0 + s, c + 1, -p.mu[i]);
    }
  }
  glp_load_matrix(lp, int(m.ar.size()) - 1, m.ia.data(), m.ja.data(), m.ar.data());
}

// Solves the loaded problem to its optimum (x: the columns, pi: the rows' duals); false when it
// has none (no equilibrium) or the solvers fail.
bool solve_to_optimum(glp_prob* lp, const Triplets& m, bool exact, std::vector<double>& x, std::vector<double>& pi) {
  glp_smcp parm;
  glp_init_smcp(&parm);
  parm.msg_lev = GLP_MSG_OFF;
  parm.presolve = GLP_OFF;
  if (!exact) {
    // Scaled, the floating-point simplex settles arches of thick rings that it calls infeasible
    // unscaled (its row norms span 1e-3 to 1e2).
    const int was = glp_term_out(GLP_OFF);
    glp_scale_prob(lp, GLP_SF_AUTO);
    glp_term_out(was);
  }
  int rc = glp_simplex(lp, &parm);
  int status = glp_get_status(lp);
  if (!exact && (rc != 0 || status != GLP_OPT)) {
    // A second opinion before "no equilibrium": the dual simplex from an advanced basis (the
    // primal one stalls on some thick arches).
    const int was = glp_term_out(GLP_OFF);
    glp_adv_basis(lp, 0);
    glp_term_out(was);
    parm.meth = GLP_DUALP;
    rc = glp_simplex(lp, &parm);
    status = glp_get_status(lp);
  }
  // The floating-point simplex ends within its tolerances (1e-7); its basis solved again in
  // double precision (polish) gives the limit to the rounding of the result, which rest needs (it
  // must end at the crossing itself). Where that basis is not certified optimal, or the
  // floating-point simplex left the problem open, the exact (rational) simplex from its basis
  // settles it.
  const bool settled = rc == 0 && (status == GLP_OPT || status == GLP_NOFEAS);
  bool polished = settled && status == GLP_OPT && polish(lp, m.ia, m.ja, m.ar, x, pi);
  if (!settled || (exact && !(polished && certified(lp, m.ia, m.ja, m.ar, x, pi)))) {
    if (glp_exact(lp, &parm) != 0) return false;
    if (glp_get_status(lp) != GLP_OPT) return false;
    polished = polish(lp, m.ia, m.ja, m.ar, x, pi);
  }
  if (glp_get_status(lp) != GLP_OPT) return false;
  if (!polished) {
    x.clear();
    pi.clear();
    for (int j = 1; j <= glp_get_num_cols(lp); ++j) x.push_back(glp_get_col_prim(lp, j));
    for (int i = 1; i <= glp_get_num_rows(lp); ++i) pi.push_back(glp_get_row_dual(lp, i));
  }
  return true;
}

}  // namespace

LoadMultiplier max_load_multiplier(const StaticProblem& p, int direction, bool exact) {
  const int nb = int(p.mass.size()), nc = int(p.contacts.size()), ni = int(p.mu.size());
  std::unique_ptr<glp_prob, LpDeleter> lp(glp_create_prob());
  Triplets m;
  // Rounding leaves entries of 1e-16 where the geometry has zeros (cos(pi/2) in a joint's normal):
  // the rational simplex takes them as they are, the floating-point one alone stalls on them.
  m.zero = exact ? 0.0 : 1e-13;
  build_equilibrium_lp(lp.get(), p, direction, m);
  LoadMultiplier out;
  std::vector<double> x, pi;
  if (!solve_to_optimum(lp.get(), m, exact, x, pi)) return out;
  const int col_t = nc + 1, col_lambda = nc + ni + 1;
  out.feasible = true;
  out.lambda = x[col_lambda - 1];
  out.mechanism.assign(3 * std::size_t(nb), 0.0);
  double power = 0.0;
  for (int b = 0; b < nb; ++b) {
    for (int k = 0; k < 3; ++k) out.mechanism[3 * b + k] = pi[3 * b + k];
    power -= p.mass[b] * direction * out.mechanism[3 * b];
  }
  if (power < 0)
    for (double& v : out.mechanism) v = -v;
  for (int c = 0; c < nc; ++c) out.normal.push_back(x[c]);
  for (int i = 0; i < ni; ++i) out.tangential.push_back(x[col_t - 1 + i]);
  return out;
}

}  // namespace blockdyn
