// SPDX-License-Identifier: Apache-2.0
// `blockdyn sweep` end to end: incremental output, kill + resume, MPI, bad definitions, plots.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

#include "test_sweep_util.hpp"

using namespace sweep_test;

namespace {

// 72 points of 0.01 - 0.1 s each: long enough to watch and interrupt, short enough for a test.
std::vector<std::string> long_sweep(const std::string& out, const std::string& threads) {
  return {"sweep",   "--k", "1e3:2e5:24",  "--inv-r", "2,3,4", "--mu", "0.3",       "--ic", "ic2",
          "--t-end", "20",  "--max-steps", "2000000", "-o",    out,    "--threads", threads};
}

std::vector<std::string> sweep_with(std::vector<std::string> a, const std::vector<std::string>& more) {
  a.insert(a.end(), more.begin(), more.end());
  return a;
}

std::size_t journal_rows(const std::string& path) {
  const std::size_t n = count_lines(slurp(path));
  return n >= 2 ? n - 2 : 0;  // identification line and header
}

struct Watch {
  std::size_t rows_while_running = 0;  // rows seen in the journal while the run was alive
  bool csv_absent_then = false;
  bool reaped = false;  // the process ended (and was reaped) before enough rows appeared
  int status = 0;
};

// Polls the journal of a spawned sweep until it holds `min_rows` rows while the process lives.
Watch watch_journal(pid_t pid, const std::string& journal, const std::string& csv, std::size_t min_rows) {
  Watch w;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (std::chrono::steady_clock::now() < deadline) {
    const std::size_t rows = journal_rows(journal);
    const bool csv_absent = !exists(csv);
    if (::waitpid(pid, &w.status, WNOHANG) != 0) {
      w.reaped = true;
      break;
    }
    if (rows >= min_rows) {
      w.rows_while_running = rows;
      w.csv_absent_then = csv_absent;
      return w;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return w;
}

// Starts a sweep and SIGKILLs it once a few rows are in its journal.
void start_and_kill(const std::vector<std::string>& args, const std::string& dir, const std::string& csv) {
  const pid_t pid = spawn_cli(args, dir);
  ASSERT_GT(pid, 0);
  const Watch w = watch_journal(pid, dir + "/" + csv + ".journal", dir + "/" + csv, 3);
  int st = w.status;
  if (!w.reaped) {
    ASSERT_EQ(::kill(pid, SIGKILL), 0);
    ASSERT_EQ(::waitpid(pid, &st, 0), pid);
  }
  ASSERT_GE(w.rows_while_running, 3u) << "the sweep finished or failed before it could be interrupted: "
                                      << slurp(dir + "/spawn.err");
  ASSERT_TRUE(WIFSIGNALED(st));
  EXPECT_FALSE(exists(dir + "/" + csv));
  EXPECT_LT(journal_rows(dir + "/" + csv + ".journal"), 72u);
}

}  // namespace

// Two ranks as root on a 2-core machine.
const std::string kMpirun2 =
    "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 "
    "mpirun -np 2 --oversubscribe --allow-run-as-root";

TEST(SweepCli, RowsAppearBeforeTheEnd) {
  const sweep_test::TmpDir tmp("sweep-incr");
  const std::string& dir = tmp.path;
  const pid_t pid = spawn_cli(sweep_with(long_sweep("s.csv", "1"), {"--progress", "plain"}), dir);
  const Watch w = watch_journal(pid, dir + "/s.csv.journal", dir + "/s.csv", 2);
  int st = w.status;
  if (!w.reaped) {
    ASSERT_EQ(::waitpid(pid, &st, 0), pid);
  }
  ASSERT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 0) << slurp(dir + "/spawn.err");
  EXPECT_GE(w.rows_while_running, 2u);
  EXPECT_TRUE(w.csv_absent_then);
  EXPECT_EQ(count_lines(slurp(dir + "/s.csv")), 73u);
  EXPECT_FALSE(exists(dir + "/s.csv.journal"));
  // Plain progress lines when stderr is not a terminal.
  const std::string err = slurp(dir + "/spawn.err");
  EXPECT_NE(err.find("sweep: 72 points, 0 already done"), std::string::npos) << err;
  EXPECT_NE(err.find("sweep: 72/72 (100.0%)"), std::string::npos) << err;
}

TEST(SweepCli, KilledSweepResumesToIdenticalBytes) {
  const sweep_test::TmpDir tmp("sweep-kill");
  const std::string& dir = tmp.path;
  const CliResult ref = run_cli(sweep_with(long_sweep("ref.csv", "2"), {"--quiet"}), dir);
  ASSERT_EQ(ref.code, 0) << ref.err;
  start_and_kill(long_sweep("s.csv", "1"), dir, "s.csv");
  if (HasFatalFailure()) return;
  const std::size_t kept = journal_rows(dir + "/s.csv.journal");
  // Without --resume the unfinished journal is protected.
  const CliResult refused = run_cli(long_sweep("s.csv", "2"), dir);
  EXPECT_EQ(refused.code, 2);
  EXPECT_NE(refused.err.find("--resume"), std::string::npos) << refused.err;
  const CliResult res = run_cli(sweep_with(long_sweep("s.csv", "2"), {"--resume", "--progress", "none"}), dir);
  ASSERT_EQ(res.code, 0) << res.err;
  EXPECT_NE(res.out.find("(" + std::to_string(72 - kept) + " computed, " + std::to_string(kept) + " resumed"),
            std::string::npos)
      << res.out;
  EXPECT_EQ(slurp(dir + "/s.csv"), slurp(dir + "/ref.csv"));
  EXPECT_FALSE(exists(dir + "/s.csv.journal"));
}

TEST(SweepCli, MpiTwoRanksMatchOneProcessAndResume) {
  if (std::system("command -v mpirun >/dev/null 2>&1") != 0) GTEST_SKIP() << "mpirun not found";
  const std::string mpirun = kMpirun2;
  const sweep_test::TmpDir tmp("sweep-mpi");
  const std::string& dir = tmp.path;
  const CliResult one = run_cli(sweep_with(long_sweep("one.csv", "1"), {"--quiet"}), dir);
  ASSERT_EQ(one.code, 0) << one.err;
  const CliResult two = run_cli(sweep_with(long_sweep("two.csv", "1"), {"--progress", "none"}), dir, mpirun);
  if (two.err.find("built without MPI") != std::string::npos) GTEST_SKIP() << "CLI built without MPI";
  ASSERT_EQ(two.code, 0) << two.err;
  EXPECT_EQ(slurp(dir + "/two.csv"), slurp(dir + "/one.csv"));
  EXPECT_NE(slurp(dir + "/two.json").find("\"mpi_ranks\": 2"), std::string::npos);
  EXPECT_NE(two.out.find("2 rank(s)"), std::string::npos) << two.out;
  // Interrupted single-process sweep resumed under MPI.
  start_and_kill(long_sweep("r.csv", "1"), dir, "r.csv");
  if (HasFatalFailure()) return;
  const CliResult res = run_cli(sweep_with(long_sweep("r.csv", "1"), {"--resume", "--quiet"}), dir, mpirun);
  ASSERT_EQ(res.code, 0) << res.err;
  EXPECT_EQ(slurp(dir + "/r.csv"), slurp(dir + "/one.csv"));
}

TEST(SweepCli, BadDefinitionsExitWithStatus2) {
  const sweep_test::TmpDir tmp("sweep-bad");
  const std::string& dir = tmp.path;
  struct Case {
    std::string toml;  // written to bad.toml if non-empty
    std::vector<std::string> flags;
    std::string expect;
  };
  const std::vector<Case> cases = {
      {"[axes]\nk = 1e5\nstiffness = 3\n", {}, "axes.stiffness: unknown key"},
      {"[axes]\nk = { min = 1e2, max = 1e8, points = 0 }\n", {}, "axes.k: points = 0 is out of range"},
      {"[axes]\nr = 0.5\ninv_r = 2\n", {}, "axes: give either r or inv_r"},
      {"[initial]\nset = 'ic9'\n", {}, "initial.set = 'ic9' is not one of"},
      {"[run]\nstop_at_first_flight = 1\n", {}, "run.stop_at_first_flight: must be true or false"},
      {"[output]\nmetrics = ['nope']\n", {}, "metric 'nope' is unknown"},
      {"", {"--k", "1e2:1e8"}, "axes.k: '1e2:1e8' is not of the form"},
      {"", {"--inv-r", "0,2"}, "axes.inv_r: value 0 is out of range"},
      {"", {"--r", "0.5", "--inv-r", "2"}, "--r and --inv-r"},
      {"", {"--t-end", "-3"}, "t-end"},
      {"", {"--ic", "ic1", "--w0-over-alpha", "1.5"}, "initial.w0_over_alpha is out of range"},
      {"", {"--k", "1e5", "--plot", "p.png", "--plot-column", "nonsense"}, "plot-column = 'nonsense'"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = {"sweep"};
    if (!c.toml.empty()) {
      std::ofstream(dir + "/bad.toml") << c.toml;
      args.push_back("bad.toml");
    }
    args.insert(args.end(), c.flags.begin(), c.flags.end());
    args.insert(args.end(), {"-o", "bad.csv", "--quiet"});
    const CliResult r = run_cli(args, dir);
    EXPECT_EQ(r.code, 2) << c.expect << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << "expected '" << c.expect << "' in: " << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    EXPECT_FALSE(exists(dir + "/bad.csv.journal"));
  }
}

TEST(SweepCli, TomlDefinitionDryRunAndPlots) {
  const sweep_test::TmpDir tmp("sweep-toml");
  const std::string& dir = tmp.path;
  std::ofstream(dir + "/map.toml") << "[axes]\nk = '1e2:1e5:4'\ninv_r = [2, 5]\nmu = 0.2\n"
                                      "[initial]\nset = 'ic2'\n[run]\nt_end = 4\n"
                                      "[output]\ncsv = 'map.csv'\nmetrics = ['event_counts']\n";
  const CliResult dry = run_cli({"sweep", "map.toml", "--dry-run"}, dir);
  ASSERT_EQ(dry.code, 0) << dry.err;
  EXPECT_NE(dry.out.find("\"point_count\": 8"), std::string::npos) << dry.out;
  EXPECT_NE(dry.out.find("\"n_takeoff\""), std::string::npos);
  EXPECT_FALSE(exists(dir + "/map.csv"));
  const CliResult list = run_cli({"sweep", "--list-metrics"}, dir);
  EXPECT_EQ(list.code, 0);
  EXPECT_NE(list.out.find("regime_time"), std::string::npos);

  const bool mpl = std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0;
  std::vector<std::string> args = {"sweep", "map.toml", "--quiet", "--threads", "2"};
  if (mpl) args.insert(args.end(), {"--plot", "map.png"});
  const CliResult run = run_cli(args, dir);
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(count_lines(slurp(dir + "/map.csv")), 9u);
  EXPECT_NE(slurp(dir + "/map.json").find("\"fingerprint\""), std::string::npos);
  if (!mpl) GTEST_SKIP() << "matplotlib not available for /usr/bin/python3: plots not tested";
  EXPECT_TRUE(exists(dir + "/map.png"));
  EXPECT_TRUE(exists(dir + "/map.svg"));
  // 1-D plot (a fresh run: --resume without earlier output just starts).
  const CliResult line = run_cli({"sweep", "map.toml", "--resume", "--inv-r", "2", "-o", "line.csv", "--plot",
                                  "line.png", "--plot-column", "ihor_final"},
                                 dir);
  ASSERT_EQ(line.code, 0) << line.err;
  EXPECT_TRUE(exists(dir + "/line.png"));
  EXPECT_TRUE(exists(dir + "/line.svg"));
  // A finished sweep is not recomputed by --resume; a text column gives a categorical map.
  const CliResult again =
      run_cli({"sweep", "map.toml", "--resume", "--plot", "status.png", "--plot-column", "status"}, dir);
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_NE(again.out.find("already complete"), std::string::npos) << again.out;
  EXPECT_TRUE(exists(dir + "/status.png"));
}

// Issue 25 item 4: under more than one rank every command either distributes its points (map:
// the CSV byte-identical to one process, each point computed once) or refuses with exit 2 naming
// MPI; none runs every point on every rank.
TEST(SweepCli, MpiEveryCommandDistributesOrRefuses) {
  if (std::system("command -v mpirun >/dev/null 2>&1") != 0) GTEST_SKIP() << "mpirun not found";
  const std::string mpirun = kMpirun2;
  const sweep_test::TmpDir tmp("mpi-commands");
  const std::string& dir = tmp.path;
  const std::vector<std::string> map = {"map",   "--k",       "1e2:1e6:5", "--inv-r",
                                        "2:6:3", "--t-end",   "3",         "--boundary-points",
                                        "0",     "--threads", "1",         "--quiet"};
  const CliResult one = run_cli(sweep_with(map, {"-o", "one.csv"}), dir);
  ASSERT_EQ(one.code, 0) << one.err;
  const CliResult two = run_cli(sweep_with(map, {"-o", "two.csv"}), dir, mpirun);
  if (two.err.find("built without MPI") != std::string::npos) GTEST_SKIP() << "CLI built without MPI";
  ASSERT_EQ(two.code, 0) << two.err;
  EXPECT_EQ(slurp(dir + "/two.csv"), slurp(dir + "/one.csv"));
  const std::string side = slurp(dir + "/two.json");
  EXPECT_NE(side.find("\"mpi_ranks\": 2"), std::string::npos);
  EXPECT_NE(side.find("\"points_computed\": 15"), std::string::npos) << side;
  // Every subcommand listed by --help: the distributing ones run (their --help), the others refuse.
  const CliResult help = run_cli({"--help"}, dir);
  const auto at = help.out.find("Subcommands:");
  ASSERT_NE(at, std::string::npos) << help.out;
  std::istringstream lines(help.out.substr(at));
  std::string line;
  const std::set<std::string> distribute = {
      "sweep", "map", "survival", "spectrum", "response-curve", "rocking-spectrum", "fragility"};
  int refused = 0, ran = 0;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string name;
    if (!(words >> name) || name == "Subcommands:") continue;
    const CliResult r = run_cli({name, "--help"}, dir, mpirun);
    if (distribute.count(name)) {
      EXPECT_EQ(r.code, 0) << name << ": " << r.err;
      ++ran;
    } else {
      EXPECT_EQ(r.code, 2) << name;
      EXPECT_NE(r.err.find("MPI"), std::string::npos) << name << ": " << r.err;
      ++refused;
    }
  }
  EXPECT_EQ(ran, 7);
  EXPECT_GT(refused, 15);
}
