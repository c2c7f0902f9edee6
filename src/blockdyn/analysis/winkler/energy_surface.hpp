// SPDX-License-Identifier: Apache-2.0
#pragma once
// Energy surfaces and their projections (thesis sec. 5.1, eqs. 5.1-5.3): the sets of states with
// total energy E (or <= E when friction dissipates), projected onto the (y, y') and (w, w') planes
// of the phase portraits (Figs. 5.1-5.2), and initial conditions on a prescribed energy surface
// (Figs. 5.8-5.11).
#include <vector>

#include "blockdyn/model/winkler/winkler_params.hpp"
#include "blockdyn/model/winkler/winkler_state.hpp"

namespace blockdyn {

// Potential energy (gravity + springs) at centre height h = y - 1/2 and tilt w.
double potential(const WinklerParams& p, double h, double w);

// min over |w| <= alpha of potential(h, w), found numerically (grid + Brent refinement); a state
// of height h can have y' at most sqrt(2 (E - this)).
double heave_potential(const WinklerParams& p, double h);
// The thesis's closed form of the same minimum (attained upright): h for h >= 0, h + k h^2 / 2 below.
double heave_potential_closed_form(const WinklerParams& p, double h);

// min over h of potential(h, w) = potential(h_R(w), w), with h_R the height where Ry = 1.
double rock_potential(const WinklerParams& p, double w);

struct HeaveBoundaryPoint {
  double y, v_min, vy_max;  // vy_max = sqrt(2 (E - v_min)), 0 outside the projection
};
struct RockBoundaryPoint {
  double w, u;
  double vw_free;     // I w'^2 / 2 <= E - U(w): mu = 0, flight, and the 6-D (friction) bound
  double vw_contact;  // (I + B(w)^2) w'^2 / 2 <= E - U(w): contact mode (x' = -B w')
};

// Boundaries sampled on n points: heave over the y-range the projection occupies (with a margin),
// rocking over |w| <= alpha.
std::vector<HeaveBoundaryPoint> heave_projection(const WinklerParams& p, double E, int n);
std::vector<RockBoundaryPoint> rock_projection(const WinklerParams& p, double E, int n);

// Initial state on the energy surface E with given w0 and y0 and all rates zero except y0',
// which is solved for (sign vy_sign): y0'^2 / 2 + potential(y0 - 1/2, w0) = E. The lowest corner
// is placed at x = 0 (like ic1) and does not move horizontally, so nothing is dissipated at the
// start. Throws std::invalid_argument if E is below the potential there.
WinklerState state_on_energy_surface(const WinklerParams& p, double E, double w0, double y0, int vy_sign = 1);

}  // namespace blockdyn
