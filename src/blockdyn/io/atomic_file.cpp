// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/io/atomic_file.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <mutex>

#include <cstdio>
#include <stdexcept>

#include "blockdyn/io/input_files.hpp"

namespace blockdyn {

namespace {

// Fixed slots, written before a path is published (ready = true) and read by the handler with
// async-signal-safe calls only.
constexpr int kSlots = 64;
struct Slot {
  std::atomic<bool> ready{false};
  char path[4096];
};
Slot g_slots[kSlots];
std::mutex g_slots_mutex;

extern "C" void cleanup_and_reraise(int sig) {
  for (auto& s : g_slots)
    if (s.ready.load()) ::unlink(s.path);
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

std::string reason() { return std::strerror(errno); }

}  // namespace

RemoveOnSignal::RemoveOnSignal(const std::string& path) {
  if (path.size() >= sizeof(Slot::path)) return;
  std::lock_guard<std::mutex> lock(g_slots_mutex);
  for (int i = 0; i < kSlots; ++i) {
    if (g_slots[i].ready.load()) continue;
    std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
    g_slots[i].ready.store(true);
    slot_ = i;
    return;
  }
}

RemoveOnSignal::~RemoveOnSignal() {
  if (slot_ >= 0) g_slots[slot_].ready.store(false);
}

void install_signal_cleanup() {
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) ::signal(sig, cleanup_and_reraise);
}

std::string resolve_symlinks(const std::string& path) {
  std::string p = path;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    char buf[4096];
    const ssize_t n = ::readlink(p.c_str(), buf, sizeof buf - 1);
    if (n <= 0) return p;
    std::string target(buf, std::size_t(n));
    if (target[0] != '/') {
      const auto slash = p.find_last_of('/');
      if (slash != std::string::npos) target = p.substr(0, slash + 1) + target;
    }
    p = target;
  }
  throw std::invalid_argument("output '" + path + "': too many levels of symbolic links");
}

AtomicFile::AtomicFile(std::string path)
    : path_(resolve_symlinks(path)), tmp_(path_ + ".tmp." + std::to_string(::getpid())), guard_(tmp_) {
  require_not_input("output", path);
  struct stat st {};
  const bool exists = ::stat(path_.c_str(), &st) == 0;
  if (exists && S_ISDIR(st.st_mode)) throw std::invalid_argument("output '" + path_ + "' is a directory");
  // A device, a FIFO or a socket (/dev/null, /dev/stdout, a process substitution) is written
  // into: renaming a temporary onto it would replace it with a regular file.
  direct_ = exists && !S_ISREG(st.st_mode);
  out_.open(direct_ ? path_ : tmp_, std::ios::out | std::ios::trunc);
  if (!out_) throw std::invalid_argument("cannot open '" + path_ + "' for writing: " + reason());
  out_.precision(17);
}

AtomicFile::~AtomicFile() {
  if (!committed_ && !direct_) {
    out_.close();
    std::remove(tmp_.c_str());
  }
}

void AtomicFile::commit() {
  out_.flush();
  if (!out_) throw std::runtime_error("write to '" + path_ + "' failed");
  out_.close();
  if (!direct_ && std::rename(tmp_.c_str(), path_.c_str()) != 0)
    throw std::runtime_error("cannot rename '" + tmp_ + "' to '" + path_ + "': " + reason());
  committed_ = true;
}

void write_file_atomically(const std::string& path, const std::string& content) {
  AtomicFile f(path);
  f.stream() << content;
  f.commit();
}

}  // namespace blockdyn
