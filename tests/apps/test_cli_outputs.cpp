// SPDX-License-Identifier: Apache-2.0
// Outputs never harm (issue 37 item 4): a runner's table streamed into a FIFO or a device is never
// read back to build the result; no output (nor the SVG, sidecar, journal or suite files it makes
// beside it) names an input or another output; a symbolic link given as an output is written
// through, not replaced.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "cli_test.hpp"

using sweep_test::spawn_cli;

namespace {

const std::string kRecord = std::string(BLOCKDYN_SOURCE_DIR) + "/tests/fixtures/synthetic_60s.AT2";

std::vector<std::string> housner(std::vector<std::string> head, const std::vector<std::string>& tail) {
  for (const char* a : {"--model", "housner", "--width", "0.3", "--height", "1.5"}) head.push_back(a);
  head.insert(head.end(), tail.begin(), tail.end());
  return head;
}

// Waits for pid up to `seconds`; its exit code, or -1 (then it is killed).
int wait_for(pid_t pid, double seconds) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  while (std::chrono::steady_clock::now() < until) {
    if (::waitpid(pid, &status, WNOHANG) == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(pid, SIGKILL);
  ::waitpid(pid, &status, 0);
  return -1;
}

}  // namespace

TEST(CliOutputs, RunnerTablesStreamIntoFifosAndDevices) {
  TmpDir d("outputs_fifo");
  ASSERT_EQ(::mkfifo((d.path + "/table").c_str(), 0600), 0);
  const std::vector<std::vector<std::string>> commands = {
      {"rocking-spectrum", "--record", kRecord, "--alpha", "0.2", "--p-values", "1,2", "--out", "table", "--overwrite",
       "--json-out", "summary.json", "--plot", "fig.png"},
      {"spectrum", "--model", "housner", "--width", "0.3", "--height", "1.5", "--durations", "0.5", "--scan-points",
       "4", "--csv", "table", "--overwrite", "--json-out", "summary.json"}};
  for (const auto& args : commands) {
    std::remove((d.path + "/summary.json").c_str());
    const pid_t pid = spawn_cli(args, d.path);
    std::string streamed;
    {
      std::ifstream fifo(d.path + "/table");  // blocks until the command opens it for writing
      std::stringstream ss;
      ss << fifo.rdbuf();
      streamed = ss.str();
    }
    ASSERT_EQ(wait_for(pid, 120), 0) << args[0] << ": " << slurp(d.path + "/spawn.err");
    EXPECT_EQ(streamed.rfind("index,", 0), 0u) << streamed;
    const json j = json::parse(slurp(d.path + "/summary.json"));
    EXPECT_FALSE(j.empty());
    EXPECT_FALSE(exists(d.path + "/table.json")) << "a sidecar beside a FIFO";
  }
  EXPECT_TRUE(exists(d.path + "/fig.png"));
  // A device: the whole run, its summary from memory, nothing written beside it.
  const auto r = run_cli({"rocking-spectrum", "--record", kRecord, "--alpha", "0.2", "--p-values", "1", "--out",
                          "/dev/null", "--overwrite", "--json"},
                         d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(json::parse(r.out)["rows"].size(), 1u);
  EXPECT_FALSE(exists("/dev/null.json"));
}

TEST(CliOutputs, NoOutputNamesAnInputOrAnotherOutputsFile) {
  TmpDir d("outputs_collide");
  std::ifstream src(kRecord, std::ios::binary);
  std::ofstream(d.path + "/R.AT2", std::ios::binary) << src.rdbuf();
  std::filesystem::create_directories(d.path + "/suite");
  std::filesystem::copy_file(d.path + "/R.AT2", d.path + "/suite/a.AT2");
  std::filesystem::create_directories(d.path + "/D");
  std::ofstream(d.path + "/scenario.toml") << "model = \"housner\"\n[physical]\nwidth = 0.3\nheight = 1.5\n"
                                              "[ground.horizontal]\nrecord = \"R.AT2\"\n[run]\nt_end = 0.5\n";
  std::ofstream(d.path + "/scenario_out.toml") << "model = \"housner\"\n[physical]\nwidth = 0.3\nheight = 1.5\n"
                                                  "[ground.horizontal]\nrecord = \"R.AT2\"\n[run]\nt_end = 0.5\n"
                                                  "[output]\ntrajectory = \"R.AT2\"\n";
  ::symlink("R.AT2", (d.path + "/alias.AT2").c_str());
  const std::string before = slurp(d.path + "/R.AT2");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {housner({"simulate"}, {"--ground-h-record", "R.AT2", "--t-end", "0.5", "--trajectory", "R.AT2"}),
       "trajectory = 'R.AT2' is the input --ground-h-record"},
      {housner({"simulate"}, {"--ground-h-record", "R.AT2", "--t-end", "0.5", "--trajectory", "alias.AT2"}),
       "is the input --ground-h-record ('R.AT2')"},
      {{"simulate", "scenario.toml", "--trajectory", "R.AT2"}, "is an input of this run"},
      {{"simulate", "scenario_out.toml"}, "is an input of this run"},
      {{"simulate", "scenario.toml", "--json-out", "scenario.toml"}, "is the input scenario"},
      {housner({"fragility"}, {"--records", "suite/*.AT2", "--levels", "0.1", "--json-out", "suite/a.AT2"}),
       "is the input --records"},
      {housner({"simulate"}, {"--w0", "0.1", "--t-end", "0.5", "--plot", "p.png", "--json-out", "p.svg"}),
       "also written by plot"},
      {housner({"fragility"},
               {"--records", "suite/*.AT2", "--levels", "0.1", "--out", "a.csv", "--json-out", "a.csv.journal"}),
       "also written by out"},
      {housner({"fragility"},
               {"--records", "suite/*.AT2", "--levels", "0.1", "--out", "a.csv", "--json-out", "a.json"}),
       "also written by out"},
      {{"motion", "generate", "--arias", "0.3", "--d5-95", "5", "--t-mid", "4", "--f-mid", "4", "--t-end", "12",
        "--out", "D", "--json-out", "D/motions.json"},
       "also written by out"},
      {{"motion", "generate", "--arias", "0.3", "--d5-95", "5", "--t-mid", "4", "--f-mid", "4", "--t-end", "12",
        "--out", "D", "--plot", "D/rezaeian_0001.AT2.png", "--json-out", "D/rezaeian_0001.AT2"},
       "a file of the suite"},
  };
  expect_usage_errors(cases, d.path);
  EXPECT_EQ(slurp(d.path + "/R.AT2"), before);
  EXPECT_FALSE(exists(d.path + "/a.csv"));
}

TEST(CliOutputs, ASymbolicLinkIsWrittenThrough) {
  TmpDir d("outputs_symlink");
  std::filesystem::create_directories(d.path + "/store");
  ::symlink("store/summary.json", (d.path + "/summary.json").c_str());
  ::symlink("store/traj.csv", (d.path + "/traj.csv").c_str());
  const auto r = run_cli(housner({"simulate"}, {"--w0", "0.1", "--t-end", "0.5", "--json-out", "summary.json",
                                                "--trajectory", "traj.csv", "--quiet"}),
                         d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  struct stat st {};
  for (const char* f : {"summary.json", "traj.csv"}) {
    ASSERT_EQ(::lstat((d.path + "/" + f).c_str(), &st), 0);
    EXPECT_TRUE(S_ISLNK(st.st_mode)) << f << " was replaced by a regular file";
  }
  EXPECT_FALSE(json::parse(slurp(d.path + "/store/summary.json")).empty());
  EXPECT_EQ(slurp(d.path + "/store/traj.csv").rfind("t,", 0), 0u);
  // Written again through the same link (the target exists now): still a link.
  ASSERT_EQ(
      run_cli(housner({"simulate"}, {"--w0", "0.2", "--t-end", "0.5", "--json-out", "summary.json", "--quiet"}), d.path)
          .code,
      0);
  ASSERT_EQ(::lstat((d.path + "/summary.json").c_str(), &st), 0);
  EXPECT_TRUE(S_ISLNK(st.st_mode));
}

TEST(CliOutputs, AResumedStudyIsTheSameRecords) {
  // The runner's fingerprint covers the records' contents (a hash of their samples), not only their
  // names: after a record is edited, a finished fragility table or rocking spectrum is not reused.
  TmpDir d("outputs_resume");
  std::filesystem::create_directories(d.path + "/suite");
  std::filesystem::copy_file(kRecord, d.path + "/suite/a.AT2");
  std::filesystem::copy_file(kRecord, d.path + "/suite/b.AT2");
  const std::vector<std::string> frag = housner({"fragility"}, {"--records", "suite/*.AT2", "--levels", "0.1,0.2",
                                                                "--bootstrap", "0", "--out", "f.csv", "--quiet"});
  const std::vector<std::string> rock = {"rocking-spectrum", "--record", "suite/a.AT2", "--alpha", "0.2",
                                         "--p-values",       "1,2",      "--out",       "r.csv",   "--quiet"};
  for (const auto& args : {frag, rock}) ASSERT_EQ(run_cli(args, d.path).code, 0) << args[0];
  auto with_resume = [](std::vector<std::string> a) {
    a.push_back("--resume");
    return a;
  };
  EXPECT_EQ(run_cli(with_resume(frag), d.path).code, 0) << "the same records resume";
  // The same name, one sample changed.
  std::string text = slurp(d.path + "/suite/a.AT2");
  const auto at = text.find("NPTS");
  const auto first = text.find("0.0000000E+00", text.find('\n', at));
  ASSERT_NE(first, std::string::npos);
  text.replace(first, 13, "1.0000000E-03");
  std::ofstream(d.path + "/suite/a.AT2", std::ios::binary | std::ios::trunc) << text;
  for (const auto& args : {frag, rock}) {
    const auto r = run_cli(with_resume(args), d.path);
    EXPECT_EQ(r.code, 2) << args[0] << ": " << r.err;
    EXPECT_NE(r.err.find("does not record a finished sweep of this definition"), std::string::npos) << r.err;
  }
}
