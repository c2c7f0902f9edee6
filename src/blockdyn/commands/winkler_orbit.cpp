// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/commands/winkler_orbit.hpp"

#include "blockdyn/simulation/run_options.hpp"

#include <optional>
#include <stdexcept>

#include "blockdyn/analysis/winkler/energy_surface.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/io/scenario.hpp"
#include "blockdyn/model/winkler/energy.hpp"
#include "blockdyn/model/winkler/initial_conditions.hpp"

namespace blockdyn {

std::vector<StudyOption> winkler_orbit_options(const std::string& method_option) {
  const WinklerParams p;
  const IntegratorOptions integ;
  return {
      {"r", "aspect ratio width/height (> 0)", Settings::exact(p.r)},
      {"mu", "friction coefficient (>= 0)", Settings::exact(p.mu)},
      {"k", "non-dimensional foundation stiffness k a b/(m g) (> 0)", Settings::exact(p.k)},
      {"rtol", rtol_help(), Settings::exact(integ.rtol)},
      {"atol", atol_help(), Settings::exact(integ.atol)},
      {method_option,
       "Runge-Kutta pair: dopri5 (Dormand-Prince 5(4)), dop853 (8(5,3), 7th-order dense output) or auto "
       "(dop853 when rtol < 1e-6)",
       "auto"},
      {"ic",
       "initial conditions: ic1 (tilted, at rest), ic2 (upright, impulse), custom, or surface (given `w0` `y0`, "
       "y' solved so that the energy is `energy` / that of `energy-of`)",
       "ic1"},
      {"energy", "surface: the total energy E of the initial state", ""},
      {"energy-of", "surface: use the energy of this set (ic1 or ic2) when `energy` is not given", "ic1"},
      {"vy-sign", "surface: sign of the solved y' (+1 or -1)", "1"},
      {"w0", "initial tilt w (ic1 override, default alpha/2; custom state)", ""},
      {"w0-alpha", "initial tilt as a fraction of alpha = atan(r) (instead of `w0`)", ""},
      {"x0", "initial x (overrides the set's value)", ""},
      {"y0", "initial y of the centre (overrides)", ""},
      {"vx0", "initial x' (overrides)", ""},
      {"vy0", "initial y' (overrides)", ""},
      {"vw0", "initial w' (overrides)", ""},
  };
}

namespace {

std::string one_of(const StudyOptions& o, const std::string& name, const std::vector<std::string>& allowed) {
  const std::string v = o.text(name);
  std::string list;
  for (const auto& a : allowed) {
    if (a == v) return v;
    list += (list.empty() ? "" : ", ") + a;
  }
  throw std::invalid_argument(std::string("`") + name + "` = '" + v + "' is not one of: " + list);
}

std::optional<double> initial_tilt(const StudyOptions& o, const WinklerParams& p) {
  if (o.given("w0") && o.given("w0-alpha")) throw std::invalid_argument("give either `w0` or `w0-alpha`, not both");
  if (o.given("w0")) return o.number("w0");
  if (!o.given("w0-alpha")) return std::nullopt;
  const double f = o.number("w0-alpha");
  require_in_range("w0-alpha", f, -1.0, 1.0);
  return f * p.alpha();
}

WinklerState initial_of(const StudyOptions& o, const WinklerOrbit& orbit) {
  const WinklerParams& p = orbit.p;
  const std::optional<double> w0 = initial_tilt(o, p);
  const std::string of = one_of(o, "energy-of", {"ic1", "ic2"});
  const long sign = o.integer("vy-sign");
  if (sign != 1 && sign != -1) throw std::invalid_argument("`vy-sign` = " + std::to_string(sign) + " is not 1 or -1");
  if (orbit.ic == "surface") {
    if (!w0 || !o.given("y0")) throw std::invalid_argument("ic = surface needs `w0` (or `w0-alpha`) and `y0`");
    const double E = o.given("energy") ? o.number("energy") : energy(p, of == "ic2" ? ic2(p) : ic1(p)).total();
    return state_on_energy_surface(p, E, *w0, o.number("y0"), int(sign));
  }
  Scenario sc;
  sc.params = p;
  sc.initial.set = orbit.ic;
  sc.initial.w0 = w0;
  for (auto [name, field] : {std::pair{"x0", &InitialSpec::x0},
                             {"y0", &InitialSpec::y0},
                             {"vx0", &InitialSpec::vx0},
                             {"vy0", &InitialSpec::vy0},
                             {"vw0", &InitialSpec::vw0}})
    if (o.given(name)) sc.initial.*field = o.number(name);
  if (sc.initial.w0) require_in_range("w0", *sc.initial.w0, -p.alpha(), p.alpha());
  return initial_state(sc);
}

}  // namespace

WinklerOrbit winkler_orbit(const StudyOptions& o, const std::string& method_option) {
  WinklerOrbit orbit;
  orbit.p = {o.number("r"), o.number("mu"), o.number("k")};
  validate(orbit.p);
  orbit.integrator.rtol = o.number("rtol");
  orbit.integrator.atol = o.number("atol");
  const auto m = method_from_string(o.text(method_option));
  if (!m)
    throw std::invalid_argument(std::string("`") + method_option + "` = '" + o.text(method_option) +
                                "' is not one of: auto, dopri5, dop853");
  orbit.integrator.method = *m;
  orbit.ic = one_of(o, "ic", {"ic1", "ic2", "custom", "surface"});
  orbit.z0 = initial_of(o, orbit);
  return orbit;
}

WinklerRunOptions orbit_run_options(double t_end, const IntegratorOptions& integ) {
  WinklerRunOptions so;
  so.t_end = t_end;
  so.integrator = integ;
  so.record_events = false;
  validate(so);
  return so;
}

nlohmann::ordered_json orbit_summary_head(const WinklerOrbit& orbit) {
  nlohmann::ordered_json j;
  j["run_info"] = run_info();
  j["params"] = to_json(orbit.p);
  j["initial"] = {{"set", orbit.ic}, {"state", state_json(orbit.z0)}, {"energy", energy(orbit.p, orbit.z0).total()}};
  j["integrator"] = to_json(orbit.integrator);
  return j;
}

}  // namespace blockdyn
