// SPDX-License-Identifier: Apache-2.0
#pragma once
// Write-to-temporary-then-rename: a reader never sees a partial file, and a failed run leaves
// no output behind.
#include <fstream>
#include <string>

namespace blockdyn {

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
  bool committed_ = false;
};

// Convenience: write a whole string atomically.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace blockdyn
