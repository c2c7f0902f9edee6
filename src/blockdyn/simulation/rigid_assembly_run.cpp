// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/simulation/rigid_assembly_run.hpp"

#include "blockdyn/base/number_text.hpp"

#include <cmath>
#include <vector>

#include "blockdyn/simulation/moreau_jean_stepping.hpp"
#include "blockdyn/simulation/simulation.hpp"

namespace blockdyn {

template <int MaxBlocks>
RunOutcome<RigidAssemblyModel<MaxBlocks>> run_rigid_assembly(const RigidAssemblyModel<MaxBlocks>& m,
                                                             typename RigidAssemblyModel<MaxBlocks>::Mode mode,
                                                             typename RigidAssemblyModel<MaxBlocks>::State z,
                                                             const AssemblyRunOptions& o,
                                                             Observer<RigidAssemblyModel<MaxBlocks>>& obs,
                                                             TimeSteppingWindows& windows) {
  using M = RigidAssemblyModel<MaxBlocks>;
  obs.on_start(m, 0.0, mode, z);
  RunOutcome<M> out;
  std::unique_ptr<MoreauJeanStepping<MaxBlocks>> window;
  auto open_window = [&] {
    if (!window) window = std::make_unique<MoreauJeanStepping<MaxBlocks>>(m, m.assembly(), m.ground(), o.step, obs);
    mode.rest = false;
  };
  auto finish_stats = [&] {
    if (!window) return;
    const auto& st = window->scheme().solve_stats();
    windows.direct = st.direct;
    windows.gauss_seidel = st.gauss_seidel;
    windows.lemke = st.lemke;
    windows.active_set_iterations = st.active_set_iterations;
    windows.sweeps = st.sweeps;
  };
  if (effective_scheme(m.assembly(), o) == AssemblyScheme::TimeStepping) {
    // The whole run on Moreau-Jean's scheme, through the same observers.
    open_window();
    bool stopped = false;
    window->run(out.t, mode, z, o.t_end, windows.steps, stopped, false);
    out.status = stopped ? RunStatus::ModelStop : RunStatus::ReachedEnd;
    out.stats.accepted = out.stats.rhs_evals = windows.steps;
    finish_stats();
    out.mode = mode;
    out.z = z;
    obs.on_finish(m, out.t, mode, z);
    return out;
  }
  while (true) {
    Simulation<M> sim(m, o.integrator, out.t, mode, z);
    out.status = sim.advance(o.t_end, obs);
    out.t = sim.t();
    mode = sim.mode();
    z = sim.state();
    const StepperStats& st = sim.stats();
    out.stats.accepted += st.accepted;
    out.stats.rejected += st.rejected;
    out.stats.rhs_evals += st.rhs_evals;
    // Events that repeat at one instant (the integrator's chatter guard) are a chattering
    // contact too.
    const bool chatter = out.status == RunStatus::Chatter;
    if (!chatter && (out.status != RunStatus::ModelStop || !m.wants_time_stepping())) break;
    // A window of time-stepping, until the contacts are quiet and a consistent mode exists.
    if (windows.count++ == 0) windows.first = chatter ? "contact events repeating at one instant" : m.problem();
    if (chatter) {
      EventInfo<typename M::Mode, M::kDim> e{out.t, z, z, mode, mode, 0, kAssemblyToTimeStepping, false};
      obs.on_event(m, e);
    }
    open_window();
    const double t_start = out.t;
    bool stopped = false, back = false;
    while (!back) {
      if (!window->run(out.t, mode, z, o.t_end, windows.steps, stopped)) break;
      if (const auto resumed = m.resume(out.t, z, mode)) {
        EventInfo<typename M::Mode, M::kDim> e{out.t, z, z, mode, *resumed, 0, kAssemblyToEventDriven, false};
        mode = *resumed;
        obs.on_event(m, e);
        back = true;
      }
    }
    windows.time += out.t - t_start;
    if (!back) {
      out.status = stopped ? RunStatus::ModelStop : RunStatus::ReachedEnd;
      break;
    }
  }
  finish_stats();
  out.mode = mode;
  out.z = z;
  obs.on_finish(m, out.t, mode, z);
  return out;
}

template RunOutcome<RigidAssemblyModel<1>> run_rigid_assembly(const RigidAssemblyModel<1>&, RigidAssemblyModel<1>::Mode,
                                                              RigidAssemblyModel<1>::State, const AssemblyRunOptions&,
                                                              Observer<RigidAssemblyModel<1>>&, TimeSteppingWindows&);
template RunOutcome<RigidAssemblyModel<3>> run_rigid_assembly(const RigidAssemblyModel<3>&, RigidAssemblyModel<3>::Mode,
                                                              RigidAssemblyModel<3>::State, const AssemblyRunOptions&,
                                                              Observer<RigidAssemblyModel<3>>&, TimeSteppingWindows&);
template RunOutcome<RigidAssemblyModel<8>> run_rigid_assembly(const RigidAssemblyModel<8>&, RigidAssemblyModel<8>::Mode,
                                                              RigidAssemblyModel<8>::State, const AssemblyRunOptions&,
                                                              Observer<RigidAssemblyModel<8>>&, TimeSteppingWindows&);
template RunOutcome<RigidAssemblyModel<24>> run_rigid_assembly(const RigidAssemblyModel<24>&,
                                                               RigidAssemblyModel<24>::Mode,
                                                               RigidAssemblyModel<24>::State, const AssemblyRunOptions&,
                                                               Observer<RigidAssemblyModel<24>>&, TimeSteppingWindows&);

}  // namespace blockdyn
