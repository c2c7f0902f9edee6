// SPDX-License-Identifier: Apache-2.0
#pragma once
// The one shape in which the integrator reports a run (hybrid_integrator.hpp): a reference to
// any observer with on_step(seg, t_lo, t_hi, mode) and on_event(info), both returning false to
// stop the run, and optionally needs_dense(). The integrator's loop takes this reference, not
// the observer's type, so it is compiled once per model rather than once per model and observer
// (the loop and its stepper were the bulk of the library's compile time); the indirect call
// costs a few nanoseconds against a step's hundreds.
#include <concepts>
#include <cstddef>
#include <type_traits>

#include "blockdyn/integrate/dense_segment.hpp"
#include "blockdyn/integrate/hybrid_model.hpp"

namespace blockdyn {

template <class Mode, std::size_t N>
class RunObserver {
 public:
  template <class O>
  requires(!std::same_as<std::remove_cv_t<O>, RunObserver>) explicit RunObserver(O& o)
      : self_(static_cast<void*>(&o)),
        step_([](void* s, const DenseSegment<N>& seg, double t_lo, double t_hi, const Mode& m) -> bool {
          return static_cast<O*>(s)->on_step(seg, t_lo, t_hi, m);
        }),
        event_([](void* s, const EventInfo<Mode, N>& e) -> bool { return static_cast<O*>(s)->on_event(e); }) {
    if constexpr (requires {
                    { o.needs_dense() } -> std::convertible_to<bool>;
                  })
      dense_ = [](const void* s) -> bool { return static_cast<const O*>(s)->needs_dense(); };
  }

  bool on_step(const DenseSegment<N>& seg, double t_lo, double t_hi, const Mode& m) const {
    return step_(self_, seg, t_lo, t_hi, m);
  }
  bool on_event(const EventInfo<Mode, N>& e) const { return event_(self_, e); }
  // Whether the observer evaluates the dense output inside a step (without needs_dense(): yes).
  bool needs_dense() const { return dense_ == nullptr || dense_(self_); }

 private:
  void* self_;
  bool (*step_)(void*, const DenseSegment<N>&, double, double, const Mode&);
  bool (*event_)(void*, const EventInfo<Mode, N>&);
  bool (*dense_)(const void*) = nullptr;
};

}  // namespace blockdyn
