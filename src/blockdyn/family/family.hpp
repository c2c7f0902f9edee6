// SPDX-License-Identifier: Apache-2.0
#pragma once
// A model family as blockdyn's commands see it, registered once (families(), family_registry.cpp):
// its name, the options `simulate` reads and the run they prepare, and the adapters the analyses
// use (a block on rigid ground, a sweep, the forced analyses' model, the free-motion Lyapunov
// study). Every command asks these descriptors; nothing outside the registration compares a
// family's name. A new family is its folder plus one row in family_registry.cpp
// (docs/architecture.md).
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace blockdyn {

class Settings;
class PreparedRun;
class StudyOptions;
struct Scenario;
struct SimulateOutputs;
struct SimulateReport;
struct SweepDefinition;
struct ForcedModel;
struct StudyReport;
struct StudyRequest;
struct RigidGroundModel;
struct Family;
struct StudyOption;

// The forced analyses' model of a family (spectrum, survival, response curves, cycles, impact
// maps, Lyapunov exponents, chaos maps).
struct ForcedFamily {
  // Options of the other families, refused with the reason: (options, why).
  std::vector<std::pair<std::vector<std::string>, std::string>> refused;
  ForcedModel (*build)(const Settings&, const Family&);  // throws std::invalid_argument
  // Default tolerances of the Lyapunov exponent's run (rtol, atol) and of a chaos map's (0: the
  // integrator's defaults): an assembly's tangent carries stiff contact modes (docs/forced-chaos.md).
  double lyapunov_rtol, lyapunov_atol, chaos_map_rtol = 0, chaos_map_atol = 0;
  // The run starts from --w0, --vw0 (and --x0, ...); false: as built.
  bool initial_state = true;
  // Friction is given per interface by angles (--phi-s, --phi-l), not by coefficients.
  bool friction_angles = false;
  // A body in space (ForcedModel::run3: three ground components, an incidence), its size set by
  // --width, --depth and --height: the rocking spectrum's 3D family.
  bool spatial = false;
};

struct Family {
  const char* name;                                          // the --model value
  const char* description;                                   // for --help
  const std::vector<std::string>& (*options)();              // the options `simulate` reads
  std::unique_ptr<PreparedRun> (*prepare)(const Settings&);  // throws std::invalid_argument
  // The options only this family has, with their help: `simulate` registers them (null: none).
  const std::vector<StudyOption>& (*own_options)() = nullptr;
  // The trajectory columns that make up its state, comma-separated (Python's Simulation.state).
  const char* state_columns = "x,y,w,vx,vy,vw";
  // A block described by a scenario file ([physical], [ground], ...); null for the others.
  SimulateReport (*run_scenario)(const Scenario&, const SimulateOutputs&) = nullptr;
  // A block on rigid ground (rocking spectra, fragility, its sweeps); null for the others.
  const RigidGroundModel* rigid_ground = nullptr;
  // `sweep --model NAME`; null: no sweep.
  SweepDefinition (*sweep)(const Settings&, const Family&) = nullptr;
  // The sweep's axes (name, what it sets) for --list-axes.
  std::vector<std::pair<std::string, std::string>> (*sweep_axes)() = nullptr;
  // The summary's keys a settings sweep's row carries (commands/settings_sweep.hpp), the first the
  // run's status; null: the family's sweep has its own rows.
  const std::vector<std::string>& (*result_keys)() = nullptr;
  const ForcedFamily* forced = nullptr;  // null: not a model of the forced analyses
  // `lyapunov` of the free (unforced) model; null: the forced study only.
  StudyReport (*free_lyapunov)(const StudyOptions&, const StudyRequest&) = nullptr;

  bool scenario() const { return run_scenario != nullptr; }
};

[[noreturn]] void throw_not_a_family(const std::string& field, const std::string& name, const std::string& names);

// Every registered family, in the order --help lists them; the first is the default.
const std::vector<Family>& families();
// The family named, or null.
const Family* find_family(const std::string& name);
// The family named; throws std::invalid_argument "<field> = '<name>' is not one of: <the names of
// the families that have `has`>" (every family without a filter).
template <class Has>
const Family& family_named(const std::string& field, const std::string& name, Has&& has);
const Family& family_named(const std::string& field, const std::string& name);
// "winkler, housner, rigid" (those that have `has`).
template <class Has>
std::string family_names(Has&& has) {
  std::string names;
  for (const Family& f : families())
    if (has(f)) names += (names.empty() ? "" : ", ") + std::string(f.name);
  return names;
}
std::string family_names();

template <class Has>
const Family& family_named(const std::string& field, const std::string& name, Has&& has) {
  const Family* f = find_family(name);
  if (f && has(*f)) return *f;
  throw_not_a_family(field, name, family_names(has));
}

}  // namespace blockdyn
