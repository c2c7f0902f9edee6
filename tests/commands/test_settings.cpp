// SPDX-License-Identifier: Apache-2.0
// Options by name (commands/settings.hpp, scenario_settings.hpp, simulate_run.hpp): parsed on use with
// errors naming the option, every family's options refused by the others, the run from Settings
// equal to the run from the parameters, the trajectory table's columns from the family.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "blockdyn/commands/scenario_settings.hpp"
#include "blockdyn/commands/simulate_run.hpp"
#include "blockdyn/io/csv_table.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"

namespace blockdyn {
namespace {

std::string error_of(const Settings& s) {
  try {
    scenario_from(s);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(Settings, NamesAreCanonicalAndValuesParsedOnUse) {
  Settings s;
  s.add("t_end", "2.5");
  s.add("--ground-h-amplitude", "0x1p-2");
  s.add("w0", "0.1rad");
  EXPECT_TRUE(s.has("t-end"));
  EXPECT_EQ(s.number("t-end", 0.0), 2.5);
  EXPECT_EQ(s.number("ground-h-amplitude", 0.0), 0.25);
  EXPECT_EQ(s.number("absent", 7.0), 7.0);
  try {
    s.number("w0");
    FAIL() << "a number with a unit suffix was read";
  } catch (const std::invalid_argument& e) {
    // The library names the option in backticks; each front end spells it (spell_options).
    EXPECT_EQ(std::string(e.what()), "`w0` = '0.1rad' is not a number");
    EXPECT_EQ(spell_options(e.what(), "--", false), "--w0 = '0.1rad' is not a number");
  }
  EXPECT_THROW(s.require_known({"t-end", "ground-h-amplitude"}, "test"), std::invalid_argument);
}

TEST(Settings, OptionsOfAnotherFamilyAreRefused) {
  Settings s;
  s.add("model", "housner");
  s.add("width", "0.3");
  s.add("height", "1.5");
  s.add("mu-s", "0.5");
  EXPECT_NE(error_of(s).find("`mu-s` belongs to `model` rigid"), std::string::npos) << error_of(s);
  Settings w;
  w.add("r", "0.2");
  w.add("restitution", "0.5");
  EXPECT_NE(error_of(w).find("`restitution` belongs to `model` housner|rigid"), std::string::npos);
  Settings m;
  m.add("model", "stone");
  EXPECT_NE(error_of(m).find("`model` = 'stone' is not one of"), std::string::npos) << error_of(m);
}

// How the front ends spell the options a message names: the command line's flags, Python's
// keywords; text in backticks that is no option name is left alone.
TEST(Settings, OptionNamesSpelledByEachFrontEnd) {
  const std::string m = "`mu-s` belongs to `model` rigid; see `t-end` and `blockdyn cycles`";
  EXPECT_EQ(spell_options(m, "--", false), "--mu-s belongs to --model rigid; see --t-end and `blockdyn cycles`");
  EXPECT_EQ(spell_options(m, "", true), "mu_s belongs to model rigid; see t_end and `blockdyn cycles`");
  EXPECT_EQ(spell_options("no options here", "--", false), "no options here");
  EXPECT_EQ(spell_options("a lone ` and ``", "--", false), "a lone ` and ``");
}

// The registry's run from Settings is the library's run from the parameters, and the trajectory
// table carries the family's columns.
TEST(Settings, ScenarioRunEqualsTheDirectRun) {
  Settings s;
  for (auto [k, v] : {std::pair{"model", "rigid"},
                      {"width", "0.3"},
                      {"height", "1.2"},
                      {"mu-s", "0.4"},
                      {"ground-h-amplitude", "0.3"},
                      {"ground-h-frequency", "2"},
                      {"t-end", "4"}})
    s.add(k, v);
  const Scenario sc = scenario_from(s);
  ColumnTable table;
  long events = 0;
  SimulateOutputs out;
  out.trajectory = &table;
  out.on_event = [&events](const nlohmann::ordered_json&) { ++events; };
  const SimulateReport rep = run_scenario(sc, out);

  RigidBlockParams p;
  p.shape.width = 0.3;
  p.shape.height = 1.2;
  p.interface = {0.4, 0.4};
  GroundMotion g;
  g.horizontal.amplitude = 0.3;
  g.horizontal.frequency = 2.0;
  RigidRunOptions o;
  o.t_end = 4;
  const RigidResult r = simulate_rigid(p, g, RigidInitial{}, o);
  EXPECT_EQ(rep.summary.get()["t_final"].get<double>(), r.t_final);
  EXPECT_EQ(rep.summary.get()["max_abs_rotation"].get<double>(), r.max_abs_rotation);
  EXPECT_EQ(events, long(r.events.size()));
  EXPECT_GT(events, 2);
  ASSERT_GE(table.data().size(), 9u);
  EXPECT_EQ(table.data()[0].name, "t");
  EXPECT_EQ(table.data()[7].name, "mode");
  EXPECT_TRUE(table.data()[7].is_text);
  EXPECT_EQ(table.data()[3].numbers.back(), r.final_state[2]);  // w at the end
  EXPECT_EQ(rep.figure.get().plot.kind, "rigid");
}

TEST(Settings, TooLongATrajectoryIsRefusedBeforeRunning) {
  Settings s;
  for (auto [k, v] : {std::pair{"model", "housner"},
                      {"width", "0.3"},
                      {"height", "1.5"},
                      {"t-end", "100"},
                      {"output-interval", "1e-6"}})
    s.add(k, v);
  ColumnTable table;
  SimulateOutputs out;
  out.trajectory = &table;
  out.max_output_rows = 1e6;
  EXPECT_THROW(run_scenario(scenario_from(s), out), std::invalid_argument);
  EXPECT_EQ(table.rows(), 0u);
}

}  // namespace
}  // namespace blockdyn
