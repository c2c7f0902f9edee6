// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a hybrid (piecewise-smooth) model gives the integrator (hybrid_integrator.hpp): the
// HybridModel concept, its transitions, the optional hooks it may declare, and the record of an
// event as observers receive it. Models include this, not the integrator.
#include <array>
#include <concepts>
#include <cstddef>
#include <limits>
#include <optional>

#include "blockdyn/integrate/dense_segment.hpp"

namespace blockdyn {

// Event index passed to transition() when the integration reaches a breakpoint of the input.
inline constexpr int kBreakpoint = -2;

template <class Mode>
struct Transition {
  Mode next{};
  bool stop = false;  // the run ends at this event (overturn, state outside the model, ...)
  int kind = 0;       // model-defined event kind, reported to observers
};

template <class M>
concept HybridModel = requires(const M& m, typename M::Mode mode, Vec<M::kDim> z, Vec<M::kDim>& dz,
                               std::array<double, M::kNumEvents>& g, double t, int i) {
  { M::kDim } -> std::convertible_to<std::size_t>;
  { M::kNumEvents } -> std::convertible_to<std::size_t>;
  m.rhs(t, mode, z, dz);
  m.events(t, mode, z, g);
  m.complete(mode, z);
  { m.transition(t, mode, dz, i) } -> std::same_as<Transition<typename M::Mode>>;  // may change z
  { m.resolve_chatter(t, mode, z) } -> std::same_as<std::optional<Transition<typename M::Mode>>>;
  { m.step_hint(mode) } -> std::convertible_to<double>;
  { m.abs_tol_scale() } -> std::convertible_to<Vec<M::kDim>>;
};

// The model's first input breakpoint after t that matters in mode `mode`:
// `double next_breakpoint(double t, const Mode&) const` or `double next_breakpoint(double t) const`
// (optional; without either the input is smooth and there is none).
template <class M>
double next_breakpoint_of(const M& m, double t, const typename M::Mode& mode) {
  if constexpr (requires {
                  { m.next_breakpoint(t, mode) } -> std::convertible_to<double>;
                })
    return m.next_breakpoint(t, mode);
  else if constexpr (requires {
                       { m.next_breakpoint(t) } -> std::convertible_to<double>;
                     })
    return m.next_breakpoint(t);
  return std::numeric_limits<double>::infinity();
}

// Whether a model's transitions may change the state (impacts). Models declare
// `static constexpr bool kStateJumps = true;` (absent: false).
template <class M>
constexpr bool has_state_jumps() {
  if constexpr (requires { M::kStateJumps; }) return M::kStateJumps;
  return false;
}

// Whether a model computes its event functions' time derivatives itself:
// `void event_rates(double t, const Mode&, const State& z, const State& dz, Events& g, Events& gdot) const`
// fills the values g (as events() does) and their rates along dz = f(t, z); a rate it leaves NaN
// is obtained by a difference quotient. Optional: without it every rate is a difference quotient
// (one more events() call per step end).
template <class M>
constexpr bool has_event_rates() {
  return requires(const M& m, double t, const typename M::Mode& mode, const Vec<M::kDim>& z,
                  std::array<double, M::kNumEvents>& g) {
    m.event_rates(t, mode, z, z, g, g);
  };
}

// The first step after an event: `double restart_step(double t, const Mode&, const State& z,
// const State& dz, double h) const` may return a step other than h, the one the step-size
// control and step_hint() give (optional; e.g. a whole free flight, which any step integrates
// exactly, where the control would grow the step from the last contact step's size six-fold per
// step).
template <class M>
double restart_step_of(const M& m, double t, const typename M::Mode& mode, const Vec<M::kDim>& z,
                       const Vec<M::kDim>& dz, double h) {
  if constexpr (requires {
                  { m.restart_step(t, mode, z, dz, h) } -> std::convertible_to<double>;
                })
    return m.restart_step(t, mode, z, dz, h);
  return h;
}

// The predicted time to the next kink of the right-hand side ahead of (t, z): a point where it
// is continuous but not smooth, and not an event (`double kink_ahead(double t, const Mode&,
// const State& z, const State& dz) const`, optional; infinity: none known).
template <class M>
double kink_ahead_of(const M& m, double t, const typename M::Mode& mode, const Vec<M::kDim>& z,
                     const Vec<M::kDim>& dz) {
  if constexpr (requires {
                  { m.kink_ahead(t, mode, z, dz) } -> std::convertible_to<double>;
                })
    return m.kink_ahead(t, mode, z, dz);
  return std::numeric_limits<double>::infinity();
}

// Completes z (complete()) and evaluates the event functions there (events()). A model may fuse
// the two (`void complete_and_events(double t, const Mode&, State& z, Events& g) const`, optional),
// e.g. to compute its trigonometry once: the event scan does this at every point it looks at.
template <class M>
void complete_and_events(const M& m, double t, const typename M::Mode& mode, Vec<M::kDim>& z,
                         std::array<double, M::kNumEvents>& g) {
  if constexpr (requires { m.complete_and_events(t, mode, z, g); }) {
    m.complete_and_events(t, mode, z, g);
  } else {
    m.complete(mode, z);
    m.events(t, mode, z, g);
  }
}

// Completes z and evaluates event function `index` alone, for the root search on it. A model may
// give one function cheaper than all of them (`double event_value(double t, const Mode&, const
// State& z, int index) const`, optional, equal to events()[index] bit for bit): a search on a
// contact's height then does not solve its reactions at every point it looks at.
template <class M>
double complete_and_event(const M& m, double t, const typename M::Mode& mode, Vec<M::kDim>& z, int index) {
  if constexpr (requires { m.event_value(t, mode, z, index); }) {
    m.complete(mode, z);
    return m.event_value(t, mode, z, index);
  } else {
    std::array<double, M::kNumEvents> g;
    complete_and_events(m, t, mode, z, g);
    return g[std::size_t(index)];
  }
}

template <class Mode, std::size_t N>
struct EventInfo {
  double t;
  Vec<N> z;         // completed state right after the event (after any jump)
  Vec<N> z_before;  // completed state at the event, before the transition
  Mode from, to;
  int index;  // which event function
  int kind;   // model-defined
  bool stop;
};

}  // namespace blockdyn
