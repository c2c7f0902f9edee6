// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/io/atomic_file.hpp"

#include <unistd.h>

#include <cstdio>
#include <stdexcept>

namespace blockdyn {

AtomicFile::AtomicFile(std::string path)
    : path_(std::move(path)), tmp_(path_ + ".tmp." + std::to_string(::getpid())) {
  out_.open(tmp_, std::ios::out | std::ios::trunc);
  if (!out_) throw std::runtime_error("cannot open '" + path_ + "' for writing");
  out_.precision(17);
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::remove(tmp_.c_str());
  }
}

void AtomicFile::commit() {
  out_.flush();
  if (!out_) throw std::runtime_error("write to '" + path_ + "' failed");
  out_.close();
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0)
    throw std::runtime_error("cannot rename '" + tmp_ + "' to '" + path_ + "'");
  committed_ = true;
}

void write_file_atomically(const std::string& path, const std::string& content) {
  AtomicFile f(path);
  f.stream() << content;
  f.commit();
}

}  // namespace blockdyn
