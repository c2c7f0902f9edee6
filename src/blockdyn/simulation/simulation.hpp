// SPDX-License-Identifier: Apache-2.0
#pragma once
// One simulation: an immutable model, the run's mutable state (time, mode, state vector) and the
// stepping strategy that advances it, reporting to an Observer<Model> (observer.hpp). Every run
// of every family and every analysis goes through here, never through the integrator directly:
//   Simulation<Model>        event-driven stepping on the hybrid integrator (any HybridModel);
//   MoreauJeanStepping<N>    time-stepping where the model has a contact problem (the rigid
//                            assemblies, moreau_jean_stepping.hpp), reporting to the same
//                            observers; run_rigid_assembly (rigid_assembly_run.hpp) hands a run
//                            between the two.
// An analysis that runs an orbit in legs (a Lyapunov exponent renormalised every interval, a
// shooting pass to the next impact) advances one Simulation leg by leg; between two legs it may
// change the state (rescale a tangent, re-seed a copy) and the next leg restarts from there.
#include "blockdyn/integrate/hybrid_integrator.hpp"
#include "blockdyn/simulation/observer.hpp"

namespace blockdyn {

// The integrator's observer calls onto an Observer<Model> (the integrator knows no model).
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
class Simulation {
 public:
  using Mode = typename Model::Mode;
  using State = Vec<Model::kDim>;

  // The run starts at (t0, mode, z); each leg first completes the state onto its mode's
  // constraints.
  Simulation(const Model& m, const IntegratorOptions& opt, double t0, const Mode& mode, const State& z)
      : model_(m), integrator_(m, opt), t_(t0), mode_(mode), z_(z) {}

  // One leg: on to t_end, or until the model or the observer stops the run; why it ended.
  RunStatus advance(double t_end, Observer<Model>& obs) {
    ObserverBridge<Model> bridge{model_, obs};
    return integrator_.run(t_, t_end, mode_, z_, bridge);
  }
  // A whole run: the observer's on_start, one leg to t_end, its on_finish.
  RunStatus run(double t_end, Observer<Model>& obs) {
    model_.complete(mode_, z_);
    obs.on_start(model_, t_, mode_, z_);
    const RunStatus st = advance(t_end, obs);
    obs.on_finish(model_, t_, mode_, z_);
    return st;
  }

  // One leg from (t, mode, z), left where it ended: for an analysis that keeps the orbit's
  // state itself between legs.
  RunStatus advance_from(double& t, Mode& mode, State& z, double t_end, Observer<Model>& obs) {
    restart(t, mode, z);
    const RunStatus st = advance(t_end, obs);
    t = t_;
    mode = mode_;
    z = z_;
    return st;
  }

  const Model& model() const { return model_; }
  double t() const { return t_; }
  const Mode& mode() const { return mode_; }
  const State& state() const { return z_; }
  // Between legs an analysis may change where the next one starts.
  Mode& mode() { return mode_; }
  State& state() { return z_; }
  void restart(double t, const Mode& mode, const State& z) {
    t_ = t;
    mode_ = mode;
    z_ = z;
  }
  const StepperStats& stats() const { return integrator_.stats(); }

 private:
  const Model& model_;
  HybridIntegrator<Model> integrator_;
  double t_;
  Mode mode_;
  State z_;
};

}  // namespace blockdyn
