// SPDX-License-Identifier: Apache-2.0
// The `blockdyn simulate` command line (issue 2, item 9): JSON summary, trajectory CSV, TOML
// scenario equivalence, and rejection of bad input (non-zero exit, a one-line `error:` message
// naming the field, and no output file left behind). Runs the real binary in a temp directory.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "blockdyn/model/winkler/initial_conditions.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

struct CliRun {
  int code = -1;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

class CliSimulate : public ::testing::Test {
 protected:
  fs::path dir;
  void SetUp() override {
    std::string tmpl = (fs::temp_directory_path() / "blockdyn-cli-XXXXXX").string();
    ASSERT_NE(::mkdtemp(tmpl.data()), nullptr);
    dir = tmpl;
  }
  void TearDown() override { fs::remove_all(dir); }

  // Runs `blockdyn simulate args...` inside dir.
  CliRun simulate(const std::vector<std::string>& args) {
    std::string cmd = "cd " + quote(dir.string()) + " && " + quote(BLOCKDYN_CLI) + " simulate";
    for (const auto& a : args) cmd += " " + quote(a);
    cmd += " > stdout.txt 2> stderr.txt";
    const int rc = std::system(cmd.c_str());
    CliRun r;
    r.code = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
    r.out = slurp(dir / "stdout.txt");
    r.err = slurp(dir / "stderr.txt");
    fs::remove(dir / "stdout.txt");
    fs::remove(dir / "stderr.txt");
    return r;
  }

  void write(const std::string& name, const std::string& text) { std::ofstream(dir / name) << text; }

  std::vector<std::string> files() const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
    return out;
  }
};

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == sep) {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

}  // namespace

TEST_F(CliSimulate, JsonSummaryHasRequiredKeysAndMatchesLibrary) {
  const CliRun r = simulate({"--r", "0.5", "--mu", "0.2", "--k", "1e4", "--t-end", "2", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  for (const char* key :
       {"parameters", "tolerances", "initial_state", "initial_energy", "status", "t_final", "final_state", "ihor",
        "first_flight_time", "max_abs_energy_error", "steps", "rhs_evals", "events"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["parameters"]["r"], 0.5);
  EXPECT_EQ(j["parameters"]["mu"], 0.2);
  EXPECT_EQ(j["parameters"]["k"], 1e4);
  EXPECT_EQ(j["tolerances"]["rtol"], 1e-10);
  EXPECT_EQ(j["status"], "t_end");
  EXPECT_EQ(j["t_final"], 2.0);
  ASSERT_TRUE(j["events"].is_array());
  ASSERT_FALSE(j["events"].empty());
  for (const auto& e : j["events"])
    for (const char* key : {"t", "kind", "from", "to"}) EXPECT_TRUE(e.contains(key)) << key;
  // The same run in-process: the command line adds nothing and loses nothing.
  const blockdyn::WinklerParams p{0.5, 0.2, 1e4};
  blockdyn::WinklerRunOptions o;
  o.t_end = 2.0;
  const blockdyn::WinklerState z0 = blockdyn::ic1(p);
  const blockdyn::WinklerResult lib = blockdyn::simulate(p, {}, z0, o);
  EXPECT_EQ(j["initial_state"]["w"].get<double>(), z0[blockdyn::kW]);  // ic1: alpha / 2
  EXPECT_DOUBLE_EQ(j["initial_state"]["w"].get<double>(), 0.5 * std::atan(0.5));
  EXPECT_EQ(j["ihor"].get<long>(), lib.upright_passages);
  EXPECT_EQ(j["events"].size(), lib.events.size());
  EXPECT_EQ(j["steps"].get<long>(), lib.stats.accepted);
  EXPECT_EQ(j["final_state"]["w"].get<double>(), lib.final_state[blockdyn::kW]);
  ASSERT_TRUE(lib.first_flight_time);
  EXPECT_EQ(j["first_flight_time"].get<double>(), *lib.first_flight_time);
  EXPECT_EQ(j["initial_energy"]["total"].get<double>(), lib.initial_energy.total());
  EXPECT_LT(j["max_abs_energy_error"].get<double>(), 1e-8);
}

TEST_F(CliSimulate, TrajectoryCsvRowsAtIntervalPlusEvents) {
  const CliRun r = simulate({"--r", "0.5", "--mu", "0.2", "--k", "1e4", "--t-end", "1", "--output-interval", "0.05",
                             "--trajectory", "traj.csv", "--json-out", "summary.json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(slurp(dir / "summary.json"));
  std::istringstream csv(slurp(dir / "traj.csv"));
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  const auto header = split(line, ',');
  ASSERT_GE(header.size(), 10u);
  EXPECT_EQ(header[0], "t");
  EXPECT_EQ(header[1], "x");
  EXPECT_EQ(header[2], "y");
  EXPECT_EQ(header[3], "w");
  std::size_t col_event = 0;
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == "event") col_event = i;
  ASSERT_GT(col_event, 0u);
  std::vector<double> regular;
  std::vector<double> event_times;
  double last_t = -1;
  while (std::getline(csv, line)) {
    const auto f = split(line, ',');
    ASSERT_EQ(f.size(), header.size()) << line;
    const double t = std::stod(f[0]);
    EXPECT_GE(t, last_t);
    last_t = t;
    if (f[col_event].empty() || f[col_event] == "start")
      regular.push_back(t);
    else
      event_times.push_back(t);
  }
  // Regular rows at t = 0, 0.05, ..., 1.0 (21 instants), events as in the JSON summary.
  ASSERT_EQ(regular.size(), 21u);
  for (std::size_t n = 0; n < regular.size(); ++n) EXPECT_NEAR(regular[n], 0.05 * n, 1e-12);
  ASSERT_EQ(event_times.size(), j["events"].size());
  for (std::size_t i = 0; i < event_times.size(); ++i) EXPECT_EQ(event_times[i], j["events"][i]["t"].get<double>());
}

TEST_F(CliSimulate, ScenarioFileEqualsFlags) {
  write("run.toml",
        "[block]\nr = 0.3\nmu = 0.25\nk = 3e4\n"
        "[initial]\nset = \"ic2\"\n"
        "[run]\nt_end = 1.5\nrtol = 1e-9\natol = 1e-11\n");
  const CliRun a = simulate({"run.toml", "--json"});
  const CliRun b = simulate({"--r", "0.3", "--mu", "0.25", "--k", "3e4", "--ic", "ic2", "--t-end", "1.5", "--rtol",
                             "1e-9", "--atol", "1e-11", "--json"});
  ASSERT_EQ(a.code, 0) << a.err;
  ASSERT_EQ(b.code, 0) << b.err;
  json ja = json::parse(a.out), jb = json::parse(b.out);
  ja.erase("run");  // program version line
  jb.erase("run");
  EXPECT_EQ(ja, jb);
  EXPECT_EQ(ja["initial_state"]["vx"], 0.06);  // ic2
  // A flag given with a scenario overrides it.
  const CliRun c = simulate({"run.toml", "--mu", "0.0", "--json"});
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_EQ(json::parse(c.out)["parameters"]["mu"], 0.0);
}

TEST_F(CliSimulate, BadInputIsRejectedCleanly) {
  write("unknown_key.toml", "[block]\nr = 0.5\nmuu = 0.2\n");
  write("unknown_table.toml", "[blok]\nr = 0.5\n");
  write("not_a_number.toml", "[run]\nt_end = \"long\"\n");
  write("nan.toml", "[run]\nt_end = nan\n");
  write("neg_k.toml", "[block]\nk = -3.0\n");
  write("bad_method.toml", "[run]\nmethod = \"euler\"\n");
  struct Case {
    std::vector<std::string> args;
    std::string field;
  };
  const std::vector<Case> cases = {
      {{"--r", "-1"}, "r ="},
      {{"--r", "0"}, "r ="},
      {{"--k", "0"}, "k ="},
      {{"--k", "-5"}, "k ="},
      {{"--t-end", "0"}, "t-end"},
      {{"--t-end", "-2"}, "t-end"},
      {{"--mu", "-0.1"}, "mu ="},
      {{"--rtol", "-1e-9"}, "rtol"},
      {{"--rtol", "0"}, "rtol"},
      {{"--atol", "-1"}, "atol"},
      {{"--r", "nan"}, "r ="},
      {{"--k", "inf"}, "k ="},
      {{"--mu", "nan"}, "mu ="},
      {{"--t-end", "inf"}, "t-end"},
      {{"--rtol", "nan"}, "rtol"},
      {{"--r", "abc"}, "--r"},
      {{"--bogus"}, "--bogus"},
      {{"--bogus=3"}, "--bogus"},
      {{"--output-interval", "-1"}, "output-interval"},
      {{"--r", "0.5", "--ic", "ic1", "--w0", "0.6"}, "w0"},
      {{"--r", "0.5", "--ic", "custom", "--w0", "0.6"}, "|w|"},
      {{"--ic", "custom", "--y0", "-0.6"}, "corners"},
      {{"--ic", "custom", "--w0", "nan"}, "w0"},
      {{"--ic", "ic9"}, "--ic"},
      {{"--method", "rk4"}, "--method"},
      {{"bad_method.toml"}, "run.method"},
      {{"unknown_key.toml"}, "muu"},
      {{"unknown_table.toml"}, "blok"},
      {{"not_a_number.toml"}, "run.t_end"},
      {{"nan.toml"}, "t_end"},
      {{"neg_k.toml"}, "k ="},
      {{"missing.toml"}, "missing.toml"},
  };
  const auto before = files();
  for (const Case& c : cases) {
    std::vector<std::string> args = c.args;
    for (const char* a : {"--trajectory", "traj.csv", "--json-out", "out.json"}) args.push_back(a);
    const CliRun r = simulate(args);
    std::string desc;
    for (const auto& a : c.args) desc += a + " ";
    EXPECT_NE(r.code, 0) << desc;
    EXPECT_TRUE(r.out.empty()) << desc << ": " << r.out;
    // Exactly one line, starting with "error:", naming the offending field.
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << desc << ": " << r.err;
    ASSERT_FALSE(r.err.empty()) << desc;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << desc << ": " << r.err;
    EXPECT_NE(r.err.find(c.field), std::string::npos) << desc << ": " << r.err;
    // Nothing written, no temporary left behind.
    EXPECT_EQ(files(), before) << desc;
  }
}

TEST_F(CliSimulate, BothRungeKuttaPairsGiveTheSameEventsAndRecordWhichRan) {
  // ic2 on a soft foundation with slides, lift-offs and landings (318 events in 10 time units):
  // both pairs at rtol 1e-11 give the event sequence of a dop853 reference at rtol 1e-13, at
  // times whose deviation grows with t (measured: dopri5 up to 8e-8, dop853 up to 3e-8 by t = 10);
  // the JSON says which pair ran (auto picks dop853 below rtol 1e-6); dop853 takes far fewer steps.
  auto run = [&](const std::string& method, const std::string& rtol) {
    const CliRun r = simulate({"--r", "0.5", "--k", "1e4", "--mu", "0.2", "--ic", "ic2", "--t-end", "10", "--rtol",
                               rtol, "--method", method, "--json", "--quiet"});
    EXPECT_EQ(r.code, 0) << r.err;
    return json::parse(r.out);
  };
  const json a = run("dopri5", "1e-11"), b = run("dop853", "1e-11"), c = run("auto", "1e-11");
  const json ref = run("dop853", "1e-13");
  EXPECT_EQ(a["tolerances"]["method"], "dopri5");
  EXPECT_EQ(b["tolerances"]["method"], "dop853");
  EXPECT_EQ(c["tolerances"]["method"], "dop853");
  EXPECT_EQ(b["events"], c["events"]);
  ASSERT_GT(ref["events"].size(), 300u);
  double dev_a = 0, dev_b = 0;
  for (const json* x : {&a, &b}) {
    ASSERT_EQ((*x)["events"].size(), ref["events"].size());
    for (std::size_t i = 0; i < ref["events"].size(); ++i) {
      EXPECT_EQ((*x)["events"][i]["kind"], ref["events"][i]["kind"]) << i;
      const double d = std::fabs((*x)["events"][i]["t"].get<double>() - ref["events"][i]["t"].get<double>());
      (x == &a ? dev_a : dev_b) = std::fmax(x == &a ? dev_a : dev_b, d);
    }
  }
  EXPECT_LT(dev_a, 2e-7);
  EXPECT_LT(dev_b, 1e-7);
  EXPECT_LT(dev_b, dev_a);
  EXPECT_LT(3 * b["steps"].get<long>(), a["steps"].get<long>());
}

TEST_F(CliSimulate, JsonOnlyWhenAskedReproducibleAndTimedOnRequest) {
  // The JSON summary (events streamed through a temporary file) is the same text on every run
  // and for --json and --json-out; --timing adds the integration's wall and CPU time, and
  // nothing else changes; the text summary counts the events the JSON lists.
  for (const char* model : {"winkler", "housner"}) {
    SCOPED_TRACE(model);
    std::vector<std::string> args =
        std::string(model) == "winkler"
            ? std::vector<std::string>{"--r", "0.5", "--k", "1e4", "--t-end", "3"}
            : std::vector<std::string>{"--model", "housner", "--width", "0.3",     "--height",
                                       "1.2",     "--w0",    "0.1",     "--t-end", "3"};
    auto with = [&](std::vector<std::string> extra) {
      std::vector<std::string> a = args;
      a.insert(a.end(), extra.begin(), extra.end());
      const CliRun r = simulate(a);
      EXPECT_EQ(r.code, 0) << r.err;
      return r;
    };
    const CliRun a = with({"--json", "--json-out", (dir / "s.json").string()});
    const CliRun b = with({"--json"});
    EXPECT_EQ(a.out, b.out);
    EXPECT_EQ(slurp(dir / "s.json"), a.out);
    const json j = json::parse(a.out);
    EXPECT_FALSE(j.contains("timing"));
    ASSERT_FALSE(j["events"].empty());
    json t = json::parse(with({"--json", "--timing"}).out);
    ASSERT_TRUE(t.contains("timing"));
    EXPECT_GE(t["timing"]["integration_cpu_s"].get<double>(), 0.0);
    EXPECT_GT(t["timing"]["integration_wall_s"].get<double>(), 0.0);
    t.erase("timing");
    EXPECT_EQ(t, j);
    if (std::string(model) == "winkler") {
      const CliRun text = with({});
      EXPECT_NE(text.out.find("events: " + std::to_string(j["events"].size()) + ","), std::string::npos) << text.out;
    }
  }
}
