# SPDX-License-Identifier: Apache-2.0
# The installed headers: the public entry points below and every blockdyn header they include,
# transitively (so an installed header never names one that is not installed). Internal helpers
# (atomic files, progress bars, TOML readers, the parallel map, recorders, study plumbing) stay out.
set(BLOCKDYN_PUBLIC_ENTRY_HEADERS
  commands/settings.hpp
  commands/scenario_settings.hpp
  commands/simulate_run.hpp
  simulation/winkler_simulation.hpp
  simulation/rigid_simulation.hpp
  simulation/run.hpp
  simulation/observer.hpp
  model/winkler/initial_conditions.hpp
  model/winkler/energy.hpp
  excitation/ground_motion.hpp
  excitation/intensity_measures.hpp
  excitation/response_spectrum.hpp
  excitation/stochastic_motion.hpp
  analysis/forced/fragility_fit.hpp
  analysis/forced/fragility_study.hpp
  analysis/masonry/limit_analysis.hpp
  simulation/rigid_ground_model.hpp
  io/json_io.hpp
  io/scenario.hpp
  io/csv_table.hpp
  simulation/winkler_trajectory.hpp
  simulation/assembly_simulation.hpp
  simulation/rigid_trajectory.hpp
  analysis/sweep/sweep_runner.hpp
  analysis/sweep/sweep_evaluator.hpp
  analysis/sweep/rigid_sweep.hpp
  analysis/dynamics/lyapunov.hpp
  analysis/winkler/flight.hpp
  analysis/winkler/stability.hpp
  analysis/winkler/equilibria.hpp
  analysis/winkler/equilibrium_bifurcation.hpp
  analysis/winkler/poincare.hpp
  analysis/winkler/response_type.hpp
  analysis/winkler/lyapunov_block.hpp
  analysis/winkler/energy_surface.hpp)

# Out: BLOCKDYN_PUBLIC_HEADERS, paths relative to src/blockdyn.
function(blockdyn_public_headers src_dir out)
  set(todo ${BLOCKDYN_PUBLIC_ENTRY_HEADERS})
  set(done "")
  while(todo)
    list(POP_FRONT todo h)
    if(h IN_LIST done)
      continue()
    endif()
    list(APPEND done ${h})
    file(STRINGS ${src_dir}/${h} lines REGEX "^#include \"blockdyn/[^\"]+\"")
    foreach(l ${lines})
      string(REGEX REPLACE "^#include \"blockdyn/([^\"]+)\".*" "\\1" inc "${l}")
      if(NOT inc STREQUAL "version.hpp" AND EXISTS ${src_dir}/${inc} AND NOT inc IN_LIST done)
        list(APPEND todo ${inc})
      endif()
    endforeach()
  endwhile()
  list(SORT done)
  set(${out} ${done} PARENT_SCOPE)
endfunction()
