// SPDX-License-Identifier: Apache-2.0
#pragma once
// Write-to-temporary-then-rename: a reader never sees a partial file, and a failed run leaves
// no output behind. A target that exists and is not a regular file (a device such as /dev/null,
// a FIFO, /dev/stdout) is written into instead, never replaced.
#include <fstream>
#include <string>

namespace blockdyn {

// Files to delete if the process is interrupted (SIGINT, SIGTERM, SIGHUP) before they are done
// with: an AtomicFile's temporary registers itself; others (a temporary CSV made for a plot) use
// a RemoveOnSignal. install_signal_cleanup() sets the handlers (the command-line program does;
// an embedding application keeps its own): they delete the registered files, then let the
// signal end the process as it would have.
class RemoveOnSignal {
 public:
  explicit RemoveOnSignal(const std::string& path);
  ~RemoveOnSignal();
  RemoveOnSignal(const RemoveOnSignal&) = delete;
  RemoveOnSignal& operator=(const RemoveOnSignal&) = delete;

 private:
  int slot_ = -1;
};
void install_signal_cleanup();

// The file a path finally names, following symbolic links (a link's own name when it dangles at
// its last hop: the target is created through it).
std::string resolve_symlinks(const std::string& path);

// A symbolic link given as the path is written through (its target is replaced, the link kept);
// a path naming one of the run's inputs (input_files.hpp) is refused.
class AtomicFile {
 public:
  explicit AtomicFile(std::string path);
  ~AtomicFile();  // removes the temporary unless commit() succeeded
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return out_; }
  void commit();  // flush, close and rename onto the target; throws on I/O failure
  const std::string& path() const { return path_; }

 private:
  std::string path_, tmp_;
  std::ofstream out_;
  RemoveOnSignal guard_;
  bool committed_ = false;
  bool direct_ = false;  // the target is not a regular file: written in place
};

// Convenience: write a whole string atomically.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace blockdyn
