// SPDX-License-Identifier: Apache-2.0
#pragma once
// How a run is integrated (tolerances, step limits, the Runge-Kutta pair) and how it ended:
// what options and results carry, without the integrator itself (hybrid_integrator.hpp).
#include <limits>
#include <optional>
#include <string>

namespace blockdyn {

enum class RunStatus { ReachedEnd, ModelStop, ObserverStop, MaxSteps, StepUnderflow, Chatter, NonFinite };

inline const char* to_string(RunStatus s) {
  switch (s) {
    case RunStatus::ReachedEnd:
      return "t_end";
    case RunStatus::ModelStop:
      return "model_stop";
    case RunStatus::ObserverStop:
      return "observer_stop";
    case RunStatus::MaxSteps:
      return "max_steps";
    case RunStatus::StepUnderflow:
      return "step_underflow";
    case RunStatus::Chatter:
      return "chatter";
    case RunStatus::NonFinite:
      return "non_finite";
  }
  return "?";
}

// The Runge-Kutta pair. Auto: DOP853 at tolerances where its higher order pays (rtol below
// kDop853BelowRtol), Dopri5 above.
enum class Method { Auto, Dopri5, Dop853 };
inline constexpr double kDop853BelowRtol = 1e-6;

inline const char* to_string(Method m) {
  switch (m) {
    case Method::Auto:
      return "auto";
    case Method::Dopri5:
      return "dopri5";
    case Method::Dop853:
      return "dop853";
  }
  return "?";
}

inline std::optional<Method> method_from_string(const std::string& s) {
  for (Method m : {Method::Auto, Method::Dopri5, Method::Dop853})
    if (s == to_string(m)) return m;
  return std::nullopt;
}

struct IntegratorOptions {
  double rtol = 1e-10;
  double atol = 1e-12;
  double h_max = std::numeric_limits<double>::infinity();
  long max_steps = 200'000'000;
  int event_samples = 1;   // interior points per step at which the event functions are sampled
  int chatter_limit = 16;  // consecutive zero-duration events before resolve_chatter()
  Method method = Method::Auto;
};

// The pair a run with these options uses.
inline Method resolved_method(const IntegratorOptions& o) {
  if (o.method != Method::Auto) return o.method;
  return o.rtol < kDop853BelowRtol ? Method::Dop853 : Method::Dopri5;
}

}  // namespace blockdyn
