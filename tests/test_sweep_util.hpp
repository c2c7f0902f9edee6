// SPDX-License-Identifier: Apache-2.0
#pragma once
// Helpers for the sweep tests: temporary directories, files, and running the CLI.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace sweep_test {

inline std::string make_tmpdir(const std::string& tag) {
  std::string tmpl = (std::filesystem::temp_directory_path() / ("blockdyn-" + tag + "-XXXXXX")).string();
  if (!::mkdtemp(tmpl.data())) throw std::runtime_error("mkdtemp failed");
  return tmpl;
}

// A temporary directory removed at scope exit unless the test failed (kept for inspection).
struct TmpDir {
  std::string path;
  explicit TmpDir(const std::string& tag) : path(make_tmpdir(tag)) {}
  ~TmpDir() {
    if (!::testing::Test::HasFailure()) {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  }
  TmpDir(const TmpDir&) = delete;
  TmpDir& operator=(const TmpDir&) = delete;
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline bool exists(const std::string& p) { return ::access(p.c_str(), F_OK) == 0; }

inline std::size_t count_lines(const std::string& s) {
  std::size_t n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

struct CliResult {
  int code = -1;
  std::string out, err;
};

inline std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Runs `[prefix] BLOCKDYN_CLI args...` through the shell and collects its output.
inline CliResult run_cli(const std::vector<std::string>& args, const std::string& dir, const std::string& prefix = "") {
  std::string cmd = "cd " + quote(dir) + " && " + prefix + " " + quote(BLOCKDYN_CLI);
  for (const auto& a : args) cmd += " " + quote(a);
  cmd += " >" + quote(dir + "/cli.out") + " 2>" + quote(dir + "/cli.err");
  const int rc = std::system(cmd.c_str());
  CliResult r;
  r.code = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  r.out = slurp(dir + "/cli.out");
  r.err = slurp(dir + "/cli.err");
  return r;
}

// Starts the CLI in `dir` without waiting (stdout/stderr to files there); returns its pid.
inline pid_t spawn_cli(const std::vector<std::string>& args, const std::string& dir) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    const int o = ::open("spawn.out", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = ::open("spawn.err", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(o, 1);
    ::dup2(e, 2);
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(BLOCKDYN_CLI));
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(BLOCKDYN_CLI, argv.data());
    ::_exit(127);
  }
  return pid;
}

// Command lines that are each a usage error: exit 2, the message naming `word` (and on one line
// when `one_line`).
using UsageCase = std::pair<std::vector<std::string>, std::string>;
inline void expect_usage_errors(const std::vector<UsageCase>& cases, const std::string& dir, bool one_line = false) {
  for (const auto& [args, word] : cases) {
    const CliResult r = run_cli(args, dir);
    EXPECT_EQ(r.code, 2) << word << ": " << r.err;
    EXPECT_NE(r.err.find(word), std::string::npos) << word << ": " << r.err;
    if (one_line) {
      EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    }
  }
}

}  // namespace sweep_test
