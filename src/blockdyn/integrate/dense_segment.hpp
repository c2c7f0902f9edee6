// SPDX-License-Identifier: Apache-2.0
#pragma once
// Fixed-size state vectors and the dense output of one accepted Runge-Kutta step, shared by the
// steppers (dopri5.hpp, dop853.hpp), the integrator and the observers.
#include <array>
#include <cstddef>

namespace blockdyn {

template <std::size_t N>
using Vec = std::array<double, N>;

// y(t0 + s h), s in [0, 1], as the nested product both Dormand-Prince continuous extensions use:
//   r0 + s (r1 + s1 (r2 + s (r3 + s1 (r4 + s (r5 + s1 (r6 + s r7)))))),  s1 = 1 - s,
// with `terms` = 5 (order 4, Dopri5) or 8 (order 7, DOP853) coefficient vectors.
template <std::size_t N>
struct DenseSegment {
  static constexpr int kMaxTerms = 8;
  double t0 = 0.0;
  double h = 0.0;
  int terms = 5;
  std::array<Vec<N>, kMaxTerms> r{};

  double t1() const { return t0 + h; }

  // The first four terms, common to both continuous extensions: the cubic Hermite interpolant of
  // the step's end values y, y_new and rates k1, k_end (the higher terms are the stepper's).
  void set_hermite(double t, double step, int n_terms, const Vec<N>& y, const Vec<N>& y_new, const Vec<N>& k1,
                   const Vec<N>& k_end) {
    t0 = t;
    h = step;
    terms = n_terms;
    for (std::size_t i = 0; i < N; ++i) {
      const double ydiff = y_new[i] - y[i];
      const double bspl = step * k1[i] - ydiff;
      r[0][i] = y[i];
      r[1][i] = ydiff;
      r[2][i] = bspl;
      r[3][i] = ydiff - step * k_end[i] - bspl;
    }
  }

  // A segment of an accepted step whose full dense output was not computed (DOP853, when neither
  // the event scan nor an observer needed it) holds the cubic Hermite interpolant of the step's
  // end values and rates instead (terms = 4: exact at both ends, 4th order inside) and can be
  // refined: while the observers see it, ensure_full() computes the full dense output in place
  // (three more stages). On any other segment it does nothing.
  void ensure_full() const {
    if (refine_ != nullptr) refine_(refine_context_);
  }
  void set_refine(void (*fn)(void*), void* context) {
    refine_ = fn;
    refine_context_ = context;
  }

  // The state at t1 as the step computed it, completed by the model (null when not at hand):
  // observers that look at step ends take it instead of evaluating and completing again.
  const Vec<N>* end_state = nullptr;

  // The completed state at the end t_end of the piece an observer is given: the step's own when
  // given, else `complete(eval(t_end))`.
  template <class Complete>
  void completed_end(double t_end, Vec<N>& y, Complete&& complete) const {
    if (end_state != nullptr) {
      y = *end_state;
      return;
    }
    eval(t_end, y);
    complete(y);
  }

  // The loop over components innermost, so it vectorizes; each component still takes the same
  // operations in the same order (the same bits as one component at a time).
  void eval(double t, Vec<N>& y) const {
    const double s = (t - t0) / h;
    const double s1 = 1.0 - s;
    Vec<N> acc = r[terms - 1];
    for (int j = terms - 1; j >= 1; --j) {
      const double c = (j & 1) ? s : s1;
      const Vec<N>& rj = r[j - 1];
      for (std::size_t i = 0; i < N; ++i) acc[i] = rj[i] + c * acc[i];
    }
    y = acc;
  }

 private:
  void (*refine_)(void*) = nullptr;
  void* refine_context_ = nullptr;
};

struct StepperStats {
  long accepted = 0;
  long rejected = 0;
  long rhs_evals = 0;
  long stiff_steps = 0;          // DOP853: accepted steps whose stiffness estimate h|lambda| exceeded 6.1
  long rejected_at_restart = 0;  // rejections before the first accepted step after a restart
  // A run of several legs (simulations one after another) counts them all.
  StepperStats& operator+=(const StepperStats& b) {
    accepted += b.accepted;
    rejected += b.rejected;
    rhs_evals += b.rhs_evals;
    stiff_steps += b.stiff_steps;
    rejected_at_restart += b.rejected_at_restart;
    return *this;
  }
};

}  // namespace blockdyn
