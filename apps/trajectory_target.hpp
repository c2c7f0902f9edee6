// SPDX-License-Identifier: Apache-2.0
#pragma once
// Where a command's trajectory CSV goes: the user's file, or a temporary file when only figures
// made from it are asked for (removed afterwards, also on failure and on SIGINT/SIGTERM).
#include <unistd.h>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "blockdyn/io/atomic_file.hpp"
#include "cli_common.hpp"

namespace blockdyn::cli {

// A trajectory file (or a temporary one when only a plot is asked), written atomically.
struct TrajectoryTarget {
  std::string path;
  bool temporary = false;
  std::unique_ptr<AtomicFile> file;
  std::unique_ptr<RemoveOnSignal> cleanup;  // the temporary CSV while the plot is made
  // tag: names the temporary file (several targets in one command need distinct tags).
  TrajectoryTarget(const std::string& trajectory, const std::string& plot, const std::string& tag = "trajectory")
      : path(trajectory) {
    if (path.empty() && !plot.empty()) {  // plot: any figure made from the trajectory
      temporary = true;
      path = "/tmp/blockdyn-" + tag + "-" + std::to_string(::getpid()) + ".csv";
      cleanup = std::make_unique<RemoveOnSignal>(path);
    }
    if (!path.empty()) file = std::make_unique<AtomicFile>(path);
  }
  // Figures from the trajectory (script, output, extra arguments); the temporary CSV is removed
  // afterwards (also when a script fails).
  struct Figure {
    std::string script, out;
    std::vector<std::string> extra;
  };
  void figures_and_clean(const std::vector<Figure>& figs) {
    if (file) file->commit();
    try {
      for (const Figure& fg : figs) {
        if (fg.out.empty()) continue;
        std::vector<std::string> args{path, fg.out};
        args.insert(args.end(), fg.extra.begin(), fg.extra.end());
        run_python(fg.script, args);
      }
    } catch (...) {
      if (temporary) std::remove(path.c_str());
      throw;
    }
    if (temporary) std::remove(path.c_str());
  }
};

}  // namespace blockdyn::cli
