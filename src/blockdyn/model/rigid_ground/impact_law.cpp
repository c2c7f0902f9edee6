// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/rigid_ground/impact_law.hpp"

#include <cmath>

namespace blockdyn {

namespace {

double kinetic(double m, double I, const std::array<double, 3>& u) {
  return 0.5 * m * (u[0] * u[0] + u[1] * u[1]) + 0.5 * I * u[2] * u[2];
}

std::optional<std::array<double, 3>> newton(const RigidBlockParams& p, const ImpactContact* c, int n,
                                            const std::array<double, 3>& u, double e, double tol_v) {
  const double m = p.shape.mass, I = p.shape.inertia_centre();
  ContactProblem cp;
  cp.m = m;
  cp.I = I;
  cp.n = n;
  cp.mu = p.interface;
  cp.b = {m * u[0], m * u[1], I * u[2]};
  for (int j = 0; j < n; ++j) {
    const double vn = u[1] + c[j].r.x * u[2];
    cp.c[j] = ContactPoint{c[j].side, c[j].r, vn < 0.0 ? -e * vn : 0.0};
  }
  const Selection s = select_contacts(cp, SelectionHints{}, 1e-12 * m * tol_v, tol_v);
  if (!s.chosen) return std::nullopt;
  return s.chosen->u;
}

}  // namespace

std::optional<std::array<double, 3>> apply_impact(const RigidBlockParams& p, const ImpactContact* c, int n,
                                                  const std::array<double, 3>& u, double tol_v, bool plastic) {
  const double m = p.shape.mass, I = p.shape.inertia_centre();
  if (p.impact == ImpactLaw::Newton) return newton(p, c, n, u, plastic ? 0.0 : p.e(), tol_v);
  // Housner: which corners hit (move into the ground)?
  int hitting = 0, k = 0;
  for (int j = 0; j < n; ++j)
    if (u[1] + c[j].r.x * u[2] < -tol_v) {
      ++hitting;
      k = j;
    }
  if (hitting != 1) return newton(p, c, n, u, 0.0, tol_v);  // flat landing (or grazing): plastic
  const Vec2 r = c[k].r;
  const double Io = I + m * (r.x * r.x + r.y * r.y);
  // Angular momentum about the impacting corner P: H_P = I w - m (r x v), r = P - G.
  const double H = I * u[2] - m * (r.x * u[1] - r.y * u[0]);
  double w = H / Io;
  if (!plastic) {
    const double eh = p.shape.housner_restitution();
    if (p.restitution && eh > 0.0) w *= *p.restitution / eh;
    if (p.restitution && eh <= 0.0) w = 0.0;
    const double wmax = std::sqrt(2.0 * kinetic(m, I, u) / Io);
    w = std::fmax(-wmax, std::fmin(wmax, w));
  }
  return std::array<double, 3>{w * r.y, -w * r.x, w};
}

}  // namespace blockdyn
