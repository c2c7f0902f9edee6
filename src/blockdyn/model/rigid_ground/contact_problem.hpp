// SPDX-License-Identifier: Apache-2.0
#pragma once
// The unilateral contact problem of one rigid block touching flat ground at one or two base
// corners, at force level (accelerations, the mechanism selection of seed 001 sec. 4.2) or at
// impulse level (velocity jumps, Newton impacts). Generalised velocity u = (vx, vy, omega),
// M = diag(m, m, I_G). Contact j at offset r_j from the centre has the normal row
// n_j = (0, 1, r_jx); the tangential row is t = (1, 0, -r_y). Two corners touch flat ground only
// at theta = 0, where they share the tangential row: one tangential unknown T with the Coulomb
// bound applied to the sum of the normal forces (any split proportional to them is admissible).
//
// A candidate ("combination") closes a subset of the contacts and puts the tangential direction
// in stick or slip (sign sigma: T = -sigma mu_k sum N). Each candidate is a linear system of at
// most three unknowns; it is consistent when every sign condition holds:
//   closed: N_j >= 0;  open: normal rate >= target;  stick: |T| <= mu_s sum N;
//   slip onset: sigma * tangential rate >= 0.
// Enumerating the candidates is an exact solution of the small complementarity problem.
#include <array>
#include <optional>

#include "blockdyn/model/common/block_kinematics.hpp"
#include "blockdyn/model/common/coulomb.hpp"

namespace blockdyn {

struct ContactPoint {
  int side = 1;         // +1 left corner A, -1 right corner B
  Vec2 r;               // offset from the centre of mass
  double target = 0.0;  // required normal rate (force level: 0; impulse level: -e vn-)
};

struct ContactProblem {
  double m = 1, I = 1;
  std::array<ContactPoint, 2> c{};
  int n = 0;                  // 1 or 2 candidate contacts
  std::array<double, 3> b{};  // force level: external forces; impulse level: momentum M u-
  // Velocity-dependent offsets of the contact rates (force level: -omega^2 r terms; impulse: 0).
  std::array<double, 2> cn{};
  double ct = 0.0;
  Coulomb mu;
  int slip_sign = 0;  // sign of the current tangential velocity (0: at rest tangentially)
};

enum class Tangential { Stick, SlipPos, SlipNeg };

struct ContactSolution {
  bool closed[2] = {false, false};
  Tangential tang = Tangential::Stick;
  double N[2] = {0, 0};           // normal force / impulse per contact
  double T = 0;                   // tangential force / impulse (total)
  std::array<double, 3> u{};      // resulting (ax, ay, alpha) or (vx, vy, omega)
  double effective_mass_inv = 0;  // pivot of the normal system (<= 0: Painleve)
  int closed_count() const { return int(closed[0]) + int(closed[1]); }
  int sigma() const { return tang == Tangential::SlipPos ? 1 : tang == Tangential::SlipNeg ? -1 : 0; }
};

// Solves one candidate; nullopt when its linear system is singular.
std::optional<ContactSolution> solve_candidate(const ContactProblem& p, const bool closed[2], Tangential tang);
// Whether a solved candidate satisfies every sign condition (tolerances scale with the data).
bool consistent(const ContactProblem& p, const ContactSolution& s, double tol_force, double tol_rate);

struct Selection {
  std::optional<ContactSolution> chosen;
  int consistent_count = 0;                      // candidates satisfying every condition
  std::array<ContactSolution, 12> consistent{};  // the first consistent_count of them
  bool painleve = false;                         // no consistent candidate, or the chosen slip system is not definite
};

// Hints from the event that triggered a selection: contacts whose normal force just reached
// zero must open; a stick that just reached its friction limit must slip.
struct SelectionHints {
  bool must_open[2] = {false, false};
  bool no_stick = false;
};

// The mechanism: stick is preferred to slip when the contact is at rest tangentially (static
// friction holds if it can), then candidates with more closed contacts.
Selection select_contacts(const ContactProblem& p, const SelectionHints& h, double tol_force, double tol_rate);

}  // namespace blockdyn
