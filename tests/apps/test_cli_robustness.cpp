// SPDX-License-Identifier: Apache-2.0
// Hostile input (issue 11): every case ends within seconds with exit status 2 and one `error:`
// line naming the field, and leaves no file behind; a bounded random generator of command lines
// and scenario files (fixed seed, a fixed budget in CI) never crashes, hangs or floods the disk.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <thread>

#include "test_sweep_util.hpp"

using namespace sweep_test;
namespace fs = std::filesystem;

namespace {

std::set<std::string> files_in(const std::string& dir) {
  std::set<std::string> s;
  for (const auto& e : fs::directory_iterator(dir)) s.insert(e.path().filename().string());
  return s;
}

// Runs with a time limit; the outputs of run_cli itself are not counted as left-behind files.
CliResult limited(const std::vector<std::string>& args, const std::string& dir, int seconds = 20) {
  return run_cli(args, dir, "timeout -s KILL " + std::to_string(seconds));
}

struct Case {
  std::vector<std::string> args;
  std::string field;  // must appear in the message
};

void expect_usage_error(const Case& c, const std::string& dir) {
  const auto before = files_in(dir);
  const auto t0 = std::chrono::steady_clock::now();
  const CliResult r = limited(c.args, dir);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::string line;
  for (const auto& a : c.args) line += a + " ";
  EXPECT_EQ(r.code, 2) << line << "\n" << r.err;
  EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << line << "\n" << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << line << "\n" << r.err;
  EXPECT_NE(r.err.find(c.field), std::string::npos) << line << "\nexpected '" << c.field << "' in: " << r.err;
  EXPECT_LT(secs, 10.0) << line;
  auto after = files_in(dir);
  after.erase("cli.out");
  after.erase("cli.err");
  EXPECT_TRUE(std::includes(before.begin(), before.end(), after.begin(), after.end())) << line << ": left a file";
}

// A command on the Housner block b = 0.3 m, h = 1.5 m: head, the model flags, tail.
std::vector<std::string> housner_cmd(std::vector<std::string> head, const std::vector<std::string>& tail) {
  for (const char* a : {"--model", "housner", "--width", "0.3", "--height", "1.5"}) head.emplace_back(a);
  head.insert(head.end(), tail.begin(), tail.end());
  return head;
}

}  // namespace

TEST(CliRobustness, HostileCommandLinesAreUsageErrors) {
  TmpDir d("hostile");
  fs::create_directory(d.path + "/adir");
  const std::vector<Case> cases = {
      {{"simulate", "--r", "1e15"}, "r = "},
      {{"simulate", "--r", "1e308"}, "r = "},
      {{"response", "--r", "1e308"}, "r = "},
      {{"poincare", "--r", "1e308"}, "r = "},
      {{"lyapunov", "--r", "1e308"}, "r = "},
      {{"energy-surface", "--r", "1e308"}, "r = "},
      {{"simulate", "--k", "1e30", "--t-end", "0.01"}, "k = "},
      {{"simulate", "--k", "4.9e-324"}, "k = "},
      {{"energy-surface", "--phase-dt", "1e-300"}, "phase-dt"},
      {{"lyapunov", "--interval", "1e-300"}, "interval"},
      {{"simulate", "--output-interval", "1e-300", "--trajectory", "t.csv"}, "output-interval"},
      {{"simulate", "--t-end", "1e308"}, "t-end"},
      {{"simulate", "--ground-h-amplitude", "1", "--ground-h-frequency", "1e9"}, "frequency"},
      {{"simulate", "--ground-h-amplitude", "1", "--ground-h-frequency", "1e300"}, "frequency"},
      {{"sweep", "--k", "1e3:1e4:1e300", "-o", "s.csv"}, "points"},
      {{"sweep", "--k", "1e3:1e4:100000000", "-o", "s.csv"}, "points"},
      {{"simulate", "/dev/zero"}, "/dev/zero"},
      {{"simulate", "adir"}, "adir"},
      {{"simulate", "--mu", ""}, "--mu"},
      {{"simulate", "--y0", ""}, "--y0"},
      {{"map", "--threads", "-1"}, "threads"},
      {{"map", "-o", ""}, "output"},
      {{"sweep", "-o", "adir", "--overwrite", "--k", "1e3"}, "adir"},
      {{"kmin", "--r-min", "1e-310"}, "r-min"},
      {{"blowup", "--r-min", "4.9e-324"}, "r-min"},
      {{"simulate", "--height", "1", "--mass", "2", "--line-stiffness", "1e6"}, "width is missing"},
      {{"simulate", "--trajectory", "adir"}, "adir"},
      {{"simulate", "--plot", "nodir/p.png"}, "nodir"},
      {{"simulate", "--no-such-option", "1"}, "no-such-option"},
  };
  for (const Case& c : cases) expect_usage_error(c, d.path);
}

TEST(CliRobustness, HostileScenariosAreUsageErrors) {
  TmpDir d("hostile-toml");
  const std::vector<std::pair<std::string, std::string>> files = {
      {"[run]\nmax_steps = 1.5\n", "run.max_steps"},
      {"[run]\nmax_steps = 1e300\n", "run.max_steps"},
      {"[run]\nevent_samples = -3\n", "run.event_samples"},
      {"[block]\nr = 0.2\n[physical]\nheight = 1\nwidth = 0.2\nmass = 1\nline_stiffness = 1e6\n", "block"},
      {"[physical]\nheight = 1\nwidth = 0.2\nmass = 1\ndensity = 2000\nthickness = 0.1\nline_stiffness = 1e6\n",
       "mass and density"},
      {"[physical]\nheight = 1\nmass = 1\nline_stiffness = 1e6\n", "width is missing"},
      {"[block]\nr = \"x\"\n", "block.r"},
      {"[run]\nt_end = 10\noutput_interval = 1e-300\n[output]\ntrajectory = \"t.csv\"\n", "output-interval"},
      {"model = \"rigid\"\n[physical]\nwidth = 0.3\nheight = 1\n[interface]\nmu_s = 0.2\nmu_k = 0.5\n", "mu-k"},
      {"[block\nr = 0.2\n", "s.toml"},
  };
  for (const auto& [text, field] : files) {
    std::ofstream(d.path + "/s.toml") << text;
    expect_usage_error({{"simulate", "s.toml"}, field}, d.path);
    fs::remove(d.path + "/s.toml");
  }
}

TEST(CliRobustness, CorruptJournalRowIsRefused) {
  TmpDir d("journal");
  const std::vector<std::string> args = {"sweep",   "--k", "1e3:1e4:3", "--r",   "0.3",
                                         "--t-end", "2",   "-o",        "s.csv", "--quiet"};
  ASSERT_EQ(run_cli(args, d.path).code, 0);
  // Rebuild a journal from the finished CSV, with a garbage row appended.
  const std::string csv = slurp(d.path + "/s.csv");
  const std::string side = slurp(d.path + "/s.json");
  const auto fp_at = side.find("\"fingerprint\": \"") + 16;
  const std::string fp = side.substr(fp_at, 16);
  std::ofstream(d.path + "/s.csv.journal") << "# blockdyn sweep journal v2 fingerprint=" << fp << " points=3\n"
                                           << csv.substr(0, csv.find('\n') + 1) << "2,garbage\n";
  fs::remove(d.path + "/s.csv");
  auto resumed = args;
  resumed.push_back("--resume");
  const CliResult r = run_cli(resumed, d.path);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("corrupt"), std::string::npos) << r.err;
  EXPECT_FALSE(exists(d.path + "/s.csv"));
}

// SIGTERM while the trajectory is being written: the temporary file is removed.
TEST(CliRobustness, InterruptedRunLeavesNoTemporaryFile) {
  TmpDir d("sigterm");
  const pid_t pid = spawn_cli(
      {"simulate", "--r", "0.2", "--k", "1e8", "--t-end", "2000", "--output-interval", "0", "--trajectory", "t.csv"},
      d.path);
  ASSERT_GT(pid, 0);
  bool temp_seen = false;
  for (int i = 0; i < 2000 && !temp_seen; ++i) {
    for (const auto& f : files_in(d.path)) temp_seen |= f.rfind("t.csv.tmp.", 0) == 0;
    if (!temp_seen) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_TRUE(temp_seen);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ASSERT_EQ(::kill(pid, SIGTERM), 0);
  int st = 0;
  ASSERT_EQ(::waitpid(pid, &st, 0), pid);
  EXPECT_TRUE(WIFSIGNALED(st) && WTERMSIG(st) == SIGTERM);
  for (const auto& f : files_in(d.path)) EXPECT_EQ(f.find(".tmp."), std::string::npos) << f;
  EXPECT_FALSE(exists(d.path + "/t.csv"));
}

namespace {

// Hostile option values: empty, non-numbers, infinities, denormals, huge, paths, format strings.
const std::vector<std::string>& hostile_values() {
  static const std::vector<std::string> v = {"",
                                             "nan",
                                             "inf",
                                             "-inf",
                                             "-1",
                                             "0",
                                             "1e308",
                                             "-1e308",
                                             "1e-310",
                                             "4.9e-324",
                                             "1e300",
                                             "abc",
                                             "1e3:1e4:5",
                                             "0.2",
                                             "1",
                                             "2",
                                             "0.5",
                                             "-0.3",
                                             "1e9",
                                             "1,2,3",
                                             "1e3:1e4:1e300",
                                             "..",
                                             "/dev/zero",
                                             "/",
                                             "%s%n",
                                             "9999999999999999999"};
  return v;
}

// The options of `simulate` the random command lines draw from.
const std::vector<std::string>& drawn_options() {
  static const std::vector<std::string> v = {"--r",
                                             "--mu",
                                             "--k",
                                             "--w0",
                                             "--vw0",
                                             "--x0",
                                             "--y0",
                                             "--vx0",
                                             "--vy0",
                                             "--rtol",
                                             "--atol",
                                             "--ic",
                                             "--ground-h",
                                             "--ground-h-amplitude",
                                             "--ground-h-frequency",
                                             "--ground-h-phase",
                                             "--ground-h-duration",
                                             "--ground-h-pulse",
                                             "--ground-h-start",
                                             "--ground-v",
                                             "--width",
                                             "--height",
                                             "--mass",
                                             "--mu-s",
                                             "--mu-k",
                                             "--restitution",
                                             "--impact",
                                             "--model",
                                             "--output-interval",
                                             "--units",
                                             "--density",
                                             "--thickness"};
  return v;
}

}  // namespace

// A bounded random generator (fixed seed): command lines from the options of `simulate` and
// `sweep` with hostile values, and scenario files mutated from a valid one. Every run ends by
// itself within the time limit, exits 0, 1 or 2 (never a signal), a usage error is one line, and
// nothing is left in the directory but what was asked for.
TEST(CliRobustness, RandomHostileInputNeverCrashesOrHangs) {
  TmpDir d("fuzz");
  std::mt19937_64 rng(20261123);
  const std::vector<std::string>& values = hostile_values();
  const std::vector<std::string>& opts = drawn_options();
  const auto t0 = std::chrono::steady_clock::now();
  int runs = 0;
  for (int i = 0; i < 120; ++i) {
    std::vector<std::string> args = {"simulate", "--t-end", (rng() % 2) ? "0.5" : "3"};
    const int n = 1 + int(rng() % 5);
    for (int j = 0; j < n; ++j) {
      args.push_back(opts[rng() % opts.size()]);
      args.push_back(values[rng() % values.size()]);
    }
    if (rng() % 4 == 0) {
      args.push_back("--model");
      args.push_back((rng() % 2) ? "rigid" : "housner");
    }
    const CliResult r = limited(args, d.path, 30);
    ++runs;
    std::string line;
    for (const auto& a : args) line += "'" + a + "' ";
    ASSERT_TRUE(r.code == 0 || r.code == 1 || r.code == 2) << line << " exit " << r.code << "\n" << r.err;
    if (r.code == 2) {
      EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << line << "\n" << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << line << "\n" << r.err;
    }
  }
  const std::string valid =
      "[block]\nr = 0.2\nmu = 0.3\nk = 1e5\n[initial]\nset = \"ic1\"\n[run]\nt_end = 1.0\nmax_steps = 100000\n"
      "[ground.horizontal]\namplitude = 0.1\nfrequency = 0.5\n";
  for (int i = 0; i < 60; ++i) {
    std::string text = valid;
    const int kind = int(rng() % 4);
    if (kind == 0) {
      text = text.substr(0, rng() % text.size());  // truncated
    } else if (kind == 1) {                        // a value replaced by a hostile one
      const auto eq = text.find(" = ", rng() % text.size());
      if (eq != std::string::npos) {
        const auto nl = text.find('\n', eq);
        text = text.substr(0, eq + 3) + "\"" + values[rng() % values.size()] + "\"" + text.substr(nl);
      }
    } else if (kind == 2) {
      text.insert(rng() % text.size(), std::string(1, char(rng() % 128)));  // a stray character
    } else {
      text += "[extra]\nkey = " + values[rng() % values.size()] + "\n";
    }
    std::ofstream(d.path + "/f.toml") << text;
    const CliResult r = limited({"simulate", "f.toml"}, d.path, 30);
    ++runs;
    ASSERT_TRUE(r.code == 0 || r.code == 1 || r.code == 2) << text << " exit " << r.code << "\n" << r.err;
    if (r.code == 2) {
      EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << text << "\n" << r.err;
    }
  }
  auto left = files_in(d.path);
  for (const char* f : {"cli.out", "cli.err", "f.toml"}) left.erase(f);
  EXPECT_TRUE(left.empty()) << *left.begin();
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ::testing::Test::RecordProperty("fuzz_runs", runs);
  ::testing::Test::RecordProperty("fuzz_seconds", std::to_string(secs));
}

// Issue 25 item 5: records with a sample spacing no instrument has (the step loop never ended),
// a FIFO given as a record (the read blocked), a Housner block whose default restitution is
// negative, an assembly of grains: usage errors within seconds, naming the field.
TEST(CliRobustness, RecordsAndBlocksOutsideTheirRangeAreUsageErrors) {
  TmpDir d("issue25");
  std::ofstream(d.path + "/tiny.AT2") << "T\nD\nU\nNPTS= 2, DT= 1e-200\n0.5 0.5\n";
  std::ofstream(d.path + "/tiny.csv") << "t,a\n0,0.5\n1e-300,0.5\n2e-300,0.5\n";
  ASSERT_EQ(::mkfifo((d.path + "/fifo.AT2").c_str(), 0600), 0);
  const std::vector<Case> cases = {
      {housner_cmd({"simulate"}, {"--ground-h-record", "tiny.AT2"}), "DT = 1e-200"},
      {housner_cmd({"simulate"}, {"--ground-h-record", "tiny.csv"}), "time step"},
      {housner_cmd({"lyapunov"}, {"--ground-h-record", "tiny.AT2"}), "DT = 1e-200"},
      {housner_cmd({"simulate"}, {"--ground-h-record", "fifo.AT2"}), "not a regular file"},
      {{"simulate", "--model", "housner", "--width", "1.6", "--height", "1", "--w0", "0.1"}, "restitution"},
      {{"cycles", "--model", "housner", "--width", "1.6", "--height", "1", "--beta", "2", "--omega", "5"},
       "restitution"},
      {{"assembly", "--preset", "trilith", "--block-width", "1e-5", "--t-end", "0.01"}, "block-width"},
      {{"assembly", "--preset", "trilith", "--block-width", "2.4e-6", "--t-end", "0.01"}, "block-width"},
  };
  for (const Case& c : cases) expect_usage_error(c, d.path);
  // The message names the ways out.
  const CliResult r = run_cli({"simulate", "--model", "housner", "--width", "1.6", "--height", "1"}, d.path);
  EXPECT_NE(r.err.find("--restitution"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--model rigid"), std::string::npos) << r.err;
  // At b/h = sqrt(2) exactly Housner's coefficient is 0: a plastic impact, allowed.
  EXPECT_EQ(
      run_cli({"simulate", "--model", "housner", "--width", "1.41", "--height", "1", "--w0", "0.1", "--t-end", "1"},
              d.path)
          .code,
      0);
}

// Issue 26 item 10 (first part): an output path that exists and is not a regular file is written
// into, never replaced by a regular file (a symlink to /dev/null stays one, /dev/null stays a
// device; a FIFO's reader receives the JSON); flags of another family are refused, not ignored;
// a negative or NaN --mu-k / --restitution is an error, not "not given".
TEST(CliRobustness, NonRegularOutputsAreWrittenIntoAndForeignFlagsRefused) {
  TmpDir d("nonregular");
  fs::create_symlink("/dev/null", d.path + "/null.json");
  const CliResult r = run_cli({"assembly", "--preset", "block", "--t-end", "0.05", "--json-out", "null.json"}, d.path);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(d.path + "/null.json"));
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  ASSERT_EQ(::mkfifo((d.path + "/pipe.json").c_str(), 0600), 0);
  const std::string cmd = "cd " + d.path + " && (cat pipe.json > got.json &) && " + BLOCKDYN_CLI +
                          " simulate --model housner --width 0.3 --height 1.5 --w0 0.1 --t-end 0.5 --json-out "
                          "pipe.json >/dev/null 2>&1; sleep 0.2";
  EXPECT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_TRUE(fs::is_fifo(d.path + "/pipe.json"));
  EXPECT_NE(sweep_test::slurp(d.path + "/got.json").find("\"model\": \"housner\""), std::string::npos);
  const std::vector<std::string> rigid = {"--model", "rigid",  "--width", "0.3",     "--height",
                                          "1.5",     "--beta", "2",       "--omega", "5"};
  auto cycles = [&](std::vector<std::string> tail) {
    std::vector<std::string> a = {"cycles"};
    a.insert(a.end(), tail.begin(), tail.end());
    return a;
  };
  auto rigid_with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = rigid;
    a.insert(a.end(), extra.begin(), extra.end());
    return cycles(a);
  };
  const std::vector<Case> cases = {
      {cycles({"--model", "assembly", "--preset", "block", "--beta", "2", "--omega", "5", "--g", "nan"}), "--g"},
      {cycles({"--model", "assembly", "--preset", "block", "--beta", "2", "--omega", "5", "--mu-s", "0.3"}), "--mu-s"},
      {cycles({"--model", "housner", "--width", "0.3", "--height", "1.5", "--preset", "block", "--beta", "2", "--omega",
               "5"}),
       "--preset"},
      {rigid_with({"--mu-k", "-1"}), "mu-k"},
      {rigid_with({"--mu-k", "nan"}), "mu-k"},
      {rigid_with({"--restitution", "-0.5"}), "restitution"},
      {rigid_with({"--restitution", "nan"}), "restitution"},
  };
  for (const Case& c : cases) expect_usage_error(c, d.path);
}

// Issue 26 item 10: every output checked before the run (a figure format matplotlib cannot write,
// two outputs on one file) and a derived run length of 0: exit 2, no file left behind.
TEST(CliRobustness, OutputsAreCheckedBeforeTheRun) {
  TmpDir d("outputs");
  const std::vector<Case> cases = {
      {housner_cmd({"cycles"}, {"--beta", "2", "--omega", "5", "--out", "same.csv", "--trace", "same.csv"}),
       "same.csv"},
      {housner_cmd({"impact-map"}, {"--beta", "2", "--omega", "5", "--out", "x.csv", "--json-out", "x.csv"}), "x.csv"},
      {housner_cmd({"impact-map"}, {"--beta", "2", "--omega", "5", "--out", "x.csv", "--json-out", "./x.csv"}),
       "x.csv"},
      {housner_cmd({"simulate"}, {"--w0", "0.1", "--t-end", "1", "--trajectory", "t.csv", "--plot", "F.gif"}), "F.gif"},
      {housner_cmd({"simulate"}, {"--w0", "0.1", "--t-end", "1", "--trajectory", "t.csv", "--plot", "F.txt"}), "F.txt"},
      {housner_cmd({"simulate"}, {"--w0", "0.1", "--t-end", "1", "--animate", "F.png"}), "F.png"},
      {housner_cmd({"survival"},
                   {"--beta-points", "2", "--omega-points", "2", "--periods", "4.9e-324", "--out", "s.csv"}),
       "periods"},
      {housner_cmd({"survival"}, {"--beta-points", "2", "--omega-points", "2", "--periods", "1e5", "--omega-min",
                                  "1e-3", "--out", "s.csv"}),
       "periods"},
  };
  for (const Case& c : cases) expect_usage_error(c, d.path);
}

// An output in a directory that does not exist is refused before any run, for every command
// (checked once for all of them).
TEST(CliRobustness, OutputDirectoriesAreCheckedBeforeTheRun) {
  TmpDir d("outdirs");
  const std::vector<Case> cases = {
      {housner_cmd({"cycles"}, {"--beta", "2", "--omega", "5", "--out", "nodir/c.csv"}), "nodir"},
      {housner_cmd({"impact-map"}, {"--beta", "2", "--omega", "5", "--json-out", "nodir/i.json"}), "nodir"},
      {housner_cmd({"survival"}, {"--beta-points", "2", "--omega-points", "2", "--plot", "nodir/s.png"}), "nodir"},
      {{"assembly", "--preset", "block", "--t-end", "0.05", "--animate", "nodir/a.gif"}, "nodir"},
  };
  for (const Case& c : cases) expect_usage_error(c, d.path);
}

// Issue 37 item 5: an error names the value given (not a value derived from it, not a rounding
// of it), and the option the user can change.
TEST(CliRobustness, MessagesNameTheValueGiven) {
  TmpDir d("messages");
  const std::string rec = std::string(BLOCKDYN_SOURCE_DIR) + "/tests/fixtures/synthetic_60s.AT2";
  std::ofstream(d.path + "/poly.toml") << "[[block]]\nvertices = [[0,0],[0.3,0],[0.3,1],[0,1]]\nmass = -5\n"
                                          "[[interface]]\nlower = \"ground\"\nupper = 0\n";
  std::ofstream(d.path + "/dens.toml") << "[[block]]\nwidth = 0.3\nheight = 1\ndensity = -5\nthickness = 0.2\n"
                                          "y = 0.5\n[[interface]]\nlower = \"ground\"\nupper = 0\n";
  std::ofstream(d.path + "/huge.AT2") << "T\nD\nU\nNPTS= 2, DT= 1e300\n0.5 0.5\n";
  const std::vector<Case> cases = {
      {{"assembly", "poly.toml"}, "block[0].mass = -5 is out of range"},
      {{"assembly", "dens.toml"}, "block[0].density = -5 is out of range"},
      {{"rocking-spectrum", "--record", rec, "--alpha", "0.2", "--p-values", "1", "--g", "0"}, "g = 0 is out of range"},
      {{"limit-analysis", "--preset", "arch", "--voussoirs", "1"}, "voussoirs = 1 over embrace = 180 degrees"},
      {{"limit-analysis", "--preset", "arch", "--radius", "1000", "--thickness-ratio", "1.9"},
       "radius = 1000 m, thickness-ratio = 1.9 and voussoirs = 9 make voussoirs 1903.02 m across"},
      {{"limit-analysis", "--preset", "arch", "--voussoirs", "3000000000"}, "voussoirs = 3000000000"},
      {housner_cmd({"simulate"}, {"--ground-h-record", "huge.AT2"}), "DT = 1e+300 is out of range"},
      {{"nonexistent"}, "'nonexistent' is not a blockdyn command"},
  };
  for (const Case& c : cases) expect_usage_error(c, d.path);
  const auto r =
      run_cli({"limit-analysis", "--preset", "arch", "--radius", "1000", "--thickness-ratio", "1.9"}, d.path);
  EXPECT_EQ(r.err.find("grains"), std::string::npos) << r.err;
}
