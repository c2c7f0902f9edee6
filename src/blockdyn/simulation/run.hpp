// SPDX-License-Identifier: Apache-2.0
#pragma once
// One run of any hybrid model from a mode and state, with its observers: the integrator's
// observer protocol bridged to Observer<Model>, the start and end announced.
#include "blockdyn/integrate/hybrid_integrator.hpp"
#include "blockdyn/simulation/observer.hpp"

namespace blockdyn {

template <class Model>
struct RunOutcome {
  RunStatus status = RunStatus::ReachedEnd;
  double t = 0;
  typename Model::Mode mode{};
  Vec<Model::kDim> z{};
  StepperStats stats;
};

// The integrator's observer protocol (on_step, on_event) onto an Observer<Model>.
template <class Model>
struct ObserverBridge {
  const Model& m;
  Observer<Model>& o;
  bool on_step(const DenseSegment<Model::kDim>& s, double a, double b, const typename Model::Mode& md) {
    return o.on_segment(m, s, a, b, md);
  }
  bool on_event(const EventInfo<typename Model::Mode, Model::kDim>& e) { return o.on_event(m, e); }
  bool needs_dense() const { return o.needs_dense(); }
};

template <HybridModel Model>
RunOutcome<Model> run_model(const Model& m, typename Model::Mode mode, Vec<Model::kDim> z, double t0, double t_end,
                            const IntegratorOptions& opt, Observer<Model>& obs) {
  ObserverBridge<Model> bridge{m, obs};
  m.complete(mode, z);
  obs.on_start(m, t0, mode, z);
  HybridIntegrator<Model> integ(m, opt);
  RunOutcome<Model> out;
  out.t = t0;
  out.status = integ.run(out.t, t_end, mode, z, bridge);
  out.mode = mode;
  out.z = z;
  out.stats = integ.stats();
  obs.on_finish(m, out.t, mode, z);
  return out;
}

}  // namespace blockdyn
