// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/orbit_continuation.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include "blockdyn/analysis/forced/linear_rocking_orbits.hpp"

namespace blockdyn {

void validate(const ContinuationOptions& o) {
  if (o.parameter != "ks" && o.parameter != "omega")
    throw std::invalid_argument("continue: the parameter must be ks or omega");
  if (!(o.min > 0 && o.max > o.min && std::isfinite(o.max)))
    throw std::invalid_argument("continue range: need 0 < min < max");
  if (!(o.ds > 0 && o.ds_min > 0 && o.ds_max >= o.ds && o.ds >= o.ds_min && o.ds_max <= 10))
    throw std::invalid_argument("continuation step: need 0 < ds-min <= ds <= ds-max <= 10");
  if (o.max_points < 1 || o.max_points > 100000) throw std::invalid_argument("max-points must be in [1, 100000]");
  if (o.direction != 1 && o.direction != -1) throw std::invalid_argument("direction must be +1 or -1");
}

namespace {

using Vec3 = std::array<double, 3>;

struct Problem {
  RockingForcing base;
  OrbitType type;
  ContinuationOptions opt;
  double alpha;
  RockingForcing at(double lam) const {
    RockingForcing f = base;
    if (opt.parameter == "ks")
      f.ks = lam * alpha;
    else
      f.omega = lam;
    return f;
  }
  double lambda_of(const RockingForcing& f) const { return opt.parameter == "ks" ? f.ks / alpha : f.omega; }
  // Residual; false when the pass fails.
  bool F(const Vec3& y, std::array<double, 2>& r, std::string* why = nullptr) const {
    if (!(y[2] > 0)) return false;
    const ImpactMapPass p = impact_map_pass(at(y[2]), type, y[0], y[1], opt.shooting.integrator);
    if (!p.ok) {
      if (why) *why = p.failure;
      return false;
    }
    r = p.residual;
    return true;
  }
  // Central-difference Jacobian (2 x 3, row-major).
  bool DF(const Vec3& y, std::array<double, 6>& J) const {
    const double h = opt.shooting.fd_step;
    for (int j = 0; j < 3; ++j) {
      Vec3 a = y, b = y;
      const double hj = h * (j == 2 ? std::fmax(1.0, std::fabs(y[2])) : 1.0);
      a[j] += hj;
      b[j] -= hj;
      std::array<double, 2> ra, rb;
      if (!F(a, ra) || !F(b, rb)) return false;
      J[j] = (ra[0] - rb[0]) / (2 * hj);
      J[3 + j] = (ra[1] - rb[1]) / (2 * hj);
    }
    return true;
  }
};

Vec3 null_vector(const std::array<double, 6>& J) {
  Vec3 t{J[1] * J[5] - J[2] * J[4], J[2] * J[3] - J[0] * J[5], J[0] * J[4] - J[1] * J[3]};
  const double n = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
  for (double& x : t) x /= n;
  return t;
}

// Solves the 3 x 3 system M x = b (Cramer); false when singular.
bool solve3(const std::array<double, 9>& M, const Vec3& b, Vec3& x) {
  auto det3 = [](const std::array<double, 9>& a) {
    return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) + a[2] * (a[3] * a[7] - a[4] * a[6]);
  };
  const double d = det3(M);
  if (!(std::fabs(d) > 0) || !std::isfinite(d)) return false;
  for (int c = 0; c < 3; ++c) {
    std::array<double, 9> A = M;
    for (int r = 0; r < 3; ++r) A[3 * r + c] = b[r];
    x[c] = det3(A) / d;
  }
  return true;
}

struct Stability {
  std::array<std::complex<double>, 2> mu{};
  double det_minus = 0, det_plus = 0;  // det(A - I), det(A + I)
};

Stability stability_of(const std::array<double, 6>& J, bool symmetric) {
  // A = D_(psi,u) map = the residual's Jacobian + I.
  const double a = J[0] + 1, b = J[1], c = J[3], d = J[4] + 1;
  Stability s;
  s.det_minus = (a - 1) * (d - 1) - b * c;
  s.det_plus = (a + 1) * (d + 1) - b * c;
  s.mu = eigenvalues2(a, b, c, d);
  if (symmetric)
    for (auto& m : s.mu) m *= m;
  return s;
}

// The step from y along the tangent t: predictor, then Newton on the orbit condition and the
// pseudo-arclength constraint; the step length adapts to the corrector's iterations (halved when
// it fails). False when it fails at the smallest step (why: the last failed pass).
bool next_point(const Problem& pb, const Vec3& y, const Vec3& t, double& ds, Vec3& yn, std::array<double, 6>& Jn,
                std::string& why) {
  const ContinuationOptions& o = pb.opt;
  std::array<double, 2> r{};
  bool ok = false;
  while (!ok && ds >= o.ds_min) {
    const Vec3 yp{y[0] + ds * t[0], y[1] + ds * t[1], y[2] + ds * t[2]};
    yn = yp;
    int it = 0;
    for (; it < 10; ++it) {
      if (!pb.F(yn, r, &why) || !pb.DF(yn, Jn)) break;
      const double g = t[0] * (yn[0] - yp[0]) + t[1] * (yn[1] - yp[1]) + t[2] * (yn[2] - yp[2]);
      if (std::hypot(r[0], r[1]) < o.shooting.tol && std::fabs(g) < o.shooting.tol) {
        ok = true;
        break;
      }
      const std::array<double, 9> M{Jn[0], Jn[1], Jn[2], Jn[3], Jn[4], Jn[5], t[0], t[1], t[2]};
      Vec3 dx;
      if (!solve3(M, {-r[0], -r[1], -g}, dx)) break;
      for (int k = 0; k < 3; ++k) yn[k] += dx[k];
    }
    if (ok && it > 4) ds = std::fmax(o.ds_min, 0.7 * ds);
    if (!ok)
      ds *= 0.5;
    else if (it <= 2)
      ds = std::fmin(o.ds_max, 1.5 * ds);
  }
  return ok;
}

// The bifurcations between two consecutive points ("fold", "multiplier_+1", "flip" or
// "symmetry_breaking", joined by '+'). A determinant also changes sign through a pole next to
// grazing (the map's derivative is unbounded there): only crossings between moderate multipliers
// are bifurcations.
std::string bifurcations(const Stability& st, const Stability& prev, bool fold, bool symmetric) {
  std::string ev;
  auto add = [&](const char* e) {
    if (!ev.empty()) ev += '+';
    ev += e;
  };
  auto moderate = [](const Stability& x) { return std::abs(x.mu[0]) < 1e4 && std::abs(x.mu[1]) < 1e4; };
  const bool regular = moderate(st) && moderate(prev);
  if (fold)
    add("fold");
  else if (regular && st.det_minus * prev.det_minus < 0)
    add("multiplier_+1");
  if (regular && st.det_plus * prev.det_plus < 0) add(symmetric ? "symmetry_breaking" : "flip");
  return ev;
}

}  // namespace

Branch continue_orbit(const RockingForcing& f, const OrbitType& type, double psi, double u,
                      const ContinuationOptions& o) {
  validate(f);
  validate(type);
  validate(o);
  Problem pb{f, type, o, f.alpha()};
  Branch br;
  br.type = type;
  Vec3 y{psi, u, pb.lambda_of(f)};
  const double lam_lo = o.parameter == "ks" ? o.min / pb.alpha : o.min;
  const double lam_hi = o.parameter == "ks" ? o.max / pb.alpha : o.max;
  std::array<double, 2> r{};
  std::array<double, 6> J{};
  if (!pb.F(y, r) || std::hypot(r[0], r[1]) > 1e3 * o.shooting.tol || !pb.DF(y, J)) {
    br.end = "the start is not an orbit (converge it first)";
    return br;
  }
  Vec3 t = null_vector(J);
  if (t[2] * o.direction < 0)
    for (double& x : t) x = -x;
  auto make_point = [&](const Vec3& yy, const std::array<double, 6>& JJ, double s) {
    BranchPoint p;
    const RockingForcing fa = pb.at(yy[2]);
    p.ks = fa.ks;
    p.omega = fa.omega;
    p.phase = std::fmod(std::fmod(yy[0], 2 * M_PI) + 2 * M_PI, 2 * M_PI);
    p.velocity = yy[1];
    p.arclength = s;
    const Stability st = stability_of(JJ, type.symmetric);
    p.multipliers = st.mu;
    p.stable = std::abs(st.mu[0]) < 1 && std::abs(st.mu[1]) < 1;
    return p;
  };
  br.points.push_back(make_point(y, J, 0.0));
  Stability prev = stability_of(J, type.symmetric);
  double ds = o.ds, s = 0;
  while (int(br.points.size()) < o.max_points) {
    Vec3 yn{};
    std::array<double, 6> Jn{};
    std::string why;
    const bool ok = next_point(pb, y, t, ds, yn, Jn, why);
    if (!ok) {
      br.end =
          "the corrector failed at the smallest step: the orbit ends as this impact sequence (grazing, an "
          "extra impact, overturn or rest)";
      if (!why.empty()) br.end += "; last failed pass: " + why;
      break;
    }
    Vec3 tn = null_vector(Jn);
    if (tn[0] * t[0] + tn[1] * t[1] + tn[2] * t[2] < 0)
      for (double& x : tn) x = -x;
    s += std::sqrt((yn[0] - y[0]) * (yn[0] - y[0]) + (yn[1] - y[1]) * (yn[1] - y[1]) + (yn[2] - y[2]) * (yn[2] - y[2]));
    BranchPoint p = make_point(yn, Jn, s);
    const Stability st = stability_of(Jn, type.symmetric);
    p.event = bifurcations(st, prev, tn[2] * t[2] < 0, type.symmetric);
    br.points.push_back(p);
    prev = st;
    y = yn;
    t = tn;
    if (y[2] < lam_lo || y[2] > lam_hi) {
      br.end = "left the parameter range";
      break;
    }
    if (!(y[1] > 0)) {
      br.end = "the rate after the impact reached 0";
      break;
    }
  }
  if (br.end.empty()) br.end = "max-points reached";
  return br;
}

}  // namespace blockdyn
