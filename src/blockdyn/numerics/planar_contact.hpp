// SPDX-License-Identifier: Apache-2.0
#pragma once
// The frictional contact problem of one time step in the plane, at the velocity level, and its
// solvers; no mechanics (model/assembly/moreau_jean.cpp builds the problem of an assembly):
//   u = W p + b            per end in contact: normal and tangential components (W the Delassus
//                          matrix, 2n x 2n, a compliance c on its diagonal),
//   0 <= p_N  _|_  u_N >= 0,
//   Coulomb:  |p_T| <= mu p_N,  p_T = -mu p_N sign(u_T) where the end slips.
// Consecutive ends of one face lie on one line along its tangent: only the sum of their
// tangential impulses acts, and the face's cone is sum |p_T| <= sum mu p_N.
// Solvers (PlanarContactSolver):
//   solve_direct        active set: for a guessed class per end (separate, stick, slip +/-) the
//                       impulses solve one linear system (Cholesky, Gauss where ends slip); the
//                       violated conditions change their classes (block pivoting, then Murty's
//                       rule); exact to the problem's tolerance;
//   solve_lemke         the whole problem as one LCP (Anitescu and Potra's form of the 2D cone,
//                       exact in the plane) by Lemke's method, whatever the redundancy: its
//                       classes are a guess for solve_direct;
//   solve_gauss_seidel  nonsmooth Gauss-Seidel: each end's 2 x 2 problem solved exactly
//                       (solve_contact_2x2: enumeration of separation, stick, slip +/-) with the
//                       others fixed, until the bodies' velocities settle.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "blockdyn/numerics/lemke.hpp"

namespace blockdyn {

enum class ContactClass : std::uint8_t { Separate, Stick, SlipPos, SlipNeg };

inline bool is_slip(ContactClass c) { return c == ContactClass::SlipPos || c == ContactClass::SlipNeg; }

// The 2 x 2 problem of one end: u = [a c; c d] [pn; pt] + [bn; bt], 0 <= pn _|_ u_N >= 0,
// |pt| <= mu pn, pt = -mu pn sign(u_T) when u_T != 0. Exact: separation, stick, or slip in the
// direction consistent with the resulting u_T.
void solve_contact_2x2(double a, double c, double d, double bn, double bt, double mu, double& pn, double& pt);

// What the solvers ask of the mechanics besides the matrices: the ends' relative velocities after
// the step for given impulses, and the bodies' velocity change, computed as the mechanics does
// (sparsely, from the bodies: more accurate than W p + b where the contacts are redundant).
class ContactVelocities {
 public:
  virtual ~ContactVelocities() = default;
  // u_N (with the problem's shift of b_N) and u_T of every end.
  virtual void relative(const double* pn, const double* pt, double* un, double* ut) = 0;
  // The bodies' generalized velocity change (`coords` of them).
  virtual void bodies(const double* pn, const double* pt, double* dv) = 0;
};

struct PlanarContactProblem {
  int n = 0;                  // ends in contact
  const double* W = nullptr;  // 2n x 2n, row-major, row stride `stride`; the compliance on its diagonal
  std::size_t stride = 0;
  const double *bn = nullptr, *bt = nullptr;            // free relative velocities
  const double* mu = nullptr;                           // friction coefficient of each end
  const int* face = nullptr;                            // the face of each end (one face's ends consecutive)
  const double *pn_warm = nullptr, *pt_warm = nullptr;  // Gauss-Seidel's start
  double compliance = 0;                                // on W's diagonal
  int coords = 0;                                       // the bodies' generalized coordinates
  ContactVelocities* velocities = nullptr;
};

class PlanarContactSolver {
 public:
  // Scratch for up to `max_ends` ends and `max_coords` generalized coordinates (allocated here).
  void reserve(int max_ends, int max_coords);

  // Each returns whether the problem was solved; tol is the velocity tolerance (kSolveTolerance
  // times the problem's velocity scale). The impulses are pn(), pt(); classes() the solution's
  // classes (solve_direct, solve_lemke), and before solve_direct the guess it starts from.
  bool solve_direct(const PlanarContactProblem& p, double tol);
  bool solve_lemke(const PlanarContactProblem& p);
  bool solve_gauss_seidel(const PlanarContactProblem& p, double tol, int max_sweeps);

  std::vector<double>& pn() { return pn_; }
  std::vector<double>& pt() { return pt_; }
  const std::vector<double>& pn() const { return pn_; }
  const std::vector<double>& pt() const { return pt_; }
  std::vector<ContactClass>& classes() { return cls_; }
  const std::vector<ContactClass>& classes() const { return cls_; }
  int sweeps() const { return sweeps_; }                                 // of the last Gauss-Seidel solve
  long active_set_iterations() const { return active_set_iterations_; }  // over every solve_direct

  // The tangential speed above which end i slips, given the scheme's noise `slip_velocity`: the
  // compliance lets a sticking face creep by c |P_T| (P_T its tangential impulse).
  double slip_threshold(const PlanarContactProblem& p, int i, double slip_velocity) const;

  // The problem is solved when no end's relative velocity is off by more than this fraction of
  // the problem's velocity scale.
  static constexpr double kSolveTolerance = 1e-12;

 private:
  int assemble_guess(const PlanarContactProblem& p);
  void solve_guess(const PlanarContactProblem& p, int m, double diag_max);
  int check_guess(const PlanarContactProblem& p, double tol, double diag_max, int& first, bool& accurate);
  int sticking_partner(const PlanarContactProblem& p, int i) const;
  void share_sticking_friction(const PlanarContactProblem& p);
  double W(const PlanarContactProblem& p, int i, int j) const {
    return p.W[std::size_t(i) * p.stride + std::size_t(j)];
  }

  int m_cap_ = 0;
  std::vector<double> pn_, pt_, un_, ut_, dv_, dv_new_;
  std::vector<double> A_, rhs_;  // the active-set iteration's linear system
  std::vector<int> col_n_, col_t_, pivots_;
  std::vector<ContactClass> cls_, next_;
  std::vector<int> flips_;                     // solve_direct: class changes of each end
  std::vector<double> lcp_m_, lcp_q_, lcp_z_;  // the problem as one LCP (solve_lemke)
  Lemke lemke_;
  std::vector<int> face_end_, face_of_;  // solve_lemke's faces: first end; face of each end
  int sweeps_ = 0;
  long active_set_iterations_ = 0;
};

}  // namespace blockdyn
